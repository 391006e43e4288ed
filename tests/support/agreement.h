// Whether two integrators converge to the same image: per 4 x 4 pixel block, Welch's t-test
// compares the mean luminance of K independent runs of each, Šidák-corrected over the blocks so
// that one comparison has the false-positive rate it is given.
#pragma once
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include "render/integrator.h"
#include "scene/load_scene.h"
#include "scene/scene.h"
#include "support/source_scene.h"
#include "support/statistics.h"

namespace gdr::test {

constexpr int kAgreementBlock = 4;

// Block luminance of an RGB image (interleaved) of width x height pixels, whole blocks only.
inline std::vector<double> block_luminance(const std::vector<float>& rgb, int width, int height) {
  std::vector<double> blocks((width / kAgreementBlock) * (height / kAgreementBlock), 0.0);
  for (int y = 0; y < height / kAgreementBlock * kAgreementBlock; ++y)
    for (int x = 0; x < width / kAgreementBlock * kAgreementBlock; ++x) {
      const float* c = &rgb[3 * (y * width + x)];
      blocks[(y / kAgreementBlock) * (width / kAgreementBlock) + x / kAgreementBlock] +=
          0.2126 * c[0] + 0.7152 * c[1] + 0.0722 * c[2];
    }
  return blocks;
}

// runs[k][block]: the block's mean luminance in run k of `runs` runs of `integrator` (seeds
// first_seed, first_seed + 1, ...).
inline std::vector<std::vector<double>> block_means(Integrator& integrator, int width, int height, int spp,
                                                    int max_depth, uint32_t first_seed, int runs) {
  std::vector<std::vector<double>> out;
  for (int k = 0; k < runs; ++k) {
    RenderSettings s;
    s.spp = spp;
    s.seed = first_seed + k;
    s.max_depth = max_depth;
    out.push_back(block_luminance(integrator.render(s).image.rgb_layer(""), width, height));
  }
  return out;
}

// A film `width` pixels wide of the scene's aspect (the field of view unchanged), whole blocks.
inline Scene small_film(Scene scene, int width) {
  int height = std::max(kAgreementBlock,
                        (width * scene.camera.height / scene.camera.width) / kAgreementBlock * kAgreementBlock);
  scene.camera.width = width;
  scene.camera.height = height;
  return scene;
}

// The project's scene `file` (in scenes/) on a film `width` pixels wide (small_film).
inline Scene project_scene(const std::string& file, int width) {
  return small_film(load_scene(source_scene(file)), width);
}

// Expects every block of the runs a and b (runs[k][block]), and their sums over the image (far
// less noisy: a bias spread thinly over many blocks shows there), to agree at family
// false-positive rate `fpr` over those tests, and more than half of b's blocks to be lit (or the
// test shows nothing). Names the blocks that differ.
inline void expect_blocks_agree(const std::vector<std::vector<double>>& a, const std::vector<std::vector<double>>& b,
                                const std::string& what, const char* a_name, const char* b_name,
                                double fpr = 1e-3) {
  const int blocks = int(a[0].size());
  const double alpha = sidak(fpr, blocks + 1);
  auto sums = [](const std::vector<std::vector<double>>& runs) {
    std::vector<double> out;
    for (const auto& r : runs) {
      double sum = 0;
      for (double v : r) sum += v;
      out.push_back(sum);
    }
    return out;
  };
  std::vector<double> sa = sums(a), sb = sums(b);
  EXPECT_GT(welch_p(sa, sb), alpha) << what << " image: " << a_name << " " << mean_and_variance(sa).mean << ", "
                                    << b_name << " " << mean_and_variance(sb).mean;
  int lit = 0;
  for (int i = 0; i < blocks; ++i) {
    std::vector<double> x, y;
    for (const auto& r : a) x.push_back(r[i]);
    for (const auto& r : b) y.push_back(r[i]);
    lit += mean_and_variance(y).mean > 0;
    EXPECT_GT(welch_p(x, y), alpha) << what << " block " << i << ": " << a_name << " " << mean_and_variance(x).mean
                                    << ", " << b_name << " " << mean_and_variance(y).mean;
  }
  EXPECT_GT(lit, blocks / 2) << what << ": too few lit blocks to show anything";
}

// The white furnace's check: every value finite, and the image mean within 5 standard errors
// (from the spread of its values: each pixel's splats come from different vertices; false-positive
// rate below 1e-6) plus `slack` of `expected`, with some noise (a noise-free image would mean
// nothing was sampled) but not much.
inline void expect_furnace_mean(const std::vector<float>& rgb, double expected, double slack = 0.0) {
  double sum = 0, sum2 = 0;
  for (float v : rgb) {
    ASSERT_TRUE(std::isfinite(v));
    sum += v;
    sum2 += double(v) * v;
  }
  double n = double(rgb.size()), mean = sum / n, se = std::sqrt((sum2 / n - mean * mean) / (n - 1));
  EXPECT_NEAR(mean, expected, 5 * se + slack) << "standard error " << se;
  EXPECT_LT(se, 0.02);
  EXPECT_GT(se, 0.0);
}

}  // namespace gdr::test
