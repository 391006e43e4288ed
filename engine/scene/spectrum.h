// Spectra to linear sRGB exactly as Mitsuba 3's RGB variants convert them while loading a scene
// (spectrum_list_to_srgb, called from Properties::get_texture_impl), so that a spectral scene
// gets the colours Mitsuba gives it:
//  - the samples are interpolated linearly and are zero outside the listed range;
//  - they are weighted by the CIE 1931 colour-matching functions (the CIE's 5 nm table over
//    360..830 nm, interpolated linearly: cie1931_d65_5nm.inc) and, for everything but emission
//    and Mitsuba's measured IOR data, by D65 normalized to luminance 1, summed at 1000 evenly spaced wavelengths from 360 to
//    830 nm and scaled so that a flat emission spectrum of 1 has luminance 1;
//  - XYZ goes to linear sRGB by Mitsuba's matrix; then a reflectance is clamped to [0, 1] and
//    anything else (emission, a conductor's eta and k) to at least 0.
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

// How a value is used decides Mitsuba's two flags: weighting by D65 and the clamping range.
enum class SpectrumUse {
  Reflectance,  // BSDF reflectances and textures: under D65, clamped to [0, 1] (bounded)
  Unbounded,    // a conductor's eta and k: under D65, clamped to >= 0
  Emission,     // radiance, intensity, irradiance: no D65, clamped to >= 0
  // A named conductor's eta and k from Mitsuba's data/ior files: no D65, clamped to >= 0 (its
  // ior_from_file passes d65 = false, unlike an eta spectrum written in the scene).
  IorFile,
};

// The CIE 1931 colour-matching functions at `nm`, zero outside 360..830 nm.
void cie1931_xyz(double nm, double xyz[3]);
// CIE D65 at `nm` scaled to luminance 1 (Mitsuba's cie_d65), zero outside 360..830 nm.
double cie_d65(double nm);

// The converted colour, and what it was before the clamping (for the warning that names it).
struct SpectrumRgb {
  Rgb rgb;
  double unclamped[3] = {0, 0, 0};
  bool clamped = false;
};

// A spectrum sampled at increasing wavelengths (nm, at least two samples; fewer give black).
SpectrumRgb spectrum_to_rgb(const std::vector<std::pair<double, double>>& samples, SpectrumUse use);

// Its CIE XYZ by that rule, weighted by the normalized D65 when `d65` (before the matrix).
void spectrum_to_xyz(const std::vector<std::pair<double, double>>& samples, bool d65, double xyz[3]);

// A single-value spectrum: (v, v, v), except as emission, where it is the flat spectrum of value
// v (illuminant E, slightly pink next to the D65 white): v times XYZ (1, 1, 1) in sRGB.
Rgb uniform_spectrum_to_rgb(double value, SpectrumUse use);

// Planck's law in W m^-2 sr^-1 nm^-1 (the constants of Mitsuba 3's blackbody plugin) between
// nm_min and nm_max, converted like a listed spectrum.
SpectrumRgb blackbody_spectrum_to_rgb(double kelvin, double nm_min, double nm_max, SpectrumUse use);

// Mitsuba 0.x's <blackbody>: the colour of Planck's law at `kelvin`, scaled to luminance 1.
Rgb blackbody_to_rgb(double kelvin);

float srgb_to_linear(float v);

}  // namespace gdr
