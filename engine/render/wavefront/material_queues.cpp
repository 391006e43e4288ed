#include "render/wavefront/material_queues.h"

#include "scene/scene_features.h"

namespace gdr {

MaterialQueues::MaterialQueues(Context& ctx, const Scene& scene, const KernelFactory& kernels,
                               const std::string& program, const std::string& stage, size_t capacity)
    : primitives_(ctx) {
  for (int t = 0; t < BSDF_TYPE_COUNT; ++t) {
    if (scene.features.bsdf[t]) kinds_.push_back({t, kernels.make(program, stage + "_" + bsdf_type_name(t)), {}});
  }
  if (!direct()) {
    keys_ = Buffer<cl_uint>(ctx, capacity);
    scratch_ = Buffer<cl_uint>(ctx, capacity);
    for (Kind& k : kinds_) k.entries = Buffer<cl_uint>(ctx, capacity);
  }
}

const std::vector<MaterialQueues::Queue>& MaterialQueues::route(cl_uint n) {
  queues_.clear();
  if (n == 0) return queues_;
  for (Kind& k : kinds_) {
    const cl_uint count = direct() ? n : primitives_.select_key(keys_, n, cl_uint(k.type), scratch_, k.entries);
    if (count > 0) queues_.push_back({count, &k.entries, &k.kernel});
  }
  return queues_;
}

}  // namespace gdr
