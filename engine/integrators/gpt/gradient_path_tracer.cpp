#include "integrators/gpt/gradient_path_tracer.h"

#include "render/progressive_loop.h"
#include "render/wavefront/chunks.h"
#include "util/error.h"

namespace gdr {

const std::vector<std::string> kGptParams = {"shift", "shift_threshold", "aux", "direct_samples", "batches",
                                             "manifold_iterations", "manifold_tolerance", "manifold_precision"};

GptSettings gpt_settings(const IntegratorParams& params) {
  GptSettings s = gpt_shift_settings(params);
  s.aux = params.flag("aux", false);
  s.direct_samples = int(params.non_negative("direct_samples", float(s.direct_samples)));
  if (params.has("batches")) s.batches = params.choice("batches", "2", {"1", "2"}) == "1" ? 1 : 2;
  return s;
}

GradientPathTracer::GradientPathTracer(const RenderInputs& in, const GptSettings& gpt, const IntegratorParams& params)
    : GradientPathTracer(in, gpt, params, GroupKind::kPaths) {}

GradientPathTracer::GradientPathTracer(const RenderInputs& in, const GptSettings& gpt, const IntegratorParams& params,
                                       GroupKind kind)
    : in_(in),
      groups_(in, gpt, GradientGroups::chunk_capacity_for(in, gpt, kind),
              size_t(in.scene.camera.width) * in.scene.camera.height, kind),
      params_(params),
      gather_(groups_.kernels().make(groups_.program(), "gpt_gather")),
      film_(in.context, in.scene.camera.width, in.scene.camera.height),
      direct_(in, groups_.kernels(), groups_.program(), gpt.direct_samples, film_.width(), film_.height(),
              groups_.capacity()) {
  if (gpt.aux) aux_.emplace(in.context, groups_.kernels(), groups_.program(), film_.pixels());
}

void GradientPathTracer::trace_chunk(const RenderSettings& settings, uint32_t sample, uint32_t first,
                                     uint32_t count) {
  groups_.trace(groups_.params(settings, sample, first, count), PrimarySamples(), aux());
  groups_.report(in_.context.stats());
}

GradientImages GradientPathTracer::render_gradients(const RenderSettings& settings) {
  Stats* stats = in_.context.stats();
  ScopedTimer timer(stats, "render/trace");
  const int w = film_.width(), h = film_.height();
  const uint32_t pixels = uint32_t(film_.pixels());
  film_.clear();
  if (aux_) aux_->clear();
  direct_.clear();
  int samples = run_progressive(settings, [&](int sample) {
    // Launches queue without a wait each; the host waits where it reads (counters, Embree maps).
    DeferredTiming deferred(in_.context);
    for_each_chunk(pixels, groups_.capacity(), [&](uint32_t first, uint32_t count) {
      trace_chunk(settings, uint32_t(sample), first, count);
    });
    end_pass();
    direct_.add(in_.device_scene.path_params(settings, uint32_t(sample), 0, pixels), groups_.acc());
    gather_.args(w, h, groups_.acc(), cl_int(direct_.samples()), direct_.flags(), direct_.taking(), film_.pass(sample))
        .run(pixels);
  });
  direct_.report(stats);
  const double seconds = timer.elapsed();
  GradientImages out = film_.images(samples);
  out.seconds = seconds;
  if (stats) {
    stats->add_count("samples/paths", uint64_t(pixels) * out.samples * (1 + GPT_OFFSETS));
    stats->set("render/spp", out.samples);
  }
  return out;
}

RenderResult GradientPathTracer::render(const RenderSettings& settings) {
  GradientImages layers = render_gradients(settings);
  RenderResult result = gradient_result(in_.context, layers, params_, in_.context.stats());
  if (aux_) aux_->add_to(result.image, result.samples);
  return result;
}

}  // namespace gdr
