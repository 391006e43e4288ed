#include "integrators/mlt/metropolis.h"

#include <algorithm>

#include "integrators/bidir/bidirectional.h"
#include "util/log.h"

namespace gdr {

const std::vector<std::string> kMltParams = [] {
  std::vector<std::string> p = metropolis_params();
  p.push_back("mis");
  return p;
}();

MltIntegratorSettings mlt_settings(const IntegratorParams& params) {
  return MltIntegratorSettings{metropolis_settings(params), bidir_mis_param(params)};
}

Metropolis::Metropolis(const RenderInputs& in, const MltIntegratorSettings& settings)
    : in_(in),
      settings_{for_film(settings.loop, in.scene), settings.mis},
      subpaths_(in, BIDIR_BDPT, settings_.loop.chains),
      contribution_(subpaths_.kernels().make(kProgram, "mlt_contribution")),
      image_sample_(subpaths_.kernels().make(kProgram, "mlt_image_sample")),
      values_(in.context, settings_.loop.chains),
      found_(in.context, subpaths_.kernels(), BidirSubpaths::kProgram, settings_.loop.chains),
      light_sums_(in.context, settings_.loop.chains),
      film_(in.context, in.scene.camera.width, in.scene.camera.height, {"radiance"}),
      loop_(in, subpaths_.kernels(), kProgram, settings_.loop, {&film_["radiance"]}) {
  values_.fill(Vec4{});
  light_sums_.fill(Vec4{});
  options_ = GdrBidirOptions{BIDIR_BDPT, settings.mis, -1, -1, 0.0f, 0.0f, 0.0f, 0.0f, 1, 0};
}

RenderResult Metropolis::render(const RenderSettings& settings) {
  Stats* stats = in_.context.stats();
  ScopedTimer timer(stats, "render/trace");
  const int segments = bdpt_segments(settings.max_depth);
  if (segments != settings.max_depth) {
    log::warn("mlt renders paths of at most ", kBdptMaxSegments, " segments (max_depth ", settings.max_depth,
              " asked for more): the light-vertex store's bound");
  }
  const size_t chains = loop_.chains();
  const GdrPrimaryLayout layout = PrimarySamples::layout_for(chains, std::max(segments, 1));
  MltSettings mutation = settings_.loop.mutation;
  mutation.lengths = unsigned(std::max(segments, 1));
  film_.clear();

  GdrPtParams base = in_.device_scene.path_params(settings, 0, 0, uint32_t(chains));
  base.max_depth = segments;
  const bool light = light_subpaths_allowed(settings.max_depth) && base.light_count > 0;
  const bool contributes = segments > 0 && base.light_count > 0;
  // b, the image's luminance summed over its pixels, from full bidirectional samples (every
  // strategy, MIS-weighted, their t = 1 contributions summed a path wherever they land).
  GdrBidirOptions all = options_;
  all.multiplex = 0;
  auto luminance = [&](uint32_t iteration, const Buffer<float>& states, Buffer<float>& f) {
    GdrPtParams p = base;
    p.sample = iteration;
    subpaths_.trace(p, all, light, PrimarySamples(states, layout), BidirSink{values_, found_, nullptr, &light_sums_},
                    nullptr);
    image_sample_.args(in_.device_scene.camera(), cl_uint(chains), values_, light_sums_, f).run(chains);
  };
  auto evaluate = [&](uint32_t iteration, const Buffer<float>& states, Buffer<GdrSplat>& records, Buffer<float>& f,
                      Buffer<cl_uint>&) {
    GdrPtParams p = base;
    p.sample = iteration;
    subpaths_.trace(p, options_, light, PrimarySamples(states, layout), BidirSink{values_, found_, nullptr},
                    nullptr);
    contribution_
        .args(in_.device_scene.camera(), p, options_, layout, states, values_, found_.slots(), records, f)
        .run(chains);
  };
  MetropolisLoop::Result r = loop_.run(settings, layout, mutation, contributes, evaluate, luminance);
  normalization_ = r.normalization;
  RenderResult result;
  result.samples = r.passes;
  result.seconds = timer.elapsed();
  result.image = Image(film_.width(), film_.height(), {});
  result.image.add_rgb_layer("", reduced_rgb(film_["radiance"], float(r.scale), stats));
  subpaths_.report(stats);
  return result;
}

}  // namespace gdr
