// Whether a consistent gradient-domain integrator (gpm, gvcm) converges: its gradients (plus the
// differences of the directly seen emission, kept out of them), primal and reconstruction against a
// long path-traced reference (4096 spp, seed 500) of a small film, paths of up to kMaxDepth
// segments. The gradients' error counts the neighbour pairs neither of which sees the light.
#pragma once
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "integrators/gpt/gradient_path_tracer.h"
#include "integrators/pt/path_tracer.h"
#include "support/agreement.h"
#include "support/gradient_unbiased.h"
#include "support/reference_cache.h"
#include "support/render.h"
#include "support/test_scenes.h"

namespace gdr::test {

struct ConsistencyScene {
  static constexpr int kMaxDepth = 6;

  explicit ConsistencyScene(const std::string& file) : name(file), scene(project_scene(file, 32)) {}
  // `name` tells the reference cache which scene this is.
  ConsistencyScene(Scene s, std::string name) : name(std::move(name)), scene(std::move(s)) {}
  std::string name;
  Scene scene;
  SceneOnDevice on_device{scene};
  std::vector<float> reference_, ref_dx_, ref_dy_;
  std::vector<char> pairs_x_, pairs_y_;  // the neighbour pairs neither of which sees the light

  // Rendered on first use, once for the suite (support/reference_cache.h). The light seen directly
  // (the reference at max_depth 1) marks the pixels whose differences the gradient errors leave
  // out: at the light's edge a pixel's coverage of it is a coin flip per sample, as noisy in every
  // integrator's directly seen emission, and would outweigh everything else.
  void render_reference() {
    if (!reference_.empty()) return;
    const int w = scene.camera.width, h = scene.camera.height;
    RenderSettings s;
    s.spp = 4096;
    s.seed = 500;
    s.max_depth = kMaxDepth;
    const std::string key = "consistency reference of " + name + ", " + std::to_string(w) + "x" + std::to_string(h) +
                            ", pt " + std::to_string(s.spp) + " spp, seed " + std::to_string(s.seed) +
                            ", max_depth " + std::to_string(s.max_depth) + " and 1";
    const std::vector<float> both = cached_render(on_device.context, key, [&] {
      PathTracer pt(on_device.inputs(), PtSettings{});
      std::vector<float> values = pt.render(s).image.rgb_layer("");
      s.max_depth = 1;
      const std::vector<float> direct = pt.render(s).image.rgb_layer("");
      values.insert(values.end(), direct.begin(), direct.end());
      return values;
    });
    reference_.assign(both.begin(), both.begin() + std::ptrdiff_t(both.size() / 2));
    const std::vector<float> direct(both.begin() + std::ptrdiff_t(both.size() / 2), both.end());
    differences(w, h, reference_, ref_dx_, ref_dy_);
    auto dark = [&](int x, int y) {
      size_t i = 3 * (size_t(y) * w + x);
      return direct[i] == 0.0f && direct[i + 1] == 0.0f && direct[i + 2] == 0.0f;
    };
    pairs_x_.assign(size_t(w) * h, 0);
    pairs_y_.assign(size_t(w) * h, 0);
    for (int y = 0; y < h; ++y) {
      for (int x = 0; x < w; ++x) {
        pairs_x_[size_t(y) * w + x] = x + 1 < w && dark(x, y) && dark(x + 1, y);
        pairs_y_[size_t(y) * w + x] = y + 1 < h && dark(x, y) && dark(x, y + 1);
      }
    }
  }

  // The relative error of differences dx, dy against the reference's, over the pairs counted.
  double gradient_relmse(const std::vector<float>& dx, const std::vector<float>& dy) {
    render_reference();
    double sum = 0;
    size_t n = 0;
    for (size_t i = 0; i < dx.size(); ++i) {
      const double scale = double(reference_[i]) * reference_[i] + 1e-2;
      if (pairs_x_[i / 3]) sum += std::pow(double(dx[i]) - ref_dx_[i], 2) / scale, ++n;
      if (pairs_y_[i / 3]) sum += std::pow(double(dy[i]) - ref_dy_[i], 2) / scale, ++n;
    }
    return sum / double(n);
  }
  // The same of an image's neighbour differences.
  double image_gradient_relmse(const std::vector<float>& image) {
    std::vector<float> dx, dy;
    differences(scene.camera.width, scene.camera.height, image, dx, dy);
    return gradient_relmse(dx, dy);
  }
};

// The project's scene `file` as a ConsistencyScene, made once per process (and its reference
// rendered once).
inline ConsistencyScene& consistency_scene(const std::string& file) {
  static std::map<std::string, std::unique_ptr<ConsistencyScene>> scenes;
  std::unique_ptr<ConsistencyScene>& s = scenes[file];
  if (!s) s = std::make_unique<ConsistencyScene>(file);
  return *s;
}
// The diffuse Cornell box (area light), the scene most consistency tests use.
inline ConsistencyScene& consistency_box() { return consistency_scene("cornell-box.xml"); }

inline RenderSettings consistency_settings(int spp, uint32_t seed) {
  RenderSettings s;
  s.spp = spp;
  s.seed = seed;
  s.max_depth = ConsistencyScene::kMaxDepth;
  return s;
}

inline double relmse(const std::vector<float>& a, const std::vector<float>& ref) {
  double sum = 0;
  for (size_t i = 0; i < a.size(); ++i) {
    double d = double(a[i]) - ref[i];
    sum += d * d / (double(ref[i]) * ref[i] + 1e-2);
  }
  return sum / double(a.size());
}

inline double mean(const std::vector<float>& v) {
  double s = 0;
  for (float x : v) s += x;
  return s / double(v.size());
}

struct ConsistencyErrors {
  double gradients = 0, primal = 0, reconstruction = 0;
};

// The gradients plus the differences of the layer kept out of them (the emission seen directly,
// and light tracing's splats where the integrator has them).
inline void add_direct_differences(int w, int h, GradientImages& g) {
  std::vector<float> ddx, ddy;
  differences(w, h, g.direct, ddx, ddy);
  for (size_t i = 0; i < g.dx.size(); ++i) {
    g.dx[i] += ddx[i];
    g.dy[i] += ddy[i];
  }
}

// One run's errors against the reference: the gradients' (relative to the reference pixel),
// the primal's and the reconstruction's.
inline ConsistencyErrors consistency_errors(GradientPathTracer& integrator, int spp, uint32_t seed,
                                            ConsistencyScene& b) {
  b.render_reference();
  const int w = b.scene.camera.width, h = b.scene.camera.height;
  RenderSettings s = consistency_settings(spp, seed);
  GradientImages g = integrator.render_gradients(s);
  add_direct_differences(w, h, g);
  ConsistencyErrors e;
  e.gradients = b.gradient_relmse(g.dx, g.dy);
  e.primal = relmse(g.primal, b.reference_);
  e.reconstruction = relmse(integrator.render(s).image.rgb_layer(""), b.reference_);
  return e;
}

// The errors fall as the passes grow: at 4, 16 and 64 passes the mean of two runs' (seeds 1, 2)
// gradient, primal and reconstruction errors each under half of those at the passes before.
inline void expect_errors_fall_with_passes(GradientPathTracer& integrator, ConsistencyScene& b) {
  ConsistencyErrors previous{INFINITY, INFINITY, INFINITY};
  for (int spp : {4, 16, 64}) {
    const ConsistencyErrors e1 = consistency_errors(integrator, spp, 1, b);
    const ConsistencyErrors e2 = consistency_errors(integrator, spp, 2, b);
    const ConsistencyErrors e{0.5 * (e1.gradients + e2.gradients), 0.5 * (e1.primal + e2.primal),
                              0.5 * (e1.reconstruction + e2.reconstruction)};
    EXPECT_LT(e.gradients, 0.5 * previous.gradients) << spp << " passes";
    EXPECT_LT(e.primal, 0.5 * previous.primal) << spp << " passes";
    EXPECT_LT(e.reconstruction, 0.5 * previous.reconstruction) << spp << " passes";
    previous = e;
  }
}

// The mean of `runs` runs' gradients (seeds 1..runs) at `spp` passes, against the reference's
// differences: a bias the shift adds stays, the noise falls with the runs.
inline double mean_gradient_relmse(GradientPathTracer& integrator, int spp, int runs, ConsistencyScene& b) {
  b.render_reference();
  std::vector<float> dx(b.reference_.size(), 0.0f), dy = dx;
  for (int seed = 1; seed <= runs; ++seed) {
    GradientImages g = integrator.render_gradients(consistency_settings(spp, uint32_t(seed)));
    add_direct_differences(b.scene.camera.width, b.scene.camera.height, g);
    for (size_t i = 0; i < dx.size(); ++i) {
      dx[i] += g.dx[i] / float(runs);
      dy[i] += g.dy[i] / float(runs);
    }
  }
  return b.gradient_relmse(dx, dy);
}

}  // namespace gdr::test
