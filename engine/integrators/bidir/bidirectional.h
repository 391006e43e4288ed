// The bidirectional integrator: light tracing (`lt`), bidirectional path tracing (`bdpt`),
// progressive photon mapping (`pm`) and vertex connection and merging (`vcm`) as one algorithm
// selected by its technique, as SmallVCM's (src/vertexcm.hxx) is; the kernels are
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
// pm: the light subpaths' vertices are photons; the camera subpath of each pixel passes delta
// surfaces and stops at its first rough vertex (a visible point, new every pass), where the
// photons within the merging radius make a density estimate; emission counts only where the
// camera subpath saw it through delta surfaces alone (Hachisuka et al. 2008, SmallVCM's ppm).
// vcm: bdpt's strategies and merging at every rough camera vertex, weighted together by VCM's MIS
// (Georgiev et al. 2012). The photons merged with are the chunk's light subpaths (the whole
// pass while the image fits one chunk, 512 x 512). The radius of pass i (from 1) is
// r_i = r_0 i^((alpha - 1) / 2): consistent, the bias vanishing as the passes grow.
//
// A pass traces one light subpath (and one camera subpath but for lt) per pixel.
//
// Parameters (IntegratorParams):
//   aux           true: also write the camera rays' first hits' albedo, normal and depth layers
//   mis           bdpt, vcm: power (default) | balance
//   strategy      bdpt: "s,t" renders that strategy alone, unweighted (pbrt's visualize strategies)
//   radius        pm, vcm: r_0 over the radius of the scene's bounding sphere (default
//                 1.5 / max(width, height): SmallVCM's 0.003 at 512 pixels, the same share of the
//                 image at other sizes)
//   radius_alpha  pm, vcm: alpha of the radius schedule (default 0.75, SmallVCM's)
#pragma once
#include <optional>

#include "render/aux_layers.h"
#include "render/film.h"
#include "render/integrator.h"
#include "render/integrator_params.h"
#include "render/splat_film.h"
#include "render/wavefront/device_counters.h"
#include "render/wavefront/kernel_factory.h"
#include "render/wavefront/primitives.h"
#include "render/wavefront/ray_queues.h"
#include "shared/bidir_types.h"

namespace gdr {

// The longest path bdpt, pm and vcm render (segments): the light-vertex store holds
// kBdptMaxSegments - 1 vertices a subpath.
constexpr int kBdptMaxSegments = 16;

struct BidirSettings {
  GdrBidirOptions options{BIDIR_LT, BIDIR_MIS_POWER, -1, -1, 0.0f, 0.0f, 0.0f, 0.0f};
  bool aux = false;
  float radius = -1.0f;  // pm, vcm: r_0 over the scene's radius; < 0: the default for the film
  float radius_alpha = 0.75f;
};
extern const std::vector<std::string> kLtParams, kBdptParams, kPmParams, kVcmParams;
BidirSettings lt_settings(const IntegratorParams& params);
BidirSettings bdpt_settings(const IntegratorParams& params);
BidirSettings pm_settings(const IntegratorParams& params);
BidirSettings vcm_settings(const IntegratorParams& params);
// The settings of `technique` (BIDIR_*) from params, and its registry name.
BidirSettings bidir_settings(int technique, const IntegratorParams& params);
const char* bidir_technique_name(int technique);

class Bidirectional : public Integrator {
 public:
  Bidirectional(const RenderInputs& inputs, const BidirSettings& settings);

  RenderResult render(const RenderSettings& settings) override;

 private:
  int technique() const { return settings_.options.technique; }
  bool lt() const { return technique() == BIDIR_LT; }
  bool connects() const { return technique() == BIDIR_BDPT || technique() == BIDIR_VCM; }
  bool merges() const { return technique() == BIDIR_PM || technique() == BIDIR_VCM; }
  // The options of pass `sample` for a chunk of `light_subpaths`: the merging radius and factors.
  GdrBidirOptions pass_options(uint32_t sample, uint32_t light_subpaths) const;
  // Pixels [first, first + count): as many light subpaths (indices first .. first + count - 1 of
  // the pass), then lt's direct emission or bdpt's camera subpaths, into the film.
  void trace_chunk(const RenderSettings& settings, uint32_t sample, uint32_t first, uint32_t count);
  void trace_light_subpaths(const GdrPtParams& params);
  void trace_direct(const GdrPtParams& params);
  void trace_camera_subpaths(const GdrPtParams& params);
  // The camera vertices of `camera_depth` segments queued in connectable_ to the store.
  void connect(const GdrPtParams& params, int camera_depth, cl_uint connectable);
  // The hash grid over the chunk's stored light vertices, and the merges of the queued camera
  // vertices with them.
  void build_grid(const GdrPtParams& params);
  void merge(const GdrPtParams& params, cl_uint connectable);
  void add_shadows(cl_uint count, const char* kind);

  RenderInputs in_;
  BidirSettings settings_;
  KernelFactory kernels_;
  Kernel lt_camera_, lt_direct_, emit_, light_shade_, camera_blocked_;
  Kernel generate_, camera_shade_, connect_, shadow_add_, grid_keys_, merge_;
  GdrBidirOptions options_;  // this chunk's
  size_t capacity_;      // subpaths of each kind in flight at once
  int store_vertices_;   // light-vertex store: vertices a light subpath (bdpt; 0 for lt)
  int stored_bound_ = 0; // the chunk's light subpaths stored at most this many vertices
  cl_uint stored_ = 0;   // and this many in all
  RayQueues queues_;
  Buffer<GdrBidirPathState> light_paths_, camera_paths_;
  Buffer<GdrBidirVertex> store_, camera_vertices_;
  Buffer<cl_uint> connectable_;
  std::optional<DevicePrimitives> primitives_;      // merging: the grid's sort
  Buffer<cl_uint> grid_keys_buffer_, grid_starts_, grid_sorted_;
  Buffer<Vec4> store_points_;
  cl_uint grid_buckets_ = 1;
  Buffer<GdrRay> shadow_rays_;
  Buffer<Vec4> shadow_values_;
  DeviceCounters counters_;
  Film film_;
  SplatFilm splats_;
  std::optional<AuxLayers> aux_;
};

}  // namespace gdr
