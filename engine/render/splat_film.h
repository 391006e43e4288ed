// The splat film: contributions to any pixel (light subpaths seen by the camera), gathered into a
// film layer deterministically: same seed, same image, on every run and device. Each path writes
// its contribution of a step into its own slot (kernels/path/splat.h: splat_write); gather()
// then sorts the slots by film row (render/wavefront/primitives.h) and adds them into the pixels
// their filter covers (each row owned by one work item, no atomics), and empties the slots for
// the next step.
#pragma once
#include <string>

#include "device/context.h"
#include "render/wavefront/kernel_factory.h"
#include "render/wavefront/primitives.h"
#include "scene/scene.h"
#include "shared/splat_types.h"

namespace gdr {

class SplatFilm {
 public:
  // `program`: the integrator's program (it holds path_splat_gather); `slots`: paths in flight.
  SplatFilm(Context& context, const KernelFactory& kernels, const std::string& program, size_t slots);

  Buffer<GdrSplat>& slots() { return slots_; }  // the kernels' `splats` argument

  // Adds slots [0, count) into `film` (a film layer of the camera's size, `height` rows) and
  // empties them.
  void gather(const Buffer<GdrCamera>& camera, int height, cl_uint count, Buffer<Vec4>& film);

  // For a gather of one's own (kernels/path/splat.h's order): slots [0, count) listed by film row,
  // row r's in sorted()[starts()[r], starts()[r + 1]); clear() empties the slots after it.
  void sort(const Buffer<GdrCamera>& camera, int height, cl_uint count);
  const Buffer<cl_uint>& starts() const { return starts_; }
  const Buffer<cl_uint>& sorted() const { return sorted_; }
  void clear() { slots_.fill(GdrSplat{}); }

 private:
  Context& ctx_;
  Kernel keys_, gather_;
  DevicePrimitives primitives_;
  Buffer<GdrSplat> slots_;
  Buffer<cl_uint> keys_buffer_, starts_, sorted_;
};

}  // namespace gdr
