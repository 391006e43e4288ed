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

// The inputs of an integrator for `scene` (which must outlive this), on `context` (default: the
// shared one, which records no stats).
struct SceneOnDevice {
  explicit SceneOnDevice(const Scene& s, Stats* stats = nullptr, Context& context = default_context())
      : scene(s), context(context), embree(s, BuildQuality::Low, stats), device(context, s) {}
  RenderInputs inputs() { return RenderInputs{context, scene, embree, device}; }

  const Scene& scene;
  Context& context;
  EmbreeScene embree;
  DeviceScene device;
};

// SceneOnDevice on a context of its own that records into `stats`: the kernels' counters
// (rejected non-finite samples, paths) and launches report to their context's stats, so the
// shared context would leave them unread.
// `scene_kernels` chooses the context's kernel builds (Context::scene_kernels) before anything is
// built on it.
struct SceneOnCountingDevice {
  SceneOnCountingDevice(const Scene& s, Stats* stats)
      : context(select_device(""), stats), on_device(s, stats, context) {}
  SceneOnCountingDevice(const Scene& s, Stats* stats, bool scene_kernels)
      : context(select_device(""), stats), on_device(s, stats, with_scene_kernels(context, scene_kernels)) {}
  RenderInputs inputs() { return on_device.inputs(); }

  Context context;
  SceneOnDevice on_device;

 private:
  static Context& with_scene_kernels(Context& c, bool on) {
    c.set_scene_kernels(on);
    return c;
  }
};

// The RGB image (interleaved) of `scene` rendered with `settings`; with `stats`, counted
// (SceneOnCountingDevice).
inline std::vector<float> render_pt(const Scene& scene, const RenderSettings& settings, Stats* stats = nullptr,
                                    const PtSettings& pt = {}) {
  if (!stats) {
    SceneOnDevice on_device(scene);
    return PathTracer(on_device.inputs(), pt).render(settings).image.rgb_layer("");
  }
  SceneOnCountingDevice on_device(scene, stats);
  return PathTracer(on_device.inputs(), pt).render(settings).image.rgb_layer("");
}

}  // namespace gdr::test
