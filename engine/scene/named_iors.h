// Mitsuba's named indices of refraction (int_ior / ext_ior given as a material name).
#pragma once
#include <string>

namespace gdr {

// The IOR of a named material ("bk7", "water", "air", ...); false when the name is unknown.
bool named_ior(const std::string& name, float* ior);
// The known names, comma separated, for error messages.
std::string named_ior_list();

}  // namespace gdr
