#include "scene/spectrum.h"
#include "shared/color.h"

#include <algorithm>
#include <cmath>

namespace gdr {
namespace {

// Piecewise Gaussian lobe of the Wyman et al. fit.
double lobe(double x, double mu, double s1, double s2) {
  double t = (x - mu) / (x < mu ? s1 : s2);
  return std::exp(-0.5 * t * t);
}

// CIE standard illuminant D65, 380..780 nm in 10 nm steps.
const double kD65[41] = {49.98,  54.65,  82.75,  91.49,  93.43,  86.68,  104.86, 117.01, 117.81,
                         114.86, 115.92, 108.81, 109.35, 107.80, 104.79, 107.69, 104.41, 104.05,
                         100.00, 96.33,  95.79,  88.69,  90.01,  89.60,  87.70,  83.29,  83.70,
                         80.03,  80.21,  82.28,  78.28,  69.72,  71.61,  74.35,  61.60,  69.89,
                         75.09,  63.59,  46.42,  66.81,  63.38};

double d65(double nm) {
  double t = std::clamp((nm - 380.0) / 10.0, 0.0, 40.0);
  int i = std::min(static_cast<int>(t), 39);
  double f = t - i;
  return kD65[i] * (1 - f) + kD65[i + 1] * f;
}

Rgb xyz_to_linear_srgb(const double xyz[3]) {
  double x = xyz[0], y = xyz[1], z = xyz[2];
  return {static_cast<float>(3.2404542 * x - 1.5371385 * y - 0.4985314 * z),
          static_cast<float>(-0.9692660 * x + 1.8760108 * y + 0.0415560 * z),
          static_cast<float>(0.0556434 * x - 0.2040259 * y + 1.0572252 * z)};
}

// Integrates f(nm) * cmf over 380..780 nm in 1 nm steps. Reflectance: weighted by D65 and
// divided, channel by channel in RGB, by the same integral of the white (f = 1), so that white
// maps exactly to (1, 1, 1) despite the fitted curves. Emission: XYZ / integral of y-bar.
template <class F>
Rgb integrate_rgb(F f, SpectrumUse use) {
  bool reflect = use == SpectrumUse::Reflectance;
  double xyz[3] = {0, 0, 0}, white[3] = {0, 0, 0};
  for (double nm = 380.0; nm <= 780.0; nm += 1.0) {
    double c[3];
    cie_xyz(nm, c);
    double w = reflect ? d65(nm) : 1.0, v = f(nm);
    for (int i = 0; i < 3; ++i) {
      xyz[i] += c[i] * w * v;
      white[i] += c[i] * w;
    }
  }
  if (!reflect) {
    for (double& v : xyz) v /= white[1];
    return xyz_to_linear_srgb(xyz);
  }
  Rgb rgb = xyz_to_linear_srgb(xyz), ref = xyz_to_linear_srgb(white);
  return {rgb.r / ref.r, rgb.g / ref.g, rgb.b / ref.b};
}

}  // namespace

void cie_xyz(double nm, double xyz[3]) {
  xyz[0] = 1.056 * lobe(nm, 599.8, 37.9, 31.0) + 0.362 * lobe(nm, 442.0, 16.0, 26.7) -
           0.065 * lobe(nm, 501.1, 20.4, 26.2);
  xyz[1] = 0.821 * lobe(nm, 568.8, 46.9, 40.5) + 0.286 * lobe(nm, 530.9, 16.3, 31.1);
  xyz[2] = 1.217 * lobe(nm, 437.0, 11.8, 36.0) + 0.681 * lobe(nm, 459.0, 26.0, 13.8);
}

Rgb spectrum_to_rgb(const std::vector<std::pair<double, double>>& samples, SpectrumUse use) {
  if (samples.empty()) return {};
  if (samples.size() == 1) return Rgb(static_cast<float>(samples[0].second));
  return integrate_rgb([&](double nm) {
    if (nm <= samples.front().first) return samples.front().second;
    if (nm >= samples.back().first) return samples.back().second;
    auto it = std::upper_bound(samples.begin(), samples.end(), nm,
                               [](double v, const std::pair<double, double>& s) { return v < s.first; });
    const auto& b = *it;
    const auto& a = *(it - 1);
    double span = b.first - a.first;
    double t = span > 0 ? (nm - a.first) / span : 0.0;
    return a.second * (1 - t) + b.second * t;
  }, use);
}

Rgb blackbody_to_rgb(double kelvin) {
  const double h = 6.62607015e-34, c = 2.99792458e8, kb = 1.380649e-23;
  auto planck = [&](double nm) {
    double l = nm * 1e-9;
    double e = std::exp(std::min(h * c / (l * kb * std::max(kelvin, 1.0)), 700.0));
    return 2 * h * c * c / (std::pow(l, 5) * (e - 1));
  };
  Rgb rgb = integrate_rgb(planck, SpectrumUse::Emission);
  double y = gdr_luminance(rgb.r, rgb.g, rgb.b);
  float s = y > 0 && std::isfinite(y) ? static_cast<float>(1.0 / y) : 0.0f;
  return {rgb.r * s, rgb.g * s, rgb.b * s};
}

float srgb_to_linear(float v) {
  return v <= 0.04045f ? v / 12.92f : std::pow((v + 0.055f) / 1.055f, 2.4f);
}

}  // namespace gdr
