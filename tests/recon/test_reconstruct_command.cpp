// The reconstruct command: EXR with primal/dx/dy layers in, EXR (R,G,B + layers) and PNG out.
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>

#include "app/reconstruct_command.h"
#include "image/image_io.h"
#include "recon_fixtures.h"
#include "support/devices.h"
#include "util/error.h"

namespace gdr {
namespace {

namespace fs = std::filesystem;

fs::path temp_dir(const std::string& name) {
  fs::path dir = fs::temp_directory_path() / ("gdr_recon_" + name + "_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

TEST(ReconstructCommand, RoundTripThroughExr) {
  fs::path dir = temp_dir("roundtrip");
  test::GradientImage g = test::exact_problem(21, 14);
  test::add_gaussian_noise(g.primal, 0.2f, 21);  // seed 21
  Image in(g.w, g.h, {});
  in.add_rgb_layer("primal", g.primal);
  in.add_rgb_layer("dx", g.dx);
  in.add_rgb_layer("dy", g.dy);
  write_exr((dir / "in.exr").string(), in);

  for (const char* norm : {"l1", "l2"}) {
    SCOPED_TRACE(norm);
    Stats stats;
    std::string out = (dir / (std::string("out_") + norm + ".exr")).string();
    EXPECT_EQ(reconstruct_command((dir / "in.exr").string(), out, recon_settings(norm, 0.2f, "fast"),
                                  test::default_context(), &stats),
              0);
    Image result = read_image(out);
    ASSERT_EQ(result.width, g.w);
    ASSERT_EQ(result.height, g.h);
    EXPECT_LT(test::rmse(result.rgb_layer(""), g.truth), test::rmse(g.primal, g.truth) / 3);
    EXPECT_EQ(result.rgb_layer("primal"), g.primal);
    EXPECT_EQ(result.rgb_layer("dx"), g.dx);
    EXPECT_EQ(result.rgb_layer("dy"), g.dy);
    EXPECT_TRUE(fs::exists(dir / (std::string("out_") + norm + ".png")));
    EXPECT_EQ(stats.to_json()["recon"]["norm"], norm[1] == '1' ? "L1" : "L2");
  }
  fs::remove_all(dir);
}

TEST(ReconstructCommand, MissingLayerIsNamed) {
  fs::path dir = temp_dir("missing");
  std::vector<float> rgb(4 * 3 * 3, 0.5f);
  Image in(4, 3, {});
  in.add_rgb_layer("primal", rgb);
  in.add_rgb_layer("dy", rgb);
  std::string path = (dir / "no_dx.exr").string();
  write_exr(path, in);
  try {
    reconstruct_command(path, (dir / "out.exr").string(), recon_settings("l2", 0.2f, "fast"),
                        test::default_context(), nullptr);
    FAIL() << "a missing dx layer must be reported";
  } catch (const Error& e) {
    std::string msg = e.what();
    EXPECT_NE(msg.find(path), std::string::npos) << msg;
    EXPECT_NE(msg.find("'dx'"), std::string::npos) << msg;
  }
  EXPECT_FALSE(fs::exists(dir / "out.exr"));
  EXPECT_THROW(recon_settings("l3", 0.2f, "fast"), Error);
  EXPECT_THROW(recon_settings("l1", 0.2f, "direct"), Error);
  EXPECT_THROW(recon_settings("l1", NAN, "fast"), Error);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace gdr
