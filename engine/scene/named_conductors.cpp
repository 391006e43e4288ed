#include "scene/named_conductors.h"

#include "scene/spd_file.h"
#include "scene/spectrum.h"

namespace gdr {
namespace {

struct NamedConductor {
  const char* name;
  ComplexIor ior;
};

const NamedConductor kConductors[] = {
    // Mitsuba's special profile, no data file: uniform eta = 0, k = 1.
    {"none", {{0.0f, 0.0f, 0.0f}, {1.0f, 1.0f, 1.0f}}},
#include "scene/named_conductors_table.inc"
};

}  // namespace

bool named_conductor(const std::string& name, ComplexIor* ior) {
  for (const NamedConductor& e : kConductors) {
    if (name == e.name) {
      *ior = e.ior;
      return true;
    }
  }
  return false;
}

std::string named_conductor_list() {
  std::string s;
  for (const NamedConductor& e : kConductors) s += (s.empty() ? "" : ", ") + std::string(e.name);
  return s;
}

ComplexIor conductor_from_spd_files(const std::string& dir, const std::string& name) {
  Rgb eta = spectrum_to_rgb(read_spd_file(dir + "/" + name + ".eta.spd"), SpectrumUse::IorFile).rgb;
  Rgb k = spectrum_to_rgb(read_spd_file(dir + "/" + name + ".k.spd"), SpectrumUse::IorFile).rgb;
  return {{eta.r, eta.g, eta.b}, {k.r, k.g, k.b}};
}

}  // namespace gdr
