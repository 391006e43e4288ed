// Mitsuba's spectral data files (.spd, as in its data/ior folder): one "wavelength value" pair a
// line, '#' starting a comment, blank lines allowed.
#pragma once
#include <string>
#include <utility>
#include <vector>

namespace gdr {

// The samples of a .spd file, in file order. InputError naming file and line when it cannot be
// read, a line does not hold exactly two numbers, a number is not finite, the wavelengths do not
// increase, or there are fewer than two samples.
std::vector<std::pair<double, double>> read_spd_file(const std::string& path);

}  // namespace gdr
