// The output of a gradient-domain render: R,G,B is the screened-Poisson reconstruction of
// (primal - direct) from the gradients, plus the directly seen emission that the gradients leave
// out; the layers primal, dx, dy, direct and variance are kept beside it.
#pragma once
#include <optional>
#include <string>

#include "device/context.h"
#include "image/image.h"
#include "integrators/gpt/gradient_path_tracer.h"
#include "recon/reconstruct.h"

namespace gdr {

// R,G,B reconstructed with `recon`, or the primal without it.
Image gradient_image(Context& ctx, const GradientImages& layers,
                     const std::optional<ReconSettings>& recon, Stats* stats);

// The layers of a saved render (primal, dx, dy required; direct and variance optional).
// Throws InputError naming `path` and the missing layer.
GradientImages gradient_layers_from(const Image& image, const std::string& path);

}  // namespace gdr
