#include "render/wavefront/kernel_factory.h"

namespace gdr {

Defines scene_kernel_defines(const Scene& scene) {
  Defines d = scene.features.kernel_defines();
  d["GDR_BSDF_SELECTED"] = "1";
  d["GDR_LIGHTS_SELECTED"] = "1";
  d["GDR_TEXTURES_SELECTED"] = "1";
  return d;
}

KernelFactory::KernelFactory(Context& ctx, const Scene& scene, const Defines& integrator_defines)
    : ctx_(ctx), defines_(ctx.scene_kernels() ? scene_kernel_defines(scene) : Defines{}) {
  for (const auto& [name, value] : integrator_defines) defines_[name] = value;
}

Kernel KernelFactory::make(const std::string& program, const std::string& name) const {
  return ctx_.program(program, defines_)->kernel(name);
}

}  // namespace gdr
