#include "integrators/gpt/gradient_path_tracer.h"

#include <algorithm>
#include <cmath>

#include "integrators/film.h"
#include "integrators/progressive_loop.h"

namespace gdr {
namespace {

// Groups in flight per chunk: a group holds five paths (about 1.5 KiB of queues and state).
constexpr size_t kMaxGroupsInFlight = size_t(1) << 17;

const char* kShiftCounterNames[GPT_COUNTER_COUNT] = {
    nullptr, nullptr, nullptr, nullptr, "samples/nonfinite_rejected",
    "shifts/reconnection", "shifts/half_vector", "shifts/delta_lobe", "shifts/direction_copy", "shifts/replay",
    "shift_failures/outside_image", "shift_failures/lobe_mismatch", "shift_failures/refraction",
    "shift_failures/occluded", "shift_failures/environment_mismatch", "shift_failures/zero_pdf_or_value",
    "shift_failures/nonfinite"};

Kernel gpt_kernel(Context& ctx, const Scene& scene, const char* name) {
  return ctx.program("gpt/gpt.cl", scene_kernel_defines(scene))->kernel(name);
}

}  // namespace

GradientPathTracer::GradientPathTracer(Context& ctx, const Scene& scene, EmbreeScene& embree, const GptSettings& gpt)
    : ctx_(ctx),
      scene_(scene),
      embree_(embree),
      gpt_(gpt),
      device_scene_(ctx, scene),
      generate_(gpt_kernel(ctx, scene, "gpt_generate")),
      scatter_(gpt_kernel(ctx, scene, "gpt_scatter")),
      shade_(gpt_kernel(ctx, scene, "gpt_shade")),
      shadow_(gpt_kernel(ctx, scene, "gpt_shadow")),
      shift_(gpt_kernel(ctx, scene, "gpt_shift")),
      gather_(gpt_kernel(ctx, scene, "gpt_gather")),
      capacity_(std::min(kMaxGroupsInFlight, size_t(scene.camera.width) * scene.camera.height)),
      base_rays_{Buffer<GdrRayHit>(ctx, capacity_, CL_MEM_READ_WRITE | CL_MEM_ALLOC_HOST_PTR),
                 Buffer<GdrRayHit>(ctx, capacity_, CL_MEM_READ_WRITE | CL_MEM_ALLOC_HOST_PTR)},
      offset_rays_(ctx, capacity_ * GPT_OFFSETS, CL_MEM_READ_WRITE | CL_MEM_ALLOC_HOST_PTR),
      reconnect_rays_(ctx, capacity_ * GPT_OFFSETS, CL_MEM_READ_WRITE | CL_MEM_ALLOC_HOST_PTR),
      shadow_rays_(ctx, capacity_ * (GPT_OFFSETS + 1), CL_MEM_READ_WRITE | CL_MEM_ALLOC_HOST_PTR),
      bases_(ctx, capacity_),
      offsets_(ctx, capacity_ * GPT_OFFSETS),
      acc_(ctx, size_t(scene.camera.width) * scene.camera.height * GPT_ACC_COUNT),
      pend_(ctx, capacity_ * GPT_PEND_COUNT),
      counters_(ctx, GPT_COUNTER_COUNT),
      primal_(ctx, size_t(scene.camera.width) * scene.camera.height),
      dx_(ctx, primal_.size()),
      dy_(ctx, primal_.size()),
      direct_(ctx, primal_.size()),
      primal_sq_(ctx, primal_.size()) {}

GdrGptParams GradientPathTracer::params(const RenderSettings& settings, uint32_t sample, uint32_t first,
                                        uint32_t count) const {
  GdrGptParams p{};
  p.path = device_scene_.path_params(settings, sample, first, count);
  p.path.strategy = PT_STRATEGY_MIS;
  p.shift = gpt_.shift;
  p.shift_threshold = gpt_.shift_threshold;
  return p;
}

void GradientPathTracer::trace_chunk(const RenderSettings& settings, uint32_t sample, uint32_t first, uint32_t count) {
  Stats* stats = ctx_.stats();
  GdrGptParams p = params(settings, sample, first, count);
  std::vector<uint64_t> totals(GPT_COUNTER_COUNT, 0);
  auto read_counters = [&] {
    std::vector<cl_uint> c = counters_.read();
    for (int i = 0; i < GPT_COUNTER_COUNT; ++i) totals[i] += c[i];
    return c;
  };
  auto intersect_offsets = [&](cl_uint rays, cl_uint reconnects) {
    if (rays > 0) {
      auto m = offset_rays_.map(rays);
      embree_.intersect(m.data(), rays, false, "offset");
    }
    if (reconnects > 0) {
      auto m = reconnect_rays_.map(reconnects);
      embree_.occluded(m.data(), reconnects, "reconnection");
    }
    scatter_.args(rays, offset_rays_, reconnects, reconnect_rays_, offsets_).run(rays + reconnects);
  };

  counters_.fill(0u);
  generate_.args(device_scene_.camera(), p, base_rays_[0], offset_rays_, bases_, offsets_, acc_, counters_).run(count);
  std::vector<cl_uint> c = read_counters();
  {
    auto m = base_rays_[0].map(count);
    embree_.intersect(m.data(), count, true, "camera");
  }
  intersect_offsets(c[GPT_COUNTER_OFFSET_RAYS], 0);

  cl_uint active = count;
  for (int cur = 0; active > 0; cur = 1 - cur) {
    counters_.fill(0u);
    shade_.args(p, active, base_rays_[cur], base_rays_[1 - cur], shadow_rays_, bases_, offsets_, acc_, pend_,
                counters_);
    device_scene_.set_args(shade_, 10);
    shade_.run(active);
    c = read_counters();
    cl_uint next = c[GPT_COUNTER_BASE_RAYS], shadows = c[GPT_COUNTER_SHADOW_RAYS];
    if (next > 0) {
      auto m = base_rays_[1 - cur].map(next);
      embree_.intersect(m.data(), next, false, "bounce");
    }
    if (shadows > 0) {
      {
        auto m = shadow_rays_.map(shadows);
        embree_.occluded(m.data(), shadows, "shadow");
      }
      shadow_.args(shadows, shadow_rays_, pend_, bases_, acc_).run(shadows);
    }
    if (next > 0) {
      counters_.fill(0u);
      shift_.args(p, next, base_rays_[1 - cur], offset_rays_, reconnect_rays_, bases_, offsets_, counters_);
      device_scene_.set_args(shift_, 8);
      shift_.run(next);
      c = read_counters();
      intersect_offsets(c[GPT_COUNTER_OFFSET_RAYS], c[GPT_COUNTER_RECONNECT_RAYS]);
    }
    active = next;
  }
  if (stats) {
    for (int i = 0; i < GPT_COUNTER_COUNT; ++i) {
      if (kShiftCounterNames[i] && totals[i]) stats->add_count(kShiftCounterNames[i], totals[i]);
    }
  }
}

GradientImages GradientPathTracer::render(const RenderSettings& settings) {
  Stats* stats = ctx_.stats();
  ScopedTimer timer(stats, "render/trace");
  const int w = scene_.camera.width, h = scene_.camera.height;
  const uint32_t pixels = uint32_t(w) * h;
  for (Buffer<Vec4>* b : {&primal_, &dx_, &dy_, &direct_, &primal_sq_}) b->fill(Vec4{});
  GradientImages out;
  out.width = w;
  out.height = h;
  out.samples = run_progressive(settings, [&](int sample) {
    for (uint32_t first = 0; first < pixels; first += uint32_t(capacity_)) {
      trace_chunk(settings, uint32_t(sample), first, std::min<uint32_t>(uint32_t(capacity_), pixels - first));
    }
    gather_.args(w, h, acc_, primal_, dx_, dy_, direct_, primal_sq_).run(pixels);
  });
  out.seconds = timer.elapsed();
  float scale = out.samples > 0 ? 1.0f / out.samples : 0.0f;
  out.primal = film_rgb(primal_, scale);
  out.dx = film_rgb(dx_, scale);
  out.dy = film_rgb(dy_, scale);
  out.direct = film_rgb(direct_, scale);
  std::vector<float> sq = film_rgb(primal_sq_, scale);
  out.variance.resize(sq.size());
  for (size_t i = 0; i < sq.size(); ++i) {
    // Variance of the mean over the passes (one sample each).
    double var = std::max(0.0, double(sq[i]) - double(out.primal[i]) * out.primal[i]);
    out.variance[i] = out.samples > 1 ? float(var / (out.samples - 1)) : 0.0f;
  }
  if (stats) {
    stats->add_count("samples/paths", uint64_t(pixels) * out.samples * (1 + GPT_OFFSETS));
    stats->set("render/spp", out.samples);
  }
  return out;
}

}  // namespace gdr
