// Gradient-domain Metropolis light transport (`gmlt`, after Lehtinen et al. 2013): Markov chains
// in primary sample space whose states are G-PT groups (integrators/gpt/gradient_groups.h): a
// base path through the chain's film position and its four offsets one pixel away by the shift
// mapping (default: the manifold perturbation where the scene has specular chains, reconnection
// and half-vector copy elsewhere), each pair's difference weighted between the forward and the
// backward shift by G-PT's MIS (a failed shift leaves its offset zero, counted by reason). The
// target is
//   f* = sum over the four pairs of |difference| + alpha * |primal| / 4
// (magnitudes as luminances of per-channel absolute values; `target_alpha`, default 0.2), so the
// chains spend their time where the gradients are. Each state splats its primal shares (the
// coarse image), its dx and dy differences and the emission it sees directly, over f*, with the
// expected-value weights; the Metropolis loop (metropolis_loop.h) normalizes them by b, the
// integral of f*. The reconstruction is the engine's L1 (default) or L2 solve: the weighted one
// needs independent passes, which a chain's are not.
//
// Parameters (IntegratorParams): chains, bootstrap, sigma, large_step, mutations_per_pixel as for
// `mlt`; target_alpha; shift (default manifold), shift_threshold, manifold_*; recon (l1 | l2 |
// none), recon_solver, alpha.
#pragma once
#include <string>
#include <vector>

#include "integrators/gpt/gradient_groups.h"
#include "integrators/mlt/metropolis_loop.h"
#include "render/film.h"
#include "render/gradient_images.h"
#include "render/integrator.h"

namespace gdr {

struct GmltSettings {
  MetropolisSettings loop;
  GptSettings gpt;
  float target_alpha = 0.2f;
};
extern const std::vector<std::string> kGmltParams;
// Also checks the reconstruction: `weighted` is refused.
GmltSettings gmlt_settings(const IntegratorParams& params);

class GradientMetropolis : public Integrator {
 public:
  GradientMetropolis(const RenderInputs& inputs, const GmltSettings& settings, const IntegratorParams& params = {});

  // The gradient layers alone, not reconstructed.
  GradientImages render_gradients(const RenderSettings& settings);
  RenderResult render(const RenderSettings& settings) override;

  double normalization() const { return normalization_; }

 private:
  static constexpr const char* kProgram = "mlt/gmlt.cl";

  RenderInputs in_;
  GmltSettings settings_;
  IntegratorParams recon_params_;  // l1 unless the parameters name another
  GradientGroups groups_;          // acc: a chain's group's sums at the chain
  Kernel contribution_;
  Film film_;                      // primal, dx, dy, direct
  MetropolisLoop loop_;
  double normalization_ = 0;
};

}  // namespace gdr
