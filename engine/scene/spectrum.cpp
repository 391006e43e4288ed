#include "scene/spectrum.h"

#include <algorithm>
#include <cmath>

namespace gdr {
namespace {

// Mitsuba keeps the tables in float and computes the integral in double; converting each
// decimal through double to float gives the same floats as its table.
struct CieRow {
  double nm, x, y, z, d65;
};
const CieRow kCie[] = {
#include "scene/cie1931_d65_5nm.inc"
};
constexpr int kCieSamples = sizeof(kCie) / sizeof(kCie[0]);
static_assert(kCieSamples == 95, "360..830 nm in 5 nm steps");

constexpr double kCieMin = 360.0, kCieMax = 830.0;
// Mitsuba's MI_CIE_Y_NORMALIZATION (a flat emission spectrum of 1 has luminance 1) and
// MI_CIE_D65_NORMALIZATION (D65 has luminance 1).
constexpr double kCieYNormalization = 1.0 / 106.7502593994140625;
constexpr double kD65Normalization = 1.0 / 98.99741751876255;

// Mitsuba's xyz_to_srgb: its float matrix, applied in double with fused multiply-adds (Dr.Jit's
// fmadd), column by column.
const float kXyzToSrgb[3][3] = {{3.240479f, -1.537150f, -0.498535f},
                                {-0.969256f, 1.875991f, 0.041556f},
                                {0.055648f, -0.204043f, 1.057311f}};

void xyz_to_srgb(const double xyz[3], double rgb[3]) {
  for (int i = 0; i < 3; ++i) {
    const float* m = kXyzToSrgb[i];
    rgb[i] = std::fma(double(m[2]), xyz[2], std::fma(double(m[1]), xyz[1], double(m[0]) * xyz[0]));
  }
}

// Linear interpolation in a column of the table, as Mitsuba's cie1931_xyz and cie_d65 do it:
// fmadd(w0, v0, w1 * v1). The fused form matters: without it results differ by up to 5 ulp.
template <class Column>
double table_lerp(double nm, Column column) {
  if (!(nm >= kCieMin && nm <= kCieMax)) return 0.0;
  double t = (nm - kCieMin) * ((kCieSamples - 1) / (kCieMax - kCieMin));
  int i0 = std::clamp(static_cast<int>(t), 0, kCieSamples - 2);
  double w1 = t - i0, w0 = 1.0 - w1;
  double v0 = static_cast<float>(column(kCie[i0])), v1 = static_cast<float>(column(kCie[i0 + 1]));
  return std::fma(w0, v0, w1 * v1);
}

// Mitsuba's integration rule: 1000 wavelengths from 360 to 830 nm inclusive, each weighted by
// (830 - 360) / 1000 (not / 999: reproduced as it is). `value(nm, &v)` is false outside the
// spectrum's range, which then contributes nothing.
template <class Value>
void integrate_xyz(Value value, bool d65, double xyz[3]) {
  const int steps = 1000;
  xyz[0] = xyz[1] = xyz[2] = 0;
  for (int i = 0; i < steps; ++i) {
    double nm = kCieMin + (i / double(steps - 1)) * (kCieMax - kCieMin);
    double v;
    if (!value(nm, &v)) continue;
    double c[3];
    cie1931_xyz(nm, c);
    double w = d65 ? cie_d65(nm) : 1.0;
    for (int k = 0; k < 3; ++k) xyz[k] += c[k] * v * w;
  }
  double scale = (kCieMax - kCieMin) * kCieYNormalization / steps;
  for (int k = 0; k < 3; ++k) xyz[k] *= scale;
}

// To sRGB, then Mitsuba's clamp: [0, 1] for a reflectance, >= 0 otherwise.
SpectrumRgb clamped_rgb(const double xyz[3], SpectrumUse use) {
  SpectrumRgb out;
  xyz_to_srgb(xyz, out.unclamped);
  double hi = use == SpectrumUse::Reflectance ? 1.0 : INFINITY;
  double c[3];
  for (int k = 0; k < 3; ++k) {
    c[k] = std::min(std::max(out.unclamped[k], 0.0), hi);
    out.clamped |= c[k] != out.unclamped[k];
  }
  out.rgb = Rgb(static_cast<float>(c[0]), static_cast<float>(c[1]), static_cast<float>(c[2]));
  return out;
}

// The samples' linear interpolant, false outside their range.
struct SampledValue {
  const std::vector<std::pair<double, double>>& samples;
  bool operator()(double nm, double* v) const {
    if (samples.size() < 2 || nm < samples.front().first || nm > samples.back().first) return false;
    // The last interval whose start is at or below nm (Mitsuba's find_interval).
    auto it = std::upper_bound(samples.begin() + 1, samples.end() - 1, nm,
                               [](double x, const std::pair<double, double>& s) { return x < s.first; });
    auto [w0, v0] = *(it - 1);
    auto [w1, v1] = *it;
    *v = ((nm - w1) * v0 + (w0 - nm) * v1) / (w0 - w1);
    return true;
  }
};

bool uses_d65(SpectrumUse use) { return use == SpectrumUse::Reflectance || use == SpectrumUse::Unbounded; }

}  // namespace

void cie1931_xyz(double nm, double xyz[3]) {
  xyz[0] = table_lerp(nm, [](const CieRow& r) { return r.x; });
  xyz[1] = table_lerp(nm, [](const CieRow& r) { return r.y; });
  xyz[2] = table_lerp(nm, [](const CieRow& r) { return r.z; });
}

double cie_d65(double nm) {
  return table_lerp(nm, [](const CieRow& r) { return r.d65; }) * kD65Normalization;
}

void spectrum_to_xyz(const std::vector<std::pair<double, double>>& samples, bool d65, double xyz[3]) {
  integrate_xyz(SampledValue{samples}, d65, xyz);
}

SpectrumRgb spectrum_to_rgb(const std::vector<std::pair<double, double>>& samples, SpectrumUse use) {
  double xyz[3];
  spectrum_to_xyz(samples, uses_d65(use), xyz);
  return clamped_rgb(xyz, use);
}

Rgb uniform_spectrum_to_rgb(double value, SpectrumUse use) {
  if (use != SpectrumUse::Emission) return Rgb(static_cast<float>(value));
  const double white[3] = {1, 1, 1};
  double rgb[3];
  xyz_to_srgb(white, rgb);
  return {static_cast<float>(value * rgb[0]), static_cast<float>(value * rgb[1]), static_cast<float>(value * rgb[2])};
}

namespace {

// Spectral radiance of a black body in W m^-2 sr^-1 nm^-1, with the constants of Mitsuba 3's
// blackbody plugin.
double planck(double nm, double kelvin) {
  const double c = 2.99792458e+8, h = 6.62607004e-34, k = 1.38064852e-23;
  double l = nm * 1e-9;
  double e = std::expm1(h * c / (l * k * kelvin));
  return e > 0 && std::isfinite(e) ? 1e-9 * 2 * h * c * c / (std::pow(l, 5) * e) : 0.0;
}

}  // namespace

SpectrumRgb blackbody_spectrum_to_rgb(double kelvin, double nm_min, double nm_max, SpectrumUse use) {
  double xyz[3];
  integrate_xyz(
      [&](double nm, double* v) {
        if (nm < nm_min || nm > nm_max) return false;
        *v = planck(nm, kelvin);
        return true;
      },
      uses_d65(use), xyz);
  return clamped_rgb(xyz, use);
}

Rgb blackbody_to_rgb(double kelvin) {
  SpectrumRgb c = blackbody_spectrum_to_rgb(kelvin, kCieMin, kCieMax, SpectrumUse::Emission);
  // Luminance by Mitsuba's weights (the Y row of its srgb_to_xyz).
  double y = 0.212671 * c.rgb.r + 0.715160 * c.rgb.g + 0.072169 * c.rgb.b;
  float s = y > 0 && std::isfinite(y) ? static_cast<float>(1.0 / y) : 0.0f;
  return {c.rgb.r * s, c.rgb.g * s, c.rgb.b * s};
}

float srgb_to_linear(float v) {
  return v <= 0.04045f ? v / 12.92f : std::pow((v + 0.055f) / 1.055f, 2.4f);
}

}  // namespace gdr
