// The device layout of every reconstruction buffer (kernels/shared/recon_layout.h): three float
// planes (R, G, B) stacked with gap rows between them, rows padded to a multiple of 16 floats, all
// gap entries zero (or NaN for absent inputs). Kernels take chunks of `vec` floats: 16 on CPU
// devices (written as float16 operations), 1 on GPUs (kernels/recon/grid.h).
#pragma once
#include <memory>
#include <string>

#include "device/context.h"
#include "shared/recon_layout.h"

namespace gdr {

using PlaneBuffer = Buffer<float>;

struct Planes {
  Planes(int width, int height, int vec);
  int w, h;
  int ws;   // row stride
  int vec;  // floats per work item

  // Buffer length: the rows, and slack for a vector load one past the last row's end.
  size_t floats() const { return size_t(ws) * size_t(gdr_recon_rows(h)) + GDR_RECON_ALIGN; }
  size_t chunks() const { return size_t(h) * ws / vec; }  // work items per plane
  Planes coarse() const { return Planes((w + 1) / 2, (h + 1) / 2, vec); }

  // A zero-filled buffer of this layout.
  PlaneBuffer buffer(Context& ctx) const;
  // Runs a kernel over every chunk: 2D (chunk, channel).
  void run(Kernel& k) const { k.run_2d(chunks(), 3, 64, 1); }
};

// Floats per work item on this device: 16 on CPUs, 1 otherwise; $GDR_RECON_VECTOR (1 or 16)
// overrides it, so that the GPU form of the kernels can be checked on a CPU device. Read at the
// first call for a context and kept with it.
int recon_vector_width(Context& ctx);

// Builds (once per context) a kernels/recon program with the defines for this device.
std::shared_ptr<Program> recon_program(Context& ctx, const std::string& file);

}  // namespace gdr
