// Renders on the tests' shared device context: a scene's Embree and device representations
// (what a render builds once and hands to its integrator), and the path tracer's image.
#pragma once
#include <vector>

#include "accel/embree_scene.h"
#include "integrators/pt/path_tracer.h"
#include "render/device_scene.h"
#include "render/integrator.h"
#include "support/devices.h"

namespace gdr::test {

// The inputs of an integrator for `scene` (which must outlive this).
struct SceneOnDevice {
  explicit SceneOnDevice(const Scene& s, Stats* stats = nullptr)
      : scene(s), embree(s, BuildQuality::Low, stats), device(default_context(), s) {}
  RenderInputs inputs() { return RenderInputs{default_context(), scene, embree, device}; }

  const Scene& scene;
  EmbreeScene embree;
  DeviceScene device;
};

// The RGB image (interleaved) of `scene` rendered with `settings`.
inline std::vector<float> render_pt(const Scene& scene, const RenderSettings& settings, Stats* stats = nullptr,
                                    const PtSettings& pt = {}) {
  SceneOnDevice on_device(scene, stats);
  PathTracer tracer(on_device.inputs(), pt);
  return tracer.render(settings).image.rgb_layer("");
}

}  // namespace gdr::test
