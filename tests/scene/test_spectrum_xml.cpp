// <spectrum> in scenes: each use gets Mitsuba 3's flags (a reflectance bounded and under D65, a
// conductor's eta and k unbounded under D65, emission unbounded without D65), clamps warn naming
// file and line, malformed spectra are errors naming file and line, and the spectrum plugins
// convert like the inline list. Reference colours: mitsuba 3.9.1, scalar_rgb, the XML loaded as
// in test_spectrum.cpp; compared within 1 float ulp.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "scene/load_scene.h"
#include "scene/scene_test_files.h"
#include "util/error.h"

namespace gdr {
namespace {
using test::all_warnings;
using test::has_warning;

const char* kPointLight = R"(<emitter type="point"><point name="position" x="0" y="2" z="0"/></emitter>)";

// The scene's lines: 1 <scene>, 2 <sensor>, 3 the point light, then `body` from line 4.
Scene load_lit(const test::TempFolder& folder, const std::string& body) {
  return load_scene(folder.write(
      "s.xml", test::scene_xml("<sensor type=\"perspective\"/>\n" + std::string(kPointLight) + "\n" + body)));
}

std::string diffuse(const std::string& spectrum) {
  return "<shape type=\"sphere\"><bsdf type=\"diffuse\">\n<spectrum name=\"reflectance\" value=\"" + spectrum +
         "\"/>\n</bsdf></shape>";
}

std::string area(const std::string& radiance_element) {
  return "<shape type=\"sphere\"><emitter type=\"area\">\n" + radiance_element + "\n</emitter></shape>";
}

void expect_ulp(float a, double b, const char* what) {
  double ulp = std::abs(b) > 0 ? std::ldexp(1.0, std::ilogb(static_cast<float>(b)) - 23) : 0.0;
  EXPECT_LE(std::abs(a - b), ulp) << what << ": " << a << " vs Mitsuba " << b;
}

void expect_rgb(const float* c, double r, double g, double b) {
  expect_ulp(c[0], r, "r");
  expect_ulp(c[1], g, "g");
  expect_ulp(c[2], b, "b");
}

const GdrLight& area_light(const Scene& s) {
  for (const GdrLight& l : s.lights)
    if (l.type == LIGHT_AREA) return l;
  throw std::runtime_error("no area light");
}

TEST(SpectrumXml, ReflectanceIsClampedToZeroOneWithAWarning) {
  test::TempFolder folder;
  // Red above 1, as Mitsuba clamps it (with its "clamping out-of-gamut color" warning).
  Scene s = load_lit(folder, diffuse("380:0.1, 780:2"));
  ASSERT_EQ(s.materials.size(), 1u);
  expect_rgb(s.materials[0].reflectance, 1.0, 0.873267233, 0.388453364);
  EXPECT_TRUE(has_warning(s, {"s.xml:5", "reflectance", "clamped", "1.34513"})) << all_warnings(s);
  // Blue below 0 (outside the sRGB gamut).
  Scene g = load_lit(folder, diffuse("500:0.2, 600:0.9"));
  expect_rgb(g.materials[0].reflectance, 0.318239361, 0.515803158, 0.0);
  EXPECT_TRUE(has_warning(g, {"s.xml:5", "reflectance", "clamped"})) << all_warnings(g);
  // Inside [0, 1]: no warning.
  Scene w = load_lit(folder, diffuse("400:0.5, 700:0.5"));
  expect_rgb(w.materials[0].reflectance, 0.497671008, 0.499878198, 0.497454554);
  EXPECT_TRUE(w.warnings.empty()) << all_warnings(w);
}

TEST(SpectrumXml, EmissionIsUnboundedButNeverNegative) {
  test::TempFolder folder;
  Scene s = load_lit(folder, area("<spectrum name=\"radiance\" value=\"400:0, 500:8, 600:15.6, 700:18.4\"/>"));
  expect_rgb(area_light(s).radiance, 20.7108364, 10.8546343, 2.77115202);
  EXPECT_TRUE(s.warnings.empty()) << all_warnings(s);
  Scene g = load_lit(folder, area("<spectrum name=\"radiance\" value=\"550:1, 560:1\"/>"));
  expect_rgb(area_light(g).radiance, 0.0122890919, 0.133081466, 0.0);
  EXPECT_TRUE(has_warning(g, {"s.xml:5", "radiance", "clamped"})) << all_warnings(g);
  // A single value is the flat spectrum of that value (illuminant E), not grey.
  Scene e = load_lit(folder, area("<spectrum name=\"radiance\" value=\"3\"/>"));
  expect_rgb(area_light(e).radiance, 3.61438179, 2.84487295, 2.72674823);
}

TEST(SpectrumXml, ConductorEtaAndKAreUnbounded) {
  test::TempFolder folder;
  Scene s = load_lit(folder, R"(<shape type="sphere"><bsdf type="conductor">
      <spectrum name="eta" value="400:0, 500:8, 600:15.6, 700:18.4"/> <spectrum name="k" value="2"/>
    </bsdf></shape>)");
  ASSERT_EQ(s.materials.size(), 1u);
  expect_rgb(s.materials[0].eta, 17.7147121, 11.3544292, 3.30450773);
  expect_rgb(s.materials[0].k, 2.0, 2.0, 2.0);
  EXPECT_TRUE(s.warnings.empty()) << all_warnings(s);
}

TEST(SpectrumXml, MalformedSpectraAreErrorsNamingFileAndLine) {
  test::TempFolder folder;
  struct Case {
    const char* value;
    const char* word;
  };
  for (Case c : {Case{"500:0.5", "two"}, Case{"400:0.5, 400:0.6", "increase"}, Case{"600:0.5, 400:0.6", "increase"},
                 Case{"400:0.5, 700:-0.1", "negative"}, Case{"400:0.5, 700:nan", "finite"},
                 Case{"400:0.5, inf:0.5", "finite"}, Case{"400:0.5, 700", "wavelength:value"},
                 Case{"400:0.5, 700:x", "not a number"}, Case{"-0.5", "negative"}}) {
    SCOPED_TRACE(c.value);
    try {
      load_lit(folder, diffuse(c.value));
      FAIL() << "no error";
    } catch (const InputError& e) {
      std::string msg = e.what();
      EXPECT_NE(msg.find("s.xml:5"), std::string::npos) << msg;
      EXPECT_NE(msg.find(c.word), std::string::npos) << msg;
    }
  }
}

TEST(SpectrumXml, SpectrumPluginsConvertLikeTheInlineList) {
  test::TempFolder folder;
  const float* inline_rgb = nullptr;
  Scene listed = load_lit(folder, area("<spectrum name=\"radiance\" value=\"400:0, 500:8, 600:15.6, 700:18.4\"/>"));
  inline_rgb = area_light(listed).radiance;
  for (const char* plugin : {R"(<spectrum type="irregular" name="radiance">
                                 <string name="wavelengths" value="400, 500, 600, 700"/>
                                 <string name="values" value="0, 8, 15.6, 18.4"/></spectrum>)",
                             R"(<spectrum type="regular" name="radiance">
                                 <float name="wavelength_min" value="400"/> <float name="wavelength_max" value="700"/>
                                 <string name="values" value="0, 8, 15.6, 18.4"/></spectrum>)"}) {
    Scene s = load_lit(folder, area(plugin));
    for (int k = 0; k < 3; ++k) EXPECT_EQ(area_light(s).radiance[k], inline_rgb[k]) << plugin;
    EXPECT_TRUE(s.warnings.empty()) << all_warnings(s);
  }
  Scene bb = load_lit(
      folder,
      area(R"(<spectrum type="blackbody" name="radiance"><float name="temperature" value="3000"/></spectrum>)"));
  const float* c = area_light(bb).radiance;
  EXPECT_GT(c[0], c[1]);
  EXPECT_GT(c[1], c[2]);
  EXPECT_TRUE(bb.warnings.empty()) << all_warnings(bb);
  // A typo inside a plugin is an unknown parameter; an unknown plugin is an error at its line.
  Scene typo =
      load_lit(folder, area(R"(<spectrum type="blackbody" name="radiance"><float name="temperature" value="3000"/>
                                    <float name="temprature" value="1"/></spectrum>)"));
  EXPECT_TRUE(has_warning(typo, {"s.xml:6", "temprature"})) << all_warnings(typo);
  try {
    load_lit(folder, area(R"(<spectrum type="cie1931" name="radiance"/>)"));
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("s.xml:5"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("cie1931"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace gdr
