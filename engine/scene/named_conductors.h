// Mitsuba's named conductors (`material` of conductor / roughconductor) as RGB complex IORs.
#pragma once
#include <string>

namespace gdr {

struct ComplexIor {
  float eta[3];
  float k[3];
};

// The complex IOR of a named conductor, with Mitsuba 3's names exactly ("Au", "Cu", "Cu_palik",
// "none", ...) and the RGB values its RGB variants give them; false when unknown.
// "none" is Mitsuba's perfect mirror: eta = 0, k = 1 (a purely imaginary IOR reflects everything).
bool named_conductor(const std::string& name, ComplexIor* ior);
std::string named_conductor_list();

// The complex IOR in Mitsuba's data files DIR/NAME.eta.spd and DIR/NAME.k.spd, converted as Mitsuba
// 3's RGB variants convert them (complex_ior_from_file; SpectrumUse::IorFile). The named table is
// this applied to Mitsuba's data/ior folder (scripts/named-conductors). InputError on a bad file.
ComplexIor conductor_from_spd_files(const std::string& dir, const std::string& name);

}  // namespace gdr
