#include "integrators/mlt/metropolis_loop.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <random>

#include "cluster/ranks.h"
#include "cluster/reduce.h"
#include "render/progressive_loop.h"
#include "util/error.h"

namespace gdr {
namespace {

// Splat slots a record gathers at once (each step writes two a chain): the sort's batch. Larger
// batches gather slower on PoCL (2^18 slots a batch took 2 to 3 times as long a slot).
constexpr size_t kSplatSlots = size_t(1) << 16;

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

std::vector<std::string> metropolis_params() {
  return {"chains", "bootstrap", "sigma", "large_step", "mutations_per_pixel", "start_cap"};
}

MetropolisSettings metropolis_settings(const IntegratorParams& params) {
  MetropolisSettings s;
  s.mutation.sigma = params.non_negative("sigma", s.mutation.sigma);
  if (!(s.mutation.sigma > 0.0f) || s.mutation.sigma > 1.0f) throw Error("integrator parameter sigma: must lie in (0, 1]");
  s.mutation.large_step = params.non_negative("large_step", s.mutation.large_step);
  if (s.mutation.large_step > 1.0f) throw Error("integrator parameter large_step: must lie in [0, 1]");
  s.chains = whole_param(params, "chains", s.chains, 1);
  s.bootstrap = whole_param(params, "bootstrap", s.bootstrap, 1);
  if (params.has("mutations_per_pixel")) s.mutations_per_pixel = int(whole_param(params, "mutations_per_pixel", 1, 1));
  s.start_cap = whole_param(params, "start_cap", 0, 0);
  return s;
}

MetropolisSettings for_film(MetropolisSettings s, const Scene& scene) {
  if (s.chains == 0) s.chains = std::min(kDefaultChains, size_t(scene.camera.width) * scene.camera.height);
  // The bootstrap seeds the chains; b gains every large step's sample as the render goes on.
  if (s.bootstrap == 0) s.bootstrap = std::max(size_t(1) << 16, 4 * s.chains);
  return s;
}

MetropolisLoop::MetropolisLoop(const RenderInputs& in, const KernelFactory& kernels, const std::string& program,
                               const MetropolisSettings& settings, std::vector<Buffer<Vec4>*> layers)
    : in_(in),
      kernels_(kernels),
      program_(program),
      settings_(settings),
      layers_(std::move(layers)),
      splat_(kernels.make(program, "mlt_splat")),
      uniform_states_(kernels.make(program, "mlt_uniform_states")),
      current_(in.context, settings.chains * layers_.size()),
      proposed_(in.context, settings.chains * layers_.size()),
      sample_f_(in.context, settings.chains),
      steps_per_gather_(std::max<size_t>(1, kSplatSlots / (2 * settings.chains))) {
  splats_.reserve(layers_.size());
  for (size_t r = 0; r < layers_.size(); ++r) {
    splats_.emplace_back(in.context, kernels, program, std::max(kSplatSlots, 2 * settings.chains));
  }
}

MarkovChains::Sample MetropolisLoop::stratified_integral(const GdrPrimaryLayout& layout, uint32_t seed,
                                                        const Sample& sample) {
  ScopedTimer timer(in_.context.stats(), "render/mlt_normalization");
  const size_t chains = settings_.chains, dims = size_t(4) * layout.blocks;
  if (sample_states_.size() != chains * dims) sample_states_ = Buffer<float>(in_.context, chains * dims);
  const size_t pixels = size_t(in_.scene.camera.width) * in_.scene.camera.height;
  const size_t samples = (settings_.bootstrap + pixels - 1) / pixels * pixels;
  MarkovChains::Sample s;
  for (size_t done = 0, round = 0; done < samples; done += chains, ++round) {
    uniform_states_.args(in_.device_scene.camera(), layout, seed, cl_uint(round), sample_states_).run(chains);
    sample(0x80000000u + uint32_t(round), sample_states_, sample_f_);  // keys apart from the chains' steps
    const std::vector<float> f = sample_f_.read();
    const size_t used = std::min(chains, samples - done);  // the last round's past the sweeps are left out
    for (size_t c = 0; c < used; ++c) s.sum += f[c];
    s.count += double(used);
  }
  std::vector<float> pooled = {float(s.sum), float(s.count)};
  cluster::sum_to_root(pooled, in_.context.stats());
  return {pooled[0], pooled[1]};
}

size_t MetropolisLoop::bootstrap_rounds() const {
  return std::max<size_t>(1, (settings_.bootstrap + settings_.chains - 1) / settings_.chains);
}

MarkovChains::Sample MetropolisLoop::bootstrap(uint32_t seed, const Evaluate& evaluate) {
  ScopedTimer timer(in_.context.stats(), "render/mlt_bootstrap");
  const size_t chains = settings_.chains;
  std::vector<float> f;  // over the bootstrap samples, round by round
  f.reserve(bootstrap_rounds() * chains);
  double total = 0;
  for (size_t r = 0; r < bootstrap_rounds(); ++r) {
    chains_->propose_fresh(seed, uint32_t(r));
    evaluate(uint32_t(r), chains_->proposed(), proposed_, chains_->f_proposed(), chains_->proposed_read());
    for (float v : chains_->f_proposed().read()) {
      f.push_back(v);
      total += v;
    }
  }
  if (!(total > 0)) return {0, double(f.size())};
  // Each chain starts at a bootstrap sample drawn in proportion to f (resampling: the chains start
  // close to their stationary distribution instead of burning in). With start_cap k, f is capped
  // at its k-th largest value there: a lone sample far brighter than every other (a path whose
  // neighbours are much darker, which a chain leaves only after many steps) would start a share of
  // the chains that its tiny neighbourhood does not hold, all stuck there, a bright blotch until
  // they leave. The cap trades that for a start further from the stationary distribution where a
  // bright region only a few samples found (a small emitter seen directly) loses its share too.
  float cap = std::numeric_limits<float>::infinity();
  if (settings_.start_cap > 0) {
    std::vector<float> sorted = f;
    const size_t rank = std::min(settings_.start_cap, sorted.size()) - 1;
    std::nth_element(sorted.begin(), sorted.begin() + rank, sorted.end(), std::greater<>());
    cap = sorted[rank];
  }
  std::vector<double> cumulative(f.size());
  double capped = 0;
  for (size_t i = 0; i < f.size(); ++i) cumulative[i] = capped += std::min(f[i], cap);
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, capped);
  std::vector<cl_uint2> picks(chains);
  for (cl_uint2& pick : picks) {
    size_t i = std::upper_bound(cumulative.begin(), cumulative.end(), u(rng)) - cumulative.begin();
    i = std::min(i, cumulative.size() - 1);
    pick = cl_uint2{{cl_uint(i % chains), cl_uint(i / chains)}};
  }
  chains_->start_at(seed, picks);
  if (Stats* stats = in_.context.stats()) {
    std::map<uint64_t, size_t> starts;  // the chains each picked bootstrap sample starts
    size_t most = 0;
    for (const cl_uint2& p : picks) most = std::max(most, ++starts[uint64_t(p.s[1]) * chains + p.s[0]]);
    stats->set("mlt/start_duplicates", most);
  }
  evaluate(uint32_t(bootstrap_rounds()), chains_->current(), current_, chains_->f_current(), chains_->current_read());
  return {total, double(f.size())};
}

void MetropolisLoop::splat(uint32_t seed, uint32_t step, size_t pending) {
  const cl_uint records = cl_uint(layers_.size());
  for (cl_uint r = 0; r < records; ++r) {
    splat_
        .args(chains_->step_params(seed, step), r, records, chains_->weights(), current_, proposed_,
              cl_uint(2 * settings_.chains * pending), splats_[r].slots())
        .run(settings_.chains);
  }
}

void MetropolisLoop::gather(size_t pending) {
  const int height = in_.scene.camera.height;
  for (size_t r = 0; r < layers_.size(); ++r) {
    splats_[r].gather(in_.device_scene.camera(), height, cl_uint(2 * settings_.chains * pending), *layers_[r]);
  }
}

MetropolisLoop::Result MetropolisLoop::run(const RenderSettings& settings, const GdrPrimaryLayout& layout,
                                           const MltSettings& mutation, bool contributes, const Evaluate& evaluate,
                                           const Sample& normalization) {
  Stats* stats = in_.context.stats();
  const size_t chains = settings_.chains;
  const size_t pixels = size_t(in_.scene.camera.width) * in_.scene.camera.height;
  chains_.emplace(in_.context, kernels_, program_, chains, size_t(4) * layout.blocks, mutation);
  const uint32_t seed = chain_seed(settings.seed, cluster::rank());
  ScopedTimer start_time(nullptr, "");  // a stopwatch: the bootstrap and b's samples count against --time
  const MarkovChains::Sample boot = contributes ? bootstrap(seed, evaluate) : MarkovChains::Sample{};
  // b's samples draw numbers apart from the chains' (another Philox key).
  const MarkovChains::Sample given = contributes && normalization
                                         ? stratified_integral(layout, seed ^ 0x62616d70u, normalization)
                                         : MarkovChains::Sample{};

  // A pass: the steps that make about one mutation a pixel.
  const size_t steps_per_pass = std::max<size_t>(1, (pixels + chains / 2) / chains);
  const uint32_t first_step = uint32_t(bootstrap_rounds()) + 1;
  RenderSettings loop = settings;
  if (settings_.mutations_per_pixel) loop.spp = *settings_.mutations_per_pixel;
  if (loop.time_budget) loop.time_budget = std::max(0.0, *loop.time_budget - start_time.elapsed());
  Result result;
  size_t pending = 0;  // steps whose splats wait in the slots
  result.passes = run_progressive(loop, [&](int sample) {
    if (!(boot.sum > 0)) return;
    for (size_t j = 0; j < steps_per_pass; ++j) {
      const uint32_t step = first_step + uint32_t(size_t(sample) * steps_per_pass + j);
      chains_->propose(seed, step);
      evaluate(step, chains_->proposed(), proposed_, chains_->f_proposed(), chains_->proposed_read());
      chains_->accept(seed, step);
      splat(seed, step, pending);
      if (++pending == steps_per_gather_) {
        gather(pending);
        pending = 0;
      }
    }
  });
  // The film is read only now: the slots gather when full and once at the end.
  if (pending > 0) gather(pending);

  // b from every uniform sample of all ranks: the bootstrap's and the large steps' proposals
  // (Kelemen et al.), far more of them than the bootstrap alone in a long render.
  const MarkovChains::Sample large = chains_->large_step_targets();
  std::vector<float> uniform = {float(boot.sum + large.sum), float(boot.count + large.count)};
  cluster::sum_to_root(uniform, stats);
  const double target_integral = uniform[1] > 0 ? double(uniform[0]) / uniform[1] : 0.0;
  const MarkovChains::Sample b = normalization ? given : MarkovChains::Sample{uniform[0], uniform[1]};
  result.normalization = b.count > 0 ? b.sum / b.count : 0.0;
  const double steps = double(result.passes) * double(steps_per_pass);
  result.scale = steps > 0 ? result.normalization / (steps * double(chains)) : 0.0;
  // The chains were made for this render: their counts are this render's.
  const std::vector<cl_uint> n = chains_->counts();
  chains_->report(stats);
  if (stats) {
    auto rate = [&](int accepted, int steps_of_kind) {
      return n[steps_of_kind] > 0 ? double(n[accepted]) / n[steps_of_kind] : 0.0;
    };
    stats->set("mlt/acceptance/small_steps", rate(MLT_COUNTER_SMALL_ACCEPTED, MLT_COUNTER_SMALL_STEPS));
    stats->set("mlt/acceptance/large_steps", rate(MLT_COUNTER_LARGE_ACCEPTED, MLT_COUNTER_LARGE_STEPS));
    stats->set("mlt/chains", chains);
    stats->set("mlt/mutations_per_pixel", steps * double(chains) / double(pixels));
    stats->set("mlt/normalization", result.normalization);
    stats->set("mlt/normalization_samples", b.count);
    stats->set("mlt/target_integral", target_integral);
    stats->set("mlt/target_integral_samples", double(uniform[1]));
    stats->add_count("mlt/bootstrap_samples", uint64_t(boot.count));
    stats->set("render/spp", result.passes);
  }
  return result;
}

}  // namespace gdr
