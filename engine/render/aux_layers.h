// First-hit auxiliary layers, for denoisers and inspection: albedo, shading normal and depth of
// the camera rays' first hits, written by the shared path stage `path_aux` (kernels/path/aux.h)
// that every path-based program compiles in. An integrator calls add() on its intersected camera
// queue and add_to() on its image.
#pragma once
#include "device/context.h"
#include "image/image.h"
#include "render/device_scene.h"
#include "render/wavefront/kernel_factory.h"
#include "shared/pt_types.h"
#include "shared/ray_types.h"

namespace gdr {

class AuxLayers {
 public:
  // `program`: the integrator's program (it holds path_aux).
  AuxLayers(Context& context, const KernelFactory& kernels, const std::string& program, size_t pixels);

  void clear();
  // The first hits of camera rays [0, count) of a chunk; ray i belongs to pixel first_pixel + i.
  void add(const GdrPtParams& params, const Buffer<GdrRayHit>& first_hits, cl_uint count,
           const DeviceScene& scene);
  // Appends the albedo, normal and depth layers (means over `samples` of all ranks; render/film.h:
  // a collective under MPI).
  void add_to(Image& image, int samples) const;

 private:
  Kernel kernel_;
  Stats* stats_;
  Buffer<Vec4> albedo_, normal_;
  Buffer<float> depth_;
};

}  // namespace gdr
