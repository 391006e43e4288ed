#include "integrators/gpt/gradient_path_tracer.h"

#include "render/progressive_loop.h"
#include "util/log.h"
#include "render/wavefront/chunks.h"

namespace gdr {

static_assert(sizeof(GptChain) == 28 + 40 * MANIFOLD_MAX_CHAIN, "GptChain layout changed");

namespace {

// Groups in flight per chunk: a group holds five paths (about 1.5 KiB of queues and state), and
// with the manifold shift up to four walks (about 2 KiB more).
constexpr size_t kMaxGroupsInFlight = size_t(1) << 17;
constexpr size_t kMaxManifoldGroupsInFlight = size_t(1) << 15;
constexpr const char* kProgram = "gpt/gpt.cl";

Defines gpt_defines(const RenderInputs& in, const GptSettings& gpt) {
  return gpt_manifold_enabled(in.scene, gpt) ? manifold_defines(in.context.device(), gpt.manifold) : Defines{};
}

}  // namespace

const std::vector<std::string> kGptParams = {"shift", "shift_threshold", "aux", "manifold_iterations",
                                             "manifold_tolerance", "manifold_precision"};

GptSettings gpt_settings(const IntegratorParams& params) {
  GptSettings s;
  std::string shift = params.choice("shift", "hybrid", {"hybrid", "replay", "manifold"});
  s.shift = shift == "replay" ? GPT_SHIFT_REPLAY : shift == "manifold" ? GPT_SHIFT_MANIFOLD : GPT_SHIFT_HYBRID;
  s.shift_threshold = params.non_negative("shift_threshold", s.shift_threshold);
  s.aux = params.flag("aux", false);
  s.manifold = manifold_settings(params);
  return s;
}

bool gpt_manifold_enabled(const Scene& scene, const GptSettings& gpt) {
  return gpt.shift == GPT_SHIFT_MANIFOLD && scene.features.specular_chains();
}

GradientPathTracer::GradientPathTracer(const RenderInputs& in, const GptSettings& gpt, const IntegratorParams& params)
    : in_(in),
      gpt_(gpt),
      params_(params),
      kernels_(in.context, in.scene, gpt_defines(in, gpt)),
      generate_(kernels_.make(kProgram, "gpt_generate")),
      scatter_(kernels_.make(kProgram, "gpt_scatter")),
      shade_(kernels_.make(kProgram, "gpt_shade")),
      shadow_(kernels_.make(kProgram, "gpt_shadow")),
      shift_(kernels_.make(kProgram, "gpt_shift")),
      gather_(kernels_.make(kProgram, "gpt_gather")),
      capacity_(chunk_capacity(gpt_manifold_enabled(in.scene, gpt) ? kMaxManifoldGroupsInFlight : kMaxGroupsInFlight,
                               in.scene.camera.width, in.scene.camera.height)),
      base_queues_(in.context, capacity_, false),
      offset_rays_(in.context, capacity_ * GPT_OFFSETS, kRayQueueFlags),
      reconnect_rays_(in.context, capacity_ * GPT_OFFSETS, kRayQueueFlags),
      shadow_rays_(in.context, capacity_ * (GPT_OFFSETS + 1), kRayQueueFlags),
      bases_(in.context, capacity_),
      offsets_(in.context, capacity_ * GPT_OFFSETS),
      acc_(in.context, size_t(in.scene.camera.width) * in.scene.camera.height * GPT_ACC_COUNT),
      pend_(in.context, capacity_ * GPT_PEND_COUNT),
      counters_(in.context, GDR_COUNTER_NAMES(GPT_COUNTERS)),
      film_(in.context, in.scene.camera.width, in.scene.camera.height) {
  if (gpt_.aux) aux_.emplace(in.context, kernels_, kProgram, film_.pixels());
  const bool manifold = gpt_manifold_enabled(in.scene, gpt);
  chains_ = Buffer<GptChain>(in.context, manifold ? capacity_ : 0);
  walks_ = Buffer<GdrManifoldWalk>(in.context, manifold ? capacity_ * GPT_OFFSETS : 0);
  walk_results_ = Buffer<GdrManifoldResult>(in.context, manifold ? capacity_ * GPT_OFFSETS : 0);
  if (manifold) {
    manifold_.emplace(in, kernels_, kProgram, capacity_ * GPT_OFFSETS, gpt.manifold);
    join_.emplace(kernels_.make(kProgram, "gpt_manifold_join"));
  }
  if (gpt.shift == GPT_SHIFT_MANIFOLD) log::verbose(manifold_description(in.scene, in.context.device(), gpt.manifold));
}

GdrGptParams GradientPathTracer::params(const RenderSettings& settings, uint32_t sample, uint32_t first,
                                        uint32_t count) const {
  GdrGptParams p{};
  p.path = in_.device_scene.path_params(settings, sample, first, count);
  p.shift = gpt_.shift;
  p.shift_threshold = gpt_.shift_threshold;
  return p;
}

void GradientPathTracer::intersect_offsets(cl_uint rays, cl_uint reconnects) {
  intersect(in_.embree, offset_rays_, rays, false, "offset");
  occlude(in_.embree, reconnect_rays_, reconnects, "reconnection");
  scatter_.args(rays, offset_rays_, reconnects, reconnect_rays_, offsets_).run(rays + reconnects);
}

void GradientPathTracer::walk_offsets(const GdrGptParams& p, cl_uint walks) {
  if (!manifold_ || walks == 0) return;
  manifold_->solve(walks_, walks, walk_results_, p.path);
  counters_.reset();
  join_->args(p, walks, walks_, walk_results_, chains_, offsets_, counters_.buffer(), in_.device_scene).run(walks);
  counters_.read();
}

void GradientPathTracer::trace_chunk(const RenderSettings& settings, uint32_t sample, uint32_t first, uint32_t count) {
  GdrGptParams p = params(settings, sample, first, count);
  Buffer<GdrRayHit>* base_rays = base_queues_.rays;

  counters_.reset();
  generate_
      .args(in_.device_scene.camera(), p, base_rays[0], offset_rays_, bases_, offsets_, chains_, acc_,
            counters_.buffer())
      .run(count);
  counters_.read();
  intersect(in_.embree, base_rays[0], count, true, "camera");
  if (aux_) aux_->add(p.path, base_rays[0], count, in_.device_scene);
  intersect_offsets(counters_[GPT_COUNTER_OFFSET_RAYS], 0);

  cl_uint active = count;
  for (int cur = 0; active > 0; cur = 1 - cur) {
    counters_.reset();
    shade_
        .args(p, active, base_rays[cur], base_rays[1 - cur], shadow_rays_, bases_, offsets_, acc_, pend_,
              counters_.buffer(), in_.device_scene)
        .run(active);
    counters_.read();
    cl_uint next = counters_[GPT_COUNTER_BASE_RAYS], shadows = counters_[GPT_COUNTER_SHADOW_RAYS];
    intersect(in_.embree, base_rays[1 - cur], next, false, "bounce");
    if (shadows > 0) {
      occlude(in_.embree, shadow_rays_, shadows, "shadow");
      shadow_.args(shadows, shadow_rays_, pend_, bases_, acc_).run(shadows);
    }
    if (next > 0) {
      counters_.reset();
      shift_
          .args(p, next, base_rays[1 - cur], offset_rays_, reconnect_rays_, bases_, offsets_, chains_, walks_,
                counters_.buffer(), in_.device_scene)
          .run(next);
      counters_.read();
      const cl_uint offset_rays = counters_[GPT_COUNTER_OFFSET_RAYS];
      const cl_uint reconnects = counters_[GPT_COUNTER_RECONNECT_RAYS];
      walk_offsets(p, counters_[GPT_COUNTER_MANIFOLD_WALKS]);
      intersect_offsets(offset_rays, reconnects);
    }
    active = next;
  }
  counters_.report(in_.context.stats());
  if (manifold_) manifold_->report(in_.context.stats());
}

GradientImages GradientPathTracer::render_gradients(const RenderSettings& settings) {
  Stats* stats = in_.context.stats();
  ScopedTimer timer(stats, "render/trace");
  const int w = film_.width(), h = film_.height();
  const uint32_t pixels = uint32_t(film_.pixels());
  film_.clear();
  if (aux_) aux_->clear();
  int samples = run_progressive(settings, [&](int sample) {
    // Launches queue without a wait each; the host waits where it reads (counters, Embree maps).
    DeferredTiming deferred(in_.context);
    for_each_chunk(pixels, capacity_, [&](uint32_t first, uint32_t count) {
      trace_chunk(settings, uint32_t(sample), first, count);
    });
    gather_.args(w, h, acc_, film_.pass(sample)).run(pixels);
  });
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
