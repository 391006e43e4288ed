// Rendering under MPI on loopback (mpiexec -np N, each rank one thread): the N-rank render
// equals the one-process render of the same seed and sample count in every layer, up to the
// order of the float sums, and its stats count the job's samples; a rank that cannot load the
// scene ends the job with its rank and reason, and nothing is written. Compiled only when CMake
// found MPI (GDR_MPIEXEC names its launcher).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "cli/cli_harness.h"
#include "image/image_io.h"

#ifdef GDR_MPIEXEC

namespace gdr::test {
namespace {

// Open MPI in a root container: the two settings it needs there (harmless elsewhere), ranks
// allowed beyond the cores (a CI machine may have fewer than 3) and left unbound.
CliResult run_mpi(int ranks, const std::string& args, const TempDir& dir) {
  return run_shell("cd '" + dir.path().string() +
                   "' && OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 "
                   "OMPI_MCA_btl_vader_single_copy_mechanism=none timeout 300 '" GDR_MPIEXEC "' -np " +
                   std::to_string(ranks) + " --oversubscribe --bind-to none " + args + " 2>&1");
}

std::string gdrender() { return "'" + gdrender_exe() + "'"; }

nlohmann::json read_json(const std::string& path) {
  std::ifstream in(path);
  return nlohmann::json::parse(std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>()));
}

// Every channel of `got` against `want`. Two float sums of the same n terms in different orders
// differ by at most 2 (n - 1) u sum|x_i| (u = 2^-24); a layer's per-pixel mean then differs by
// at most 2 (n - 1) u times the mean of |x|, which for the non-negative layers is the value
// itself and for the signed ones (gradients, normals) is bounded by the layer's mean magnitude.
// The variance layers join float Welford sums (one process) or combine them in double (several).
// Each Welford term is a product of deviations from a float running mean, whose rounding (u times
// the mean) the term carries times the deviation: over n passes the variance of the mean v then
// errs by about u |mean| sqrt(n v), which where the mean dwarfs the spread (a pixel that sees the
// light in every pass) is many times n u v. The L2 reconstruction is a linear,
// well-conditioned solve of those layers. The tolerance is 10 n u (|value| + the channel's mean
// magnitude), and for a variance layer 10 n u |mean| sqrt(n |value|) besides: a reduction
// that lost a pass, counted one twice or summed squared deviations instead of combining them
// errs by a fraction 1/n of the values, thousands of times more. The L1 reconstruction is not
// held to it (its reweighting by 1 / |residual| magnifies rounding near zero residuals to about
// 1e-3 here); `skip` names channels left out.
void expect_same_image(const std::string& want_path, const std::string& got_path, int n,
                       const std::vector<std::string>& skip = {}) {
  Image want = read_image(want_path), got = read_image(got_path);
  ASSERT_EQ(want.channels, got.channels);
  ASSERT_EQ(want.width, got.width);
  ASSERT_EQ(want.height, got.height);
  const double u = std::ldexp(1.0, -24);
  const size_t channels = want.channel_count(), pixels = size_t(want.width) * want.height;
  // The channel holding the mean whose variance channel c holds ("primal_variance.R": "primal.R"), or -1.
  auto mean_channel = [&](size_t c) {
    const std::string& name = want.channels[c];
    const std::string suffix = "_variance";
    const size_t at = name.find(suffix);
    if (at == std::string::npos) return -1;
    return want.channel(name.substr(0, at) + name.substr(at + suffix.size()));
  };
  for (size_t c = 0; c < channels; ++c) {
    if (std::find(skip.begin(), skip.end(), want.channels[c]) != skip.end()) continue;
    const int mean_of = mean_channel(c);
    double magnitude = 0;
    for (size_t p = 0; p < pixels; ++p) magnitude += std::abs(want.pixels[p * channels + c]);
    magnitude /= double(pixels);
    int bad = 0;
    for (size_t p = 0; p < pixels && bad < 3; ++p) {
      const double a = want.pixels[p * channels + c], b = got.pixels[p * channels + c];
      ASSERT_TRUE(std::isfinite(b));
      double tolerance = 10.0 * n * u * (std::abs(a) + magnitude);
      if (mean_of >= 0) {
        tolerance += 10.0 * n * u * std::abs(want.pixels[p * channels + mean_of]) * std::sqrt(n * std::abs(a));
      }
      if (std::abs(a - b) > tolerance) {
        ++bad;
        ADD_FAILURE() << want.channels[c] << " at pixel " << p << ": " << a << " (one process) vs " << b
                      << " (ranks), tolerance " << tolerance;
      }
    }
  }
}

// The one-process render and the N-rank one of the same seed and sample count (`options`: the
// integrator and its parameters). With `l1`, R,G,B (the L1 reconstruction) must instead be
// exactly the reconstruction of the N-rank render's own saved layers: it ran once, on the sums.
void check_ranks_equal_one_process(const std::string& options, int ranks, uint64_t paths_per_pixel_sample,
                                   bool l1 = false) {
  TempDir dir;
  const int spp = 6, w = 40, h = 32;
  const std::string args = source_scene("cornell-box.xml") + " " + options + " --aux --seed 11 --spp " +
                           std::to_string(spp) + " --resolution " + std::to_string(w) + "x" + std::to_string(h) +
                           " --threads 1 --quiet";
  CliResult one = run_gdrender(args + " -o one.exr", dir);
  ASSERT_EQ(one.code, 0) << one.output;
  CliResult many = run_mpi(ranks, gdrender() + " " + args + " -o many.exr --stats many.json", dir);
  ASSERT_EQ(many.code, 0) << many.output;
  expect_same_image(dir.file("one.exr"), dir.file("many.exr"), spp,
                    l1 ? std::vector<std::string>{"R", "G", "B"} : std::vector<std::string>{});
  if (l1) {
    CliResult again = run_gdrender("--reconstruct many.exr -o again.exr --threads 1 --quiet", dir);
    ASSERT_EQ(again.code, 0) << again.output;
    Image got = read_image(dir.file("many.exr")), want = read_image(dir.file("again.exr"));
    EXPECT_EQ(got.rgb_layer(""), want.rgb_layer("")) << "R,G,B is not the L1 reconstruction of the reduced layers";
    std::filesystem::remove(dir.file("again.exr"));
    std::filesystem::remove(dir.file("again.png"));
  }

  nlohmann::json stats = read_json(dir.file("many.json"));
  EXPECT_EQ(stats["render"]["spp"], spp);
  EXPECT_EQ(stats["mpi"]["ranks"], ranks);
  EXPECT_EQ(stats["mpi"]["passes"], spp);
  EXPECT_EQ(stats["counters"]["samples"]["paths"].get<uint64_t>(), uint64_t(w) * h * spp * paths_per_pixel_sample);
  ASSERT_EQ(stats["mpi"]["per_rank"].size(), size_t(ranks));
  for (int r = 0; r < ranks; ++r) {
    const nlohmann::json& mine = stats["mpi"]["per_rank"][r];
    EXPECT_EQ(mine["rank"], r);
    EXPECT_EQ(mine["passes"], (spp - 1 - r) / ranks + 1) << "rank " << r << " traces passes r, r + N, ...";
  }
  EXPECT_GT(stats["counters"]["mpi"]["reduce_bytes"].get<uint64_t>(), 0u);
  // Only rank 0 writes: no temporaries or second copies are left.
  EXPECT_EQ(count_files(dir, ".exr"), 2);
  EXPECT_EQ(count_files(dir, ".png"), 2);
}

TEST(MpiRender, PtOnTwoRanksEqualsOneProcess) { check_ranks_equal_one_process("--integrator pt", 2, 1); }

// Three ranks: each half of the gradient film (even and odd passes) is held by several ranks,
// so its variance layers go through the pairwise combination; two ranks hold a half each.
TEST(MpiRender, GptOnTwoAndThreeRanksEqualsOneProcess) {
  check_ranks_equal_one_process("--integrator gpt --recon l2", 2, 5);
  check_ranks_equal_one_process("--integrator gpt --recon l2", 3, 5);
}

TEST(MpiRender, GptL1ReconstructsOnceFromTheReducedLayers) {
  check_ranks_equal_one_process("--integrator gpt", 3, 5, /*l1=*/true);
}

// Metropolis chains cannot be split by pass: each rank runs chains of its own (their numbers
// keyed by the rank) over its share of the passes, and b pools the uniform samples of all
// ranks. The two-rank image then estimates the same image as one process with another set of
// chains: fixed seeds (11), 40 x 32 pixels, 16 mutations a pixel, so the check is deterministic;
// the image sums agree within 10% (b's relative error here is about 2%).
TEST(MpiRender, MltOnTwoRanksPoolsTheirChains) {
  TempDir dir;
  const std::string args = source_scene("cornell-box.xml") +
                           " --integrator mlt --seed 11 --spp 16 --resolution 40x32 --threads 1 --quiet";
  CliResult one = run_gdrender(args + " -o one.exr --stats one.json", dir);
  ASSERT_EQ(one.code, 0) << one.output;
  CliResult many = run_mpi(2, gdrender() + " " + args + " -o many.exr --stats many.json", dir);
  ASSERT_EQ(many.code, 0) << many.output;
  auto sum = [](const Image& image) {
    double s = 0;
    for (float v : image.rgb_layer("")) {
      EXPECT_TRUE(std::isfinite(v));
      s += v;
    }
    return s;
  };
  const double a = sum(read_image(dir.file("one.exr"))), b = sum(read_image(dir.file("many.exr")));
  EXPECT_NEAR(b / a, 1.0, 0.1) << "one process " << a << ", two ranks " << b;
  nlohmann::json s1 = read_json(dir.file("one.json")), s2 = read_json(dir.file("many.json"));
  EXPECT_EQ(s2["mpi"]["ranks"], 2);
  EXPECT_EQ(s2["render"]["spp"], 16);
  // Both ranks' bootstraps (and large steps) in b.
  EXPECT_GT(s2["mlt"]["normalization_samples"].get<double>(), 1.5 * s1["mlt"]["normalization_samples"].get<double>());
}

TEST(MpiRender, ARankThatCannotLoadTheSceneEndsTheJobNamingIt) {
  TempDir dir;
  std::string broken = dir.write("broken.xml", "<scene version=\"3.0.0\">\n<shape type=\"obj\">\n</scene>\n");
  const std::string common = " --spp 2 --resolution 16x16 --threads 1 --quiet -o out.exr --stats s.json";
  CliResult r = run_mpi(1, gdrender() + " " + source_scene("cornell-box.xml") + common + " : -np 1 " + gdrender() +
                               " broken.xml" + common,
                        dir);
  EXPECT_NE(r.code, 0) << r.output;
  EXPECT_NE(r.code, 124) << "the job hung: " << r.output;
  EXPECT_NE(r.output.find("rank 1 of 2"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("broken.xml:3"), std::string::npos) << r.output;
  EXPECT_EQ(count_files(dir, ".exr"), 0);
  EXPECT_EQ(count_files(dir, ".png"), 0);
  EXPECT_EQ(count_files(dir, ".json"), 0);
}

TEST(MpiRender, RanksThatWouldRenderDifferentFilmsAreRefused) {
  TempDir dir;
  const std::string scene = " " + source_scene("cornell-box.xml") + " --spp 2 --threads 1 --quiet -o out.exr";
  CliResult r = run_mpi(1, gdrender() + scene + " --resolution 16x16 : -np 1 " + gdrender() + scene +
                               " --resolution 16x8", dir);
  EXPECT_NE(r.code, 0) << r.output;
  EXPECT_NE(r.output.find("rank 1 of 2: error: its render"), std::string::npos) << r.output;
  EXPECT_EQ(count_files(dir, ".exr"), 0);
}

TEST(MpiRender, OnlyRenderingRunsAcrossRanks) {
  TempDir dir;
  CliResult r = run_mpi(2, gdrender() + " --list-integrators", dir);
  EXPECT_NE(r.code, 0) << r.output;
  EXPECT_NE(r.output.find("only a render runs across MPI ranks"), std::string::npos) << r.output;
}

}  // namespace
}  // namespace gdr::test

#endif  // GDR_MPIEXEC
