#include "render/seen_emission.h"

#include "render/wavefront/ray_queues.h"

namespace gdr {

SeenEmission::SeenEmission(const RenderInputs& in, const KernelFactory& kernels, const std::string& program)
    : in_(in),
      camera_(kernels.make(program, "seen_camera")),
      emission_(kernels.make(program, "seen_emission")),
      counters_(in.context, GDR_COUNTER_NAMES(SEEN_COUNTERS)) {
  counters_.reset();
}

void SeenEmission::add(const GdrPtParams& p, cl_int extra, Buffer<GdrRayHit>& rays, const SeenFilm& to,
                       AuxLayers* aux) {
  camera_.args(in_.device_scene.camera(), p, extra, rays).run(p.pixel_count);
  intersect(in_.embree, rays, p.pixel_count, true, "camera");
  if (aux) aux->add(p, rays, p.pixel_count, in_.device_scene);
  emission_.args(p, p.pixel_count, rays, to.film, to.stride, to.slot, counters_.buffer(), in_.device_scene)
      .run(p.pixel_count);
}

void SeenEmission::read() {
  counters_.read();
  counters_.reset();
}

}  // namespace gdr
