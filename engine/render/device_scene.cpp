#include "render/device_scene.h"

#include "render/coating_tables.h"
#include "render/environment_distribution.h"
#include "render/light_distribution.h"

namespace gdr {

SceneArrays scene_arrays(Context& ctx, const Scene& s) {
  SceneArrays a;
  a.triangles = s.triangles;
  a.positions = s.positions;
  a.normals = s.normals;
  a.uvs = s.uvs;
  a.shapes = s.shapes;
  a.materials = s.materials;
  std::vector<bool> used(s.materials.size(), false);  // no table for a material no shape uses
  for (const GdrShape& shape : s.shapes) {
    if (shape.material >= 0 && size_t(shape.material) < used.size()) used[shape.material] = true;
  }
  build_coating_tables(ctx, a.materials, a.coating_tables, used);
  a.textures = s.textures;
  a.texels = s.texels;
  a.lights = s.lights;
  build_environment_tables(s, a.lights, a.env_tables, a.texels);
  a.light_cdf = light_selection_cdf(s);
  return a;
}

DeviceScene::DeviceScene(Context& ctx, const Scene& s)
    : camera_(ctx, std::vector<GdrCamera>{s.camera}, CL_MEM_READ_ONLY),
      light_count_(static_cast<int>(s.lights.size())),
      width_(s.camera.width),
      height_(s.camera.height) {
  SceneArrays a = scene_arrays(ctx, s);
#define GDR_SCENE_UPLOAD(ktype, htype, name, what) name##_ = Buffer<htype>(ctx, a.name, CL_MEM_READ_ONLY);
  GDR_SCENE_BUFFERS(GDR_SCENE_UPLOAD, GDR_SCENE_UPLOAD)
#undef GDR_SCENE_UPLOAD
  for (size_t i = 0; i < s.lights.size(); ++i) {
    if (s.lights[i].type == LIGHT_CONSTANT || s.lights[i].type == LIGHT_ENVMAP) env_light_ = static_cast<int>(i);
  }
}

cl_uint DeviceScene::bind_to(Kernel& k, cl_uint first) const {
  cl_uint i = first;
#define GDR_SCENE_BIND(ktype, htype, name, what) k.set_arg(i++, name##_);
  GDR_SCENE_BUFFERS(GDR_SCENE_BIND, GDR_SCENE_BIND)
#undef GDR_SCENE_BIND
  return i - first;
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
  p.strategy = PT_STRATEGY_MIS;
  p.width = width_;
  p.height = height_;
  return p;
}

}  // namespace gdr
