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
// A pass traces one light subpath (and one camera subpath but for lt) per pixel, in chunks of
// pixels (BidirSubpaths, integrators/bidir/subpaths.h).
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

#include "integrators/bidir/subpaths.h"
#include "render/aux_layers.h"
#include "render/film.h"
#include "render/integrator.h"
#include "render/integrator_params.h"
#include "render/splat_film.h"
#include "shared/bidir_types.h"

namespace gdr {

struct BidirSettings {
  GdrBidirOptions options{BIDIR_LT, BIDIR_MIS_POWER, -1, -1, 0.0f, 0.0f, 0.0f, 0.0f, 0, 0};
  bool aux = false;
  float radius = -1.0f;  // pm, vcm: r_0 over the scene's radius; < 0: the default for the film
  float radius_alpha = 0.75f;
  size_t in_flight = 0;  // subpaths a chunk at most (0: the device's default, device_chunk_capacity)
};
extern const std::vector<std::string> kLtParams, kBdptParams, kPmParams, kVcmParams;
BidirSettings lt_settings(const IntegratorParams& params);
BidirSettings bdpt_settings(const IntegratorParams& params);
BidirSettings pm_settings(const IntegratorParams& params);
BidirSettings vcm_settings(const IntegratorParams& params);
// The settings of `technique` (BIDIR_*) from params, and its registry name.
BidirSettings bidir_settings(int technique, const IntegratorParams& params);
const char* bidir_technique_name(int technique);
// "power" (default) or "balance" from the parameter `mis`, as BIDIR_MIS_*.
int bidir_mis_param(const IntegratorParams& params);

// pm's and vcm's options for pass `sample` (from 0) merging with `light_subpaths` subpaths: the
// radius of the schedule above, the density estimate's normalization and VCM's MIS factors.
GdrBidirOptions merging_pass_options(const BidirSettings& settings, const Scene& scene, uint32_t sample,
                                     uint32_t light_subpaths);

// bdpt's, pm's and vcm's longest path for the settings' max_depth (segments).
int bdpt_segments(int max_depth);
// Warns, naming `integrator`, where max_depth asks for longer paths than bdpt_segments allows.
void warn_beyond_store(const char* integrator, int max_depth);
// Mitsuba's max_depth: a light subpath's first vertex connected to the camera is 2 segments.
inline bool light_subpaths_allowed(int max_depth) { return max_depth < 0 || max_depth >= 2; }

class Bidirectional : public Integrator {
 public:
  Bidirectional(const RenderInputs& inputs, const BidirSettings& settings);

  RenderResult render(const RenderSettings& settings) override;

 private:
  int technique() const { return settings_.options.technique; }
  bool merges() const { return technique() == BIDIR_PM || technique() == BIDIR_VCM; }
  // The options of pass `sample` for a chunk of `light_subpaths`: the merging radius and factors.
  GdrBidirOptions pass_options(uint32_t sample, uint32_t light_subpaths) const;
  // Pixels [first, first + count) into the film.
  void trace_chunk(const RenderSettings& settings, uint32_t sample, uint32_t first, uint32_t count);

  RenderInputs in_;
  BidirSettings settings_;
  BidirSubpaths subpaths_;
  Film film_;
  SplatFilm splats_;
  std::optional<AuxLayers> aux_;
};

}  // namespace gdr
