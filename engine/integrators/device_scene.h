// The scene's arrays on the OpenCL device, in the order of SCENE_DATA_ARGS
// (kernels/scene/scene_data.h), plus what the host knows about lights for the kernels.
#pragma once
#include <vector>

#include "device/context.h"
#include "integrators/render_settings.h"
#include "scene/scene.h"
#include "shared/pt_types.h"

namespace gdr {

class DeviceScene {
 public:
  DeviceScene(Context& context, const Scene& scene);

  // Sets the SCENE_DATA_ARGS of `kernel` starting at argument `first`.
  void set_args(Kernel& kernel, cl_uint first) const;

  const Buffer<GdrCamera>& camera() const { return camera_; }

  // The launch parameters every path-based kernel shares, for pixels [first, first + count).
  GdrPtParams path_params(const RenderSettings& settings, uint32_t sample, uint32_t first, uint32_t count) const;

 private:
  // env_tables is filled while lights_ is built (members initialise in declaration order).
  DeviceScene(Context& context, const Scene& scene, std::vector<float> env_tables);

  Buffer<GdrTriangle> triangles_;
  Buffer<Vec4> positions_;
  Buffer<Vec4> normals_;
  Buffer<float> uvs_;
  Buffer<GdrShape> shapes_;
  Buffer<GdrMaterial> materials_;
  Buffer<GdrTexture> textures_;
  Buffer<Vec4> texels_;
  Buffer<GdrLight> lights_;
  Buffer<float> light_cdf_;
  Buffer<float> env_cdf_;
  Buffer<GdrCamera> camera_;
  int light_count_ = 0;
  int env_light_ = -1;
  int width_ = 0, height_ = 0;
};

// The -D defines of the kernels for a scene: only its BSDF and light types.
Defines scene_kernel_defines(const Scene& scene);

}  // namespace gdr
