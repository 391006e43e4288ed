// The command line rejects bad values with a clear message and a non-zero exit, leaves no image
// behind when it fails, and its informational commands succeed.
#include <gtest/gtest.h>

#include <fstream>
#include <iterator>

#include <nlohmann/json.hpp>

#include "cli/cli_harness.h"
#include "image/image.h"
#include "image/image_io.h"

namespace gdr::test {
namespace {

// A failed run: non-zero exit, the output mentions `needle`, no image was written.
void expect_failure(const CliResult& r, const std::string& needle, const TempDir& dir) {
  EXPECT_NE(r.code, 0) << r.output;
  EXPECT_NE(r.code, -1) << "gdrender crashed: " << r.output;
  EXPECT_NE(r.code, 124) << "gdrender did not stop: " << r.output;
  EXPECT_NE(r.output.find(needle), std::string::npos) << "expected '" << needle << "' in: " << r.output;
  EXPECT_EQ(count_files(dir, ".exr") + count_files(dir, ".png"), 0) << "an image was left behind";
}

TEST(Cli, NonPositiveSppIsRejected) {
  TempDir dir;
  for (const char* spp : {"0", "-4", "abc"}) {
    expect_failure(run_gdrender(kCornell + " --spp " + spp + " -o out.exr", dir), "--spp", dir);
  }
}

TEST(Cli, NonPositiveTimeIsRejected) {
  TempDir dir;
  for (const char* t : {"0", "-1", "nan", "inf"}) {
    expect_failure(run_gdrender(kCornell + " --time " + t + " -o out.exr", dir), "--time", dir);
  }
}

TEST(Cli, UnknownIntegratorIsRejected) {
  TempDir dir;
  CliResult r = run_gdrender(kCornell + " --integrator bogus -D res=8 --spp 1 -o out.exr", dir);
  expect_failure(r, "bogus", dir);
  EXPECT_NE(r.output.find("integrator"), std::string::npos) << r.output;
}

TEST(Cli, UnknownDeviceListsTheDevices) {
  TempDir dir;
  CliResult r = run_gdrender(kCornell + " --device no-such-device-xyz -D res=8 --spp 1 -o out.exr", dir);
  expect_failure(r, "no-such-device-xyz", dir);
  CliResult list = run_gdrender("--list-devices", dir);
  ASSERT_EQ(list.code, 0) << list.output;
  // The first listed device line appears in the error too, so the user sees what exists.
  std::string first = list.output.substr(0, list.output.find('\n'));
  EXPECT_NE(r.output.find(first), std::string::npos) << "error does not list devices: " << r.output;
}

TEST(Cli, MissingSceneFileIsRejected) {
  TempDir dir;
  expect_failure(run_gdrender("no-such-scene.xml -o out.exr", dir), "no-such-scene.xml", dir);
  expect_failure(run_gdrender("--info no-such-scene.xml", dir), "no-such-scene.xml", dir);
}

TEST(Cli, MalformedXmlNamesFileAndLine) {
  TempDir dir;
  dir.write("bad.xml", "<scene version=\"3.0.0\">\n  <shape type=\"sphere\">\n    <float name=\"radius\" value=\"1\"\n"
                       "  </shape>\n</scene>\n");
  CliResult r = run_gdrender("bad.xml -o out.exr --spp 1", dir);
  expect_failure(r, "bad.xml:", dir);
  // "bad.xml:LINE:" with a line number in the file's range.
  size_t at = r.output.find("bad.xml:");
  ASSERT_NE(at, std::string::npos);
  int line = std::atoi(r.output.c_str() + at + 8);
  EXPECT_GE(line, 2) << r.output;
  EXPECT_LE(line, 5) << r.output;
}

TEST(Cli, BadValueInSceneNamesFileAndLine) {
  TempDir dir;
  dir.write("badvalue.xml", "<scene version=\"3.0.0\">\n  <shape type=\"sphere\">\n"
                            "    <float name=\"radius\" value=\"one\"/>\n  </shape>\n</scene>\n");
  expect_failure(run_gdrender("badvalue.xml -o out.exr --spp 1", dir), "badvalue.xml:3", dir);
}

TEST(Cli, NanVertexInMeshIsRejected) {
  TempDir dir;
  dir.write("nan.obj", "v 0 0 0\nv 1 0 0\nv nan 1 0\nf 1 2 3\n");
  dir.write("nan.xml", "<scene version=\"3.0.0\">\n  <shape type=\"obj\">\n"
                       "    <string name=\"filename\" value=\"nan.obj\"/>\n  </shape>\n</scene>\n");
  CliResult r = run_gdrender("nan.xml -o out.exr --spp 1", dir);
  expect_failure(r, "nan.obj", dir);
}

// A transform that takes vertices beyond float range would leave infinite positions in the scene.
TEST(Cli, HugeTransformIsRejected) {
  TempDir dir;
  dir.write("huge.xml", "<scene version=\"3.0.0\">\n  <shape type=\"sphere\">\n"
                        "    <float name=\"radius\" value=\"1e200\"/>\n  </shape>\n</scene>\n");
  expect_failure(run_gdrender("huge.xml -o out.exr --spp 1", dir), "huge.xml:2", dir);
}

TEST(Cli, MalformedDefineIsRejected) {
  TempDir dir;
  expect_failure(run_gdrender(kCornell + " -D res -o out.exr", dir), "-D", dir);
  expect_failure(run_gdrender(kCornell + " -D =5 -o out.exr", dir), "-D", dir);
}

TEST(Cli, ResolutionDefineSetsTheImageSize) {
  TempDir dir;
  CliResult r = run_gdrender(kCornell + " -D res=12 --spp 1 --quiet -o out.exr", dir);
  ASSERT_EQ(r.code, 0) << r.output;
  Image img = read_image(dir.file("out.exr"));
  EXPECT_EQ(img.width, 12);
  EXPECT_EQ(img.height, 12);
  EXPECT_EQ(count_files(dir, ".png"), 1);
}

// --resolution replaces the film's size; a width alone keeps the film's aspect ratio (the
// glossy plates' film is 384x256, the Cornell box's square).
TEST(Cli, ResolutionOptionSetsTheImageSize) {
  TempDir dir;
  const std::string plates = "'" + source_scene("glossy-plates.xml") + "'";
  CliResult r = run_gdrender(plates + " --resolution 30 --spp 1 --quiet -o wide.exr", dir);
  ASSERT_EQ(r.code, 0) << r.output;
  Image wide = read_image(dir.file("wide.exr"));
  EXPECT_EQ(wide.width, 30);
  EXPECT_EQ(wide.height, 20);
  r = run_gdrender(kCornell + " --resolution 16x9 --spp 1 --quiet -o both.exr", dir);
  ASSERT_EQ(r.code, 0) << r.output;
  Image both = read_image(dir.file("both.exr"));
  EXPECT_EQ(both.width, 16);
  EXPECT_EQ(both.height, 9);
  r = run_gdrender("--info " + kCornell + " --resolution 20x10", dir);
  ASSERT_EQ(r.code, 0) << r.output;
  EXPECT_NE(r.output.find("resolution: 20x10"), std::string::npos) << r.output;
}

TEST(Cli, BadResolutionIsRejected) {
  TempDir dir;
  for (const char* bad : {"0", "12x", "x12", "12x0", "-4", "100000", "3.5", "12X12"}) {
    expect_failure(run_gdrender(kCornell + " --resolution " + bad + " --spp 1 -o out.exr", dir), "--resolution", dir);
  }
}

// --kernels chooses the kernel builds (the stats say which); $GDR_KERNELS gives the default, and
// a value either does not know stops the render before it writes anything.
TEST(Cli, KernelBuildsAreChosen) {
  TempDir dir;
  for (const std::string mode : {"scene", "all"}) {
    CliResult r =
        run_gdrender(kCornell + " --kernels " + mode + " -D res=8 --spp 1 --quiet -o out.exr --stats s.json", dir);
    ASSERT_EQ(r.code, 0) << r.output;
    std::ifstream in(dir.file("s.json"));
    EXPECT_EQ(nlohmann::json::parse(in)["device"]["kernels"], mode);
  }
  TempDir bad;
  expect_failure(run_gdrender(kCornell + " --kernels some -D res=8 --spp 1 -o out.exr", bad), "--kernels", bad);
  expect_failure(run_shell("cd '" + bad.path().string() + "' && GDR_KERNELS=some timeout 60 '" + gdrender_exe() + "' " +
                           kCornell + " -D res=8 --spp 1 -o out.exr 2>&1"),
                 "GDR_KERNELS=some", bad);
}

// A parameter the scene does not have is not silently ignored: a warning names it and the
// scene's parameters; with --strict it is an error.
TEST(Cli, UnknownDefineIsReported) {
  TempDir dir;
  const std::string plates = "'" + source_scene("glossy-plates.xml") + "'";
  CliResult r = run_gdrender(plates + " -D res=8 -D width=8 -D height=8 --spp 1 --quiet -o out.exr", dir);
  ASSERT_EQ(r.code, 0) << r.output;
  EXPECT_NE(r.output.find("no parameter $res"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("width"), std::string::npos) << r.output;
  EXPECT_EQ(r.output.find("$width"), std::string::npos) << "a used parameter was reported: " << r.output;
  TempDir strict;
  expect_failure(run_gdrender(plates + " -D res=8 --strict --spp 1 -o out.exr", strict), "no parameter $res", strict);
}

TEST(Cli, InfoOfAGoodScene) {
  TempDir dir;
  CliResult r = run_gdrender("--info " + kCornell, dir);
  EXPECT_EQ(r.code, 0) << r.output;
  EXPECT_NE(r.output.find("device"), std::string::npos) << r.output;
}

TEST(Cli, ListDevices) {
  TempDir dir;
  CliResult r = run_gdrender("--list-devices", dir);
  EXPECT_EQ(r.code, 0) << r.output;
  EXPECT_NE(r.output.find("[0]"), std::string::npos) << "no device listed: " << r.output;
}

TEST(Cli, Version) {
  TempDir dir;
  CliResult r = run_gdrender("--version", dir);
  EXPECT_EQ(r.code, 0) << r.output;
  EXPECT_NE(r.output.find(std::string("gdrender ") + GDR_VERSION), std::string::npos) << r.output;
}

TEST(Cli, NothingToDoIsAUsageError) {
  TempDir dir;
  CliResult r = run_gdrender("", dir);
  EXPECT_EQ(r.code, 2) << r.output;
}

TEST(Cli, UnknownReconSolverIsRejected) {
  TempDir dir;
  CliResult r = run_gdrender(kCornell + " --integrator gpt --recon-solver bogus -D res=8 --spp 1 -o out.exr", dir);
  expect_failure(r, "--recon-solver", dir);
}

// Both solvers reconstruct a saved render and record which one ran.
TEST(Cli, ReconstructWithEitherSolver) {
  TempDir dir;
  CliResult render = run_gdrender(kCornell + " --integrator gpt --recon none -D res=16 --spp 2 -o in.exr", dir);
  ASSERT_EQ(render.code, 0) << render.output;
  for (const char* solver : {"fast", "cg"}) {
    SCOPED_TRACE(solver);
    CliResult r = run_gdrender(std::string("--reconstruct in.exr -o out.exr --stats s.json --recon-solver ") + solver, dir);
    ASSERT_EQ(r.code, 0) << r.output;
    EXPECT_EQ(read_image(dir.file("out.exr")).width, 16);
    std::ifstream stats(dir.file("s.json"));
    std::string json((std::istreambuf_iterator<char>(stats)), std::istreambuf_iterator<char>());
    EXPECT_NE(json.find(std::string("\"solver\": \"") + solver + "\""), std::string::npos) << json;
  }
}

TEST(Cli, ReconstructWithoutLayersIsRejected) {
  TempDir dir;
  Image img(4, 4, {});
  img.add_rgb_layer("", std::vector<float>(4 * 4 * 3, 0.5f));
  write_exr(dir.file("plain.exr"), img);
  CliResult r = run_gdrender("--reconstruct plain.exr -o recon.exr", dir);
  EXPECT_NE(r.code, 0) << r.output;
  EXPECT_NE(r.output.find("plain.exr"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("primal"), std::string::npos) << r.output;
  EXPECT_FALSE(std::filesystem::exists(dir.file("recon.exr")));
}

// A render with the default reconstruction (weighted) saves the variance layers and the halves'
// layers, from which --reconstruct rebuilds it; a render without the halves is refused by name
// when --recon weighted is asked for.
TEST(Cli, WeightedReconstructionSavesAndReadsItsLayers) {
  TempDir dir;
  CliResult render = run_gdrender(kCornell + " --integrator gpt -D res=16 --spp 4 -o weighted.exr --stats w.json", dir);
  ASSERT_EQ(render.code, 0) << render.output;
  Image img = read_image(dir.file("weighted.exr"));
  for (const char* layer : {"primal_variance", "dx_variance", "dy_variance", "even.primal", "even.direct",
                            "odd.dx_variance", "odd.dy"}) {
    EXPECT_TRUE(img.has_rgb_layer(layer)) << layer;
  }
  std::ifstream stats_file(dir.file("w.json"));
  EXPECT_EQ(nlohmann::json::parse(stats_file)["recon"]["norm"], "weighted");
  CliResult r = run_gdrender("--reconstruct weighted.exr -o again.exr", dir);
  ASSERT_EQ(r.code, 0) << r.output;
  EXPECT_EQ(read_image(dir.file("again.exr")).rgb_layer(""), img.rgb_layer(""));

  CliResult l1 = run_gdrender(kCornell + " --integrator gpt --recon l1 -D res=16 --spp 4 -o l1.exr", dir);
  ASSERT_EQ(l1.code, 0) << l1.output;
  EXPECT_TRUE(read_image(dir.file("l1.exr")).has_rgb_layer("dx_variance"));
  EXPECT_FALSE(read_image(dir.file("l1.exr")).has_rgb_layer("even.primal"));
  r = run_gdrender("--reconstruct l1.exr --recon weighted -o refused.exr", dir);
  EXPECT_NE(r.code, 0) << r.output;
  EXPECT_NE(r.output.find("l1.exr"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("'even.primal'"), std::string::npos) << r.output;
  EXPECT_FALSE(std::filesystem::exists(dir.file("refused.exr")));
  // Without --recon, a render saved without the halves is reconstructed by L1.
  r = run_gdrender("--reconstruct l1.exr -o again_l1.exr --stats l1.json", dir);
  ASSERT_EQ(r.code, 0) << r.output;
  EXPECT_EQ(read_image(dir.file("again_l1.exr")).rgb_layer(""), read_image(dir.file("l1.exr")).rgb_layer(""));
}

// --compare over two renders: runs at 1.2 and 1.4 against a reference of 1 everywhere. Per value
// m = 1.3, s^2 = 0.02: mean relMSE (0.04 + 0.16) / 2, variance s^2, bias^2 the rest (m - 1)^2 -
// s^2 / 2 = 0.08, all over 1 + 1e-2; brightness 1.3.
TEST(Cli, CompareSplitsSeveralRunsIntoBiasAndVariance) {
  TempDir dir;
  for (auto [name, value] : {std::pair<const char*, float>{"a.exr", 1.2f}, {"b.exr", 1.4f}, {"ref.exr", 1.0f}}) {
    Image img(4, 3, {});
    img.add_rgb_layer("", std::vector<float>(4 * 3 * 3, value));
    write_exr(dir.file(name), img);
  }
  CliResult r = run_gdrender("--compare a.exr b.exr ref.exr", dir);
  ASSERT_EQ(r.code, 0) << r.output;
  nlohmann::json j = nlohmann::json::parse(r.output.substr(r.output.rfind('{')));
  EXPECT_EQ(j["runs"], 2);
  EXPECT_NEAR(double(j["relmse"]), 0.1 / 1.01, 1e-5);
  EXPECT_NEAR(double(j["variance"]), 0.02 / 1.01, 1e-5);
  EXPECT_NEAR(double(j["bias2"]), 0.08 / 1.01, 1e-5);
  EXPECT_NEAR(double(j["brightness"]), 1.3, 1e-5);
  r = run_gdrender("--compare a.exr ref.exr", dir);
  ASSERT_EQ(r.code, 0) << r.output;
  j = nlohmann::json::parse(r.output.substr(r.output.rfind('{')));
  EXPECT_FALSE(j.contains("bias2"));
  EXPECT_NEAR(double(j["brightness"]), 1.2, 1e-5);
}

}  // namespace
}  // namespace gdr::test
