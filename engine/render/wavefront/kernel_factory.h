// Builds an integrator's kernels for a scene. It owns every -D define a kernel build gets: the
// scene's (only the BSDF, light and texture code the scene uses is compiled: SceneFeatures; none
// where the Context builds every type, Context::scene_kernels) and the integrator's own.
// Programs are built once per (program, defines) by the Context.
#pragma once
#include <string>

#include "device/context.h"
#include "scene/scene.h"

namespace gdr {

class KernelFactory {
 public:
  KernelFactory(Context& context, const Scene& scene, const Defines& integrator_defines = {});

  // Kernel `name` of kernels/<program> (e.g. "pt/pt.cl").
  Kernel make(const std::string& program, const std::string& name) const;
  const Defines& defines() const { return defines_; }

 private:
  Context& ctx_;
  Defines defines_;
};

// The defines of a scene build: GDR_{BSDF,LIGHTS,TEXTURES}_SELECTED (only what is named is
// compiled) and the scene's GDR_BSDF_<TYPE>, GDR_LIGHT_<TYPE>, GDR_TEXTURES.
Defines scene_kernel_defines(const Scene& scene);

}  // namespace gdr
