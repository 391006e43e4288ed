#include "scene/spd_file.h"

#include <cmath>
#include <cstdlib>
#include <fstream>

#include "util/error.h"

namespace gdr {

std::vector<std::pair<double, double>> read_spd_file(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw InputError(path, 0, "cannot read the spectral data file");
  std::vector<std::pair<double, double>> samples;
  std::string text;
  for (int line = 1; std::getline(in, text); ++line) {
    text = text.substr(0, text.find('#'));
    std::vector<double> numbers;
    const char* s = text.c_str();
    for (;;) {
      while (*s == ' ' || *s == '\t' || *s == '\r') ++s;
      if (!*s) break;
      char* end = nullptr;
      double v = std::strtod(s, &end);
      if (end == s || !std::isfinite(v)) throw InputError(path, line, "expected finite numbers, found '" + text + "'");
      numbers.push_back(v);
      s = end;
    }
    if (numbers.empty()) continue;
    if (numbers.size() != 2) throw InputError(path, line, "expected 'wavelength value', found '" + text + "'");
    if (!samples.empty() && !(numbers[0] > samples.back().first)) {
      throw InputError(path, line, "wavelengths must increase");
    }
    samples.emplace_back(numbers[0], numbers[1]);
  }
  if (samples.size() < 2) throw InputError(path, 0, "a spectral data file needs at least two samples");
  return samples;
}

}  // namespace gdr
