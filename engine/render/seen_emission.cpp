#include "render/seen_emission.h"

#include "render/wavefront/ray_queues.h"

namespace gdr {

SeenEmission::SeenEmission(const RenderInputs& in, const KernelFactory& kernels, const std::string& program)
    : in_(in),
      camera_(kernels.make(program, "seen_camera")),
      camera_listed_(kernels.make(program, "seen_camera_listed")),
      emission_(kernels.make(program, "seen_emission")),
      counters_(in.context, GDR_COUNTER_NAMES(SEEN_COUNTERS)) {
  counters_.reset();
}

void SeenEmission::add(const GdrPtParams& p, cl_int extra, Buffer<GdrRayHit>& rays, const SeenFilm& to,
                       AuxLayers* aux) {
  if (p.max_depth == 0) return;  // Mitsuba's max_depth 0 renders nothing, not even emitters seen
  camera_.args(in_.device_scene.camera(), p, extra, rays).run(p.pixel_count);
  trace(p, p.pixel_count, rays, to, aux);
}

void SeenEmission::add_listed(const GdrPtParams& p, cl_int extra, const Buffer<cl_uint>& list, cl_uint first,
                              cl_uint count, Buffer<GdrRayHit>& rays, const SeenFilm& to) {
  if (p.max_depth == 0) return;
  camera_listed_.args(in_.device_scene.camera(), p, extra, list, first, count, rays).run(count);
  GdrPtParams by_id = p;  // a listed ray's id is its pixel
  by_id.first_pixel = 0;
  trace(by_id, count, rays, to, nullptr);
}

void SeenEmission::trace(const GdrPtParams& p, cl_uint count, Buffer<GdrRayHit>& rays, const SeenFilm& to,
                         AuxLayers* aux) {
  intersect(in_.embree, rays, count, true, "camera");
  if (aux) aux->add(p, rays, count, in_.device_scene);
  emission_
      .args(p, count, rays, to.film, to.stride, to.slot, to.hit_mark, counters_.buffer(), in_.device_scene)
      .run(count);
}

void SeenEmission::read() {
  counters_.read();
  counters_.reset();
}

void SeenEmission::report(Stats* stats) {
  read();
  counters_.report(stats);
}

}  // namespace gdr
