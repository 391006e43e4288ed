#include "render/wavefront/material_queues.h"

#include <algorithm>

#include "scene/scene_features.h"

namespace gdr {
namespace {

constexpr size_t kShadingLanes = 8;  // LANES of kernels/core/lanes.h
// Work items a group of a lane kernel, whose items each hold eight paths' state: on PoCL small
// groups shade faster (pt on the Cornell box, scripts/bench-ab at 512x512, 16 spp, two cores: 8
// took 0.90 of 64's trace time, 4 0.94 of 8's, 1 1.03 of 4's; gpt, which they leave alone, moved
// by up to 4% in the same runs).
constexpr size_t kLaneGroup = 4;

}  // namespace

MaterialQueues::MaterialQueues(Context& ctx, const Scene& scene, const KernelFactory& kernels,
                               const std::string& program, const std::string& stage, size_t capacity, bool routed,
                               const LaneKernels& lanes)
    : primitives_(ctx) {
  std::vector<cl_uint> types;
  for (int t = 0; t < BSDF_TYPE_COUNT; ++t) {
    if (scene.features.bsdf[t]) types.push_back(cl_uint(t));
  }
  if (!routed && types.size() > 1) {
    kinds_.push_back(kernels.make(program, stage));
    lanes_.push_back(1);
    return;
  }
  for (cl_uint t : types) {
    const bool laned = std::find(lanes.types.begin(), lanes.types.end(), int(t)) != lanes.types.end();
    kinds_.push_back(kernels.make(program, (laned ? lanes.stage : stage) + "_" + bsdf_type_name(int(t))));
    lanes_.push_back(laned ? kShadingLanes : 1);
  }
  if (!direct()) {
    types_ = Buffer<cl_uint>(ctx, types);
    keys_ = Buffer<cl_uint>(ctx, capacity);
    scratch_ = Buffer<cl_uint>(ctx, types.size() * capacity + 1);
    entries_ = Buffer<cl_uint>(ctx, capacity);
  }
}

void MaterialQueues::Queue::run() const {
  if (lanes > 1) {
    kernel->run_lanes(count, lanes, kLaneGroup);
  } else {
    kernel->run(count);
  }
}

const std::vector<MaterialQueues::Queue>& MaterialQueues::route(cl_uint n) {
  queues_.clear();
  if (n == 0) return queues_;
  if (direct()) {
    queues_.push_back({n, 0, &kinds_[0], lanes_[0]});
    return queues_;
  }
  const std::vector<cl_uint> starts = primitives_.select_keys(keys_, n, types_, scratch_, entries_);
  for (size_t i = 0; i < kinds_.size(); ++i) {
    if (starts[i + 1] > starts[i]) queues_.push_back({starts[i + 1] - starts[i], starts[i], &kinds_[i], lanes_[i]});
  }
  return queues_;
}

}  // namespace gdr
