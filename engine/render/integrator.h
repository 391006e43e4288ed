// What an integrator is to the rest of the engine: built from the scene's shared device and
// Embree representations and its own parameters, it renders passes until the settings say stop
// and returns the image (with its integrator-specific layers).
#pragma once
#include "accel/embree_scene.h"
#include "device/context.h"
#include "render/device_scene.h"
#include "render/render_settings.h"
#include "scene/scene.h"

namespace gdr {

// Built once per render and shared by whatever integrator runs.
struct RenderInputs {
  Context& context;
  const Scene& scene;
  EmbreeScene& embree;
  const DeviceScene& device_scene;
};

class Integrator {
 public:
  virtual ~Integrator() = default;
  virtual RenderResult render(const RenderSettings& settings) = 0;
};

}  // namespace gdr
