// Whether a gradient-domain integrator is unbiased: its gradients (plus the difference of the
// directly seen emission, which is kept out of the gradients) and its primal agree with neighbour
// differences and pixels of the path tracer. K independent runs (seeds 1..K) of each; per 4x4
// pixel block, for the primal also over the whole image (a bias of one sign spread over many
// blocks), and over the image's outer ring of pixels (where the pixel filter is cut at the edge and
// the pixel shift has a Jacobian), Welch's t-test on the run means; Šidák-corrected so each
// scene/integrator case has a false-positive rate of 1e-3. The cases of one scene share the path
// tracer's runs: each case's rate stays 1e-3, their failures are no longer independent.
#pragma once
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <tuple>
#include <vector>

#include "integrators/gpt/gradient_path_tracer.h"
#include "support/render.h"
#include "support/statistics.h"

namespace gdr::test {

struct GradientCase {
  int width = 24, runs = 24, spp = 4;
  // The path tracer's samples a pixel and run (0: spp). More where its runs are heavy-tailed
  // (caustics it finds rarely) and the integrator's are not: the t-test needs the means of both
  // near normal.
  int reference_spp = 0;
  int max_depth = 8;  // paths of up to 8 segments, so Russian roulette (from the 5th bounce) decides some
};

namespace gradient_detail {

constexpr int kBlock = 4;

struct Stat {  // per run, per block: sums of dx, dy and of the primal; the primal's total; the border
  std::vector<double> dx, dy, primal;
  double total = 0;
  double border_dx = 0, border_dy = 0, border_primal = 0;
};

inline Stat block_sums(int w, int h, const std::vector<float>& dx, const std::vector<float>& dy,
                       const std::vector<float>& primal) {
  int bw = w / kBlock, bh = h / kBlock;
  Stat s{std::vector<double>(bw * bh), std::vector<double>(bw * bh), std::vector<double>(bw * bh)};
  for (int y = 0; y < bh * kBlock; ++y) {
    for (int x = 0; x < bw * kBlock; ++x) {
      int b = (y / kBlock) * bw + x / kBlock;
      for (int c = 0; c < 3; ++c) {
        size_t i = 3 * (size_t(y) * w + x) + c;
        if (x + 1 < w) s.dx[b] += dx[i];
        if (y + 1 < h) s.dy[b] += dy[i];
        s.primal[b] += primal[i];
        s.total += primal[i];
      }
    }
  }
  // The differences that involve a border pixel, and the border pixels themselves.
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      for (int c = 0; c < 3; ++c) {
        size_t i = 3 * (size_t(y) * w + x) + c;
        if (x == 0 || x == w - 2) s.border_dx += dx[i];
        if (y == 0 || y == h - 2) s.border_dy += dy[i];
        if (x == 0 || y == 0 || x == w - 1 || y == h - 1) s.border_primal += primal[i];
      }
    }
  }
  return s;
}

}  // namespace gradient_detail

// Neighbour differences of an RGB image, as the gradient layers dx/dy define them.
inline void differences(int w, int h, const std::vector<float>& img, std::vector<float>& dx, std::vector<float>& dy) {
  dx.assign(img.size(), 0.0f);
  dy.assign(img.size(), 0.0f);
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      for (int c = 0; c < 3; ++c) {
        size_t i = 3 * (size_t(y) * w + x) + c;
        if (x + 1 < w) dx[i] = img[i + 3] - img[i];
        if (y + 1 < h) dy[i] = img[i + 3 * size_t(w)] - img[i];
      }
    }
  }
}

using GradientFactory = std::function<std::unique_ptr<GradientPathTracer>(const RenderInputs&)>;

// Renders `scene` (resized to c.width pixels wide) c.runs times with the integrator `make` builds
// and with the path tracer, and expects them to agree as the header says. `name` names the scene:
// one name, one scene (the path tracer's runs are kept by it).
inline void expect_gradients_unbiased(Scene scene, const std::string& name, const GradientFactory& make,
                                      const GradientCase& c = {}) {
  using namespace gradient_detail;
  const int w = c.width;
  const int h = std::max(kBlock, (w * scene.camera.height / scene.camera.width) / kBlock * kBlock);
  scene.camera.width = w;
  scene.camera.height = h;
  SceneOnDevice on_device(scene);
  std::unique_ptr<GradientPathTracer> gradient = make(on_device.inputs());
  std::vector<Stat> a;
  for (int k = 0; k < c.runs; ++k) {
    RenderSettings s;
    s.spp = c.spp;
    s.seed = 1 + k;
    s.max_depth = c.max_depth;
    GradientImages g = gradient->render_gradients(s);
    std::vector<float> ddx, ddy;
    differences(w, h, g.direct, ddx, ddy);
    for (size_t i = 0; i < g.dx.size(); ++i) {
      ASSERT_TRUE(std::isfinite(g.dx[i]) && std::isfinite(g.dy[i]) && std::isfinite(g.primal[i]));
      g.dx[i] += ddx[i];
      g.dy[i] += ddy[i];
    }
    a.push_back(block_sums(w, h, g.dx, g.dy, g.primal));
  }
  // The path tracer's runs (seeds 1000..) depend on the scene and these settings only: the cases
  // of one scene in a test process (one shift each) share them.
  const int reference_spp = c.reference_spp > 0 ? c.reference_spp : c.spp;
  static std::map<std::tuple<std::string, int, int, int, int>, std::vector<Stat>> references;
  std::vector<Stat>& b = references[{name, w, c.runs, reference_spp, c.max_depth}];
  if (b.empty()) {
    PathTracer pt(on_device.inputs(), PtSettings{});
    for (int k = 0; k < c.runs; ++k) {
      RenderSettings s;
      s.spp = reference_spp;
      s.seed = 1000 + k;
      s.max_depth = c.max_depth;
      std::vector<float> img = pt.render(s).image.rgb_layer("");
      std::vector<float> pdx, pdy;
      differences(w, h, img, pdx, pdy);
      b.push_back(block_sums(w, h, pdx, pdy, img));
    }
  }
  const int blocks = static_cast<int>(a[0].dx.size());
  const double alpha = sidak(1e-3, 3 * blocks + 4);
  auto column = [](const std::vector<Stat>& runs, std::vector<double> Stat::*field, int blk) {
    std::vector<double> v;
    for (const Stat& s : runs) v.push_back((s.*field)[blk]);
    return v;
  };
  for (int blk = 0; blk < blocks; ++blk) {
    EXPECT_GT(welch_p(column(a, &Stat::dx, blk), column(b, &Stat::dx, blk)), alpha)
        << name << " block " << blk << ": dx is biased";
    EXPECT_GT(welch_p(column(a, &Stat::dy, blk), column(b, &Stat::dy, blk)), alpha)
        << name << " block " << blk << ": dy is biased";
    EXPECT_GT(welch_p(column(a, &Stat::primal, blk), column(b, &Stat::primal, blk)), alpha)
        << name << " block " << blk << ": the primal differs from path tracing";
  }
  auto whole = [](const std::vector<Stat>& runs, double Stat::*field) {
    std::vector<double> v;
    for (const Stat& s : runs) v.push_back(s.*field);
    return v;
  };
  EXPECT_GT(welch_p(whole(a, &Stat::total), whole(b, &Stat::total)), alpha)
      << name << ": the primal's image total differs from path tracing";
  EXPECT_GT(welch_p(whole(a, &Stat::border_dx), whole(b, &Stat::border_dx)), alpha)
      << name << ": dx at the border is biased";
  EXPECT_GT(welch_p(whole(a, &Stat::border_dy), whole(b, &Stat::border_dy)), alpha)
      << name << ": dy at the border is biased";
  EXPECT_GT(welch_p(whole(a, &Stat::border_primal), whole(b, &Stat::border_primal)), alpha)
      << name << ": the primal of the border pixels differs from path tracing";
}

}  // namespace gdr::test
