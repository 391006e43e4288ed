// G-PM's merges (Hua et al. 2017): at each group's visible point (the base's first rough vertex,
// recorded by the shade step: gbidir/camera_vertex.h) the photons within the radius make pm's
// density estimate for the base, and each offset's estimate at its own visible point comes from
// the same photons shifted (gbidir/photon_shift.h). Three launches over the recorded groups:
//   gpm_count        the photons each base merges with (the first GPM_LISTED of them listed for
//                    the later launches, which then need not walk the grid again), and their
//                    number where an offset can take them shifted (the host scans these counts
//                    into starts);
//   gpm_shift_rays   for each of them and each offset, the ray that finds the offset photon
//                    (rays[4 (start + i) + k]), or a ray Embree skips where the shift is refused;
//   gpm_merge        after Embree: base and offset values under the pair weight
//                    1 / (1 + p(y) |J| / p(x)) (both directions of the pair; a failed shift
//                    leaves the base weight 1), into the group's accumulators.
// G-VCM (GDR_GVCM) merges at each rough camera vertex of its groups with the same stage: offsets
// at the base's vertex merge the same photon, and base and offset share G-VCM's weight over every
// strategy of both paths (gbidir/weights.h), the offset photon's light-side sums re-aimed with it
// (photon_shift_sums).
// Where gpm or gvcm walks (GDR_MANIFOLD: --shift manifold), a photon whose parent is a delta
// vertex is shifted by the manifold photon shift (gbidir/photon_chain.h; G-VCM's light-side sums
// recomputed along the new chain, photon_chain_sums): its ray leaves the chain's last vertex, and
// a fourth launch between Embree and gpm_merge,
//   gpm_photon_walks  for each of them that found a photon within the offset's radius, the walk
//                     (walk_of[ray] its index, GPM_NO_WALK for none), which the host's manifold
//                     stage solves before gpm_merge reads them;
//   gpm_photon_reverse_rays  for each solved walk, the segment from its chain's last vertex to
//                     the base photon, which Embree checks: the reverse shift's ray from there
//                     must find the base photon (the reference's visibility check), else the
//                     shift is not invertible.
// All of them take the photons in the same order (bidir/photon_query.h). A slice of the groups at a
// time: [first, first + count) of `connectable`, its rays from starts[first] on (rays past the
// buffer's capacity are not traced: their shifts fail).
#pragma once
#include "bidir/photon_query.h"
#include "gbidir/photon_shift.h"
#include "gbidir/weights.h"
#include "gradient/accumulators.h"
#include "path/film.h"
#include "path/shadow.h"
#include "shared/gbidir_types.h"
#include "shared/gpt_types.h"
#include "shared/manifold_types.h"
#include "shift/delta_lobe.h"
#include "wavefront/counter_shard.h"
// The kernel sources join each header once, whatever the conditions around its #include: a header
// first included under a condition that fails is gone for the rest of the program. So the manifold
// headers come in wherever the program has GDR_MANIFOLD, as gpt/manifold_step.h needs them too.
#if defined(GDR_MANIFOLD)
#include "gbidir/photon_chain.h"
#if defined(GDR_GPM) || defined(GDR_GVCM)
#define GPM_PHOTON_WALKS 1
#endif
#endif

// Whether an offset's merge point is a vertex of its own (the photon is shifted there): G-PM's
// visible points all are; G-VCM's offsets at a glossy vertex of their own too (a merge ends the
// camera subpath there, so no half vector is copied beyond it).
inline int merge_own_point(int state) { return state == GBDPT_OFFSET_OWN || state == GBDPT_OFFSET_GLOSSY; }

// G-VCM's weights of a merge at camera vertex z (BSDF b, frame f, local direction wo_l toward its
// subpath) of a photon arriving from wi: the BSDF's pdfs toward the photon and back (MERGE_PDFS),
// then the "others" from both sides' sums, the photon's y_dvcm and y_dvm and z's without and with
// light tracing's share (z's all_dvcm, all_dvm; MERGE_OTHERS). G-PM merges by one strategy.
#if defined(GDR_GVCM)
inline float2 gvcm_merge_pdfs(const Bsdf* b, const Frame* f, float3 wo_l, float3 wi) {
  float3 wi_l = frame_to_local(f, wi);
  return (float2)(bsdf_pdf(b, wo_l, wi_l), bsdf_pdf(b, wi_l, wo_l));
}
inline float2 gvcm_merge_others(float2 pdfs, float y_dvcm, float y_dvm, const GdrBidirVertex* z, float all_dvcm,
                                float all_dvm, const GdrBidirOptions* o) {
  float light = mis_merge_side(y_dvcm, y_dvm, pdfs.x, o);
  return (float2)(light + mis_merge_side(z->dvcm, z->dvm, pdfs.y, o),
                  light + mis_merge_side(all_dvcm, all_dvm, pdfs.y, o));
}
#define MERGE_PDFS(b, f, wo_l, wi) gvcm_merge_pdfs(b, f, wo_l, wi)
#define MERGE_OTHERS(pdfs, y_dvcm, y_dvm, z, all_dvcm, all_dvm, o) \
  gvcm_merge_others(pdfs, y_dvcm, y_dvm, z, all_dvcm, all_dvm, o)
#else  // fixed arities: NVIDIA's OpenCL compiler refuses variadic macros
#define MERGE_PDFS(b, f, wo_l, wi) ((float2)(0.0f))
#define MERGE_OTHERS(pdfs, y_dvcm, y_dvm, z, all_dvcm, all_dvm, o) ((float2)(0.0f))
#endif

// A photon of light depth `light_depth` merges at a camera vertex `camera_depth` segments from the
// camera where the path's light_depth + camera_depth segments are allowed.
inline int gpm_path_allowed(int max_depth, int light_depth, int camera_depth) {
  return max_depth < 0 || light_depth + camera_depth <= max_depth;
}

// The next photon of query q whose path the depth bound allows (gpm_path_allowed): a camera
// vertex `depth` segments from the camera merges it.
inline int photon_query_next_allowed(PhotonQuery* q, __global const uint* starts, __global const uint* sorted,
                                     __global const float4* points, __global const GdrBidirVertex* store,
                                     int max_depth, int depth, uint* entry) {
  while (photon_query_next(q, starts, sorted, points, entry)) {
    if (gpm_path_allowed(max_depth, store[*entry].depth, depth)) return 1;
  }
  return 0;
}

// The photons group q merges with, in the grid's order: gpm_count's list (lists[q * GPM_LISTED +
// i], listed[q] of them), or, where it holds more than the list, the grid walked again as
// gpm_count walks it (the same photons in the same order). p: the base's vertex, of depth `depth`.
typedef struct MergePhotons {
  PhotonQuery pq;
  __global const uint* list;
  uint n, i;
  int max_depth, depth;
} MergePhotons;

inline MergePhotons merge_photons(uint q, __global const uint* lists, __global const uint* listed, float3 p,
                                  float radius, uint buckets, int max_depth, int depth) {
  MergePhotons m;
  m.list = lists + (size_t)q * GPM_LISTED;
  m.n = listed[q];
  m.i = 0u;
  m.max_depth = max_depth;
  m.depth = depth;
  if (m.n > GPM_LISTED) m.pq = photon_query(p, radius, buckets);
  return m;
}

inline int merge_photons_next(MergePhotons* m, __global const uint* starts, __global const uint* sorted,
                              __global const float4* points, __global const GdrBidirVertex* store, uint* entry) {
  if (m->n <= GPM_LISTED) {
    if (m->i >= m->n) return 0;
    *entry = m->list[m->i++];
    return 1;
  }
  return photon_query_next_allowed(&m->pq, starts, sorted, points, store, m->max_depth, m->depth, entry);
}

__kernel void gpm_count(GdrGptParams params, GdrBidirOptions opts, uint count, __global const uint* connectable,
                        __global const GbdptCameraVertex* records, __global const GdrBidirVertex* store,
                        __global const float4* points, __global const uint* starts, __global const uint* sorted,
                        uint buckets, __global uint* counts, __global uint* lists, __global uint* listed,
                        SCENE_DATA_ARGS) {
  uint q = get_global_id(0);
  if (q == 0) counts[count] = 0;  // the scan's total lands there
  if (q >= count) return;
  __global const GbdptCameraVertex* rec = &records[connectable[q]];
  SceneData s = path_scene(&params.path, SCENE_DATA_NAMES);
  PhotonQuery pq = photon_query(surface_at(&s, rec->base.prim, rec->base.u, rec->base.v).p, opts.radius, buckets);
  __global uint* list = lists + (size_t)q * GPM_LISTED;
  uint n = 0, e;
  while (photon_query_next_allowed(&pq, starts, sorted, points, store, params.path.max_depth, rec->base.depth, &e)) {
    if (n < GPM_LISTED) list[n] = e;
    ++n;
  }
  listed[q] = n;
  // Rays only for the groups with an offset at a merge point of its own: the others' offsets merge
  // the base's photons or none.
  int shifting = 0;
  for (int k = 0; k < GPT_OFFSETS; ++k) shifting |= merge_own_point(rec->state[k]);
  counts[q] = shifting ? n : 0u;
}

__kernel void gpm_shift_rays(GdrGptParams params, GdrBidirOptions opts, uint first, uint count,
                             __global const uint* connectable, __global const GbdptCameraVertex* records,
                             __global const GdrBidirVertex* store, __global const float4* points,
                             __global const uint* starts, __global const uint* sorted, uint buckets,
                             __global const uint* lists, __global const uint* listed,
                             __global const GdrLightOrigin* origins, __global const GdrManifoldPoint* delta_points,
                             uint delta_depths, uint stride, __global const uint* ray_starts,
                             __global GdrRayHit* rays, uint ray_capacity, SCENE_DATA_ARGS) {
  uint q = first + get_global_id(0);
  if (q >= first + count) return;
  SceneData s = path_scene(&params.path, SCENE_DATA_NAMES);
  __global const GbdptCameraVertex* rec = &records[connectable[q]];
  Surface sx = surface_at(&s, rec->base.prim, rec->base.u, rec->base.v);
  Surface so[GPT_OFFSETS];
  int shifting = 0;  // some offset can take a shifted photon
  for (int k = 0; k < GPT_OFFSETS; ++k) {
    if (!merge_own_point(rec->state[k])) continue;
    so[k] = surface_at(&s, rec->offset[k].prim, rec->offset[k].u, rec->offset[k].v);
    shifting = 1;
  }
  if (!shifting) return;  // no rays counted for the group (gpm_count)
  uint r = 4u * (ray_starts[q] - ray_starts[first]), e;
  MergePhotons mp =
      merge_photons(q, lists, listed, sx.p, opts.radius, buckets, params.path.max_depth, rec->base.depth);
  while (merge_photons_next(&mp, starts, sorted, points, store, &e)) {
    GdrBidirVertex y = store[e];
    PhotonParent pa = photon_parent(&s, store, origins, stride, e, &y);
    int chained = 0;
#if defined(GPM_PHOTON_WALKS)
    PhotonChain ch;
    int reason;
    chained = pa.kind == GPM_PARENT_NONE &&
              photon_chain(&s, store, origins, delta_points, delta_depths, stride, e, &y, &ch, &reason);
#endif
    for (int k = 0; k < GPT_OFFSETS && r < ray_capacity; ++k, ++r) {
      float3 target;
      if (merge_own_point(rec->state[k]) && (pa.kind != GPM_PARENT_NONE || chained) &&
          photon_shift_target(sx.p, sx.ns, so[k].p, so[k].ns, points[e].xyz, &target)) {
#if defined(GPM_PHOTON_WALKS)
        if (chained) {
          photon_chain_ray(&s, &rays[r], &ch, target, r);
          continue;
        }
#endif
        photon_shift_ray(&rays[r], &pa, target, r);
      } else {
        photon_no_ray(&rays[r], r);
      }
    }
  }
}

#if defined(GPM_PHOTON_WALKS)
__kernel void gpm_photon_walks(GdrGptParams params, GdrBidirOptions opts, uint first, uint count,
                               __global const uint* connectable, __global const GbdptCameraVertex* records,
                               __global const GdrBidirVertex* store, __global const float4* points,
                               __global const uint* starts, __global const uint* sorted, uint buckets,
                               __global const uint* lists, __global const uint* listed,
                               __global const GdrLightOrigin* origins, __global const GdrManifoldPoint* delta_points,
                               uint delta_depths, uint stride, __global const uint* ray_starts,
                               __global const GdrRayHit* rays, uint ray_capacity, __global uint* walk_of,
                               __global GdrManifoldWalk* walks, __global uint* counters, SCENE_DATA_ARGS) {
  uint q = first + get_global_id(0);
  if (q >= first + count) return;
  SceneData s = path_scene(&params.path, SCENE_DATA_NAMES);
  __global const GbdptCameraVertex* rec = &records[connectable[q]];
  Surface so[GPT_OFFSETS];
  int shifting = 0;
  for (int k = 0; k < GPT_OFFSETS; ++k) {
    if (!merge_own_point(rec->state[k])) continue;
    so[k] = surface_at(&s, rec->offset[k].prim, rec->offset[k].u, rec->offset[k].v);
    shifting = 1;
  }
  if (!shifting) return;
  float r2 = opts.radius * opts.radius;
  uint r = 4u * (ray_starts[q] - ray_starts[first]), e;
  MergePhotons mp = merge_photons(q, lists, listed, surface_at(&s, rec->base.prim, rec->base.u, rec->base.v).p,
                                  opts.radius, buckets, params.path.max_depth, rec->base.depth);
  while (merge_photons_next(&mp, starts, sorted, points, store, &e)) {
    GdrBidirVertex y = store[e];
    PhotonChain ch;
    int reason;
    if (photon_parent(&s, store, origins, stride, e, &y).kind != GPM_PARENT_NONE ||
        !photon_chain(&s, store, origins, delta_points, delta_depths, stride, e, &y, &ch, &reason)) {
      r += GPT_OFFSETS;
      continue;
    }
    for (int k = 0; k < GPT_OFFSETS && r < ray_capacity; ++k, ++r) {
      uint w = GPM_NO_WALK;
      GdrRayHit h = rays[r];
      if (merge_own_point(rec->state[k]) && h.hit.geomID != GDR_INVALID_ID) {
        float3 o = (float3)(h.ray.org_x, h.ray.org_y, h.ray.org_z), d = (float3)(h.ray.dir_x, h.ray.dir_y, h.ray.dir_z);
        GdrManifoldPoint at = manifold_refine_hit(&s, h.hit.primID, o, d);
        float3 d2 = manifold_point_on(&s, at) - so[k].p;
        if (dot(d2, d2) <= r2) {
          // One walk a ray at most: the buffer holds as many walks as rays.
          w = atomic_inc(&counters[GPT_COUNTER_MANIFOLD_WALKS]);
          GdrManifoldPoint origin = {y.prim, y.u, y.v};
          walks[w] = photon_chain_walk(&s, &ch, origin, at, r);
        }
      }
      walk_of[r] = w;
    }
  }
}

__kernel void gpm_photon_reverse_rays(GdrGptParams params, uint count, __global const GdrManifoldWalk* walks,
                                      __global const GdrManifoldResult* results, __global GdrRay* rays,
                                      SCENE_DATA_ARGS) {
  uint i = get_global_id(0);
  if (i >= count) return;
  if (results[i].status != 0) {
    write_ray(&rays[i], (float3)(0.0f), (float3)(0.0f, 0.0f, 1.0f), 1.0f, 0.0f, i);  // skipped: no walk
    return;
  }
  SceneData s = path_scene(&params.path, SCENE_DATA_NAMES);
  GdrManifoldPoint last = results[i].v[0];
  Surface sl = surface_at(&s, last.prim, last.b1, last.b2);
  write_segment_ray(&rays[i], sl.p, sl.ng, manifold_point_on(&s, walks[i].origin), i);
}
#endif

__kernel void gpm_merge(GdrGptParams params, GdrBidirOptions opts, uint first, uint count,
                        __global const uint* connectable, __global const GbdptCameraVertex* records,
                        __global const GptBaseState* bases, __global const GdrBidirVertex* store,
                        __global const float4* points, __global const uint* starts, __global const uint* sorted,
                        uint buckets, __global const uint* lists, __global const uint* listed,
                        __global const GdrLightOrigin* origins,
                        __global const GdrManifoldPoint* delta_points, uint delta_depths, uint stride,
                        __global const uint* ray_starts, __global const GdrRayHit* rays, uint ray_capacity,
                        __global const uint* walk_of, __global const GdrManifoldWalk* walks,
                        __global const GdrManifoldResult* walk_results, __global const GdrRay* reverse_rays,
                        __global float4* acc,
                        __global uint* counters, SCENE_DATA_ARGS) {
  uint q = first + get_global_id(0);
  if (q >= first + count) return;
  SceneData s = path_scene(&params.path, SCENE_DATA_NAMES);
  __global uint* stats = counter_shard(counters);
  __global uint* nonfinite = &stats[GPT_COUNTER_NONFINITE];
  uint g = connectable[q];
  uint pixel = bases[g].path.pixel;
  GbdptCameraVertex rec = records[g];
  Surface sx = surface_at(&s, rec.base.prim, rec.base.u, rec.base.v);
  Bsdf bx = surface_bsdf(&s, &sx);
  Frame fx = frame_from_normal(sx.ns);
  float3 wo_x = frame_to_local(&fx, vload3(0, rec.base.wo));
  float3 beta = vload3(0, rec.base.throughput) * opts.vm_normalization;
#if defined(GDR_GVCM)
  GdrBidirOptions mo = gbdpt_options(&params);
#endif
  // The offsets' merge points: their own visible points (surface, BSDF: none on a delta surface,
  // no estimate there; frame), or the base's point where they share it; each toward its previous
  // vertex.
  Surface so[GPT_OFFSETS];
  Bsdf bo[GPT_OFFSETS];
  Frame fo[GPT_OFFSETS];
  float3 wo_o[GPT_OFFSETS];
  // same[k]: offset k shares the base's point and direction, so its merges are the base's.
  int own[GPT_OFFSETS], shared[GPT_OFFSETS], same[GPT_OFFSETS], opened = 0;
  for (int k = 0; k < GPT_OFFSETS; ++k) {
    own[k] = merge_own_point(rec.state[k]);
    shared[k] = rec.state[k] == GBDPT_OFFSET_SHARED;
    if (shared[k]) {
      so[k] = sx;
      bo[k] = bx;
      fo[k] = fx;
    } else if (own[k]) {
      so[k] = surface_at(&s, rec.offset[k].prim, rec.offset[k].u, rec.offset[k].v);
      bo[k] = surface_bsdf(&s, &so[k]);
      fo[k] = frame_from_normal(so[k].ns);
      if (bsdf_is_delta(&bo[k])) {
        own[k] = 0;
        atomic_inc(&stats[GPT_COUNTER_FAIL_LOBE]);
      }
    }
    if (own[k] || shared[k]) wo_o[k] = frame_to_local(&fo[k], vload3(0, rec.offset[k].wo));
    same[k] = shared[k] && all(wo_o[k] == wo_x);
    opened += own[k];
  }
  float3 sum_base[GPT_OFFSETS], sum_off[GPT_OFFSETS];
  for (int k = 0; k < GPT_OFFSETS; ++k) sum_base[k] = sum_off[k] = (float3)(0.0f);
  // Counted per group, one atomic each at the end (not one per photon on one counter).
  uint r = 4u * (ray_starts[q] - ray_starts[first]), e, merged = 0, orphans = 0, lost = 0, walked = 0, unwalked = 0,
       long_chains = 0, irreversible = 0;
  float r2 = opts.radius * opts.radius;
  MergePhotons mp =
      merge_photons(q, lists, listed, sx.p, opts.radius, buckets, params.path.max_depth, rec.base.depth);
  while (merge_photons_next(&mp, starts, sorted, points, store, &e)) {
    GdrBidirVertex y = store[e];
    uint r0 = r;
    r += GPT_OFFSETS;
    float3 phi = vload3(0, y.throughput), wi = vload3(0, y.wo);
    float3 mv = photon_merge_value(&bx, &fx, sx.ng, wo_x, wi);
    float3 cb = beta * mv * phi;
    if (!(max3(cb) > 0.0f)) continue;
    ++merged;
    float2 pdfs = MERGE_PDFS(&bx, &fx, wo_x, wi);
    float2 ox = MERGE_OTHERS(pdfs, y.dvcm, y.dvm, &rec.base, rec.all_dvcm[0], rec.all_dvm[0], &mo);
    // The photon's parent and surface, where some offset can take it shifted.
    PhotonParent pa;
    pa.kind = GPM_PARENT_NONE;
    Surface sy;
    int chained = 0;
#if defined(GPM_PHOTON_WALKS)
    PhotonChain ch;
#endif
    if (opened) {
      pa = photon_parent(&s, store, origins, stride, e, &y);
      int reason = GPT_COUNTER_FAIL_PHOTON_PARENT;
#if defined(GPM_PHOTON_WALKS)
      chained = pa.kind == GPM_PARENT_NONE &&
                photon_chain(&s, store, origins, delta_points, delta_depths, stride, e, &y, &ch, &reason);
#endif
      if (pa.kind != GPM_PARENT_NONE || chained) sy = surface_at(&s, y.prim, y.u, y.v);
      else if (reason == GPT_COUNTER_FAIL_CHAIN_LONG) long_chains += (uint)opened;
      else orphans += (uint)opened;
    }
    for (int k = 0; k < GPT_OFFSETS; ++k) {
      // The offset's merge: its value co, its pdf ratio to the base's and its "others".
      int formed = 0;
      float3 co = (float3)(0.0f);
      float ratio = 0.0f;
      float2 oy = (float2)(0.0f);
      // A shift tried (1: reconnection from the parent, 2: a manifold walk) and, where it moved
      // the photon to the offset's point, its throughput, density ratio, direction toward its
      // parent's side and (G-VCM) light-side sums.
      int tried = 0, moved = 0;
      float3 phi2 = (float3)(0.0f), wi2 = (float3)(0.0f);
      float photon_ratio = 0.0f, y2_dvcm = 0.0f, y2_dvc = 0.0f, y2_dvm = 0.0f;
      if (shared[k]) {
        // At the base's point: the same photon (and, from the base's direction, the base's BSDF
        // values and pdfs).
        float3 mv_k = same[k] ? mv : photon_merge_value(&bo[k], &fo[k], so[k].ng, wo_o[k], wi);
        co = vload3(0, rec.offset[k].throughput) * opts.vm_normalization * mv_k * phi;
        formed = max3(co) > 0.0f;
        ratio = rec.ratio[k];
        if (formed) {
          float2 pdfs_k = same[k] ? pdfs : MERGE_PDFS(&bo[k], &fo[k], wo_o[k], wi);
          oy = MERGE_OTHERS(pdfs_k, y.dvcm, y.dvm, &rec.offset[k], rec.all_dvcm[1 + k], rec.all_dvm[1 + k], &mo);
        }
      } else if (own[k] && pa.kind != GPM_PARENT_NONE) {
        tried = 1;
        GdrRayHit h;
        h.hit.geomID = GDR_INVALID_ID;
        if (r0 + (uint)k < ray_capacity) h = rays[r0 + (uint)k];
        if (h.hit.geomID != GDR_INVALID_ID) {
          Surface sy2 = surface_at(&s, h.hit.primID, h.hit.u, h.hit.v);
          float3 d = sy2.p - so[k].p;
          float2 parent_pdfs;
          if (dot(d, d) <= r2 &&
              photon_shift_eval(&s, &pa, sy.p, sy.ng, phi, &sy2, &phi2, &photon_ratio, &parent_pdfs)) {
            moved = 1;
            wi2 = photon_toward_parent(&pa, sy2.p);
#if defined(GDR_GVCM)
            photon_shift_sums(&pa, &y, sy.p, sy.ng, &sy2, parent_pdfs, &mo, &y2_dvcm, &y2_dvc, &y2_dvm);
#endif
          }
        }
      }
#if defined(GPM_PHOTON_WALKS)
      else if (own[k] && chained) {
        // The walk gpm_photon_walks started for this ray, if the ray found a photon in the radius.
        uint walk = r0 + (uint)k < ray_capacity ? walk_of[r0 + (uint)k] : GPM_NO_WALK;
        if (walk != GPM_NO_WALK) {
          tried = 2;
          GdrManifoldResult res = walk_results[walk];
          GdrManifoldPoint start = walks[walk].start;
          Surface sy2 = surface_at(&s, start.prim, start.b1, start.b2);
          const int reversible = shadow_unoccluded(reverse_rays[walk].tfar);
          irreversible += res.status == 0 && !reversible;
          if (res.status == 0 && reversible && res.g_walk > 0.0f && res.g_origin > 0.0f) {
            PhotonChainPoints pts = photon_chain_points(&s, &ch, &res, &sy, &sy2);
            float2 chain_pdfs;
            moved = photon_chain_eval(&s, &ch, &res, &pts, &sy, &sy2, phi, &phi2, &photon_ratio, &wi2, &chain_pdfs);
#if defined(GDR_GVCM)
            if (moved) {
              photon_chain_sums(&s, &ch, &res, &pts, chain_pdfs, &y, &sy, &sy2, &mo, &y2_dvcm, &y2_dvc, &y2_dvm);
            }
#endif
          }
        } else {
          lost += 1;
        }
      }
#endif
      if (moved) {
        co = vload3(0, rec.offset[k].throughput) * opts.vm_normalization *
             photon_merge_value(&bo[k], &fo[k], so[k].ng, wo_o[k], wi2) * phi2;
        formed = max3(co) > 0.0f;
        ratio = rec.ratio[k] * photon_ratio;
        if (formed) {
          oy = MERGE_OTHERS(MERGE_PDFS(&bo[k], &fo[k], wo_o[k], wi2), y2_dvcm, y2_dvm, &rec.offset[k],
                            rec.all_dvcm[1 + k], rec.all_dvm[1 + k], &mo);
        }
      }
      lost += tried == 1 && !formed;
      walked += tried == 2 && formed;
      unwalked += tried == 2 && !formed;
      float2 w = gbdpt_pair_weights(ox, oy, ratio, formed);
      sum_base[k] += w.x * cb;
      if (formed) sum_off[k] += w.y * co;
    }
  }
  if (orphans) atomic_add(&stats[GPT_COUNTER_FAIL_PHOTON_PARENT], orphans);
  if (lost) atomic_add(&stats[GPT_COUNTER_FAIL_PHOTON_LOST], lost);
  if (walked) atomic_add(&stats[GPT_COUNTER_SHIFT_MANIFOLD], walked);
  if (unwalked) atomic_add(&stats[GPT_COUNTER_FAIL_MANIFOLD], unwalked);
  if (long_chains) atomic_add(&stats[GPT_COUNTER_FAIL_CHAIN_LONG], long_chains);
  if (irreversible) atomic_add(&stats[GPT_COUNTER_FAIL_NOT_INVERTIBLE], irreversible);
  if (merged == 0) return;
  atomic_add(&stats[GPT_COUNTER_MERGES], merged);
  for (int k = 0; k < GPT_OFFSETS; ++k) {
    acc_add(acc, pixel, GPT_ACC_BASE(k), checked(sum_base[k], nonfinite));
    acc_add(acc, pixel, GPT_ACC_OFFSET(k), checked(sum_off[k], nonfinite));
  }
}
