// G-PM's merges (Hua et al. 2017): at each group's visible point (the base's first rough vertex,
// recorded by the shade step: gbidir/camera_vertex.h) the photons within the radius make pm's
// density estimate for the base, and each offset's estimate at its own visible point comes from
// the same photons shifted (gbidir/photon_shift.h). Three launches over the recorded groups:
//   gpm_count        the photons each base merges with (the host scans the counts into starts);
//   gpm_shift_rays   for each of them and each offset, the ray that finds the offset photon
//                    (rays[4 (start + i) + k]), or a ray Embree skips where the shift is refused;
//   gpm_merge        after Embree: base and offset values under the pair weight
//                    1 / (1 + p(y) |J| / p(x)) (both directions of the pair; a failed shift
//                    leaves the base weight 1), into the group's accumulators.
// All three walk the photons in the same order (bidir/photon_query.h). A slice of the groups at a
// time: [first, first + count) of `connectable`, its rays from starts[first] on (rays past the
// buffer's capacity are not traced: their shifts fail).
#pragma once
#include "bidir/photon_query.h"
#include "gbidir/photon_shift.h"
#include "gradient/accumulators.h"
#include "path/film.h"
#include "shared/gbidir_types.h"
#include "shared/gpt_types.h"

// A photon of light depth `light_depth` merges at a camera vertex `camera_depth` segments from the
// camera where the path's light_depth + camera_depth segments are allowed.
inline int gpm_path_allowed(int max_depth, int light_depth, int camera_depth) {
  return max_depth < 0 || light_depth + camera_depth <= max_depth;
}

__kernel void gpm_count(GdrGptParams params, GdrBidirOptions opts, uint count, __global const uint* connectable,
                        __global const GbdptCameraVertex* records, __global const GdrBidirVertex* store,
                        __global const float4* points, __global const uint* starts, __global const uint* sorted,
                        uint buckets, __global uint* counts, SCENE_DATA_ARGS) {
  uint q = get_global_id(0);
  if (q == 0) counts[count] = 0;  // the scan's total lands there
  if (q >= count) return;
  SceneData s = path_scene(&params.path, SCENE_DATA_NAMES);
  GdrBidirVertex z = records[connectable[q]].base;
  PhotonQuery pq = photon_query(surface_at(&s, z.prim, z.u, z.v).p, opts.radius, buckets);
  uint n = 0, e;
  while (photon_query_next(&pq, starts, sorted, points, &e)) {
    n += gpm_path_allowed(params.path.max_depth, store[e].depth, z.depth) ? 1u : 0u;
  }
  counts[q] = n;
}

__kernel void gpm_shift_rays(GdrGptParams params, GdrBidirOptions opts, uint first, uint count,
                             __global const uint* connectable, __global const GbdptCameraVertex* records,
                             __global const GdrBidirVertex* store, __global const float4* points,
                             __global const uint* starts, __global const uint* sorted, uint buckets,
                             __global const GdrLightOrigin* origins, uint stride, __global const uint* ray_starts,
                             __global GdrRayHit* rays, uint ray_capacity, SCENE_DATA_ARGS) {
  uint q = first + get_global_id(0);
  if (q >= first + count) return;
  SceneData s = path_scene(&params.path, SCENE_DATA_NAMES);
  GbdptCameraVertex rec = records[connectable[q]];
  Surface sx = surface_at(&s, rec.base.prim, rec.base.u, rec.base.v);
  Surface so[GPT_OFFSETS];
  int shifting = 0;  // some offset can take a shifted photon (else no parent is looked up)
  for (int k = 0; k < GPT_OFFSETS; ++k) {
    if (rec.state[k] != GBDPT_OFFSET_OWN) continue;
    so[k] = surface_at(&s, rec.offset[k].prim, rec.offset[k].u, rec.offset[k].v);
    shifting = 1;
  }
  uint r = 4u * (ray_starts[q] - ray_starts[first]), e;
  PhotonQuery pq = photon_query(sx.p, opts.radius, buckets);
  while (photon_query_next(&pq, starts, sorted, points, &e)) {
    GdrBidirVertex y = store[e];
    if (!gpm_path_allowed(params.path.max_depth, y.depth, rec.base.depth)) continue;
    PhotonParent pa;
    pa.kind = GPM_PARENT_NONE;
    if (shifting) pa = photon_parent(&s, store, origins, stride, e, &y);
    for (int k = 0; k < GPT_OFFSETS && r < ray_capacity; ++k, ++r) {
      float3 target;
      if (rec.state[k] == GBDPT_OFFSET_OWN && pa.kind != GPM_PARENT_NONE &&
          photon_shift_target(sx.p, sx.ns, so[k].p, so[k].ns, points[e].xyz, &target)) {
        photon_shift_ray(&rays[r], &pa, target, r);
      } else {
        photon_no_ray(&rays[r], r);
      }
    }
  }
}

__kernel void gpm_merge(GdrGptParams params, GdrBidirOptions opts, uint first, uint count,
                        __global const uint* connectable, __global const GbdptCameraVertex* records,
                        __global const GptBaseState* bases, __global const GdrBidirVertex* store,
                        __global const float4* points, __global const uint* starts, __global const uint* sorted,
                        uint buckets, __global const GdrLightOrigin* origins, uint stride,
                        __global const uint* ray_starts, __global const GdrRayHit* rays, uint ray_capacity,
                        __global float4* acc, __global uint* counters, SCENE_DATA_ARGS) {
  uint q = first + get_global_id(0);
  if (q >= first + count) return;
  SceneData s = path_scene(&params.path, SCENE_DATA_NAMES);
  __global uint* nonfinite = &counters[GPT_COUNTER_NONFINITE];
  uint g = connectable[q];
  uint pixel = bases[g].path.pixel;
  GbdptCameraVertex rec = records[g];
  Surface sx = surface_at(&s, rec.base.prim, rec.base.u, rec.base.v);
  Bsdf bx = surface_bsdf(&s, &sx);
  Frame fx = frame_from_normal(sx.ns);
  float3 wo_x = frame_to_local(&fx, vload3(0, rec.base.wo));
  float3 beta = vload3(0, rec.base.throughput) * opts.vm_normalization;
  // The offsets' visible points: surface, BSDF (none on a delta surface: no estimate there), frame.
  Surface so[GPT_OFFSETS];
  Bsdf bo[GPT_OFFSETS];
  Frame fo[GPT_OFFSETS];
  int open[GPT_OFFSETS], opened = 0;
  for (int k = 0; k < GPT_OFFSETS; ++k) {
    open[k] = rec.state[k] == GBDPT_OFFSET_OWN;
    if (!open[k]) continue;
    so[k] = surface_at(&s, rec.offset[k].prim, rec.offset[k].u, rec.offset[k].v);
    bo[k] = surface_bsdf(&s, &so[k]);
    fo[k] = frame_from_normal(so[k].ns);
    if (bsdf_is_delta(&bo[k])) {
      open[k] = 0;
      atomic_inc(&counters[GPT_COUNTER_FAIL_LOBE]);
    }
    opened += open[k];
  }
  float3 sum_base[GPT_OFFSETS], sum_off[GPT_OFFSETS];
  for (int k = 0; k < GPT_OFFSETS; ++k) sum_base[k] = sum_off[k] = (float3)(0.0f);
  // Counted per group, one atomic each at the end (not one per photon on one counter).
  uint r = 4u * (ray_starts[q] - ray_starts[first]), e, merged = 0, orphans = 0, lost = 0;
  float r2 = opts.radius * opts.radius;
  PhotonQuery pq = photon_query(sx.p, opts.radius, buckets);
  while (photon_query_next(&pq, starts, sorted, points, &e)) {
    GdrBidirVertex y = store[e];
    if (!gpm_path_allowed(params.path.max_depth, y.depth, rec.base.depth)) continue;
    uint r0 = r;
    r += GPT_OFFSETS;
    float3 phi = vload3(0, y.throughput);
    float3 cb = beta * photon_merge_value(&bx, &fx, sx.ng, wo_x, vload3(0, y.wo)) * phi;
    if (!(max3(cb) > 0.0f)) continue;
    ++merged;
    // The photon's parent and surface, where some offset can take it shifted.
    PhotonParent pa;
    pa.kind = GPM_PARENT_NONE;
    Surface sy;
    if (opened) {
      pa = photon_parent(&s, store, origins, stride, e, &y);
      if (pa.kind == GPM_PARENT_NONE) orphans += (uint)opened;
      else sy = surface_at(&s, y.prim, y.u, y.v);
    }
    for (int k = 0; k < GPT_OFFSETS; ++k) {
      float w = 1.0f;
      if (open[k] && pa.kind != GPM_PARENT_NONE) {
        int shifted = 0;
        GdrRayHit h;
        h.hit.geomID = GDR_INVALID_ID;
        if (r0 + (uint)k < ray_capacity) h = rays[r0 + (uint)k];
        if (h.hit.geomID != GDR_INVALID_ID) {
          Surface sy2 = surface_at(&s, h.hit.primID, h.hit.u, h.hit.v);
          float3 d = sy2.p - so[k].p, phi2;
          float ratio;
          if (dot(d, d) <= r2 && photon_shift_eval(&s, &pa, sy.p, sy.ng, phi, &sy2, &phi2, &ratio)) {
            float3 wo_o = frame_to_local(&fo[k], vload3(0, rec.offset[k].wo));
            float3 co = vload3(0, rec.offset[k].throughput) * opts.vm_normalization *
                        photon_merge_value(&bo[k], &fo[k], so[k].ng, wo_o, photon_toward_parent(&pa, sy2.p)) * phi2;
            if (max3(co) > 0.0f) {
              w = 1.0f / (1.0f + rec.ratio[k] * ratio);
              if (!isfinite(w)) w = 1.0f;
              else sum_off[k] += w * co;
              shifted = 1;
            }
          }
        }
        lost += !shifted;
      }
      sum_base[k] += w * cb;
    }
  }
  if (orphans) atomic_add(&counters[GPT_COUNTER_FAIL_PHOTON_PARENT], orphans);
  if (lost) atomic_add(&counters[GPT_COUNTER_FAIL_PHOTON_LOST], lost);
  if (merged == 0) return;
  atomic_add(&counters[GPT_COUNTER_MERGES], merged);
  for (int k = 0; k < GPT_OFFSETS; ++k) {
    acc_add(acc, pixel, GPT_ACC_BASE(k), checked(sum_base[k], nonfinite));
    acc_add(acc, pixel, GPT_ACC_OFFSET(k), checked(sum_off[k], nonfinite));
  }
}
