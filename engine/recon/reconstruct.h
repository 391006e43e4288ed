// Poisson reconstruction: the image I minimising
//   ||alpha (I - P)|| + ||dx I - Gx|| + ||dy I - Gy||
// per colour channel, in the L2 norm (one linear solve) or the L1 norm (iteratively reweighted
// least squares), from a primal P and forward-difference gradients G, in kernels on the device.
// The weighted form (Rousselle, Jarosz and Novak 2016, "Image-space control variate
// reconstruction") is the L2 solve with every term weighted by the inverse of its input's
// per-pixel variance estimate,
//   sum alpha^2 wP (I - P)^2 + wX (dx I - Gx)^2 + wY (dy I - Gy)^2,  w = 1 / (v / s + floor),
// s the image's variance scale (per channel, the median of the positive estimates of all three
// inputs), so that a pixel whose gradients are noisier than its primal leans on the primal and
// the reverse; the floor bounds every weight (a zero estimate gets 1 / floor, not infinity).
// Which estimates weight which data is the caller's choice: render/gradient_images.h weights each
// half of a render's passes by the other half's.
#pragma once
#include <string>
#include <vector>

#include "device/context.h"
#include "stats/stats.h"

namespace gdr {

enum class ReconNorm { L1, L2, Weighted };

// "L1", "L2", "weighted" (logs and stats).
const char* recon_norm_name(ReconNorm norm);

// Per-pixel variance estimates of the means primal, dx and dy (interleaved RGB, the images'
// size): what the weighted form turns into term weights.
struct ReconVariance {
  std::vector<float> primal, dx, dy;
};

struct ReconSettings {
  ReconNorm norm = ReconNorm::L1;
  float alpha = 0.2f;
  // Weighted form: the floor of the variance relative to the image's scale (see above).
  float variance_floor = 1e-2f;
  // The published defaults (Kettunen et al. 2015 / Manzi et al.): L2 50 CG iterations; L1 20
  // reweighting rounds of 50 CG iterations, weights 1/(|e| + reg), reg from 0.05 halving each
  // round.
  int cg_iterations = 50;
  int l1_rounds = 20;
  float l1_reg = 0.05f;
  // Relative residual |b - Ax| / |b| at which a linear solve stops early (0: iteration cap only
  // for CG; the fast solver then stops at 1e-4 for L2). The fast solver judges each warm-started
  // L1 round against the round's first residual instead (default target 0.15, and at most 3 PCG
  // iterations per round).
  double tolerance = 0.0;
  // CG: baseline conjugate gradients on the normal equations. Fast: multigrid-preconditioned CG,
  // and for L2 with every input finite a direct DCT solve (the PCG then only checks it; the
  // weighted form's per-pixel weights rule that out).
  enum class Solver { CG, Fast } solver = Solver::Fast;
};

struct ReconResult {
  std::vector<float> rgb;  // interleaved RGB, width * height * 3, always finite
  int iterations = 0;      // (P)CG iterations over all solves
  double residual = 0;     // relative residual of the last linear solve (worst channel)
  double seconds = 0;
  double energy = 0;       // objective value (sum over channels) of the result, in the chosen norm
};

// Settings from their command-line names: norm "l1" | "l2" | "weighted", solver "fast" | "cg".
// Throws gdr::Error naming an unknown value.
ReconSettings recon_settings(const std::string& norm, float alpha, const std::string& solver);

// Images are interleaved RGB float, row-major from the top row. dx(x,y) = I(x+1,y) - I(x,y) for
// x < width-1 and dy(x,y) = I(x,y+1) - I(x,y) for y < height-1; the last column of dx and last
// row of dy are ignored. Non-finite inputs are dropped from the objective and counted in stats
// ("recon/nonfinite_inputs"). The weighted form needs `variance` (a non-finite estimate stands
// for the image's scale and is counted with the inputs). Throws gdr::Error on mismatched sizes
// and for the weighted form without variance estimates.
// Stats: "recon/iterations", "recon/residual", "recon/norm", "recon/energy", time "recon/solve".
ReconResult reconstruct(Context& ctx, int width, int height, const std::vector<float>& primal_rgb,
                        const std::vector<float>& dx_rgb, const std::vector<float>& dy_rgb,
                        const ReconSettings& settings, Stats* stats,
                        const ReconVariance* variance = nullptr);

}  // namespace gdr
