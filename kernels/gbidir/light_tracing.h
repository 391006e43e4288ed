// G-BDPT's light tracing (t = 1) with gradients (Manzi et al. 2015: light-tracing paths shifted
// from their splat pixel). A light subpath's vertex x1 seen by the camera at film position r
// (bidir/bidir.cl splats it, under bdpt's or vcm's weight w_lt over every strategy) is path x; its
// offset y for neighbour k is the light path with x1 replaced by y1, the first hit of the camera
// ray through r + d_k, reconnected to x1's parent p (the vertex before it: a rough light vertex,
// the light point, or a light at infinity). Where x1's parent is a delta vertex, under the manifold
// shift (GDR_MANIFOLD, the light subpaths keeping their delta vertices' points), y1 is joined
// instead to the last rough light vertex by a manifold walk that moves the chain between, as G-PM's
// manifold photon shift does (photon_chain.h: throughput, density and light-side sums), the walk's
// own tracing standing for the shadow ray. Other paths whose parent is a delta vertex (no chain: a
// point or spot light before it, or a chain too long) have no offsets, nor has any path they could
// be shifted from (the shift keeps the parent and the chain's length): they join the layer kept
// out of the gradients, as the emission seen directly. The light prefix up to p is the base's, so
// (photon_shift.h's re-aimed segment)
//   f(y)/p(x) = beta(x1) F(p -> y1)/F(p -> x1) G(p, y1)/G(p, x1),
// and the film shift has unit Jacobian on the film, so in surface area
//   |J| = dA(y1)/dA(x1) = pc(x1) / pc(y1),   pc: the camera's area density at the vertex,
// the offset's splat value being f(y)|J|/p(x) times y's own light-tracing weight w_lt(y) (its
// light-side sums re-aimed as G-VCM's offset photons' are). Light tracing's share of every path
// is one layer of the image on its own (the shifted strategies share the rest: weights.h), in
// which base and offset split by the pair weight 1 / (1 + R), R = p(y)|J| / p(x) (the re-aimed
// segment's density ratio times |J|), both directions of the pair (y, shifted by -d_k, gives x
// back: x1 is the first hit of its camera ray). An offset whose segment to the parent is blocked,
// or that could not exist (outside the film, escaped, delta, nothing sent toward it), leaves the
// base weight 1, as does a pixel whose neighbour is outside the image.
//
// Per light bounce, after the camera connections' shadow rays:
//   gbdpt_lt_offset_rays     the offsets' camera rays (pairs zeroed; GBDPT_LT_UNSHIFTED marks an
//                            unshifted delta parent's);
//   gbdpt_lt_offset_walks    (GDR_MANIFOLD) after Embree: the walk of each offset whose parent is
//                            a delta vertex (walk_of[ray], or GPM_NO_WALK), which the host's
//                            manifold stage solves;
//   gbdpt_lt_offset_eval     each offset's value and R into pairs[4 i + k], and the shadow ray
//                            from y1 to the parent (none after a walk);
//   gbdpt_lt_offset_blocked  zeroes the pairs whose ray was blocked;
//   gbdpt_lt_gather          base and offsets into the pass's layers (the accumulators' BASE and
//                            OFFSET slots, or DIRECT, whole image), rows owned as the splat film's
//                            gather;
// and at the end of the pass gbdpt_add_light_tracing adds the layers into the accumulators.
#pragma once
#include "bidir/camera_connection.h"
#include "bidir/subpath_mis.h"
#include "camera/importance.h"
#include "gbidir/photon_shift.h"
#include "gradient/neighbours.h"
#include "path/camera_sample.h"
#include "path/scene.h"
#include "path/shadow.h"
#include "shared/gbidir_types.h"
#include "shared/gpt_types.h"
#include "shared/splat_types.h"
#include "wavefront/counter_shard.h"
#include "wavefront/group_reserve.h"
// As in merge.h: the manifold headers wherever the program has GDR_MANIFOLD.
#if defined(GDR_MANIFOLD)
#include "gbidir/photon_chain.h"
#endif

// Light vertex x, seen by the camera from light subpath i (`seen`, after the bounce that reached
// it), as a store entry: its own, or the one after the last where it was not stored; the vertex
// before it is the entry's parent.
inline uint lt_entry(const GdrBidirVertex* x, uint i, uint stride, __global const GdrBidirPathState* light_paths,
                     __global const GdrBidirVertex* store) {
  int j = light_paths[i].stored;
  if (j > 0 && store[(uint)(j - 1) * stride + i].depth == x->depth) j -= 1;
  return (uint)j * stride + i;
}

inline PhotonParent lt_parent(const SceneData* s, const GdrBidirVertex* x, uint i, uint stride,
                              __global const GdrBidirPathState* light_paths, __global const GdrBidirVertex* store,
                              __global const GdrLightOrigin* origins) {
  return photon_parent(s, store, origins, stride, lt_entry(x, i, stride, light_paths, store), x);
}

#if defined(GDR_MANIFOLD)
// Whether light vertex x (parent a delta vertex) has a chain the manifold shift walks (*ch).
inline int lt_chain(const SceneData* s, const GdrBidirVertex* x, uint i, uint stride,
                    __global const GdrBidirPathState* light_paths, __global const GdrBidirVertex* store,
                    __global const GdrLightOrigin* origins, __global const GdrManifoldPoint* delta_points,
                    uint delta_depths, PhotonChain* ch) {
  int reason;
  return photon_chain(s, store, origins, delta_points, delta_depths, stride,
                      lt_entry(x, i, stride, light_paths, store), x, ch, &reason);
}
#endif

// Splat slot i's offsets: the camera rays through the neighbours' film positions (traced[k],
// rs[k]; *n of them).
__attribute__((always_inline)) inline void gbdpt_lt_offset_rays_of(
    GdrGptParams params, uint i, uint stride, __global const GdrCamera* camera, __global const GdrSplat* splats,
    __global const GdrBidirVertex* seen, __global const GdrBidirPathState* light_paths,
    __global const GdrBidirVertex* store, __global const GdrLightOrigin* origins,
    __global const GdrManifoldPoint* delta_points, uint delta_depths, __global float4* pairs, __global uint* stats,
    CameraRay* rs, int* traced, uint* n, SCENE_DATA_ARGS) {
  for (int k = 0; k < GPT_OFFSETS; ++k) pairs[i * GPT_OFFSETS + k] = (float4)(0.0f);
  if (!splats[i].valid) return;
  SceneData s = path_scene(&params.path, SCENE_DATA_NAMES);
  GdrBidirVertex x = seen[i];
  if (lt_parent(&s, &x, i, stride, light_paths, store, origins).kind == GPM_PARENT_NONE) {
    int walks = 0;
#if defined(GDR_MANIFOLD)
    PhotonChain ch;
    walks = lt_chain(&s, &x, i, stride, light_paths, store, origins, delta_points, delta_depths, &ch);
#endif
    if (!walks) {
      // No offset of this path, nor of any it could be shifted from, exists.
      pairs[i * GPT_OFFSETS].w = GBDPT_LT_UNSHIFTED;
      atomic_inc(&stats[GPT_COUNTER_FAIL_PHOTON_PARENT]);
      return;
    }
  }
  GdrCamera cam = *camera;
  float2 r = (float2)(splats[i].raster[0], splats[i].raster[1]);
  for (int k = 0; k < GPT_OFFSETS; ++k) {
    float2 r2 = r + (float2)(OFFSET_PIXEL_DX(k), OFFSET_PIXEL_DY(k));
    traced[k] = camera_raster_inside(&cam, r2);
    if (traced[k]) camera_ray(&cam, r2.x, r2.y, &rs[k].o, &rs[k].d, &rs[k].tnear, &rs[k].tfar);
    *n += (uint)traced[k];
  }
  if (*n < GPT_OFFSETS) atomic_add(&stats[GPT_COUNTER_FAIL_OUTSIDE], GPT_OFFSETS - *n);
}

// Each work-group appends its slots' offset rays together (group_reserve).
__kernel void gbdpt_lt_offset_rays(GdrGptParams params, uint count, uint stride, __global const GdrCamera* camera,
                                   __global const GdrSplat* splats, __global const GdrBidirVertex* seen,
                                   __global const GdrBidirPathState* light_paths,
                                   __global const GdrBidirVertex* store, __global const GdrLightOrigin* origins,
                                   __global const GdrManifoldPoint* delta_points, uint delta_depths,
                                   __global float4* pairs, __global GdrRayHit* rays, __global uint* counters,
                                   SCENE_DATA_ARGS) {
  __local uint scratch[GROUP_RESERVE_SCRATCH];
  uint i = get_global_id(0);
  CameraRay rs[GPT_OFFSETS];
  int traced[GPT_OFFSETS];
  uint n = 0u;
  for (int k = 0; k < GPT_OFFSETS; ++k) traced[k] = 0;
  if (i < count) {
    gbdpt_lt_offset_rays_of(params, i, stride, camera, splats, seen, light_paths, store, origins, delta_points,
                            delta_depths, pairs, counter_shard(counters), rs, traced, &n, SCENE_DATA_NAMES);
  }
  const uint which[1] = {GPT_COUNTER_LT_OFFSET_RAYS};
  uint slot = n;
  group_reserve(scratch, counters, which, 1, &slot);
  for (int k = 0; k < GPT_OFFSETS; ++k) {
    if (traced[k]) write_camera_ray(&rays[slot++], &rs[k], i * GPT_OFFSETS + (uint)k);
  }
}

// The value (f(y)|J|/p(x) w_lt(y)) and R of offset y1 (surface sy) of light vertex x (surface sx),
// from the shifted light path's throughput phi2 at y1, its density ratio p(y)/p(x) (`ratio`) and
// its direction wo from y1 toward the light side; *yv holds y's light-side sums. 0 where it cannot
// be formed. *yv becomes y1 as the light subpath's vertex (its throughput f/p of the light path up
// to it, wo and the sums; prim, u and v are the caller's).
inline int lt_offset_value(const SceneData* s, const GdrCamera* cam, const GdrBidirOptions* o, const Surface* sx,
                           const Surface* sy, float3 phi2, float ratio, float3 wo, GdrBidirVertex* yv,
                           float3* value, float* r) {
  CameraProjection px, py;
  if (!camera_project(cam, sx->p, &px) || !camera_project(cam, sy->p, &py)) return 0;
  float pc_y = camera_pdf_area(cam, &py, sy->ng);
  float jac = pc_y > 0.0f ? camera_pdf_area(cam, &px, sx->ng) / pc_y : 0.0f;
  vstore3(wo, 0, yv->wo);
  vstore3(ratio > 0.0f ? phi2 / ratio : (float3)(0.0f), 0, yv->throughput);
  Bsdf by = surface_bsdf(s, sy);
  Frame fy = frame_from_normal(sy->ns);
  float scale;
  float3 f = camera_connection(cam, &py, &by, &fy, sy->ng, wo, yv->dvcm, yv->dvc, o, 1, &scale);
  *value = phi2 * f * (scale * jac);
  *r = ratio * jac;
  return max3(*value) > 0.0f && is_finite3(*value) && *r > 0.0f && isfinite(*r);
}

// lt_offset_value for offset y1 of light vertex x whose parent is pa, reconnected to it.
inline int lt_offset(const SceneData* s, const GdrCamera* cam, const GdrBidirOptions* o, const PhotonParent* pa,
                     const GdrBidirVertex* x, const Surface* sx, const Surface* sy, GdrBidirVertex* yv,
                     float3* value, float* r) {
  float3 phi2;
  float ratio;
  float2 pdfs;
  if (!photon_shift_eval(s, pa, sx->p, sx->ng, vload3(0, x->throughput), sy, &phi2, &ratio, &pdfs)) return 0;
  *yv = *x;
  photon_shift_sums(pa, x, sx->p, sx->ng, sy, pdfs, o, &yv->dvcm, &yv->dvc, &yv->dvm);
  return lt_offset_value(s, cam, o, sx, sy, phi2, ratio, photon_toward_parent(pa, sy->p), yv, value, r);
}

#if defined(GDR_MANIFOLD)
// lt_offset_value for offset y1 of light vertex x behind chain ch, which walk R moved to join y1.
inline int lt_offset_walked(const SceneData* s, const GdrCamera* cam, const GdrBidirOptions* o,
                            const PhotonChain* ch, const GdrManifoldResult* R, const GdrBidirVertex* x,
                            const Surface* sx, const Surface* sy, GdrBidirVertex* yv, float3* value, float* r) {
  PhotonChainPoints pts = photon_chain_points(s, ch, R, sx, sy);
  float3 phi2, wo;
  float ratio;
  float2 pdfs;
  if (!photon_chain_eval(s, ch, R, &pts, sx, sy, vload3(0, x->throughput), &phi2, &ratio, &wo, &pdfs)) return 0;
  *yv = *x;
  photon_chain_sums(s, ch, R, &pts, pdfs, x, sx, sy, o, &yv->dvcm, &yv->dvc, &yv->dvm);
  return lt_offset_value(s, cam, o, sx, sy, phi2, ratio, wo, yv, value, r);
}

__kernel void gbdpt_lt_offset_walks(GdrGptParams params, uint count, uint stride, __global const GdrRayHit* rays,
                                    __global const GdrBidirVertex* seen,
                                    __global const GdrBidirPathState* light_paths,
                                    __global const GdrBidirVertex* store, __global const GdrLightOrigin* origins,
                                    __global const GdrManifoldPoint* delta_points, uint delta_depths,
                                    __global uint* walk_of, __global GdrManifoldWalk* walks,
                                    __global uint* counters, SCENE_DATA_ARGS) {
  uint q = get_global_id(0);
  if (q >= count) return;
  walk_of[q] = GPM_NO_WALK;
  GdrRayHit rh = rays[q];
  if (rh.hit.geomID == GDR_INVALID_ID) return;
  SceneData s = path_scene(&params.path, SCENE_DATA_NAMES);
  uint i = rh.ray.id / GPT_OFFSETS;
  GdrBidirVertex x = seen[i];
  PhotonChain ch;
  if (lt_parent(&s, &x, i, stride, light_paths, store, origins).kind != GPM_PARENT_NONE ||
      !lt_chain(&s, &x, i, stride, light_paths, store, origins, delta_points, delta_depths, &ch)) {
    return;
  }
  float3 o = (float3)(rh.ray.org_x, rh.ray.org_y, rh.ray.org_z), d = (float3)(rh.ray.dir_x, rh.ray.dir_y, rh.ray.dir_z);
  GdrManifoldPoint origin = {x.prim, x.u, x.v};
  uint w = atomic_inc(&counters[GPT_COUNTER_MANIFOLD_WALKS]);
  walks[w] = photon_chain_walk(&s, &ch, origin, manifold_refine_hit(&s, rh.hit.primID, o, d), q);
  walk_of[q] = w;
}
#endif

// walk_of, walks, walk_results: gbdpt_lt_offset_walks' and the manifold stage's (unread without
// GDR_MANIFOLD).
__kernel void gbdpt_lt_offset_eval(GdrGptParams params, GdrBidirOptions opts, uint count, uint stride,
                                   __global const GdrCamera* camera, __global const GdrRayHit* rays,
                                   __global const GdrBidirVertex* seen, __global const GdrBidirPathState* light_paths,
                                   __global const GdrBidirVertex* store, __global const GdrLightOrigin* origins,
                                   __global const GdrManifoldPoint* delta_points, uint delta_depths,
                                   __global const uint* walk_of, __global const GdrManifoldWalk* walks,
                                   __global const GdrManifoldResult* walk_results, __global float4* pairs,
                                   __global GdrRay* shadow_rays, __global uint* counters, SCENE_DATA_ARGS) {
  uint q = get_global_id(0);
  if (q >= count) return;
  GdrRayHit rh = rays[q];
  uint id = rh.ray.id, i = id / GPT_OFFSETS;
  write_ray(&shadow_rays[q], (float3)(0.0f), (float3)(0.0f, 0.0f, 1.0f), 1.0f, 0.0f, id);  // skipped unless formed
  if (rh.hit.geomID == GDR_INVALID_ID) {
    atomic_inc(&counter_shard(counters)[GPT_COUNTER_FAIL_ENVIRONMENT]);
    return;
  }
  SceneData s = path_scene(&params.path, SCENE_DATA_NAMES);
  GdrBidirVertex x = seen[i];
  PhotonParent pa = lt_parent(&s, &x, i, stride, light_paths, store, origins);
  GdrCamera cam = *camera;
  Surface sx = surface_at(&s, x.prim, x.u, x.v), sy = surface_at(&s, rh.hit.primID, rh.hit.u, rh.hit.v);
  GdrBidirVertex y;
  float3 v;
  float r;
#if defined(GDR_MANIFOLD)
  if (pa.kind == GPM_PARENT_NONE) {
    // Behind a delta vertex: the walk joined y1 (the walk's own start point) to the chain.
    uint w = walk_of[q];
    PhotonChain ch;
    if (w == GPM_NO_WALK || walk_results[w].status != 0 ||
        !lt_chain(&s, &x, i, stride, light_paths, store, origins, delta_points, delta_depths, &ch)) {
      atomic_inc(&counter_shard(counters)[GPT_COUNTER_FAIL_MANIFOLD]);
      return;
    }
    GdrManifoldResult R = walk_results[w];
    GdrManifoldPoint at = walks[w].start;
    sy = surface_at(&s, at.prim, at.b1, at.b2);
    if (!lt_offset_walked(&s, &cam, &opts, &ch, &R, &x, &sx, &sy, &y, &v, &r)) {
      atomic_inc(&counter_shard(counters)[GPT_COUNTER_FAIL_ZERO]);
      return;
    }
    pairs[id] = (float4)(v, r);  // the walk traced the chain: no shadow ray
    atomic_inc(&counter_shard(counters)[GPT_COUNTER_SHIFT_MANIFOLD]);
    return;
  }
#endif
  if (!lt_offset(&s, &cam, &opts, &pa, &x, &sx, &sy, &y, &v, &r)) {
    atomic_inc(&counter_shard(counters)[GPT_COUNTER_FAIL_ZERO]);
    return;
  }
  pairs[id] = (float4)(v, r);
  if (pa.kind == GPM_PARENT_INFINITE) {
    write_light_ray(&shadow_rays[q], sy.p, sy.ng, pa.wo, INFINITY, id);
  } else {
    write_segment_ray(&shadow_rays[q], sy.p, sy.ng, pa.p, id);
  }
}

__kernel void gbdpt_lt_offset_blocked(uint count, __global const GdrRay* shadow_rays, __global float4* pairs,
                                      __global uint* counters) {
  uint q = get_global_id(0);
  if (q >= count) return;
  GdrRay r = shadow_rays[q];
  if (!(pairs[r.id].w > 0.0f)) return;  // not formed: Embree skipped its ray
  if (shadow_unoccluded(r.tfar)) {
    atomic_inc(&counter_shard(counters)[GPT_COUNTER_LT_OFFSETS]);
  } else {
    pairs[r.id] = (float4)(0.0f);
    atomic_inc(&counter_shard(counters)[GPT_COUNTER_FAIL_OCCLUDED]);
  }
}

// A splat's share of the primal into pixel px's layers, where G-BDPT's primal is its own
// (gbidir/weights.h; the splat's value times its `primal`, and the pixel's filter).
inline void lt_add_own_primal(__global float4* px, float3 c) {
#if defined(GDR_GBDPT_POWER_PRIMAL)
  px[GPT_ACC_PRIMAL] += (float4)(c, 0.0f);
#endif
}

// Whether pixel p of an axis of `size` pixels samples its filter's whole support (filter_range).
inline int lt_axis_uncut(const GdrCamera* cam, int p, int size) {
  float2 range = filter_range(cam, p, size);
  return range.x == -cam->filter_radius && range.y == cam->filter_radius;
}

// Work item y adds to film row y of `layers` the splats of the rows whose footprints reach it (the
// splat film's order: path/splat.h): for pixel P there, BASE(k) gets the base's value times P's
// filter at r and the pair weight (1 where P's neighbour P + d_k is outside the image), OFFSET(k)
// the offset's value times the neighbour's filter at r + d_k and the pair weight (the offset lands
// in the neighbour, as G-PT's offsets: gradient/gather.h).
__kernel void gbdpt_lt_gather(__global const GdrCamera* camera, __global const uint* starts,
                              __global const uint* sorted, __global const GdrSplat* splats,
                              __global const float4* pairs, __global float4* layers) {
  int y = (int)get_global_id(0);
  GdrCamera cam = *camera;
  if (y >= cam.height) return;
  int w = cam.width, h = cam.height;
  float full = camera_filter_full_mass(&cam);
  int reach = (int)ceil(cam.filter_radius) + 1;
  for (int row = max(y - reach, 0); row <= min(y + reach, h - 1); ++row) {
    for (uint n = starts[row], end = starts[row + 1]; n < end; ++n) {
      uint i = sorted[n];
      float2 raster = (float2)(splats[i].raster[0], splats[i].raster[1]);
      int2 lo, hi;
      camera_pixel_footprint(&cam, raster, &lo, &hi);
      if (y < lo.y || y > hi.y) continue;
      float wy = camera_axis_weight_full(&cam, y, h, raster.y, full);
      float3 c = vload3(0, splats[i].value), cp = c * splats[i].primal;
      float4 pr[GPT_OFFSETS];
      for (int k = 0; k < GPT_OFFSETS; ++k) pr[k] = pairs[i * GPT_OFFSETS + k];
      if (pr[0].w == GBDPT_LT_UNSHIFTED) {
        for (int x = lo.x; x <= hi.x; ++x) {
          float hb = wy * camera_axis_weight_full(&cam, x, w, raster.x, full);
          if (!(hb > 0.0f)) continue;
          __global float4* px = &layers[(uint)(y * w + x) * GBDPT_LT_LAYERS];
          px[GPT_ACC_DIRECT] += (float4)(c * hb, 0.0f);
          lt_add_own_primal(px, cp * hb);
        }
        continue;
      }
      // An offset lands in the neighbour at r + d_k: along d_k's axis the neighbour's filter there
      // is this pixel's at r unless the image cuts either's range; across it, the same pixel's.
      float wy_n[GPT_OFFSETS];
      for (int k = 0; k < GPT_OFFSETS; ++k) {
        int dy = OFFSET_PIXEL_DY(k);
        wy_n[k] = dy == 0 || lt_axis_uncut(&cam, y, h) && lt_axis_uncut(&cam, y + dy, h)
                      ? wy
                      : camera_axis_weight_full(&cam, y + dy, h, raster.y + (float)dy, full);
      }
      for (int x = lo.x; x <= hi.x; ++x) {
        float wx = camera_axis_weight_full(&cam, x, w, raster.x, full), hb = wy * wx;
        __global float4* px = &layers[(uint)(y * w + x) * GBDPT_LT_LAYERS];
        if (hb > 0.0f) lt_add_own_primal(px, cp * hb);
        for (int k = 0; k < GPT_OFFSETS; ++k) {
          int dx = OFFSET_PIXEL_DX(k), nx = x + dx, ny = y + OFFSET_PIXEL_DY(k);
          if (nx < 0 || ny < 0 || nx >= w || ny >= h) {
            if (hb > 0.0f) px[GPT_ACC_BASE(k)] += (float4)(c * hb, 0.0f);
            continue;
          }
          float pair = 1.0f / (1.0f + pr[k].w);
          if (hb > 0.0f) px[GPT_ACC_BASE(k)] += (float4)(c * (hb * pair), 0.0f);
          if (!(pr[k].w > 0.0f)) continue;
          float wx_n = dx == 0 || lt_axis_uncut(&cam, x, w) && lt_axis_uncut(&cam, nx, w)
                           ? wx
                           : camera_axis_weight_full(&cam, nx, w, raster.x + (float)dx, full);
          float ho = wx_n * wy_n[k];
          if (ho > 0.0f) px[GPT_ACC_OFFSET(k)] += (float4)(pr[k].xyz * (ho * pair), 0.0f);
        }
      }
    }
  }
}

// The pass's light-tracing layers into the accumulators (before the gather), emptied.
__kernel void gbdpt_add_light_tracing(uint pixels, __global float4* layers, __global float4* acc) {
  uint p = get_global_id(0);
  if (p >= pixels) return;
  for (int l = 0; l < GBDPT_LT_LAYERS; ++l) {
    acc[p * GPT_ACC_COUNT + l] += layers[p * GBDPT_LT_LAYERS + l];
    layers[p * GBDPT_LT_LAYERS + l] = (float4)(0.0f);
  }
}
