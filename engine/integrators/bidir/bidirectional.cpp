#include "integrators/bidir/bidirectional.h"

#include <algorithm>
#include <charconv>
#include <cmath>

#include "render/radiance_render.h"
#include "render/wavefront/chunks.h"
#include "util/error.h"
#include "util/log.h"

// The kernels see these layouts too (4-byte scalars only: the same on both sides).
static_assert(sizeof(GdrBidirOptions) == 32, "GdrBidirOptions layout changed");
static_assert(sizeof(GdrBidirPathState) == 48, "GdrBidirPathState layout changed");
static_assert(sizeof(GdrBidirVertex) == 52, "GdrBidirVertex layout changed");

namespace gdr {
namespace {

// Subpaths in flight per chunk: bounds the queues' and the light-vertex store's memory (about
// 1 KB a pixel under bdpt).
constexpr size_t kMaxPathsInFlight = size_t(1) << 18;
constexpr const char* kProgram = "bidir/bidir.cl";

// Mitsuba's max_depth: a light subpath's first vertex connected to the camera is 2 segments.
bool light_subpaths_allowed(int max_depth) { return max_depth < 0 || max_depth >= 2; }

// bdpt's longest path for the settings' max_depth (segments).
int bdpt_segments(int max_depth) {
  return max_depth < 0 || max_depth > kBdptMaxSegments ? kBdptMaxSegments : max_depth;
}

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

int mis_param(const IntegratorParams& params) {
  return params.choice("mis", "power", {"power", "balance"}) == "balance" ? BIDIR_MIS_BALANCE : BIDIR_MIS_POWER;
}

BidirSettings merging_settings(int technique, const IntegratorParams& params) {
  BidirSettings s;
  s.options.technique = technique;
  if (technique == BIDIR_VCM) s.options.mis = mis_param(params);
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
  s.options.mis = mis_param(params);
  if (params.has("strategy")) parse_strategy(params.values().at("strategy"), &s.options);
  s.aux = params.flag("aux", false);
  return s;
}

BidirSettings pm_settings(const IntegratorParams& params) { return merging_settings(BIDIR_PM, params); }
BidirSettings vcm_settings(const IntegratorParams& params) { return merging_settings(BIDIR_VCM, params); }

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
      kernels_(in.context, in.scene),
      lt_camera_(kernels_.make(kProgram, "lt_camera")),
      lt_direct_(kernels_.make(kProgram, "lt_direct")),
      emit_(kernels_.make(kProgram, "bidir_emit")),
      light_shade_(kernels_.make(kProgram, "bidir_light_shade")),
      camera_blocked_(kernels_.make(kProgram, "bidir_camera_blocked")),
      generate_(kernels_.make(kProgram, "bdpt_generate")),
      camera_shade_(kernels_.make(kProgram, "bdpt_camera_shade")),
      connect_(kernels_.make(kProgram, "bdpt_connect")),
      shadow_add_(kernels_.make(kProgram, "path_shadow_add")),
      grid_keys_(kernels_.make(kProgram, "vcm_grid_keys")),
      merge_(kernels_.make(kProgram, "vcm_merge")),
      options_(settings.options),
      capacity_(chunk_capacity(kMaxPathsInFlight, in.scene.camera.width, in.scene.camera.height)),
      store_vertices_(lt() ? 0 : kBdptMaxSegments - 1),
      queues_(in.context, capacity_, true),
      light_paths_(in.context, capacity_),
      camera_paths_(in.context, lt() ? 0 : capacity_),
      store_(in.context, capacity_ * size_t(store_vertices_)),
      camera_vertices_(in.context, lt() ? 0 : capacity_),
      connectable_(in.context, lt() ? 0 : capacity_),
      shadow_rays_(in.context, capacity_, kRayQueueFlags),
      shadow_values_(in.context, lt() ? 0 : capacity_),
      counters_(in.context, GDR_COUNTER_NAMES(BIDIR_COUNTERS)),
      film_(in.context, in.scene.camera.width, in.scene.camera.height, {"radiance"}),
      splats_(in.context, kernels_, kProgram, capacity_) {
  if (settings_.aux) aux_.emplace(in.context, kernels_, kProgram, film_.pixels());
  if (merges()) {
    const size_t entries = capacity_ * size_t(store_vertices_);
    primitives_.emplace(in.context);
    grid_keys_buffer_ = Buffer<cl_uint>(in.context, entries);
    grid_starts_ = Buffer<cl_uint>(in.context, entries + 1);
    grid_sorted_ = Buffer<cl_uint>(in.context, entries);
    store_points_ = Buffer<Vec4>(in.context, entries);
  }
}

GdrBidirOptions Bidirectional::pass_options(uint32_t sample, uint32_t light_subpaths) const {
  GdrBidirOptions o = settings_.options;
  if (!merges()) return o;
  const int width = in_.scene.camera.width, height = in_.scene.camera.height;
  const double scene_radius = in_.scene.bounding_radius();
  const float r0 = (settings_.radius > 0 ? settings_.radius : 1.5f / float(std::max(width, height))) *
                   float(scene_radius > 0 ? scene_radius : 1.0);
  o.radius = r0 * std::pow(float(sample) + 1.0f, 0.5f * (settings_.radius_alpha - 1.0f));
  const double eta = M_PI * double(o.radius) * o.radius * light_subpaths;
  o.vm_normalization = float(1.0 / eta);
  if (technique() == BIDIR_VCM) {
    const double m = o.mis == BIDIR_MIS_POWER ? eta * eta : eta;
    o.vm_factor = float(m);
    o.vc_factor = float(1.0 / m);
  }
  return o;
}

void Bidirectional::trace_light_subpaths(const GdrPtParams& p) {
  const GdrBidirOptions& o = options_;
  counters_.reset();
  emit_.args(p, o, queues_.rays[0], queues_.slots[0], light_paths_, counters_.buffer(), in_.device_scene)
      .run(p.pixel_count);
  cl_uint active = counters_.read()[BIDIR_COUNTER_NEXT_RAYS];
  for (int cur = 0; active > 0; cur = 1 - cur) {
    intersect(in_.embree, queues_.rays[cur], active, false, "light");
    counters_.reset();
    light_shade_
        .args(p, o, active, cl_uint(capacity_), in_.device_scene.camera(), queues_.rays[cur], queues_.slots[cur],
              queues_.rays[1 - cur], queues_.slots[1 - cur], shadow_rays_, splats_.slots(), light_paths_, store_,
              counters_.buffer(), in_.device_scene)
        .run(active);
    counters_.read();
    if (counters_[BIDIR_COUNTER_LIGHT_VERTICES] > 0) ++stored_bound_;
    stored_ += counters_[BIDIR_COUNTER_LIGHT_VERTICES];
    cl_uint shadows = counters_[BIDIR_COUNTER_SHADOW_RAYS];
    if (shadows > 0) {
      occlude(in_.embree, shadow_rays_, shadows, "camera_connection");
      camera_blocked_.args(shadows, shadow_rays_, splats_.slots()).run(shadows);
      splats_.gather(in_.device_scene.camera(), film_.height(), p.pixel_count, film_["radiance"]);
    }
    active = counters_[BIDIR_COUNTER_NEXT_RAYS];
  }
}

void Bidirectional::trace_direct(const GdrPtParams& p) {
  lt_camera_.args(in_.device_scene.camera(), p, queues_.rays[0]).run(p.pixel_count);
  intersect(in_.embree, queues_.rays[0], p.pixel_count, true, "camera");
  if (aux_) aux_->add(p, queues_.rays[0], p.pixel_count, in_.device_scene);
  counters_.reset();
  lt_direct_.args(p, p.pixel_count, queues_.rays[0], film_["radiance"], counters_.buffer(), in_.device_scene)
      .run(p.pixel_count);
  counters_.read();
}

void Bidirectional::add_shadows(cl_uint count, const char* kind) {
  if (count == 0) return;
  occlude(in_.embree, shadow_rays_, count, kind);
  shadow_add_.args(count, shadow_rays_, shadow_values_, film_["radiance"]).run(count);
}

void Bidirectional::connect(const GdrPtParams& p, int camera_depth, cl_uint connectable) {
  // Vertex j of a light subpath lies j + 1 bounces or more from its light, and the connection
  // adds a segment.
  const int last = std::min(stored_bound_, p.max_depth - camera_depth - 1);
  for (int j = 0; j < last; ++j) {
    counters_.reset();
    connect_
        .args(p, options_, connectable, cl_uint(j), cl_uint(capacity_), connectable_, camera_vertices_,
              light_paths_, store_, shadow_rays_, shadow_values_, counters_.buffer(), in_.device_scene)
        .run(connectable);
    counters_.read();
    add_shadows(counters_[BIDIR_COUNTER_SHADOW_RAYS], "connection");
  }
}

void Bidirectional::build_grid(const GdrPtParams& p) {
  ScopedTimer timer(in_.context.stats(), "render/grid_build");
  const size_t entries = capacity_ * size_t(stored_bound_);
  grid_buckets_ = std::max<cl_uint>(1, stored_);
  grid_keys_
      .args(p, options_, cl_uint(capacity_), cl_uint(entries), light_paths_, store_, grid_buckets_, grid_keys_buffer_,
            store_points_, in_.device_scene)
      .run(entries);
  primitives_->sort_by_key(grid_keys_buffer_, entries, grid_buckets_, grid_starts_, grid_sorted_);
}

void Bidirectional::merge(const GdrPtParams& p, cl_uint connectable) {
  counters_.reset();
  merge_
      .args(p, options_, connectable, cl_uint(capacity_), connectable_, camera_vertices_, store_, store_points_,
            grid_starts_, grid_sorted_, grid_buckets_, film_["radiance"], counters_.buffer(), in_.device_scene)
      .run(connectable);
  counters_.read();
}

void Bidirectional::trace_camera_subpaths(const GdrPtParams& p) {
  const GdrBidirOptions& o = options_;
  generate_.args(in_.device_scene.camera(), p, o, queues_.rays[0], queues_.slots[0], camera_paths_).run(p.pixel_count);
  cl_uint active = p.pixel_count;
  for (int depth = 0, cur = 0; active > 0; ++depth, cur = 1 - cur) {
    intersect(in_.embree, queues_.rays[cur], active, depth == 0, depth == 0 ? "camera" : "bounce");
    if (depth == 0 && aux_) aux_->add(p, queues_.rays[cur], active, in_.device_scene);
    counters_.reset();
    camera_shade_
        .args(p, o, active, queues_.rays[cur], queues_.slots[cur], queues_.rays[1 - cur], queues_.slots[1 - cur],
              shadow_rays_, shadow_values_, camera_paths_, camera_vertices_, connectable_, film_["radiance"],
              counters_.buffer(), in_.device_scene)
        .run(active);
    counters_.read();
    cl_uint connectable = counters_[BIDIR_COUNTER_CONNECTABLE];
    active = counters_[BIDIR_COUNTER_NEXT_RAYS];
    add_shadows(counters_[BIDIR_COUNTER_SHADOW_RAYS], "shadow");
    if (connectable > 0 && connects()) connect(p, depth + 1, connectable);
    if (connectable > 0 && merges() && stored_ > 0) merge(p, connectable);
  }
}

void Bidirectional::trace_chunk(const RenderSettings& settings, uint32_t sample, uint32_t first, uint32_t count) {
  GdrPtParams p = in_.device_scene.path_params(settings, sample, first, count);
  bool light = light_subpaths_allowed(settings.max_depth) && p.light_count > 0;
  options_ = pass_options(sample, count);
  if (!lt()) {
    p.max_depth = bdpt_segments(settings.max_depth);
    stored_bound_ = 0;
    stored_ = 0;
    if (light) trace_light_subpaths(p);
    if (merges() && stored_ > 0) build_grid(p);
    trace_camera_subpaths(p);
  } else {
    if (p.max_depth != 0) trace_direct(p);
    if (light) trace_light_subpaths(p);
  }
  counters_.report(in_.context.stats());
}

RenderResult Bidirectional::render(const RenderSettings& settings) {
  if (!lt() && bdpt_segments(settings.max_depth) != settings.max_depth) {
    log::warn("bdpt, pm and vcm render paths of at most ", kBdptMaxSegments, " segments (max_depth ", settings.max_depth,
              " asked for more): the light-vertex store's bound");
  }
  return render_radiance(in_.context, settings, film_, aux_, capacity_, [&](uint32_t sample, uint32_t first, uint32_t count) {
    trace_chunk(settings, sample, first, count);
  });
}

}  // namespace gdr
