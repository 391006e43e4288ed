// Gradient-domain bidirectional path tracing (`gbdpt`, Manzi et al. 2015): per pixel sample a light
// subpath (the bidirectional kernels', BidirSubpaths) and a group of camera subpaths, the base and
// its four offsets through the neighbouring pixels, shifted by G-PT's shifts (GradientGroups
// built connecting: kernels/gbidir). Every strategy with s >= 0 light and t >= 2 camera vertices
// is evaluated on the base and on each offset: the emission the camera subpaths find (s = 0),
// their connections to a light point (s = 1) and to each stored vertex of the pixel's light
// subpath (s >= 2). An offset that shares the base's vertex shares its connection segment; one at
// a vertex of its own reconnects to the same light vertex, where both camera vertices and the light
// vertex are diffuse (else that connection's shift fails, counted in
// shift_failures/glossy_connection). Base and offset of a strategy share the balance heuristic
// over those strategies of both paths (kernels/gbidir/weights.h); the primal is the sum of the base
// paths' shares, as G-PT's. Light tracing (t = 1), under bdpt's weight over every strategy, is
// shifted from its splat pixel (LightTracingShifts): after each light bounce the light vertices the
// camera sees are moved to the neighbour pixels by camera rays through the shifted film positions,
// reconnected to their parents, and base and offsets splat into the pairs' accumulators by their
// own pair weight; the shifted strategies' weights leave each path light tracing's share. Outputs
// and reconstruction are G-PT's.
//
// Gradient-domain vertex connection and merging (`gvcm`, Sun et al. 2017) is the same integrator
// with merging: every rough camera vertex of base and offsets also merges with the pass's photons
// (all groups' light subpaths, in their hash grid) by G-PM's merge stage (PhotonShifts): an offset
// at a vertex of its own merges the photons shifted there (kernels/gbidir/photon_shift.h), one at
// the base's vertex the same photons. The light subpaths are vcm's, the radius schedule vcm's, and
// every strategy's weight (connections, merges, emission, light points) is the balance heuristic
// over all of VCM's strategies of base and offset, the sums carrying merging's factors; light
// tracing, under vcm's weight over every strategy, is shifted as gbdpt's.
//
// The manifold shift walks the camera subpaths' offsets across specular chains as gpt's does, their
// bidirectional sums carried through the walk's vertices (kernels/gpt/manifold_step.h), and gvcm's
// photons whose parent is a delta vertex as gpm's do (kernels/gbidir/photon_chain.h), their
// light-side sums recomputed along the new chain. Left out: light-traced vertices whose parent is
// a delta vertex are not shifted (they go to the direct layer), nor, under the other shifts, such
// photons (counted in shift_failures/photon_parent).
//
// Parameters (IntegratorParams): shift (hybrid, the default, | replay | manifold), shift_threshold,
// aux and the manifold walk's as gpt's; gvcm: radius and radius_alpha as vcm's; recon,
// recon_solver, alpha: the reconstruction (render/gradient_images.h). Paths are bdpt's: at most
// kBdptMaxSegments segments.
#pragma once
#include <optional>

#include "integrators/bidir/bidirectional.h"
#include "integrators/bidir/subpaths.h"
#include "integrators/gbidir/light_tracing_shifts.h"
#include "integrators/gbidir/photon_shifts.h"
#include "integrators/gpt/gradient_path_tracer.h"
#include "render/splat_film.h"

namespace gdr {

extern const std::vector<std::string> kGbdptParams, kGvcmParams;
GptSettings gbdpt_settings(const IntegratorParams& params);
GptSettings gvcm_settings(const IntegratorParams& params);
// gvcm's light subpaths and radius schedule: vcm's, under the balance heuristic.
BidirSettings gvcm_photon_settings(const IntegratorParams& params);
// gbdpt's light subpaths: bdpt's store and connections to the camera, the balance heuristic (the
// options the kernels weigh the camera subpaths by: kernels/gbidir/weights.h, gbdpt_options), and
// with `power_sums` the power heuristic's sums too (--primal power).
GdrBidirOptions gbdpt_light_options(bool power_sums = false);

class GradientBidirectional : public GradientPathTracer {
 public:
  // `merging`: gvcm's photons (else gbdpt).
  GradientBidirectional(const RenderInputs& inputs, const GptSettings& gpt, const IntegratorParams& params = {},
                        std::optional<BidirSettings> merging = std::nullopt);

  RenderResult render(const RenderSettings& settings) override;

 private:
  void trace_chunk(const RenderSettings& settings, uint32_t sample, uint32_t first, uint32_t count) override;
  void end_pass() override;

  std::optional<BidirSettings> merging_;
  const GdrBidirOptions light_options_;  // gbdpt's (gvcm's are the pass's)
  BidirSubpaths subpaths_;  // the light subpaths, one a group
  SplatFilm splats_;        // their connections to the camera (t = 1)
  LightTracingShifts light_tracing_;  // and those shifted to the neighbour pixels
  std::optional<PhotonShifts> shifts_;  // gvcm's merges
};

}  // namespace gdr
