#include "integrators/device_scene.h"


#include "integrators/environment_distribution.h"
#include "integrators/light_distribution.h"

namespace gdr {
namespace {

// The lights as the kernels see them (with their sampling tables' offsets), and the tables.
std::vector<GdrLight> device_lights(const Scene& s, std::vector<float>& env_tables) {
  std::vector<GdrLight> lights = s.lights;
  build_environment_tables(s, lights, env_tables);
  return lights;
}

}  // namespace

DeviceScene::DeviceScene(Context& ctx, const Scene& s) : DeviceScene(ctx, s, std::vector<float>()) {}

DeviceScene::DeviceScene(Context& ctx, const Scene& s, std::vector<float> env_tables)
    : triangles_(ctx, s.triangles, CL_MEM_READ_ONLY),
      positions_(ctx, s.positions, CL_MEM_READ_ONLY),
      normals_(ctx, s.normals, CL_MEM_READ_ONLY),
      uvs_(ctx, s.uvs, CL_MEM_READ_ONLY),
      shapes_(ctx, s.shapes, CL_MEM_READ_ONLY),
      materials_(ctx, s.materials, CL_MEM_READ_ONLY),
      textures_(ctx, s.textures, CL_MEM_READ_ONLY),
      texels_(ctx, s.texels, CL_MEM_READ_ONLY),
      lights_(ctx, device_lights(s, env_tables), CL_MEM_READ_ONLY),
      light_cdf_(ctx, light_selection_cdf(s), CL_MEM_READ_ONLY),
      env_cdf_(ctx, env_tables, CL_MEM_READ_ONLY),
      camera_(ctx, std::vector<GdrCamera>{s.camera}, CL_MEM_READ_ONLY),
      light_count_(static_cast<int>(s.lights.size())),
      width_(s.camera.width),
      height_(s.camera.height) {
  for (size_t i = 0; i < s.lights.size(); ++i) {
    if (s.lights[i].type == LIGHT_CONSTANT || s.lights[i].type == LIGHT_ENVMAP) env_light_ = static_cast<int>(i);
  }
}

void DeviceScene::set_args(Kernel& k, cl_uint first) const {
  k.set_arg(first + 0, triangles_);
  k.set_arg(first + 1, positions_);
  k.set_arg(first + 2, normals_);
  k.set_arg(first + 3, uvs_);
  k.set_arg(first + 4, shapes_);
  k.set_arg(first + 5, materials_);
  k.set_arg(first + 6, textures_);
  k.set_arg(first + 7, texels_);
  k.set_arg(first + 8, lights_);
  k.set_arg(first + 9, light_cdf_);
  k.set_arg(first + 10, env_cdf_);
}


GdrPtParams DeviceScene::path_params(const RenderSettings& settings, uint32_t sample, uint32_t first,
                                     uint32_t count) const {
  GdrPtParams p{};
  p.seed = settings.seed;
  p.first_pixel = first;
  p.pixel_count = count;
  p.sample = sample;
  p.max_depth = settings.max_depth;
  p.rr_depth = settings.rr_depth;
  p.light_count = light_count_;
  p.env_light = env_light_;
  p.strategy = settings.strategy;
  p.width = width_;
  p.height = height_;
  return p;
}

Defines scene_kernel_defines(const Scene& scene) {
  Defines d = scene.features.kernel_defines();
  d["GDR_BSDF_SELECTED"] = "1";
  d["GDR_LIGHTS_SELECTED"] = "1";
  return d;
}

}  // namespace gdr
