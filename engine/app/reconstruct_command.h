// `gdrender reconstruct`: Poisson reconstruction of a gradient-domain EXR (layers primal, dx, dy,
// and the variance layers for the weighted form).
#pragma once
#include <optional>
#include <string>

#include "device/context.h"
#include "recon/reconstruct.h"
#include "render/integrator_params.h"
#include "stats/stats.h"

namespace gdr {

// Reads primal.R/G/B, dx.R/G/B and dy.R/G/B (and for the weighted form their variance layers)
// from `in_exr`, reconstructs with `settings` (none: R,G,B is the primal, as a render with
// --recon none writes it, so that one render can be compared under every reconstruction), and
// writes R,G,B plus the original layers as an
// EXR and the R,G,B as a PNG, named from `out_path` as app/output_paths.h says (.exr or .png; a
// device or pipe gets the one image).
// Throws gdr::Error naming the file and the missing layer for an incomplete input. Returns 0.
int reconstruct_command(const std::string& in_exr, const std::string& out_path,
                        const std::optional<ReconSettings>& settings, Context& ctx, Stats* stats);
// The same with the reconstruction from the command line's parameters (recon, recon_solver,
// alpha); without `recon`, the default (weighted) where the file holds the halves, else L1.
int reconstruct_command(const std::string& in_exr, const std::string& out_path, const IntegratorParams& params,
                        Context& ctx, Stats* stats);

}  // namespace gdr
