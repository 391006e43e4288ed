// Metropolis light transport (`mlt`): primary-sample-space Markov chains (mlt/chains.h) whose
// states feed the bidirectional kernels' paths (kernels/bidir, through the sampler seam), one
// multiplexed strategy a path (bidir/strategies.h). After the bidirectional kernels traced a
// batch of states, mlt_contribution turns what each path found into its contribution record and
// the target f; the Metropolis loop's kernels (mlt/splats.h, path/splat.h) splat and gather them.
#include "bidir/strategies.h"
#include "mlt/splats.h"
#include "mlt/uniform_states.h"
#include "path/camera_sample.h"
#include "path/splat.h"
#include "shared/color.h"
#include "shared/pt_types.h"

// A path's contribution scaled to the image's integral over primary sample space: what its camera
// subpaths found at its film position (t >= 2) over the film positions' density, and what its
// light vertices seen by the camera carry (t = 1) times the light subpaths a pixel would have
// (bidir/subpath_mis.h: one a pixel). mlt_contribution and mlt_image_sample scale alike.
inline float3 mlt_scaled(const GdrCamera* cam, float3 camera_part, float3 light_part) {
  return camera_part * camera_sample_area(cam) + light_part * (float)(cam->width * cam->height);
}

// Chain c's contribution at the state `states` holds, once the bidirectional kernels traced it:
// its strategy (t >= 2) added into values[c], at the film position its camera block gives, or
// (t = 1) wrote its splat slot, where the light vertex projects. Scaled to the image's integral
// over primary sample space (the film position's region for t >= 2, one light subpath a pixel
// for t = 1) and by 1 / the strategy's selection probability, it is stored as its film position
// and its value over f, f being its luminance (0: no contribution). Empties values[c] and the slot.
__kernel void mlt_contribution(__global const GdrCamera* camera, GdrPtParams params, GdrBidirOptions opts,
                               GdrPrimaryLayout layout, __global const float* states, __global float4* values,
                               __global GdrSplat* found, __global GdrSplat* contributions, __global float* f) {
  uint c = get_global_id(0);
  if (c >= layout.chains) return;
  GdrCamera cam = *camera;
  PathSampler ps = path_sampler_bound(params.seed, c, params.sample, states, layout);
  int2 shown = bidir_path_strategy(&opts, &ps, params.max_depth);
  float2 raster;
  float3 value;
  if (shown.y == 1) {
    raster = (float2)(found[c].raster[0], found[c].raster[1]);
    value = mlt_scaled(&cam, (float3)(0.0f), found[c].valid ? vload3(0, found[c].value) : (float3)(0.0f));
  } else {
    raster = camera_primary_raster(&cam, &ps);
    value = mlt_scaled(&cam, values[c].xyz, (float3)(0.0f));
  }
  value *= bidir_selection_count(shown, params.max_depth);
  float y = gdr_luminance(value.x, value.y, value.z);
  int valid = y > 0.0f && isfinite(y) && is_finite3(value);
  GdrSplat out;
  out.raster[0] = raster.x;
  out.raster[1] = raster.y;
  vstore3(valid ? value / y : (float3)(0.0f), 0, out.value);
  out.valid = valid;
  out.primal = 1.0f;
  out.pad0 = 0;
  contributions[c] = out;
  f[c] = valid ? y : 0.0f;
  values[c] = (float4)(0.0f);
  found[c].valid = 0;
}

// One sample of the image's luminance summed over its pixels (the integral of f): the luminance of
// everything path c found with all strategies, MIS-weighted, scaled as mlt_contribution scales
// its camera and light parts. Empties values[c] and light[c].
__kernel void mlt_image_sample(__global const GdrCamera* camera, uint chains, __global float4* values,
                               __global float4* light, __global float* f) {
  uint c = get_global_id(0);
  if (c >= chains) return;
  GdrCamera cam = *camera;
  float3 v = mlt_scaled(&cam, values[c].xyz, light[c].xyz);
  float y = gdr_luminance(v.x, v.y, v.z);
  f[c] = isfinite(y) ? y : 0.0f;
  values[c] = (float4)(0.0f);
  light[c] = (float4)(0.0f);
}
