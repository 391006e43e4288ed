#include "render/integrator_params.h"

#include <cmath>
#include <cstdlib>

#include "util/error.h"

namespace gdr {

std::string IntegratorParams::choice(const std::string& name, const std::string& fallback,
                                     const std::vector<std::string>& choices) const {
  auto it = values_.find(name);
  if (it == values_.end()) return fallback;
  for (const std::string& c : choices) {
    if (c == it->second) return c;
  }
  std::string list;
  for (const std::string& c : choices) list += (list.empty() ? "" : ", ") + c;
  throw Error("integrator parameter " + name + ": '" + it->second + "' is not one of " + list);
}

float IntegratorParams::non_negative(const std::string& name, float fallback) const {
  auto it = values_.find(name);
  if (it == values_.end()) return fallback;
  const char* text = it->second.c_str();
  char* end = nullptr;
  float v = std::strtof(text, &end);
  if (end == text || *end != '\0' || !std::isfinite(v) || v < 0) {
    throw Error("integrator parameter " + name + ": '" + it->second + "' is not a finite number >= 0");
  }
  return v;
}

bool IntegratorParams::flag(const std::string& name, bool fallback) const {
  auto it = values_.find(name);
  if (it == values_.end()) return fallback;
  if (it->second == "true") return true;
  if (it->second == "false") return false;
  throw Error("integrator parameter " + name + ": '" + it->second + "' is not true or false");
}

}  // namespace gdr
