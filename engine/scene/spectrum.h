// Spectra to linear sRGB for an RGB renderer: sampled spectra are integrated against analytic
// fits of the CIE 1931 observer (Wyman, Sloan, Shirley 2013).
//  - Reflectances are seen under D65 (the sRGB white) and normalized by it, so a flat spectrum of
//    value c is the neutral grey (c, c, c): a neutral surface must not tint the light it reflects.
//  - Emission is converted as the colour it is (XYZ normalized by the integral of y-bar, as
//    Mitsuba does): a flat emission spectrum is illuminant E, slightly pink next to D65.
#pragma once
#include <utility>
#include <vector>

namespace gdr {

struct Rgb {
  float r = 0, g = 0, b = 0;
  Rgb() = default;
  Rgb(float v) : r(v), g(v), b(v) {}
  Rgb(float r_, float g_, float b_) : r(r_), g(g_), b(b_) {}
  float max() const { return r > g ? (r > b ? r : b) : (g > b ? g : b); }
};

// The CIE 1931 colour matching functions (multi-lobe fit) at `nm`.
void cie_xyz(double nm, double xyz[3]);

// A spectrum sampled at increasing wavelengths (nm), linearly interpolated between the samples
// and constant beyond the ends (Mitsuba's irregular spectrum), as linear sRGB.
enum class SpectrumUse { Reflectance, Emission };
Rgb spectrum_to_rgb(const std::vector<std::pair<double, double>>& samples, SpectrumUse use);

// Planck's law at `kelvin` as an emission colour, scaled so that its luminance is 1 (the
// absolute scale of Mitsuba's blackbody is not reproduced).
Rgb blackbody_to_rgb(double kelvin);

float srgb_to_linear(float v);

}  // namespace gdr
