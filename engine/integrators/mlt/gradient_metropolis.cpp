#include "integrators/mlt/gradient_metropolis.h"

#include <algorithm>

#include "util/error.h"

namespace gdr {
namespace {

// The longest camera path whose numbers a chain's state holds (segments); the numbers of longer
// paths (max_depth -1, Russian roulette) come fresh at each evaluation.
constexpr int kHeldSegments = 16;

// Record r's film layer (kernels/mlt/gmlt.cl: GMLT_*).
std::vector<std::string> record_layers() {
  return {"primal", "primal", "primal", "primal", "primal", "dx", "dx", "dy", "dy", "direct"};
}

IntegratorParams recon_params(const IntegratorParams& params) {
  IntegratorParams p = params;
  if (!p.has("recon")) p.set("recon", "l1");
  if (p.values().at("recon") == "weighted") {
    throw Error("integrator parameter recon: gmlt reconstructs with l1, l2 or none; the weighted form needs "
                "independent passes, which a Markov chain's are not");
  }
  return p;
}

}  // namespace

const std::vector<std::string> kGmltParams = [] {
  std::vector<std::string> p = metropolis_params();
  for (const char* name : {"target_alpha", "shift", "shift_threshold", "manifold_iterations", "manifold_tolerance",
                           "manifold_precision"}) {
    p.push_back(name);
  }
  return p;
}();

GmltSettings gmlt_settings(const IntegratorParams& params) {
  GmltSettings s;
  s.loop = metropolis_settings(params);
  s.gpt = gpt_shift_settings(params, "manifold");
  s.target_alpha = params.non_negative("target_alpha", s.target_alpha);
  if (!(s.target_alpha > 0.0f)) {
    throw Error("integrator parameter target_alpha: must be above 0 (the coarse image needs f > 0 wherever the "
                "primal is)");
  }
  recon_params(params);
  return s;
}

GradientMetropolis::GradientMetropolis(const RenderInputs& in, const GmltSettings& settings,
                                       const IntegratorParams& params)
    : in_(in),
      settings_{for_film(settings.loop, in.scene), settings.gpt, settings.target_alpha},
      recon_params_(recon_params(params)),
      groups_(in, settings_.gpt, settings_.loop.chains, settings_.loop.chains),
      contribution_(groups_.kernels().make(kProgram, "gmlt_contribution")),
      film_(in.context, in.scene.camera.width, in.scene.camera.height, {"primal", "dx", "dy", "direct"}),
      loop_(in, groups_.kernels(), kProgram, settings_.loop, [this] {
        std::vector<Buffer<Vec4>*> layers;
        for (const std::string& name : record_layers()) layers.push_back(&film_[name]);
        return layers;
      }()) {}

GradientImages GradientMetropolis::render_gradients(const RenderSettings& settings) {
  Stats* stats = in_.context.stats();
  ScopedTimer timer(stats, "render/trace");
  const size_t chains = loop_.chains();
  const int held = settings.max_depth < 0 ? kHeldSegments : std::clamp(settings.max_depth, 1, kHeldSegments);
  const GdrPrimaryLayout layout = PrimarySamples::layout_for(chains, held, true);
  film_.clear();
  const GdrGptParams base = groups_.params(settings, 0, 0, uint32_t(chains));
  const bool contributes = settings.max_depth != 0 && base.path.light_count > 0;
  // A group reads the camera blocks of its base path's depth alone: its chain reports them, and a
  // step moves those and draws the rest fresh.
  MltSettings mutation = settings_.loop.mutation;
  mutation.reported = true;
  MetropolisLoop::Result r = loop_.run(
      settings, layout, mutation, contributes,
      [&](uint32_t iteration, const Buffer<float>& states, Buffer<GdrSplat>& records, Buffer<float>& f,
          Buffer<cl_uint>& read) {
        GdrGptParams p = base;
        p.path.sample = iteration;
        groups_.trace(p, PrimarySamples(states, layout), nullptr);
        contribution_
            .args(in_.device_scene.camera(), p, layout, settings_.target_alpha, states, groups_.acc(),
                  groups_.bases(), records, f, read)
            .run(chains);
      });
  normalization_ = r.normalization;
  groups_.report(stats);

  GradientImages out;
  out.width = film_.width();
  out.height = film_.height();
  out.samples = r.passes;
  const float scale = float(r.scale);
  out.dx = reduced_rgb(film_["dx"], scale, stats);
  out.dy = reduced_rgb(film_["dy"], scale, stats);
  out.direct = reduced_rgb(film_["direct"], scale, stats);
  out.primal = reduced_rgb(film_["primal"], scale, stats);
  for (size_t i = 0; i < out.primal.size() && i < out.direct.size(); ++i) out.primal[i] += out.direct[i];
  out.seconds = timer.elapsed();
  return out;
}

RenderResult GradientMetropolis::render(const RenderSettings& settings) {
  return gradient_result(in_.context, render_gradients(settings), recon_params_, in_.context.stats());
}

}  // namespace gdr
