// Renders a scene with the path tracer on the tests' shared device context.
#pragma once
#include <vector>

#include "accel/embree_scene.h"
#include "integrators/pt/path_tracer.h"
#include "support/devices.h"

namespace gdr::test {

// The RGB image (interleaved) of `scene` rendered with `settings`.
inline std::vector<float> render_pt(const Scene& scene, const RenderSettings& settings, Stats* stats = nullptr) {
  Context& ctx = default_context();
  EmbreeScene embree(scene, BuildQuality::Low, stats);
  PathTracer tracer(ctx, scene, embree);
  return tracer.render(settings).image.rgb_layer("");
}

}  // namespace gdr::test
