#include "scene/named_iors.h"

#include <cctype>

namespace gdr {
namespace {

struct NamedIor {
  const char* name;
  float ior;
};

// The names and values of Mitsuba's table of named IORs (sodium D line, 589 nm).
const NamedIor kIors[] = {
    {"vacuum", 1.0f},        {"helium", 1.000036f},   {"hydrogen", 1.000132f},
    {"air", 1.000277f},      {"carbon dioxide", 1.00045f}, {"water", 1.3330f},
    {"acetone", 1.36f},      {"ethanol", 1.361f},     {"carbon tetrachloride", 1.461f},
    {"glycerol", 1.4729f},   {"benzene", 1.501f},     {"silicone oil", 1.52045f},
    {"bromine", 1.661f},     {"water ice", 1.31f},    {"fused quartz", 1.458f},
    {"pyrex", 1.470f},       {"acrylic glass", 1.49f}, {"polypropylene", 1.49f},
    {"bk7", 1.5046f},        {"sodium chloride", 1.544f}, {"amber", 1.55f},
    {"pet", 1.5750f},        {"diamond", 2.419f},
};

}  // namespace

bool named_ior(const std::string& name, float* ior) {
  std::string lower;
  for (char c : name) lower += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  for (const NamedIor& e : kIors) {
    if (lower == e.name) {
      *ior = e.ior;
      return true;
    }
  }
  return false;
}

std::string named_ior_list() {
  std::string s;
  for (const NamedIor& e : kIors) s += (s.empty() ? "" : ", ") + std::string(e.name);
  return s;
}

}  // namespace gdr
