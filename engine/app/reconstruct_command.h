// `gdrender reconstruct`: Poisson reconstruction of a gradient-domain EXR (layers primal, dx, dy).
#pragma once
#include <string>

#include "device/context.h"
#include "recon/reconstruct.h"
#include "stats/stats.h"

namespace gdr {

// Reads primal.R/G/B, dx.R/G/B and dy.R/G/B from `in_exr`, reconstructs with `settings`, and
// writes R,G,B plus the original layers as an EXR at `out_path` (an
// out_path ending in .png writes the EXR beside it) and the R,G,B as a PNG with the same stem.
// Throws gdr::Error naming the file and the missing layer for an incomplete input. Returns 0.
int reconstruct_command(const std::string& in_exr, const std::string& out_path,
                        const ReconSettings& settings, Context& ctx, Stats* stats);

}  // namespace gdr
