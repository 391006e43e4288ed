// The scene on the OpenCL device: one buffer per entry of the scene-buffer list
// (kernels/shared/scene_buffers.h), built once per render and handed to every integrator like
// the EmbreeScene. Passed to Kernel::args where a kernel declares SCENE_DATA_ARGS, it binds all of
// them there.
#pragma once
#include <vector>

#include "device/context.h"
#include "render/render_settings.h"
#include "scene/scene.h"
#include "shared/pt_types.h"
#include "shared/scene_buffers.h"

namespace gdr {

// The host's arrays of the scene buffers, as uploaded (the lights with their table offsets, the
// light selection cdf and the environment tables are derived from the scene here, and so are
// the materials' coating tables, computed on the context's device).
#define GDR_SCENE_ARRAY(ktype, htype, name, what) std::vector<htype> name;
struct SceneArrays {
  GDR_SCENE_BUFFERS(GDR_SCENE_ARRAY, GDR_SCENE_ARRAY)
};
#undef GDR_SCENE_ARRAY

SceneArrays scene_arrays(Context& context, const Scene& scene);

class DeviceScene {
 public:
  DeviceScene(Context& context, const Scene& scene);

  // Sets the kernel's SCENE_DATA_ARGS, starting at parameter `first`; returns their number.
  cl_uint bind_to(Kernel& kernel, cl_uint first) const;

  const Buffer<GdrCamera>& camera() const { return camera_; }

  // The launch parameters every path-based kernel shares, for pixels [first, first + count)
  // (strategy: PT_STRATEGY_MIS).
  GdrPtParams path_params(const RenderSettings& settings, uint32_t sample, uint32_t first, uint32_t count) const;

 private:
#define GDR_SCENE_MEMBER(ktype, htype, name, what) Buffer<htype> name##_;
  GDR_SCENE_BUFFERS(GDR_SCENE_MEMBER, GDR_SCENE_MEMBER)
#undef GDR_SCENE_MEMBER
  Buffer<GdrCamera> camera_;
  int light_count_ = 0;
  int env_light_ = -1;
  int width_ = 0, height_ = 0;
};

}  // namespace gdr
