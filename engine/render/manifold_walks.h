// The manifold solver stage: walks on the specular manifold (kernels/manifold/walk.h) as an
// iterative wavefront. Each iteration proposes a Newton step for every active walk on the
// device, has Embree re-trace the proposed chains one segment per round on the host, accepts or
// rejects the proposals on the device, and drops the converged and failed walks from the active
// list. Compiled into an integrator's program only where the scene has specular chains and the
// integrator asks for the manifold shift (GDR_MANIFOLD); its precision is chosen per device.
//
// Settings (IntegratorParams):
//   manifold_iterations  Newton iterations per walk (20)
//   manifold_tolerance   distance from the target end at which a walk has converged, relative
//                        to the scene's bounding radius (1e-4)
//   manifold_precision   auto (double where the device has cl_khr_fp64) | float | double
#pragma once
#include <string>
#include <vector>

#include "render/integrator.h"
#include "render/integrator_params.h"
#include "render/wavefront/device_counters.h"
#include "render/wavefront/kernel_factory.h"
#include "shared/manifold_types.h"
#include "shared/pt_types.h"

namespace gdr {

struct ManifoldSettings {
  int max_iterations = 20;
  float tolerance = 1e-4f;  // relative to the scene's bounding radius
  std::string precision = "auto";
  // How far the walk back may end from the base chain's vertices, in tolerances: a walk that
  // converges lands within a few; one that found another solution lands far away.
  float reverse_factor = 100.0f;
};
extern const std::vector<std::string> kManifoldParams;
// `default_iterations`: where manifold_iterations is not given.
ManifoldSettings manifold_settings(const IntegratorParams& params, int default_iterations = 20);

// Whether the solve runs in double on `device` (throws DeviceError for "double" on a device
// without cl_khr_fp64).
bool manifold_uses_fp64(const DeviceInfo& device, const ManifoldSettings& settings);
// The defines that compile the stage into a program: GDR_MANIFOLD, and GDR_MANIFOLD_FP64.
Defines manifold_defines(const DeviceInfo& device, const ManifoldSettings& settings);
// Whether the scene calls for manifold walks (it has specular chains) and in which precision they
// would run on `device`, as one line for the log and --info.
std::string manifold_description(const Scene& scene, const DeviceInfo& device, const ManifoldSettings& settings);

class ManifoldWalks {
 public:
  // `kernels` builds `program`, which includes manifold/walk.h under manifold_defines(). At most
  // `capacity` walks per solve.
  ManifoldWalks(const RenderInputs& inputs, const KernelFactory& kernels, const std::string& program,
                size_t capacity, const ManifoldSettings& settings);

  // Solves walks[0, count) into results[0, count). `scene`: the launch's scene view.
  void solve(const Buffer<GdrManifoldWalk>& walks, cl_uint count, Buffer<GdrManifoldResult>& results,
             const GdrPtParams& scene);
  size_t capacity() const { return capacity_; }
  // Adds the walks' counters (outcomes by reason, iterations, rays) to the stats.
  void report(Stats* stats) { counters_.report(stats); }

 private:
  RenderInputs in_;
  size_t capacity_;
  GdrManifoldParams params_{};
  Kernel begin_, propose_, retrace_, accept_;
  Buffer<cl_uint> states_;  // MANIFOLD_STATE_WORDS fields of `capacity_` walks each
  Buffer<cl_uint> active_[2];
  Buffer<GdrRayHit> rays_[2];
  DeviceCounters counters_;
};

}  // namespace gdr
