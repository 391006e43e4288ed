#include "integrators/mlt/metropolis.h"

#include <algorithm>
#include <cmath>
#include <random>

#include "cluster/ranks.h"
#include "cluster/reduce.h"
#include "integrators/bidir/bidirectional.h"
#include "render/progressive_loop.h"
#include "util/error.h"
#include "util/log.h"

namespace gdr {
namespace {

// Splat slots gathered at once (each step writes two a chain): the sort's batch.
constexpr size_t kSplatSlots = size_t(1) << 20;

size_t whole_param(const IntegratorParams& params, const std::string& name, size_t fallback, size_t lowest) {
  if (!params.has(name)) return fallback;
  float v = params.non_negative(name, float(fallback));
  if (v != std::floor(v) || v < float(lowest) || v > float(1u << 30)) {
    throw Error("integrator parameter " + name + ": must be a whole number from " + std::to_string(lowest) +
                " to 2^30");
  }
  return size_t(v);
}

// The chains' own random numbers: apart from the paths' (keyed by the render seed), and apart
// on every rank.
uint32_t chain_seed(uint32_t seed, int rank) {
  uint64_t x = (uint64_t(seed) << 32 | uint32_t(rank)) * 0x9E3779B97F4A7C15ull;
  return uint32_t(x >> 32) ^ 0x6d6c7421u;
}

}  // namespace

const std::vector<std::string> kMltParams = {"chains", "bootstrap", "sigma", "large_step", "mutations_per_pixel", "mis"};

MetropolisSettings mlt_settings(const IntegratorParams& params) {
  MetropolisSettings s;
  s.mutation.sigma = params.non_negative("sigma", s.mutation.sigma);
  if (!(s.mutation.sigma > 0.0f) || s.mutation.sigma > 1.0f) throw Error("integrator parameter sigma: must lie in (0, 1]");
  s.mutation.large_step = params.non_negative("large_step", s.mutation.large_step);
  if (s.mutation.large_step > 1.0f) throw Error("integrator parameter large_step: must lie in [0, 1]");
  s.mis = bidir_mis_param(params);
  s.chains = whole_param(params, "chains", s.chains, 1);
  s.bootstrap = whole_param(params, "bootstrap", s.bootstrap, 1);
  if (params.has("mutations_per_pixel")) s.mutations_per_pixel = int(whole_param(params, "mutations_per_pixel", 1, 1));
  return s;
}

Metropolis::Metropolis(const RenderInputs& in, const MetropolisSettings& settings)
    : in_(in),
      settings_(settings),
      subpaths_(in, BIDIR_BDPT, settings.chains),
      contribution_(subpaths_.kernels().make(kProgram, "mlt_contribution")),
      splat_(subpaths_.kernels().make(kProgram, "mlt_splat")),
      values_(in.context, settings.chains),
      found_(in.context, subpaths_.kernels(), BidirSubpaths::kProgram, settings.chains),
      current_(in.context, settings.chains),
      proposed_(in.context, settings.chains),
      splats_(in.context, subpaths_.kernels(), kProgram, std::max(kSplatSlots, 2 * settings.chains)),
      steps_per_gather_(std::max<size_t>(1, kSplatSlots / (2 * settings.chains))),
      film_(in.context, in.scene.camera.width, in.scene.camera.height, {"radiance"}) {
  values_.fill(Vec4{});
  options_ = GdrBidirOptions{BIDIR_BDPT, settings.mis, -1, -1, 0.0f, 0.0f, 0.0f, 0.0f, 1, 0};
}

void Metropolis::evaluate(const GdrPtParams& p, const Buffer<float>& states, Buffer<GdrSplat>& contributions,
                          Buffer<float>& f) {
  subpaths_.trace(p, options_, light_, PrimarySamples(states, layout_), BidirSink{values_, found_, nullptr}, nullptr);
  contribution_
      .args(in_.device_scene.camera(), p, options_, layout_, states, values_, found_.slots(), contributions, f)
      .run(layout_.chains);
}

MarkovChains::Sample Metropolis::bootstrap(const GdrPtParams& base, uint32_t seed) {
  ScopedTimer timer(in_.context.stats(), "render/mlt_bootstrap");
  const size_t chains = settings_.chains;
  std::vector<double> cumulative;  // of f over the bootstrap samples, round by round
  cumulative.reserve(bootstrap_rounds() * chains);
  double total = 0;
  for (size_t r = 0; r < bootstrap_rounds(); ++r) {
    chains_->propose_fresh(seed, uint32_t(r));
    GdrPtParams p = base;
    p.sample = uint32_t(r);
    evaluate(p, chains_->proposed(), proposed_, chains_->f_proposed());
    for (float f : chains_->f_proposed().read()) cumulative.push_back(total += f);
  }
  if (!(total > 0)) return {0, double(cumulative.size())};
  // Each chain starts at a bootstrap sample drawn in proportion to f (resampling: the chains start
  // close to their stationary distribution instead of burning in).
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, total);
  std::vector<cl_uint2> picks(chains);
  for (cl_uint2& pick : picks) {
    size_t i = std::upper_bound(cumulative.begin(), cumulative.end(), u(rng)) - cumulative.begin();
    i = std::min(i, cumulative.size() - 1);
    pick = cl_uint2{{cl_uint(i % chains), cl_uint(i / chains)}};
  }
  chains_->start_at(seed, picks);
  GdrPtParams p = base;
  p.sample = uint32_t(bootstrap_rounds());
  evaluate(p, chains_->current(), current_, chains_->f_current());
  return {total, double(cumulative.size())};
}

RenderResult Metropolis::render(const RenderSettings& settings) {
  Stats* stats = in_.context.stats();
  ScopedTimer timer(stats, "render/trace");
  const int segments = bdpt_segments(settings.max_depth);
  if (segments != settings.max_depth) {
    log::warn("mlt renders paths of at most ", kBdptMaxSegments, " segments (max_depth ", settings.max_depth,
              " asked for more): the light-vertex store's bound");
  }
  const size_t chains = settings_.chains, pixels = film_.pixels();
  layout_ = PrimarySamples::layout_for(chains, std::max(segments, 1));
  MltSettings mutation = settings_.mutation;
  mutation.lengths = unsigned(std::max(segments, 1));
  chains_.emplace(in_.context, subpaths_.kernels(), kProgram, chains, size_t(4) * layout_.blocks, mutation);
  film_.clear();

  GdrPtParams base = in_.device_scene.path_params(settings, 0, 0, uint32_t(chains));
  base.max_depth = segments;
  light_ = light_subpaths_allowed(settings.max_depth) && base.light_count > 0;
  const uint32_t seed = chain_seed(settings.seed, cluster::rank());
  const MarkovChains::Sample boot = segments > 0 && base.light_count > 0 ? bootstrap(base, seed) : MarkovChains::Sample{};
  const bool contributes = boot.sum > 0;

  // A pass: the steps that make about one mutation a pixel.
  const size_t steps_per_pass = std::max<size_t>(1, (pixels + chains / 2) / chains);
  const uint32_t first_step = uint32_t(bootstrap_rounds()) + 1;
  RenderSettings loop = settings;
  if (settings_.mutations_per_pixel) loop.spp = *settings_.mutations_per_pixel;
  size_t pending = 0;  // steps whose splats wait in the slots
  auto gather = [&] {
    splats_.gather(in_.device_scene.camera(), film_.height(), cl_uint(2 * chains * pending), film_["radiance"]);
    pending = 0;
  };
  RenderResult result;
  result.samples = run_progressive(loop, [&](int sample) {
    if (!contributes) return;
    for (size_t j = 0; j < steps_per_pass; ++j) {
      const uint32_t step = first_step + uint32_t(size_t(sample) * steps_per_pass + j);
      chains_->propose(seed, step);
      GdrPtParams p = base;
      p.sample = step;
      evaluate(p, chains_->proposed(), proposed_, chains_->f_proposed());
      chains_->accept(seed, step);
      splat_.args(chains_->step_params(seed, step), chains_->weights(), current_, proposed_,
                  cl_uint(2 * chains * pending), splats_.slots())
          .run(chains);
      if (++pending == steps_per_gather_) gather();
    }
    if (pending > 0) gather();
  });
  result.seconds = timer.elapsed();

  // The normalization b from every uniform sample of all ranks: the bootstrap's and the large
  // steps' proposals (Kelemen et al.), far more of them than the bootstrap alone in a long render.
  const MarkovChains::Sample large = chains_->large_step_targets();
  std::vector<float> uniform = {float(boot.sum + large.sum), float(boot.count + large.count)};
  cluster::sum_to_root(uniform, stats);
  normalization_ = uniform[1] > 0 ? double(uniform[0]) / uniform[1] : 0.0;
  const double steps = double(result.samples) * double(steps_per_pass);
  const float scale = steps > 0 ? float(normalization_ / (steps * double(chains))) : 0.0f;
  result.image = Image(film_.width(), film_.height(), {});
  result.image.add_rgb_layer("", reduced_rgb(film_["radiance"], scale, stats));
  subpaths_.report(stats);
  chains_->report(stats);
  if (stats) {
    stats->set("mlt/chains", chains);
    stats->set("mlt/mutations_per_pixel", steps * double(chains) / double(pixels));
    stats->set("mlt/normalization", normalization_);
    stats->set("mlt/normalization_samples", double(uniform[1]));
    stats->add_count("mlt/bootstrap_samples", uint64_t(boot.count));
    stats->set("render/spp", result.samples);
  }
  return result;
}

}  // namespace gdr
