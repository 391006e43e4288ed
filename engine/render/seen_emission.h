// Emission seen directly by camera rays (kernels/path/seen_emission.h): a camera ray a pixel of a
// batch, its filter offset from the pixel's camera numbers or an extra sample's, and what its
// first hit emits toward the camera or what its escape direction sees, added to one slot a pixel
// of a film. Light tracing's estimate of that emission (the camera's own numbers), and the
// gradient-domain integrators' extra samples of their direct layer (--direct-samples:
// kernels/sampling/dimensions.h, RNG_BLOCK_SEEN; integrators/gpt/direct_samples.h).
#pragma once
#include "render/aux_layers.h"
#include "render/integrator.h"
#include "render/wavefront/device_counters.h"
#include "render/wavefront/kernel_factory.h"
#include "shared/pt_types.h"
#include "shared/ray_types.h"

namespace gdr {

// Where the emission goes: film[pixel * stride + slot], with hit_mark added to w where a ray saw
// some.
struct SeenFilm {
  Buffer<Vec4>& film;
  cl_uint stride = 1;
  cl_uint slot = 0;
  float hit_mark = 0.0f;
};

class SeenEmission {
 public:
  // `program`: a program that compiles kernels/path/seen_emission.h in.
  SeenEmission(const RenderInputs& inputs, const KernelFactory& kernels, const std::string& program);

  // Pixels [p.first_pixel, + p.pixel_count), a ray each in `rays` (which holds that many), from
  // the camera's numbers of (p.seed, pixel, p.sample) (extra -1) or extra sample `extra`'s.
  // `aux`: their first hits too.
  void add(const GdrPtParams& p, cl_int extra, Buffer<GdrRayHit>& rays, const SeenFilm& to, AuxLayers* aux = nullptr);
  // The same for the pixels list[first, first + count).
  void add_listed(const GdrPtParams& p, cl_int extra, const Buffer<cl_uint>& list, cl_uint first, cl_uint count,
                  Buffer<GdrRayHit>& rays, const SeenFilm& to);
  // SEEN_COUNTERS (the kernels' `counters`); read() reads them (a wait) and zeroes them, report()
  // reads them and adds their totals to the stats.
  DeviceCounters& counters() { return counters_; }
  void read();
  void report(Stats* stats);

 private:
  // The rays' hits, and their emission into `to` (ray i's pixel: p.first_pixel + its id).
  void trace(const GdrPtParams& p, cl_uint count, Buffer<GdrRayHit>& rays, const SeenFilm& to, AuxLayers* aux);

  RenderInputs in_;
  Kernel camera_, camera_listed_, emission_;
  DeviceCounters counters_;
};

}  // namespace gdr
