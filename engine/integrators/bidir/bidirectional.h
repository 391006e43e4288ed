// The bidirectional integrator: light tracing (`lt`) and bidirectional path tracing (`bdpt`) as
// one algorithm selected by its technique, as SmallVCM's (src/vertexcm.hxx) is; the kernels are
// kernels/bidir/bidir.cl.
//
// lt: light subpaths traced from the lights in wavefront batches (emission sampling, importance
// transport), each vertex connected to the camera through a shadow ray and splatted into the film
// (render/splat_film.h, gathered deterministically). Emission the camera sees directly (an area
// light or the environment behind a pixel) is what a light subpath cannot reach through the
// pinhole: one camera ray per pixel and pass adds it, as Mitsuba's ptracer does with
// hide_emitters = false.
//
// bdpt: the same light subpaths also keep their vertices in the light-vertex store; then a camera
// subpath per pixel connects each of its vertices to a light point and to every stored vertex of
// its pixel's light subpath (one batch of shadow rays per stored vertex), and adds the emission it
// finds; every strategy (s light vertices, t camera vertices) is weighted by the balance or power
// heuristic over all strategies of its path. The store bounds the path length: an unbounded
// max_depth (or one above kBdptMaxSegments) renders paths of up to kBdptMaxSegments segments.
//
// A pass traces one light subpath (and under bdpt one camera subpath) per pixel.
//
// Parameters (IntegratorParams):
//   aux       true: also write the camera rays' first hits' albedo, normal and depth layers
//   mis       bdpt: power (default) | balance
//   strategy  bdpt: "s,t" renders that strategy alone, unweighted (pbrt's visualize strategies)
#pragma once
#include <optional>

#include "render/aux_layers.h"
#include "render/film.h"
#include "render/integrator.h"
#include "render/integrator_params.h"
#include "render/splat_film.h"
#include "render/wavefront/device_counters.h"
#include "render/wavefront/kernel_factory.h"
#include "render/wavefront/ray_queues.h"
#include "shared/bidir_types.h"

namespace gdr {

// The longest path bdpt renders (segments): the light-vertex store holds kBdptMaxSegments - 2
// vertices a subpath.
constexpr int kBdptMaxSegments = 16;

struct BidirSettings {
  GdrBidirOptions options{BIDIR_LT, BIDIR_MIS_POWER, -1, -1};
  bool aux = false;
};
extern const std::vector<std::string> kLtParams, kBdptParams;
BidirSettings lt_settings(const IntegratorParams& params);
BidirSettings bdpt_settings(const IntegratorParams& params);

class Bidirectional : public Integrator {
 public:
  Bidirectional(const RenderInputs& inputs, const BidirSettings& settings);

  RenderResult render(const RenderSettings& settings) override;

 private:
  bool bdpt() const { return settings_.options.technique == BIDIR_BDPT; }
  // Pixels [first, first + count): as many light subpaths (indices first .. first + count - 1 of
  // the pass), then lt's direct emission or bdpt's camera subpaths, into the film.
  void trace_chunk(const RenderSettings& settings, uint32_t sample, uint32_t first, uint32_t count);
  void trace_light_subpaths(const GdrPtParams& params);
  void trace_direct(const GdrPtParams& params);
  void trace_camera_subpaths(const GdrPtParams& params);
  // The camera vertices of `camera_depth` segments queued in connectable_ to the store.
  void connect(const GdrPtParams& params, int camera_depth, cl_uint connectable);
  void add_shadows(cl_uint count, const char* kind);

  RenderInputs in_;
  BidirSettings settings_;
  KernelFactory kernels_;
  Kernel lt_camera_, lt_direct_, emit_, light_shade_, camera_blocked_;
  Kernel generate_, camera_shade_, connect_, shadow_add_;
  size_t capacity_;      // subpaths of each kind in flight at once
  int store_vertices_;   // light-vertex store: vertices a light subpath (bdpt; 0 for lt)
  int stored_bound_ = 0; // the chunk's light subpaths stored at most this many vertices
  RayQueues queues_;
  Buffer<GdrBidirPathState> light_paths_, camera_paths_;
  Buffer<GdrBidirVertex> store_, camera_vertices_;
  Buffer<cl_uint> connectable_;
  Buffer<GdrRay> shadow_rays_;
  Buffer<Vec4> shadow_values_;
  DeviceCounters counters_;
  Film film_;
  SplatFilm splats_;
  std::optional<AuxLayers> aux_;
};

}  // namespace gdr
