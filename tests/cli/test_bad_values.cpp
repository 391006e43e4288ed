// Values that must not pass silently, through the command line: each bad scene exits non-zero
// with file, line and the problem, and leaves nothing but the scene in the folder; the warnings
// name file and line and the render goes on.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "cli/cli_harness.h"

namespace gdr::test {
namespace {

// A scene whose line 3 holds `line3` (a light is on line 2).
std::string scene_with(const std::string& line3) {
  return "<scene version=\"3.0.0\">\n"
         "<emitter type=\"point\"><point name=\"position\" x=\"0\" y=\"2\" z=\"-4\"/></emitter>\n" +
         line3 +
         "\n<sensor type=\"perspective\"><film type=\"hdrfilm\"><integer name=\"width\" value=\"4\"/>"
         "<integer name=\"height\" value=\"4\"/></film></sensor>\n</scene>\n";
}

int files_in(const TempDir& dir) {
  int n = 0;
  for (const auto& e : std::filesystem::directory_iterator(dir.path())) n += e.is_regular_file() ? 1 : 0;
  return n;
}

void expect_rejected(const std::string& line3, const std::vector<std::string>& words, const std::string& flags = "") {
  TempDir dir;
  std::ofstream(dir.file("bad.xml")) << scene_with(line3);
  CliResult r = run_gdrender("bad.xml --spp 1 -o out.exr --stats s.json " + flags, dir);
  EXPECT_EQ(r.code, 1) << r.output;
  EXPECT_NE(r.output.find("bad.xml:3"), std::string::npos) << r.output;
  for (const std::string& w : words) EXPECT_NE(r.output.find(w), std::string::npos) << r.output;
  EXPECT_EQ(files_in(dir), 1) << "only the scene may remain";
}

TEST(BadValues, NonFiniteAndNegativeColoursAreRejected) {
  expect_rejected("<shape type=\"sphere\"><bsdf type=\"diffuse\"><rgb name=\"reflectance\" value=\"nan\"/></bsdf></shape>",
                  {"reflectance", "not finite"});
  expect_rejected("<shape type=\"sphere\"><emitter type=\"area\"><rgb name=\"radiance\" value=\"1, -2, 1\"/></emitter></shape>",
                  {"radiance", "negative"});
  expect_rejected("<emitter type=\"envmap\"><string name=\"filename\" value=\"sky.exr\"/><float name=\"scale\" value=\"-1\"/></emitter>",
                  {"scale", "negative"});
}

TEST(BadValues, UnknownParameterIsAnErrorWithStrict) {
  expect_rejected("<shape type=\"sphere\"><bsdf type=\"diffuse\"><rgb name=\"reflectanse\" value=\"0.5\"/></bsdf></shape>",
                  {"reflectanse"}, "--strict");
}

TEST(BadValues, WarningsNameFileAndLineAndTheRenderGoesOn) {
  TempDir dir;
  std::ofstream(dir.file("warn.xml")) << scene_with(
      "<shape type=\"sphere\"><bsdf type=\"diffuse\"><rgb name=\"reflectanse\" value=\"0.5\"/>"
      "<rgb name=\"reflectance\" value=\"3\"/></bsdf></shape>");
  CliResult r = run_gdrender("warn.xml --spp 1 -o out.exr", dir);
  ASSERT_EQ(r.code, 0) << r.output;
  EXPECT_NE(r.output.find("warn.xml:3: <rgb name=\"reflectanse\">"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("clamped to 1"), std::string::npos) << r.output;
  EXPECT_TRUE(std::filesystem::exists(dir.file("out.exr")));
}

}  // namespace
}  // namespace gdr::test
