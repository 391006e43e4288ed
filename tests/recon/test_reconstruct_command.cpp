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
  // No reconstruction: the image is the primal, as a render with --recon none writes it.
  std::string none = (dir / "out_none.exr").string();
  EXPECT_EQ(reconstruct_command((dir / "in.exr").string(), none, std::nullopt, test::default_context(), nullptr), 0);
  EXPECT_EQ(read_image(none).rgb_layer(""), g.primal);
  fs::remove_all(dir);
}

// A weighted render's EXR: the halves (even and odd passes) with their own noise and variance
// layers (seeds 22, 23). --reconstruct --recon weighted reads them back and weights each half by
// the other's estimates; without them it names the first missing layer and the file.
TEST(ReconstructCommand, WeightedReadsTheHalves) {
  fs::path dir = temp_dir("weighted");
  test::GradientImage g = test::exact_problem(21, 14);
  Image in(g.w, g.h, {});
  std::vector<float> half_primal[2];
  for (int h = 0; h < 2; ++h) {
    const std::string prefix = h == 0 ? "even." : "odd.";
    half_primal[h] = g.primal;
    test::add_gaussian_noise(half_primal[h], 0.2f, 22 + h);
    in.add_rgb_layer(prefix + "primal", half_primal[h]);
    in.add_rgb_layer(prefix + "dx", g.dx);
    in.add_rgb_layer(prefix + "dy", g.dy);
    in.add_rgb_layer(prefix + "direct", std::vector<float>(g.primal.size(), 0.0f));
    in.add_rgb_layer(prefix + "primal_variance", std::vector<float>(g.primal.size(), 0.04f));
    in.add_rgb_layer(prefix + "dx_variance", std::vector<float>(g.primal.size(), 0.0f));
    in.add_rgb_layer(prefix + "dy_variance", std::vector<float>(g.primal.size(), 0.0f));
  }
  std::vector<float> primal(g.primal.size());
  for (size_t i = 0; i < primal.size(); ++i) primal[i] = 0.5f * (half_primal[0][i] + half_primal[1][i]);
  Image without_halves(g.w, g.h, {});
  for (Image* image : {&in, &without_halves}) {
    image->add_rgb_layer("primal", primal);
    image->add_rgb_layer("dx", g.dx);
    image->add_rgb_layer("dy", g.dy);
  }
  write_exr((dir / "in.exr").string(), in);
  write_exr((dir / "no_halves.exr").string(), without_halves);

  Stats stats;
  std::string out = (dir / "out.exr").string();
  ASSERT_EQ(reconstruct_command((dir / "in.exr").string(), out, recon_settings("weighted", 1.0f, "fast"),
                                test::default_context(), &stats),
            0);
  Image result = read_image(out);
  EXPECT_LT(test::rmse(result.rgb_layer(""), g.truth), test::rmse(primal, g.truth) / 5);
  EXPECT_EQ(result.rgb_layer("odd.primal"), half_primal[1]);
  EXPECT_EQ(stats.to_json()["recon"]["norm"], "weighted");

  std::string path = (dir / "no_halves.exr").string();
  try {
    reconstruct_command(path, (dir / "out2.exr").string(), recon_settings("weighted", 1.0f, "fast"),
                        test::default_context(), nullptr);
    FAIL() << "a render without the halves' layers must be reported";
  } catch (const Error& e) {
    std::string msg = e.what();
    EXPECT_NE(msg.find(path), std::string::npos) << msg;
    EXPECT_NE(msg.find("'even.primal'"), std::string::npos) << msg;
  }
  EXPECT_FALSE(fs::exists(dir / "out2.exr"));
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
