// Gradient-domain photon mapping (`gpm`, Hua et al. 2017): per pixel sample a group of camera
// subpaths, the base and its four offsets through the neighbouring pixels, shifted by G-PT's
// shifts up to the base's first rough vertex (the visible point; GradientGroups built merging), and
// per pass the photons of one light subpath a pixel (the bidirectional kernels', BidirSubpaths, as
// pm's). At each visible point the photons within the radius make pm's density estimate for the
// base; each offset merges the same photons shifted to its own visible point (PhotonShifts:
// kernels/gbidir/photon_shift.h), and base and offset share the pair weight 1 / (1 + p(y)|J|/p(x)).
// Emission counts where the camera subpaths see it through delta vertices only, as pm's, under
// the same pair weight. The radius schedule and its parameters are pm's; outputs and
// reconstruction are G-PT's.
//
// A photon whose parent is a delta vertex is shifted by a manifold walk under --shift manifold
// (kernels/gbidir/photon_chain.h: the chain moved with the last rough light vertex fixed, as the
// reference's shiftPhotonManifold; counted in shifts/manifold and shift_failures/manifold, the
// walks' own outcomes in manifold/*); under the other shifts, and behind a point, spot or
// infinite light or a chain over MANIFOLD_MAX_CHAIN vertices, such shifts fail (counted in
// shift_failures/photon_parent or manifold/fail_chain_too_long) and the base keeps its full weight.
// The camera subpaths end at their first rough vertex, so --shift manifold shifts them as hybrid.
//
// Parameters (IntegratorParams): shift (hybrid, the default, | replay | manifold), shift_threshold,
// aux and the manifold walk's (manifold_iterations, _tolerance, _precision) as gpt's; radius and
// radius_alpha as pm's; recon, recon_solver, alpha: the reconstruction
// (render/gradient_images.h). Paths are pm's: at most kBdptMaxSegments segments.
#pragma once
#include "integrators/bidir/bidirectional.h"
#include "integrators/bidir/subpaths.h"
#include "integrators/gbidir/photon_shifts.h"
#include "integrators/gpt/gradient_path_tracer.h"

namespace gdr {

extern const std::vector<std::string> kGpmParams;
GptSettings gpm_settings(const IntegratorParams& params);

class GradientPhotonMapping : public GradientPathTracer {
 public:
  GradientPhotonMapping(const RenderInputs& inputs, const GptSettings& gpt, const IntegratorParams& params = {});

  RenderResult render(const RenderSettings& settings) override;

 private:
  void trace_chunk(const RenderSettings& settings, uint32_t sample, uint32_t first, uint32_t count) override;

  BidirSettings photons_;   // pm's options and radius schedule
  BidirSubpaths subpaths_;  // the photons: one light subpath a group
  SplatFilm splats_;        // unused by pm's light subpaths, which connect to no camera
  PhotonShifts shifts_;
};

}  // namespace gdr
