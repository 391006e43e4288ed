// Spectra to RGB as Mitsuba 3's RGB variants do it: properties of the conversion, and reference
// colours produced by Mitsuba 3 itself.
//
// Reference values: the pip package mitsuba 3.9.1, variant scalar_rgb, loading an XML string and
// reading the resulting texture, e.g.
//   mi.traverse(mi.load_string('<bsdf version="3.0.0" type="diffuse"><spectrum
//       name="reflectance" value="380:0.1, 780:2"/></bsdf>'))['reflectance.value']
// (a conductor's <spectrum name="eta"> for the unbounded use, a point emitter's
// <spectrum name="intensity"> for emission), printed with 9 significant digits. That path
// converts in double from float tables and rounds to float, as spectrum.cpp does; the
// agreement reached is exact (0 ulp) in every case below, and the tests allow 1 ulp.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "scene/scene_test_files.h"
#include "scene/spectrum.h"
#include "util/error.h"

namespace gdr {
namespace {

using Samples = std::vector<std::pair<double, double>>;

// |a - b| within one float ulp of b (and exactly 0 where b is 0).
void expect_ulp(float a, double b, const std::string& what) {
  double ulp = std::abs(b) > 0 ? std::ldexp(1.0, std::ilogb(static_cast<float>(b)) - 23) : 0.0;
  EXPECT_LE(std::abs(a - b), ulp) << what << ": " << a << " vs Mitsuba " << b;
}

void expect_rgb(Rgb c, const double ref[3], const std::string& what) {
  expect_ulp(c.r, ref[0], what + " r");
  expect_ulp(c.g, ref[1], what + " g");
  expect_ulp(c.b, ref[2], what + " b");
}

// "400:0.5, 700:0.5" -> samples.
Samples parse(const std::string& text) {
  Samples s;
  size_t i = 0;
  while (i < text.size()) {
    size_t colon = text.find(':', i), end = text.find(',', colon);
    if (end == std::string::npos) end = text.size();
    s.emplace_back(std::stod(text.substr(i, colon - i)), std::stod(text.substr(colon + 1, end - colon - 1)));
    i = end + 1;
  }
  return s;
}

struct SpectrumReference {
  const char* spectrum;
  SpectrumUse use;
  double rgb[3];
};

const SpectrumReference kReferences[] = {
    {"400:0.5, 700:0.5", SpectrumUse::Reflectance, {0.497671008, 0.499878198, 0.497454554}},
    {"400:0.5, 700:0.5", SpectrumUse::Emission, {0.59984678, 0.474760175, 0.451721668}},
    {"400:0, 500:8, 600:15.6, 700:18.4", SpectrumUse::Emission, {20.7108364, 10.8546343, 2.77115202}},
    {"400:0, 500:8, 600:15.6, 700:18.4", SpectrumUse::Unbounded, {17.7147121, 11.3544292, 3.30450773}},
    {"380:0.1, 780:2", SpectrumUse::Unbounded, {1.34513164, 0.873267233, 0.388453364}},
    {"380:0.1, 780:2", SpectrumUse::Emission, {1.58111095, 0.832236886, 0.339028597}},
    // Clamped by Mitsuba (with its warning): above 1 for a reflectance, below 0 for any use.
    {"380:0.1, 780:2", SpectrumUse::Reflectance, {1.0, 0.873267233, 0.388453364}},
    {"400:0, 500:8, 600:15.6, 700:18.4", SpectrumUse::Reflectance, {1.0, 1.0, 1.0}},
    {"500:0.2, 600:0.9", SpectrumUse::Reflectance, {0.318239361, 0.515803158, 0.0}},
    {"500:0.2, 600:0.9", SpectrumUse::Emission, {0.358584702, 0.505289555, 0.0}},
    {"550:1, 560:1", SpectrumUse::Unbounded, {0.0124792596, 0.137198403, 0.0}},
};

TEST(Spectrum, AgreesWithMitsuba) {
  for (const SpectrumReference& r : kReferences) {
    SpectrumRgb c = spectrum_to_rgb(parse(r.spectrum), r.use);
    expect_rgb(c.rgb, r.rgb, std::string(r.spectrum) + " use " + std::to_string(static_cast<int>(r.use)));
  }
}

TEST(Spectrum, ConstantReflectanceOfOneIsMitsubasWhite) {
  // Over the whole CIE range: not exactly 1 (the integration rule sums 1000 points with a step of
  // 470/1000 nm), but Mitsuba's value, and neutral to 2e-4.
  const double mitsuba[3] = {0.998985291, 0.998873711, 0.998801589};
  SpectrumRgb c = spectrum_to_rgb({{360, 1}, {830, 1}}, SpectrumUse::Reflectance);
  expect_rgb(c.rgb, mitsuba, "white");
  EXPECT_FALSE(c.clamped);
  EXPECT_LT(c.rgb.max() - std::min({c.rgb.r, c.rgb.g, c.rgb.b}), 2e-4f);
  // A flat emission spectrum is illuminant E (pinkish next to D65's white).
  const double e[3] = {1.20488369, 0.94822818, 0.909266829};
  expect_rgb(spectrum_to_rgb({{360, 1}, {830, 1}}, SpectrumUse::Emission).rgb, e, "illuminant E");
}

TEST(Spectrum, SingleValues) {
  // As a reflectance (Mitsuba's uniform texture) the value itself; as emission the flat spectrum
  // of that value: Mitsuba's v * xyz_to_srgb(1, 1, 1).
  Rgb r = uniform_spectrum_to_rgb(0.3, SpectrumUse::Reflectance);
  EXPECT_EQ(r.r, 0.3f);
  EXPECT_EQ(r.g, 0.3f);
  EXPECT_EQ(r.b, 0.3f);
  EXPECT_EQ(uniform_spectrum_to_rgb(2.5, SpectrumUse::Unbounded).b, 2.5f);
  const double three[3] = {3.61438179, 2.84487295, 2.72674823};
  expect_rgb(uniform_spectrum_to_rgb(3, SpectrumUse::Emission), three, "3");
  const double tenth[3] = {0.120479397, 0.0948290974, 0.0908916071};
  expect_rgb(uniform_spectrum_to_rgb(0.1, SpectrumUse::Emission), tenth, "0.1");
}

TEST(Spectrum, IsLinearBeforeClamping) {
  // Same wavelengths, so the interpolant is linear in the values; emission is never clamped
  // above, and these stay inside the gamut.
  Samples a = {{400, 0.2}, {450, 0.9}, {520, 0.4}, {610, 0.7}, {700, 0.1}};
  Samples b = {{400, 1.0}, {450, 0.1}, {520, 0.3}, {610, 0.2}, {700, 0.8}};
  Samples mix = a;
  for (size_t i = 0; i < a.size(); ++i) mix[i].second = 2.5 * a[i].second + 0.75 * b[i].second;
  SpectrumRgb ca = spectrum_to_rgb(a, SpectrumUse::Emission), cb = spectrum_to_rgb(b, SpectrumUse::Emission),
              cm = spectrum_to_rgb(mix, SpectrumUse::Emission);
  for (int k = 0; k < 3; ++k) {
    double expected = 2.5 * ca.unclamped[k] + 0.75 * cb.unclamped[k];
    EXPECT_NEAR(cm.unclamped[k], expected, 1e-12 * std::abs(expected)) << k;
  }
}

TEST(Spectrum, NothingOutsideTheCieRange) {
  for (const Samples& s : {Samples{{200, 5}, {359.9, 5}}, Samples{{830.1, 3}, {2000, 3}}}) {
    for (SpectrumUse use : {SpectrumUse::Reflectance, SpectrumUse::Emission}) {
      SpectrumRgb c = spectrum_to_rgb(s, use);
      EXPECT_EQ(c.rgb.r, 0.0f);
      EXPECT_EQ(c.rgb.g, 0.0f);
      EXPECT_EQ(c.rgb.b, 0.0f);
      EXPECT_FALSE(c.clamped);
    }
  }
  double xyz[3];
  for (double nm : {359.999, 830.001, 1000.0}) {
    cie1931_xyz(nm, xyz);
    EXPECT_EQ(xyz[0] + xyz[1] + xyz[2], 0.0) << nm;
    EXPECT_EQ(cie_d65(nm), 0.0) << nm;
  }
  // Zero outside the listed range (not its end values held): 450..650 nm is the same as that
  // range padded with zeros, and differs from the flat spectrum over the whole CIE range.
  double listed[3], padded[3], whole[3];
  spectrum_to_xyz({{450, 1}, {650, 1}}, false, listed);
  spectrum_to_xyz({{360, 0}, {450 - 1e-6, 0}, {450, 1}, {650, 1}, {650 + 1e-6, 0}, {830, 0}}, false, padded);
  spectrum_to_xyz({{360, 1}, {830, 1}}, false, whole);
  for (int k = 0; k < 3; ++k) {
    EXPECT_NEAR(listed[k], padded[k], 1e-12) << k;
    EXPECT_LT(listed[k], 0.99 * whole[k]) << k;  // y-bar loses the least: 2%
  }
}

TEST(Spectrum, NarrowBandGivesTheColourMatchingValue) {
  // A triangle around one of the 1000 integration wavelengths, narrower than their spacing
  // (470/999 nm), holds that one wavelength with value 1: its XYZ is the colour-matching value
  // there times the rule's weight, 470/1000 nm over Mitsuba's Y normalization 106.75...
  // The CIE 1931 table values around it (CIE 015, 5 nm): 550 nm and 555 nm.
  const int i = 414;
  double nm = 360.0 + (i / 999.0) * 470.0;  // 554.77 nm
  double t = (nm - 550.0) / 5.0;
  const double cie550[3] = {0.4334499, 0.994950100, 0.008749999}, cie555[3] = {0.5120501, 1.0, 0.005749999};
  double xyz[3];
  spectrum_to_xyz({{nm - 0.1, 0}, {nm, 1}, {nm + 0.1, 0}}, false, xyz);
  double weight = 0.47 / 106.7502593994140625;
  for (int k = 0; k < 3; ++k) {
    double expected = (1 - t) * cie550[k] + t * cie555[k];
    EXPECT_NEAR(xyz[k] / weight, expected, 1e-6 * expected) << k;
  }
  double direct[3];
  cie1931_xyz(555.0, direct);
  EXPECT_NEAR(direct[1], 1.0, 1e-7);
  EXPECT_NEAR(direct[0], 0.5120501, 1e-7);
}

TEST(Spectrum, BlackbodyPluginIsPlancksLawInMitsubasUnits) {
  // Restricted to one integration wavelength, the blackbody equals a narrow band whose value is
  // the spectral radiance Mitsuba's blackbody plugin gives there (mitsuba 3.9.1 scalar_spectral:
  // mi.load_dict({'type': 'blackbody', 'temperature': T}).eval(si) with si.wavelengths set;
  // float evaluation, so within 2e-6).
  struct Case {
    double kelvin;
    int i;
    double radiance;  // W m^-2 sr^-1 nm^-1
  };
  for (Case c : {Case{5000, 414, 12739.1768}, Case{3000, 700, 728.881104}, Case{6500, 100, 46550.3945}}) {
    double nm = 360.0 + (c.i / 999.0) * 470.0;
    SpectrumRgb bb = blackbody_spectrum_to_rgb(c.kelvin, nm - 0.1, nm + 0.1, SpectrumUse::Emission);
    SpectrumRgb band = spectrum_to_rgb({{nm - 0.1, 0}, {nm, c.radiance}, {nm + 0.1, 0}}, SpectrumUse::Emission);
    for (int k = 0; k < 3; ++k) {
      EXPECT_NEAR(bb.unclamped[k], band.unclamped[k], 2e-6 * std::abs(band.unclamped[k])) << c.kelvin << " " << k;
    }
  }
  // Warm at 3000 K, blue at 12000 K; the 0.x <blackbody> has luminance 1.
  Rgb warm = blackbody_spectrum_to_rgb(3000, 360, 830, SpectrumUse::Emission).rgb;
  Rgb cold = blackbody_spectrum_to_rgb(12000, 360, 830, SpectrumUse::Emission).rgb;
  EXPECT_GT(warm.r, warm.g);
  EXPECT_GT(warm.g, warm.b);
  EXPECT_GT(cold.b, cold.r);
  Rgb unit = blackbody_to_rgb(6500);
  EXPECT_NEAR(0.212671 * unit.r + 0.715160 * unit.g + 0.072169 * unit.b, 1.0, 1e-6);
}

}  // namespace
}  // namespace gdr
