// Checks shared by the stability tests: render with counters, every value finite, and the image
// mean against an expected radiance with the pixels' own standard error.
#pragma once
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "scene/load_scene.h"
#include "support/render.h"
#include "support/test_scenes.h"

namespace gdr::test {

struct Rendered {
  std::vector<float> rgb;
  uint64_t nonfinite = 0;
};

inline Rendered render_checked(const Scene& scene, uint32_t seed, int spp, int max_depth = -1) {
  RenderSettings settings;
  settings.spp = spp;
  settings.seed = seed;
  settings.max_depth = max_depth;
  Stats stats;
  Rendered r;
  r.rgb = render_pt(scene, settings, &stats);
  r.nonfinite = stats.count("samples/nonfinite_rejected");
  // The counters were read from the render's own stats (a render that recorded nothing would
  // make the non-finite count vacuous).
  EXPECT_EQ(stats.count("samples/paths"), uint64_t(scene.camera.width) * scene.camera.height * spp);
  return r;
}

// Calls f(path, scene) for every project scene (scenes/*.xml), each on a film `width` pixels wide
// of its aspect (the field of view unchanged); returns how many there were.
template <class F>
int for_each_project_scene(int width, F&& f) {
  int scenes = 0;
  for (const auto& entry : std::filesystem::directory_iterator(std::string(GDR_SOURCE_DIR) + "/scenes")) {
    if (entry.path().extension() != ".xml") continue;
    ++scenes;
    Scene scene = load_scene(entry.path().string());
    scene.camera.height = std::max(1, width * scene.camera.height / std::max(1, scene.camera.width));
    scene.camera.width = width;
    f(entry.path().string(), scene);
  }
  return scenes;
}

// A diffuse wall 16 x 16 pixels wide, lit by a point light (a delta position) and by a degenerate
// (zero-area) emitting triangle, which can emit nothing.
inline Scene point_light_beside_zero_area_emitter() {
  SceneBuilder b;
  int wall = b.material(diffuse_material(0.5f), "wall");
  b.shape(quad_mesh({-5, -5, 10}, {-5, 5, 10}, {5, 5, 10}, {5, -5, 10}), wall, 0.0f, "wall");
  b.shape(triangle_mesh({0, 0, 8}, {1, 1, 8}, {2, 2, 8}), wall, 10.0f, "zero-area light");
  GdrLight point{};
  point.type = LIGHT_POINT;
  point.texture = -1;
  point.triangle = -1;
  point.radiance[0] = point.radiance[1] = point.radiance[2] = 20.0f;
  point.position[2] = 5.0f;
  b.scene().lights.push_back(point);
  return b.finish(camera_looking_z(0, 0, 0, 40.0f, 16));
}

inline bool all_finite(const std::vector<float>& v) {
  for (float x : v) {
    if (!std::isfinite(x)) return false;
  }
  return true;
}

// z of mean(rgb - expected) against its standard error. The unit is the pixel (its three
// channels averaged): channels of one pixel share their paths, pixels are independent, so
// |z| < 5 fails with probability 5.7e-7 when the expectation is right.
inline double mean_z(const std::vector<float>& rgb, const std::vector<double>& expected, double* mean_out = nullptr,
                     double* se_out = nullptr) {
  double n = double(rgb.size() / 3), sum = 0, sq = 0;
  for (size_t p = 0; p + 2 < rgb.size(); p += 3) {
    double d = 0;
    for (size_t c = 0; c < 3; ++c) d += (double(rgb[p + c]) - expected[p + c]) / 3.0;
    sum += d;
    sq += d * d;
  }
  double mean = sum / n;
  double se = std::sqrt(std::max(0.0, sq / n - mean * mean) / (n - 1));
  if (mean_out) *mean_out = mean;
  if (se_out) *se_out = se;
  return se > 0 ? mean / se : (mean == 0 ? 0.0 : INFINITY);
}

}  // namespace gdr::test
