// Mitsuba's named conductors (`material` of conductor / roughconductor) as RGB complex IORs.
#pragma once
#include <string>

namespace gdr {

struct ComplexIor {
  float eta[3];
  float k[3];
};

// The complex IOR of a named conductor ("Au", "Cu", "none", ...); false when unknown.
// "none" is Mitsuba's perfect mirror: eta = 0, k = 1 (a purely imaginary IOR reflects everything).
bool named_conductor(const std::string& name, ComplexIor* ior);
std::string named_conductor_list();

}  // namespace gdr
