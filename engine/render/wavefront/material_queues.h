// Per-material queues (pbrt-v4's wavefront design): after an intersection an integrator's routing
// kernel writes each queue entry's key, its hit's BSDF type (kernels/path/material_queues.h), and
// the entries of each type the scene has become that type's queue (in order: the images do not
// depend on the routing), all types selected together with one read of their counts. Each queue
// is shaded by its own kernel, `<stage>_<type>` (e.g. pt_shade_diffuse), specialized for that
// material; a type the scene lacks has no queue and no launch. With one type there is nothing to
// route: its kernel takes the whole queue (direct). Unrouted, a scene of several types has one
// queue, shaded by `<stage>` itself (built for the scene's types), also direct. Types with a
// kernel that shades eight entries a work item (`<lane stage>_<type>`, for CPU devices) may use it.
#pragma once
#include <string>
#include <vector>

#include "render/wavefront/kernel_factory.h"
#include "render/wavefront/primitives.h"
#include "scene/scene.h"

namespace gdr {

class MaterialQueues {
 public:
  // The kernels `stage`_<type> of `program` for the scene's types; up to `capacity` entries.
  // `routed` false: `stage` for all of them, where the scene has several.
  // `lanes`: the types shaded by `lanes.stage`_<type> instead, eight entries a work item.
  struct LaneKernels {
    std::string stage;
    std::vector<int> types;
  };
  MaterialQueues(Context& context, const Scene& scene, const KernelFactory& kernels, const std::string& program,
                 const std::string& stage, size_t capacity, bool routed = true, const LaneKernels& lanes = {});

  struct Queue {
    cl_uint count;                  // entries
    cl_uint first;                  // where they start in entries() (0 when direct)
    Kernel* kernel;
    // Entries a work item of the kernel takes (1, or LANES of kernels/core/lanes.h).
    size_t lanes;
    void run() const;
  };

  // The routing kernel's output: each entry's key (BSDF type, or BSDF_TYPE_COUNT for none); only
  // where routing is needed (not direct).
  Buffer<cl_uint>& keys() { return keys_; }
  // The routed entries' positions in the routed queue, each type's from its queue's `first` on
  // (unused when direct).
  const Buffer<cl_uint>& entries() const { return entries_; }
  // No routing: the scene has one material type, whose kernel takes the queue as it is (or the
  // queues are not routed).
  bool direct() const { return kinds_.size() == 1; }
  // The non-empty queues of the first n routed entries (direct: the one type's, all n entries).
  const std::vector<Queue>& route(cl_uint n);

 private:
  std::vector<Kernel> kinds_;  // one shading kernel per type the scene has
  std::vector<size_t> lanes_;  // and the entries each one's work items take
  Buffer<cl_uint> types_;      // and those types, on the device
  Buffer<cl_uint> keys_, scratch_, entries_;
  DevicePrimitives primitives_;
  std::vector<Queue> queues_;
};

}  // namespace gdr
