#include "integrators/bidir/bidirectional.h"

#include <algorithm>
#include <charconv>
#include <cmath>

#include "render/radiance_render.h"
#include "render/wavefront/chunks.h"
#include "util/error.h"
#include "util/log.h"

namespace gdr {
namespace {

// Subpaths in flight per chunk: bounds the queues' and the light-vertex store's memory (about
// 1 KB a pixel under bdpt).
constexpr size_t kMaxPathsInFlight = size_t(1) << 18;

// "s,t": s light vertices, t camera vertices, a strategy of at least one segment that the
// pinhole can take part in (t = 1 connects a light vertex beyond the light to the camera).
void parse_strategy(const std::string& text, GdrBidirOptions* o) {
  size_t comma = text.find(',');
  int s = -1, t = -1;
  auto whole = [](const char* a, const char* b, int* v) {
    auto r = std::from_chars(a, b, *v);
    return r.ec == std::errc() && r.ptr == b && *v >= 0;
  };
  bool ok = comma != std::string::npos && whole(text.data(), text.data() + comma, &s) &&
            whole(text.data() + comma + 1, text.data() + text.size(), &t) && (t >= 2 || (t == 1 && s >= 2));
  if (!ok) {
    throw Error("integrator parameter strategy: '" + text +
                "' is not s,t (s light and t camera vertices: t >= 2, or t = 1 with s >= 2)");
  }
  o->strategy_s = s;
  o->strategy_t = t;
}

}  // namespace

const std::vector<std::string> kLtParams = {"aux"};
const std::vector<std::string> kBdptParams = {"aux", "mis", "strategy"};
const std::vector<std::string> kPmParams = {"aux", "radius", "radius_alpha"};
const std::vector<std::string> kVcmParams = {"aux", "mis", "radius", "radius_alpha"};

namespace {

BidirSettings merging_settings(int technique, const IntegratorParams& params) {
  BidirSettings s;
  s.options.technique = technique;
  if (technique == BIDIR_VCM) s.options.mis = bidir_mis_param(params);
  if (params.has("radius")) {
    s.radius = params.non_negative("radius", 0.0f);
    if (!(s.radius > 0.0f)) throw Error("integrator parameter radius: must be above 0");
  }
  s.radius_alpha = params.non_negative("radius_alpha", 0.75f);
  if (!(s.radius_alpha > 0.0f) || s.radius_alpha > 1.0f) {
    throw Error("integrator parameter radius_alpha: must lie in (0, 1]");
  }
  s.aux = params.flag("aux", false);
  return s;
}

}  // namespace

BidirSettings lt_settings(const IntegratorParams& params) {
  BidirSettings s;
  s.options.technique = BIDIR_LT;
  s.aux = params.flag("aux", false);
  return s;
}

BidirSettings bdpt_settings(const IntegratorParams& params) {
  BidirSettings s;
  s.options.technique = BIDIR_BDPT;
  s.options.mis = bidir_mis_param(params);
  if (params.has("strategy")) parse_strategy(params.values().at("strategy"), &s.options);
  s.aux = params.flag("aux", false);
  return s;
}

BidirSettings pm_settings(const IntegratorParams& params) { return merging_settings(BIDIR_PM, params); }
BidirSettings vcm_settings(const IntegratorParams& params) { return merging_settings(BIDIR_VCM, params); }

int bidir_mis_param(const IntegratorParams& params) {
  return params.choice("mis", "power", {"power", "balance"}) == "balance" ? BIDIR_MIS_BALANCE : BIDIR_MIS_POWER;
}

int bdpt_segments(int max_depth) {
  return max_depth < 0 || max_depth > kBdptMaxSegments ? kBdptMaxSegments : max_depth;
}

void warn_beyond_store(const char* integrator, int max_depth) {
  if (bdpt_segments(max_depth) == max_depth) return;
  log::warn(integrator, " renders paths of at most ", kBdptMaxSegments, " segments (max_depth ", max_depth,
            " asked for more): the light-vertex store's bound");
}

const char* bidir_technique_name(int technique) {
  switch (technique) {
    case BIDIR_BDPT: return "bdpt";
    case BIDIR_PM: return "pm";
    case BIDIR_VCM: return "vcm";
    default: return "lt";
  }
}

BidirSettings bidir_settings(int technique, const IntegratorParams& params) {
  switch (technique) {
    case BIDIR_BDPT: return bdpt_settings(params);
    case BIDIR_PM: return pm_settings(params);
    case BIDIR_VCM: return vcm_settings(params);
    default: return lt_settings(params);
  }
}

Bidirectional::Bidirectional(const RenderInputs& in, const BidirSettings& settings)
    : in_(in),
      settings_(settings),
      subpaths_(in, settings.options.technique,
                device_chunk_capacity(kMaxPathsInFlight, in.context.is_cpu() && !merges(),
                                      settings.in_flight, in.scene.camera.width, in.scene.camera.height)),
      film_(in.context, in.scene.camera.width, in.scene.camera.height, {"radiance"}),
      splats_(in.context, subpaths_.kernels(), BidirSubpaths::kProgram, subpaths_.capacity()) {
  if (settings_.aux) aux_.emplace(in.context, subpaths_.kernels(), BidirSubpaths::kProgram, film_.pixels());
}

GdrBidirOptions merging_pass_options(const BidirSettings& settings, const Scene& scene, uint32_t sample,
                                     uint32_t light_subpaths) {
  GdrBidirOptions o = settings.options;
  const int width = scene.camera.width, height = scene.camera.height;
  const double scene_radius = scene.bounding_radius();
  const float r0 = (settings.radius > 0 ? settings.radius : 1.5f / float(std::max(width, height))) *
                   float(scene_radius > 0 ? scene_radius : 1.0);
  o.radius = r0 * std::pow(float(sample) + 1.0f, 0.5f * (settings.radius_alpha - 1.0f));
  const double eta = M_PI * double(o.radius) * o.radius * light_subpaths;
  o.vm_normalization = float(1.0 / eta);
  if (o.technique == BIDIR_VCM) {
    const double m = o.mis == BIDIR_MIS_POWER ? eta * eta : eta;
    o.vm_factor = float(m);
    o.vc_factor = float(1.0 / m);
  }
  return o;
}

GdrBidirOptions Bidirectional::pass_options(uint32_t sample, uint32_t light_subpaths) const {
  return merges() ? merging_pass_options(settings_, in_.scene, sample, light_subpaths) : settings_.options;
}

void Bidirectional::trace_chunk(const RenderSettings& settings, uint32_t sample, uint32_t first, uint32_t count) {
  GdrPtParams p = in_.device_scene.path_params(settings, sample, first, count);
  if (technique() != BIDIR_LT) p.max_depth = bdpt_segments(settings.max_depth);
  bool light = light_subpaths_allowed(settings.max_depth) && p.light_count > 0;
  subpaths_.trace(p, pass_options(sample, count), light, PrimarySamples(),
                  BidirSink{film_["radiance"], splats_, &film_["radiance"]}, aux_ ? &*aux_ : nullptr);
  subpaths_.report(in_.context.stats());
}

RenderResult Bidirectional::render(const RenderSettings& settings) {
  if (technique() != BIDIR_LT) warn_beyond_store(bidir_technique_name(technique()), settings.max_depth);
  return render_radiance(in_.context, settings, film_, aux_, subpaths_.capacity(), [&](uint32_t sample, uint32_t first, uint32_t count) {
    trace_chunk(settings, sample, first, count);
  });
}

}  // namespace gdr
