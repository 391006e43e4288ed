#include "render/manifold_walks.h"

#include "render/wavefront/ray_queues.h"
#include "stats/stats.h"
#include "util/error.h"

namespace gdr {

// The walks' layouts, shared with the kernels (4-byte members only, so both sides agree).
static_assert(sizeof(GdrManifoldPoint) == 12, "GdrManifoldPoint layout changed");
static_assert(sizeof(GdrManifoldVertex) == 32, "GdrManifoldVertex layout changed");
static_assert(sizeof(GdrManifoldWalk) == 48 + 32 * MANIFOLD_MAX_CHAIN, "GdrManifoldWalk layout changed");
static_assert(sizeof(GdrManifoldResult) == 24 + 12 * MANIFOLD_MAX_CHAIN, "GdrManifoldResult layout changed");
static_assert(sizeof(GdrManifoldParams) == 16, "GdrManifoldParams layout changed");

const std::vector<std::string> kManifoldParams = {"manifold_iterations", "manifold_tolerance", "manifold_precision"};

ManifoldSettings manifold_settings(const IntegratorParams& params, int default_iterations) {
  ManifoldSettings s;
  float iterations = params.non_negative("manifold_iterations", float(default_iterations));
  if (!(iterations >= 1.0f) || iterations != float(int(iterations)) || iterations > 1000.0f) {
    throw Error("integrator parameter manifold_iterations: must be a whole number in [1, 1000]");
  }
  s.max_iterations = int(iterations);
  s.tolerance = params.non_negative("manifold_tolerance", s.tolerance);
  if (!(s.tolerance > 0.0f) || s.tolerance > 0.1f) {
    throw Error("integrator parameter manifold_tolerance: must lie in (0, 0.1]");
  }
  s.precision = params.choice("manifold_precision", s.precision, {"auto", "float", "double"});
  return s;
}

bool manifold_uses_fp64(const DeviceInfo& device, const ManifoldSettings& settings) {
  if (settings.precision == "float") return false;
  if (settings.precision == "double" && !device.fp64) {
    throw DeviceError("--manifold-precision double: device '" + device.name + "' has no cl_khr_fp64");
  }
  return device.fp64;
}

Defines manifold_defines(const DeviceInfo& device, const ManifoldSettings& settings) {
  Defines d{{"GDR_MANIFOLD", "1"}};
  if (manifold_uses_fp64(device, settings)) d["GDR_MANIFOLD_FP64"] = "1";
  return d;
}

std::string manifold_description(const Scene& scene, const DeviceInfo& device, const ManifoldSettings& settings) {
  if (!scene.features.specular_chains()) {
    return "manifold walks: off (no specular chains: nothing of the manifold shift is compiled, and --shift manifold "
           "is the hybrid shift)";
  }
  std::string precision = settings.precision == "float" ? "float (asked for)"
                          : device.fp64                 ? "double (the device has cl_khr_fp64)"
                                                        : "float (the device has no cl_khr_fp64)";
  return "manifold walks: on for gpt --shift manifold (specular chains), solved in " + precision +
         ", at most " + std::to_string(MANIFOLD_MAX_CHAIN) + " specular vertices per chain";
}

ManifoldWalks::ManifoldWalks(const RenderInputs& in, const KernelFactory& kernels, const std::string& program,
                             size_t capacity, const ManifoldSettings& settings)
    : in_(in),
      capacity_(capacity),
      begin_(kernels.make(program, "manifold_begin")),
      propose_(kernels.make(program, "manifold_propose")),
      retrace_(kernels.make(program, "manifold_retrace")),
      accept_(kernels.make(program, "manifold_accept")),
      states_(in.context, capacity * MANIFOLD_STATE_WORDS),
      active_{Buffer<cl_uint>(in.context, capacity), Buffer<cl_uint>(in.context, capacity)},
      rays_{Buffer<GdrRayHit>(in.context, capacity, ray_queue_flags(in.context)),
            Buffer<GdrRayHit>(in.context, capacity, ray_queue_flags(in.context))},
      counters_(in.context, GDR_COUNTER_NAMES(MANIFOLD_COUNTERS)) {
  params_.tolerance = float(settings.tolerance * in.scene.bounding_radius());
  params_.max_iterations = settings.max_iterations;
  params_.reverse_tolerance = params_.tolerance * settings.reverse_factor;
  params_.ray_epsilon = float(1e-5 * in.scene.bounding_radius());
}

void ManifoldWalks::solve(const Buffer<GdrManifoldWalk>& walks, cl_uint count, Buffer<GdrManifoldResult>& results,
                          const GdrPtParams& scene) {
  if (count == 0) return;
  if (count > capacity_) throw Error("manifold walks: " + std::to_string(count) + " walks exceed the stage's capacity");
  ScopedTimer timer(in_.context.stats(), "render/manifold");
  // Each round is several launches and counter fills: queued without a wait each, the host waits
  // only at the counter reads (also where the caller's pass does not defer).
  DeferredTiming deferred(in_.context);
  counters_.reset();
  begin_.args(count, states_, cl_uint(capacity_), results, active_[0], counters_.buffer()).run(count);
  counters_.read();
  cl_uint active = count;
  for (int cur = 0; active > 0; cur = 1 - cur) {
    counters_.reset();
    propose_
        .args(params_, active, active_[cur], walks, states_, cl_uint(capacity_), results, rays_[0],
              counters_.buffer(), scene, in_.device_scene)
        .run(active);
    cl_uint rays = counters_.read()[MANIFOLD_COUNTER_TRACING];
    // One round per chain segment: at most MANIFOLD_MAX_CHAIN + 1.
    for (int round = 0; rays > 0 && round <= MANIFOLD_MAX_CHAIN; ++round) {
      Buffer<GdrRayHit>& in = rays_[round % 2];
      intersect(in_.embree, in, rays, false, "manifold");
      counters_.reset();
      retrace_
          .args(params_, rays, in, rays_[1 - round % 2], walks, states_, cl_uint(capacity_), counters_.buffer(),
                scene, in_.device_scene)
          .run(rays);
      rays = counters_.read()[MANIFOLD_COUNTER_TRACING];
    }
    counters_.reset();
    accept_
        .args(params_, active, active_[cur], active_[1 - cur], walks, states_, cl_uint(capacity_), results,
              counters_.buffer(), scene, in_.device_scene)
        .run(active);
    active = counters_.read()[MANIFOLD_COUNTER_ACTIVE];
  }
}

}  // namespace gdr
