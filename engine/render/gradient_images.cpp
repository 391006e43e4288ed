#include "render/gradient_images.h"

#include "recon/reconstruct.h"
#include "util/error.h"
#include "util/log.h"

namespace gdr {

const std::vector<std::string> kReconParams = {"recon", "recon_solver", "alpha"};

std::optional<ReconSettings> recon_from_params(const IntegratorParams& p) {
  std::string norm = p.choice("recon", "l1", {"l1", "l2", "none"});
  if (norm == "none") return std::nullopt;
  ReconSettings defaults;
  return recon_settings(norm, p.non_negative("alpha", defaults.alpha), p.choice("recon_solver", "fast", {"fast", "cg"}));
}

RenderResult gradient_result(Context& ctx, const GradientImages& layers, const IntegratorParams& params,
                             Stats* stats) {
  ScopedTimer t(stats, "recon/total");
  RenderResult result;
  result.image = gradient_image(ctx, layers, recon_from_params(params), stats);
  result.samples = layers.samples;
  result.seconds = layers.seconds + t.elapsed();
  return result;
}

Image gradient_image(Context& ctx, const GradientImages& g,
                     const std::optional<ReconSettings>& recon, Stats* stats) {
  std::vector<float> rgb = g.primal;
  if (recon) {
    std::vector<float> indirect = g.primal;
    bool has_direct = g.direct.size() == indirect.size();
    if (has_direct) {
      for (size_t i = 0; i < indirect.size(); ++i) indirect[i] -= g.direct[i];
    }
    ReconResult r = reconstruct(ctx, g.width, g.height, indirect, g.dx, g.dy, *recon, stats);
    log::verbose("reconstruction (", recon->norm == ReconNorm::L1 ? "L1" : "L2", ", alpha ",
                 recon->alpha, "): ", r.iterations, " iterations, residual ", r.residual, ", ",
                 r.seconds, " s");
    rgb = r.rgb;
    if (has_direct) {
      for (size_t i = 0; i < rgb.size(); ++i) rgb[i] += g.direct[i];
    }
  }
  Image out(g.width, g.height, {});
  out.add_rgb_layer("", rgb);
  out.add_rgb_layer("primal", g.primal);
  out.add_rgb_layer("dx", g.dx);
  out.add_rgb_layer("dy", g.dy);
  if (!g.direct.empty()) out.add_rgb_layer("direct", g.direct);
  if (!g.variance.empty()) out.add_rgb_layer("variance", g.variance);
  return out;
}

GradientImages gradient_layers_from(const Image& in, const std::string& path) {
  for (const char* layer : {"primal", "dx", "dy"}) {
    if (!in.has_rgb_layer(layer)) {
      std::string l(layer);
      throw InputError(path, 0, "missing layer '" + l + "' (needs channels " + l + ".R, " + l + ".G and " + l + ".B)");
    }
  }
  GradientImages g;
  g.width = in.width;
  g.height = in.height;
  g.primal = in.rgb_layer("primal");
  g.dx = in.rgb_layer("dx");
  g.dy = in.rgb_layer("dy");
  if (in.has_rgb_layer("direct")) g.direct = in.rgb_layer("direct");
  if (in.has_rgb_layer("variance")) g.variance = in.rgb_layer("variance");
  return g;
}

}  // namespace gdr
