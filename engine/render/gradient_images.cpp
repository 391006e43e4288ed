#include "render/gradient_images.h"

#include <optional>

#include "cluster/ranks.h"
#include "recon/reconstruct.h"
#include "util/error.h"
#include "util/log.h"

namespace gdr {

const std::vector<std::string> kReconParams = {"recon", "recon_solver", "alpha"};

std::optional<ReconSettings> recon_from_params(const IntegratorParams& p) {
  std::string norm = p.choice("recon", "weighted", {"l1", "l2", "weighted", "none"});
  if (norm == "none") return std::nullopt;
  // The weighted form's weights already set the primal's share against the gradients': its alpha
  // stays 1 unless given (measured better than 0.2 there on the Cornell box and its caustics).
  float alpha = norm == "weighted" ? 1.0f : ReconSettings{}.alpha;
  return recon_settings(norm, p.non_negative("alpha", alpha), p.choice("recon_solver", "fast", {"fast", "cg"}));
}

RenderResult gradient_result(Context& ctx, const GradientImages& layers, const IntegratorParams& params,
                             Stats* stats) {
  ScopedTimer t(nullptr, "");  // gradient_image records recon/total
  RenderResult result;
  // L1 is not linear: the solve runs once, on rank 0's sums of all ranks, never per rank. The
  // other ranks' layers are their own share, which nobody writes.
  std::optional<ReconSettings> recon = recon_from_params(params);
  if (!cluster::root()) recon.reset();
  result.image = gradient_image(ctx, layers, recon, stats);
  result.samples = layers.samples;
  result.seconds = layers.seconds + t.elapsed();
  return result;
}

namespace {

const char* const kHalfPrefix[2] = {"even.", "odd."};

// a - b, or a when b is empty (no direct layer).
std::vector<float> minus(const std::vector<float>& a, const std::vector<float>& b) {
  std::vector<float> d = a;
  if (b.size() == a.size()) {
    for (size_t i = 0; i < d.size(); ++i) d[i] -= b[i];
  }
  return d;
}

bool has_half(const GradientLayers& h, size_t values) { return h.primal.size() == values && values > 0; }

// The reconstruction of `data`'s (primal - direct) with the variance estimates of `weights`
// (the same layers for the L1 and L2 forms, which do not read them), plus data's direct.
std::vector<float> reconstruct_layers(Context& ctx, int w, int h, const GradientLayers& data,
                                      const GradientLayers& weights, const ReconSettings& recon, Stats* stats) {
  std::optional<ReconVariance> variance;
  if (recon.norm == ReconNorm::Weighted) {
    variance = ReconVariance{weights.primal_variance, weights.dx_variance, weights.dy_variance};
  }
  ReconResult r = reconstruct(ctx, w, h, minus(data.primal, data.direct), data.dx, data.dy, recon, stats,
                              variance ? &*variance : nullptr);
  log::verbose("reconstruction (", recon_norm_name(recon.norm), ", alpha ", recon.alpha, "): ", r.iterations,
               " iterations, residual ", r.residual, ", ", r.seconds, " s");
  if (data.direct.size() == r.rgb.size()) {
    for (size_t i = 0; i < r.rgb.size(); ++i) r.rgb[i] += data.direct[i];
  }
  return r.rgb;
}

// f(name, layer) for each layer of `g` (const or not), in the order they are saved.
template <class Layers, class F>
void for_each_layer(Layers& g, F f) {
  f("primal", g.primal);
  f("dx", g.dx);
  f("dy", g.dy);
  f("direct", g.direct);
  f("primal_variance", g.primal_variance);
  f("dx_variance", g.dx_variance);
  f("dy_variance", g.dy_variance);
}

void add_layers(Image& out, const std::string& prefix, const GradientLayers& g) {
  for_each_layer(g, [&](const char* name, const std::vector<float>& values) {
    if (!values.empty()) out.add_rgb_layer(prefix + name, values);
  });
}

// The layers under `prefix` that `in` holds; those in `required` must be there, else an
// InputError naming `path`, the layer and `why`.
GradientLayers read_layers(const Image& in, const std::string& path, const std::string& prefix,
                           const std::vector<std::string>& required, const std::string& why) {
  for (const std::string& name : required) {
    std::string l = prefix + name;
    if (!in.has_rgb_layer(l)) {
      throw InputError(path, 0, "missing layer '" + l + "' (needs channels " + l + ".R, " + l + ".G and " + l + ".B)" + why);
    }
  }
  GradientLayers g;
  for_each_layer(g, [&](const char* name, std::vector<float>& values) {
    if (in.has_rgb_layer(prefix + name)) values = in.rgb_layer(prefix + name);
  });
  return g;
}

}  // namespace

Image gradient_image(Context& ctx, const GradientImages& g, const std::optional<ReconSettings>& recon, Stats* stats) {
  ScopedTimer timer(stats, "recon/total");
  std::vector<float> rgb = g.primal;
  const bool weighted = recon && recon->norm == ReconNorm::Weighted;
  const bool halves = has_half(g.halves[0], g.primal.size()) && has_half(g.halves[1], g.primal.size());
  if (weighted && halves) {
    // Each half weighted by the other's estimates (see the header), the two results averaged.
    std::vector<float> a = reconstruct_layers(ctx, g.width, g.height, g.halves[0], g.halves[1], *recon, stats);
    std::vector<float> b = reconstruct_layers(ctx, g.width, g.height, g.halves[1], g.halves[0], *recon, stats);
    for (size_t i = 0; i < rgb.size(); ++i) rgb[i] = 0.5f * (a[i] + b[i]);
  } else if (recon) {
    // A weighted render of one pass has no second half; its estimates are all 0 and weight
    // every term alike.
    rgb = reconstruct_layers(ctx, g.width, g.height, g, g, *recon, stats);
  }
  Image out(g.width, g.height, {});
  out.add_rgb_layer("", rgb);
  add_layers(out, "", g);
  if (weighted && halves) {
    for (int h = 0; h < 2; ++h) add_layers(out, kHalfPrefix[h], g.halves[h]);
  }
  return out;
}

GradientImages gradient_layers_from(const Image& in, const std::string& path, bool halves_required) {
  GradientImages g;
  static_cast<GradientLayers&>(g) = read_layers(in, path, "", {"primal", "dx", "dy"}, "");
  if (g.primal_variance.empty() && in.has_rgb_layer("variance")) g.primal_variance = in.rgb_layer("variance");
  g.width = in.width;
  g.height = in.height;
  std::vector<std::string> all;
  for_each_layer(g, [&](const char* name, const std::vector<float>&) { all.push_back(name); });
  for (int h = 0; h < 2; ++h) {
    if (halves_required || in.has_rgb_layer(std::string(kHalfPrefix[h]) + "primal")) {
      g.halves[h] = read_layers(in, path, kHalfPrefix[h], all,
                                "; the weighted reconstruction needs the layers of the even and the odd passes, which "
                                "a render with --recon weighted saves");
    }
  }
  return g;
}

}  // namespace gdr
