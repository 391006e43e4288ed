// Gradient-domain Metropolis light transport (`gmlt`, after Lehtinen et al. 2013): primary-sample-
// space Markov chains (mlt/chains.h) whose states feed G-PT's groups (kernels/gpt through the
// sampler seam): a base path from the chain's film position and its four offsets one pixel away
// by the shift mapping, weighted between the forward and the backward shift by G-PT's MIS. After
// the groups of a batch of states were traced, gmlt_contribution turns each group's sums into its
// contribution records and the target; the Metropolis loop's kernels (mlt/splats.h,
// path/splat.h) splat and gather them.
#include "camera/importance.h"
#include "gradient/neighbours.h"
#include "mlt/splats.h"
#include "mlt/uniform_states.h"
#include "path/camera_sample.h"
#include "path/splat.h"
#include "shared/color.h"
#include "shared/gpt_types.h"

// The records of a chain (record r of chain c at r * chains + c), each gathered into its layer.
#define GMLT_PRIMAL_BASE 0       // primal: the base's shares, at the film position x
#define GMLT_PRIMAL_OFFSET(k) (1 + (k))  // primal: offset k's share, at x + e_k
#define GMLT_DX_FORWARD 5        // dx: offset +x minus base, the pair (x, x + e_x), at x
#define GMLT_DX_BACKWARD 6       // dx: base minus offset -x, the pair (x - e_x, x), at x - e_x
#define GMLT_DY_FORWARD 7
#define GMLT_DY_BACKWARD 8
#define GMLT_DIRECT 9            // emission seen directly from the camera, at x
#define GMLT_RECORDS 10

inline float gmlt_magnitude(float3 c) { return gdr_luminance(fabs(c.x), fabs(c.y), fabs(c.z)); }

inline void gmlt_record(__global GdrSplat* records, uint chains, uint c, int r, float2 raster, float3 value,
                        int valid) {
  GdrSplat s;
  s.raster[0] = raster.x;
  s.raster[1] = raster.y;
  vstore3(valid ? value : (float3)(0.0f), 0, s.value);
  s.valid = valid && (value.x != 0.0f || value.y != 0.0f || value.z != 0.0f);
  s.primal = 1.0f;
  s.pad0 = 0;
  records[(size_t)r * chains + c] = s;
}

// Chain c's records and target from its group's sums acc[c] (GPT_ACC_*), every value scaled to
// the image's integral over primary sample space (the film position's region). A pixel pair's
// difference estimated from this base is the offset's share minus the base's (G-PT's MIS between
// the pair's two shifts is already in them); a pair with a pixel outside the sampled region does
// not exist. The target: the four differences' magnitudes plus alpha times a quarter of the
// primal's (Lehtinen et al.'s form), so that a state whose differences vanish still has f > 0
// where it adds to the coarse image. Records hold value / f. read[c]: the dimensions the group
// read at most, the camera blocks up to the BSDF block of the depth its base path ended at.
__kernel void gmlt_contribution(__global const GdrCamera* camera, GdrGptParams params, GdrPrimaryLayout layout,
                                float alpha, __global const float* states, __global const float4* acc,
                                __global const GptBaseState* bases, __global GdrSplat* records, __global float* f,
                                __global uint* read) {
  uint c = get_global_id(0);
  if (c >= layout.chains) return;
  read[c] = 4u * min(layout.blocks, RNG_BLOCK_BSDF(bases[c].path.depth) + 1u);
  GdrCamera cam = *camera;
  PathSampler ps = path_sampler_bound(params.path.seed, c, params.path.sample, states, layout);
  float2 x = camera_primary_raster(&cam, &ps);
  float scale = camera_sample_area(&cam);
  __global const float4* a = &acc[(size_t)c * GPT_ACC_COUNT];
  float3 base[GPT_OFFSETS], off[GPT_OFFSETS], delta[GPT_OFFSETS];
  float2 at[GPT_OFFSETS];
  int inside[GPT_OFFSETS];
  float3 direct = (a[GPT_ACC_DIRECT].xyz + a[GPT_ACC_SEEN].xyz) * scale;
  float3 primal = direct;
  float target = 0.0f;
  for (int k = 0; k < GPT_OFFSETS; ++k) {
    base[k] = a[GPT_ACC_BASE(k)].xyz * scale;
    off[k] = a[GPT_ACC_OFFSET(k)].xyz * scale;
    delta[k] = off[k] - base[k];
    at[k] = x + (float2)(OFFSET_PIXEL_DX(k), OFFSET_PIXEL_DY(k));
    inside[k] = camera_raster_inside(&cam, at[k]);
    primal += 0.25f * (base[k] + off[k]);
    if (inside[k]) target += gmlt_magnitude(delta[k]);
  }
  target += alpha * 0.25f * gmlt_magnitude(primal);
  int valid = target > 0.0f && isfinite(target);
  float inv = valid ? 1.0f / target : 0.0f;
  f[c] = valid ? target : 0.0f;
  float3 shares = 0.25f * (base[0] + base[1] + base[2] + base[3]);
  gmlt_record(records, layout.chains, c, GMLT_PRIMAL_BASE, x, shares * inv, valid);
  for (int k = 0; k < GPT_OFFSETS; ++k) {
    gmlt_record(records, layout.chains, c, GMLT_PRIMAL_OFFSET(k), at[k], 0.25f * off[k] * inv, valid && inside[k]);
  }
  gmlt_record(records, layout.chains, c, GMLT_DX_FORWARD, x, delta[GPT_DIR_PX] * inv, valid && inside[GPT_DIR_PX]);
  gmlt_record(records, layout.chains, c, GMLT_DX_BACKWARD, at[GPT_DIR_NX], -delta[GPT_DIR_NX] * inv,
              valid && inside[GPT_DIR_NX]);
  gmlt_record(records, layout.chains, c, GMLT_DY_FORWARD, x, delta[GPT_DIR_PY] * inv, valid && inside[GPT_DIR_PY]);
  gmlt_record(records, layout.chains, c, GMLT_DY_BACKWARD, at[GPT_DIR_NY], -delta[GPT_DIR_NY] * inv,
              valid && inside[GPT_DIR_NY]);
  gmlt_record(records, layout.chains, c, GMLT_DIRECT, x, direct * inv, valid);
}
