// The bidirectional integrator: light tracing (`lt`), bidirectional path tracing (`bdpt`),
// progressive photon mapping (`pm`) and vertex connection and merging (`vcm`) as one algorithm,
// SmallVCM's (src/vertexcm.hxx), with the host tracing every ray with Embree between the kernels.
//
// Light subpaths start at the lights (emission sampling) and scatter by importance transport;
// every vertex on a non-delta surface is connected to the camera and splatted (t = 1; not by
// pm), and but for lt also kept in the light-vertex store. lt adds the emission the camera sees
// directly with one camera ray per pixel (a light subpath cannot reach the pinhole by itself).
// The others trace a camera subpath per pixel instead, whose vertices add what they find
// emitting (s = 0); under bdpt and vcm each rough vertex connects to a light point (s = 1) and to
// each stored vertex of its pixel's light subpath (s >= 2); under pm and vcm it merges with the
// stored vertices of every light subpath of the chunk within the radius (pm: at the first rough
// vertex only, where the subpath ends). bdpt and vcm weight every strategy by MIS from the
// running sums of bidir/subpath_mis.h.
//
// Path lengths follow Mitsuba's max_depth (segments): a strategy with s light and t camera
// vertices makes a path of s + t - 1 segments; emission seen directly is one segment; a merge of
// light vertex k bounces from its light at camera vertex t segments from the camera, k + t.
#include "camera/importance.h"
#include "light/emission.h"
#include "path/aux.h"
#include "path/camera_sample.h"
#include "path/continuation.h"
#include "path/emission.h"
#include "path/film.h"
#include "path/scene.h"
#include "path/seen_emission.h"
#include "path/shadow.h"
#include "path/spawn.h"
#include "path/nee.h"
#include "path/splat.h"
#include "bidir/append.h"
#include "bidir/camera_connection.h"
#include "bidir/connection.h"
#include "bidir/photon_query.h"
#include "bidir/strategies.h"
#include "bidir/subpath_mis.h"
#include "shared/bidir_types.h"
#include "shared/manifold_types.h"
#include "shared/ray_types.h"
#include "wavefront/counter_shard.h"
#include "wavefront/group_reserve.h"

// Mitsuba's max_depth allows `segments` path segments (< 0: unbounded).
inline int segments_allowed(int max_depth, int segments) { return max_depth < 0 || segments <= max_depth; }

// A subpath's vertex as kept for connections and merges: its hit, the direction back along its
// subpath, its throughput and MIS sums, its depth.
inline GdrBidirVertex bidir_vertex(const GdrHit* hit, float3 wo, float3 beta, const GdrBidirPathState* st, int depth) {
  GdrBidirVertex v;
  v.prim = hit->primID;
  v.u = hit->u;
  v.v = hit->v;
  vstore3(wo, 0, v.wo);
  vstore3(beta, 0, v.throughput);
  v.dvcm = st->dvcm;
  v.dvc = st->dvc;
  v.dvm = st->dvm;
  v.power_dvcm = st->power_dvcm;
  v.power_dvc = st->power_dvc;
  v.depth = depth;
  return v;
}

// Continues subpath *st (in `slot`) from surface su by BSDF sampling in `mode` (block `block` of
// its numbers, Russian roulette after rr_depth), updating its MIS sums; its ray is appended to the
// next queue (*out). The state is written back whether it continues or not (a light subpath's
// stored count must survive its end).
inline void bidir_continue(GdrBidirPathState* st, const GdrBidirOptions* o, const PathSampler* ps, uint block,
                           int rr_depth, int mode, const Bsdf* b, const Frame* frame, const Surface* su,
                           float3 wo_local, float3 beta, uint slot, __global GdrBidirPathState* paths,
                           __global uint* stats, BidirAppend* out) {
  BsdfSample bs;
  float3 wi;
  float rr;
  int next = path_continue_transport(st->depth, ps, block, rr_depth, st->rr_scale, mode, b, frame, su->ng, wo_local,
                                     &beta, &bs, &wi, &rr);
  if (next == PATH_ENDS_NONFINITE) atomic_inc(&stats[BIDIR_COUNTER_NONFINITE]);
  if (next == PATH_CONTINUES) {
    mis_scatter(&bs, bsdf_pdf(b, bs.wi, wo_local), fabs(dot(su->ng, wi)), o, st);
    st->depth += 1;
    vstore3(beta, 0, st->throughput);
  }
  paths[slot] = *st;
  if (next != PATH_CONTINUES) return;
  out->next = 1u;
  out->next_p = su->p;
  out->next_ng = su->ng;
  out->next_wi = wi;
}

// Light subpaths [first_pixel, first_pixel + pixel_count) of the pass leave their lights: the
// emission sample, the first throughput and MIS sums, where each left (origins), and the ray into
// queue 0 (compacted).
// Subpath i's emission; *o, *d: its ray (1 if it has one).
__attribute__((always_inline)) inline int bidir_emit_one(GdrPtParams params, GdrBidirOptions opts, uint i,
                                                         __global GdrBidirPathState* paths,
                                                         __global GdrLightOrigin* origins, __global uint* stats,
                                                         float3* o, float3* d, PRIMARY_SAMPLE_ARGS, SCENE_DATA_ARGS) {
  SceneData s = path_scene(&params, SCENE_DATA_NAMES);
  uint index = params.first_pixel + i;
  paths[i].stored = 0;
  origins[i].light = -1;
  PathSampler ps = path_sampler_bound(params.seed, index, params.sample, PRIMARY_SAMPLE_NAMES);
  // Strategies with s < 2 take no light subpath (s = 1 samples its light point from the camera).
  int2 shown = bidir_path_strategy(&opts, &ps, params.max_depth);
  if (shown.x >= 0 && shown.x < 2) return 0;
  float4 ue = sampler_block(&ps, RNG_BLOCK_EMISSION), ud = sampler_block(&ps, RNG_BLOCK_EMISSION_DIR);
  EmissionSample e;
  if (!light_emission_sample(&s, ue.x, ue.yz, ud.xy, &e)) return 0;
  float3 beta = emission_throughput(&e);
  if (!finite_or_count(beta, &stats[BIDIR_COUNTER_NONFINITE]) || !(max3(beta) > 0.0f)) return 0;
  atomic_inc(&stats[BIDIR_COUNTER_SUBPATHS]);
  GdrBidirPathState st;
  vstore3(beta, 0, st.throughput);
  st.rr_scale = max3(beta);
  st.index = index;
  st.sample = params.sample;
  st.depth = 0;
  st.stored = 0;
  bidir_set_strategy(&st, shown);
  mis_light_start(&s, &e, &opts, &st);
  paths[i] = st;
  GdrLightOrigin origin;
  vstore3(e.p, 0, origin.p);
  vstore3(e.n, 0, origin.n);
  origin.light = e.light;
  origin.pad0 = 0;
  origins[i] = origin;
  // Area lights: off the emitting surface; the other lights' points lie on no surface.
  *o = dot(e.n, e.n) > 0.0f ? leaving_origin(e.p, e.n, e.dir) : e.p;
  *d = e.dir;
  return 1;
}

__kernel void bidir_emit(GdrPtParams params, GdrBidirOptions opts, __global GdrRayHit* rays, __global uint* queue,
                         __global GdrBidirPathState* paths, __global GdrLightOrigin* origins, __global uint* counters,
                         PRIMARY_SAMPLE_ARGS, SCENE_DATA_ARGS) {
  __local uint scratch[GROUP_RESERVE_SCRATCH];
  uint i = get_global_id(0);
  float3 o, d;
  int traced = i < params.pixel_count && bidir_emit_one(params, opts, i, paths, origins, counter_shard(counters), &o,
                                                        &d, PRIMARY_SAMPLE_NAMES, SCENE_DATA_NAMES);
  const uint which[1] = {BIDIR_COUNTER_NEXT_RAYS};
  uint k = (uint)traced;
  group_reserve(scratch, counters, which, 1, &k);
  if (!traced) return;
  queue[k] = i;
  write_ray_hit(&rays[k], o, d, 0.0f, INFINITY, i);
}

// A light subpath's new vertex: under bdpt it joins the light-vertex store (vertex j of subpath
// `slot` at store[j * stride + slot]), or, a delta vertex, its point is kept where the caller asks
// (the vertex k bounces from the light at delta_points[(k - 1) * stride + slot], for k up to
// delta_depths: G-PM's manifold photon shift, gbidir/photon_chain.h); its connection to the camera (a splat in the path's slot,
// the vertex it came from in seen[slot] for the gradient integrators' shifts, and a shadow ray
// toward the camera); its continuation by importance transport.
__attribute__((always_inline)) inline void bidir_light_shade_one(
    GdrPtParams params, GdrBidirOptions opts, uint q, uint stride, __global const GdrCamera* camera,
    __global const GdrRayHit* rays_in, __global const uint* queue_in, __global GdrSplat* splats,
    __global GdrBidirVertex* seen, __global GdrBidirPathState* paths, __global GdrBidirVertex* store,
    __global GdrManifoldPoint* delta_points, uint delta_depths, __global uint* stats, BidirAppend* out,
    PRIMARY_SAMPLE_ARGS, SCENE_DATA_ARGS) {
  GdrRayHit rh = rays_in[q];
  if (rh.hit.geomID == GDR_INVALID_ID) return;
  SceneData s = path_scene(&params, SCENE_DATA_NAMES);
  __global uint* nonfinite = &stats[BIDIR_COUNTER_NONFINITE];
  uint slot = queue_in[q];
  out->slot = slot;
  GdrBidirPathState st = paths[slot];
  float3 beta = vload3(0, st.throughput);
  int k = st.depth + 1;  // this vertex's bounces from the light
  float3 wo = -(float3)(rh.ray.dir_x, rh.ray.dir_y, rh.ray.dir_z);
  Surface su = surface_at(&s, rh.hit.primID, rh.hit.u, rh.hit.v);
  Bsdf b = surface_bsdf(&s, &su);
  Frame frame = frame_from_normal(su.ns);
  float3 wo_local = frame_to_local(&frame, wo);
  int connects = bidir_connects(&opts);

  // Where the shading normal puts the light-side direction on the other side of the surface, the
  // path ends, as a camera path's sample toward the light does (path/sides.h): lt and pt accept
  // the same paths. The camera-side direction is left to the BSDF, as a camera ray's is.
  if (!sides_agree(wo, su.ng, wo_local.z)) return;
  mis_arrive(rh.ray.tfar, fabs(dot(su.ng, wo)), opts.mis, &st);
  int delta = bsdf_is_delta(&b);
  if (delta && (uint)k <= delta_depths) {
    GdrManifoldPoint at = {rh.hit.primID, rh.hit.u, rh.hit.v};
    delta_points[(uint)(k - 1) * stride + slot] = at;
  }

  // Kept for connections (a camera vertex and the connection make two more segments at least) and
  // for merging (a camera vertex, one more).
  if (!delta && ((connects && segments_allowed(params.max_depth, k + 2)) ||
                 (bidir_merges(&opts) && segments_allowed(params.max_depth, k + 1)))) {
    store[(uint)st.stored * stride + slot] = bidir_vertex(&rh.hit, wo, beta, &st, k);
    st.stored += 1;
    atomic_inc(&stats[BIDIR_COUNTER_LIGHT_VERTICES]);
  }

  // Connection to the camera: beta f (cos / d^2) cos_theta We, spread by the pixels' filters.
  GdrCamera cam = *camera;
  CameraProjection pr;
  if ((connects || opts.technique == BIDIR_LT) && segments_allowed(params.max_depth, k + 1) && !delta &&
      bidir_strategy_shown(&st, k + 1, 1) && camera_project(&cam, su.p, &pr)) {
    float scale;
    float3 f = camera_connection(&cam, &pr, &b, &frame, su.ng, wo, st.dvcm, st.dvc, &opts, connects, &scale);
    float3 c = beta * f * scale;
    if (max3(c) > 0.0f && finite_or_count(c, nonfinite)) {
      splat_write(&splats[slot], pr.raster, c);
      if (opts.power_sums) {  // G-BDPT's primal: the weight under the power heuristic over c's
        GdrBidirOptions po = mis_power_options();
        splats[slot].primal =
            camera_connection_weight(&cam, &pr, &b, &frame, su.ng, wo, st.power_dvcm, st.power_dvc, &po) /
            camera_connection_weight(&cam, &pr, &b, &frame, su.ng, wo, st.dvcm, st.dvc, &opts);
      }
      seen[slot] = bidir_vertex(&rh.hit, wo, beta, &st, k);
      atomic_inc(&stats[BIDIR_COUNTER_CAMERA_CONNECTIONS]);
      out->shadow = 1u;
      out->shadow_p = su.p;
      out->shadow_ng = su.ng;
      out->shadow_to = camera_position(&cam);
      out->shadow_to_point = 1;
      out->shadow_id = slot;
    }
  }

  // Continuation: the next vertex would make k + 2 segments once connected.
  if (!segments_allowed(params.max_depth, k + 2) || !bidir_light_subpath_grows(&st, k + 1)) {
    paths[slot] = st;
    return;
  }
  PathSampler ps = path_sampler_bound(params.seed, st.index, st.sample, PRIMARY_SAMPLE_NAMES);
  bidir_continue(&st, &opts, &ps, RNG_BLOCK_SUBPATH_BSDF(st.depth), params.rr_depth, TRANSPORT_IMPORTANCE, &b, &frame,
                 &su, wo_local, beta, slot, paths, stats, out);
}

__kernel void bidir_light_shade(GdrPtParams params, GdrBidirOptions opts, uint count, uint stride,
                                __global const GdrCamera* camera, __global const GdrRayHit* rays_in,
                                __global const uint* queue_in, __global GdrRayHit* rays_out, __global uint* queue_out,
                                __global GdrRay* shadow_rays, __global GdrSplat* splats, __global GdrBidirVertex* seen,
                                __global GdrBidirPathState* paths, __global GdrBidirVertex* store,
                                __global GdrManifoldPoint* delta_points, uint delta_depths,
                                __global uint* counters, PRIMARY_SAMPLE_ARGS, SCENE_DATA_ARGS) {
  __local uint scratch[GROUP_RESERVE_SCRATCH];
  uint q = get_global_id(0);
  BidirAppend out;
  bidir_append_none(&out);
  if (q < count) {
    bidir_light_shade_one(params, opts, q, stride, camera, rays_in, queue_in, splats, seen, paths, store,
                          delta_points, delta_depths, counter_shard(counters), &out, PRIMARY_SAMPLE_NAMES,
                          SCENE_DATA_NAMES);
  }
  uint slots[3];
  bidir_append(scratch, counters, &out, shadow_rays, 0, queue_out, rays_out, slots);
}

// Empties the splat slots whose shadow ray toward the camera Embree found blocked.
__kernel void bidir_camera_blocked(uint count, __global const GdrRay* shadow_rays, __global GdrSplat* splats) {
  uint k = get_global_id(0);
  if (k >= count) return;
  if (!shadow_unoccluded(shadow_rays[k].tfar)) splat_drop(&splats[shadow_rays[k].id]);
}

// Adds each path's splat slot into its entry of `sums` (what its light vertices seen by the camera
// carry, wherever they land) and empties the slot.
__kernel void bidir_splats_to_paths(uint count, __global GdrSplat* splats, __global float4* sums) {
  uint k = get_global_id(0);
  if (k >= count || !splats[k].valid) return;
  sums[k] += (float4)(vload3(0, splats[k].value), 0.0f);
  splat_drop(&splats[k]);
}

// The camera subpaths of bdpt, pm and vcm for pixels [first_pixel, first_pixel + pixel_count) (or
// Metropolis chains: the film position is then a primary sample): the ray, the state and the MIS
// sums of the camera vertex. Under multiplexing the rays are compacted and counted in
// BIDIR_COUNTER_NEXT_RAYS; a pixel's ray keeps its pixel's slot.
// Pixel i's subpath; *ray: its camera ray, if it traces one (1).
__attribute__((always_inline)) inline int bdpt_generate_one(__global const GdrCamera* camera, GdrPtParams params,
                                                            GdrBidirOptions opts, uint i,
                                                            __global GdrBidirPathState* paths, CameraRay* ray,
                                                            PRIMARY_SAMPLE_ARGS) {
  GdrCamera cam = *camera;
  uint pixel = params.first_pixel + i;
  PathSampler ps = path_sampler_bound(params.seed, pixel, params.sample, PRIMARY_SAMPLE_NAMES);
  CameraRay r = sampler_camera_ray(&cam, &ps, pixel);
  int2 shown = bidir_path_strategy(&opts, &ps, params.max_depth);
  GdrBidirPathState st;
  st.throughput[0] = st.throughput[1] = st.throughput[2] = 1.0f;
  st.rr_scale = 1.0f;
  st.index = pixel;
  st.sample = params.sample;
  st.depth = 0;
  st.stored = 0;
  bidir_set_strategy(&st, shown);
  mis_camera_start(&cam, camera_cos_theta(&cam, r.d), opts.mis, &st);
  paths[i] = st;
  *ray = r;
  // A multiplexed path whose strategy connects a light vertex to the camera (t = 1) traces no
  // camera subpath.
  return !(opts.multiplex && shown.y == 1);
}

__kernel void bdpt_generate(__global const GdrCamera* camera, GdrPtParams params, GdrBidirOptions opts,
                            __global GdrRayHit* rays, __global uint* queue, __global GdrBidirPathState* paths,
                            __global uint* counters, PRIMARY_SAMPLE_ARGS) {
  __local uint scratch[GROUP_RESERVE_SCRATCH];
  uint i = get_global_id(0);
  CameraRay r;
  int traced = i < params.pixel_count && bdpt_generate_one(camera, params, opts, i, paths, &r, PRIMARY_SAMPLE_NAMES);
  uint k = i;
  if (opts.multiplex) {  // the same for the whole launch: every item reaches the barriers or none
    const uint which[1] = {BIDIR_COUNTER_NEXT_RAYS};
    k = (uint)traced;
    group_reserve(scratch, counters, which, 1, &k);
  }
  if (!traced) return;
  write_camera_ray(&rays[k], &r, i);
  queue[k] = i;
}

// The weight of emission a camera subpath found (s = 0): 1 seen directly (no other strategy
// reaches the pinhole), else against the other strategies' share (`others`, from the light
// point's direct and emission pdfs). pm sees
// emission only through delta scatterings (its merges find the rest).
inline float bdpt_emission_weight(const GdrBidirOptions* o, const GdrBidirPathState* st, float others) {
  if (o->technique == BIDIR_PM) return (st->flags & BIDIR_PATH_ALL_SPECULAR) ? 1.0f : 0.0f;
  return st->depth == 0 ? 1.0f : bidir_weight(o, mis_weight(others));
}

// A camera subpath's new vertex: what it sees emitting (s = 0), its connection to a light point
// (s = 1, a shadow ray with its value), its record for the connections and merges with the
// light-vertex store (camera_vertices[slot], the slot queued in `connectable`), and its
// continuation.
__attribute__((always_inline)) inline void bdpt_camera_shade_one(
    GdrPtParams params, GdrBidirOptions opts, uint q, __global const GdrRayHit* rays_in, __global const uint* queue_in,
    __global GdrBidirPathState* paths, __global GdrBidirVertex* camera_vertices, __global float4* film,
    __global uint* stats, BidirAppend* out, float3* shadow_value, PRIMARY_SAMPLE_ARGS, SCENE_DATA_ARGS) {
  SceneData s = path_scene(&params, SCENE_DATA_NAMES);
  __global uint* nonfinite = &stats[BIDIR_COUNTER_NONFINITE];
  uint slot = queue_in[q];
  out->slot = slot;
  GdrBidirPathState st = paths[slot];
  GdrRayHit rh = rays_in[q];
  float3 dir = (float3)(rh.ray.dir_x, rh.ray.dir_y, rh.ray.dir_z);
  float3 beta = vload3(0, st.throughput);
  int t = st.depth + 1;  // this vertex's segments from the camera
  if (!segments_allowed(params.max_depth, t)) return;

  if (rh.hit.geomID == GDR_INVALID_ID) {
#if defined(GDR_LIGHT_CONSTANT) || defined(GDR_LIGHT_ENVMAP)
    if (s.env_light >= 0 && bidir_strategy_shown(&st, 0, t + 1)) {
      float w = bdpt_emission_weight(&opts, &st, mis_escaped_emission_others(&s, dir, st.dvcm, st.dvc, opts.mis));
      film_add(film, st.index, beta * escaped_radiance(&s, dir) * w, nonfinite);
    }
#endif
    return;
  }

  Surface su = surface_at(&s, rh.hit.primID, rh.hit.u, rh.hit.v);
  float3 wo = -dir;
  mis_arrive(rh.ray.tfar, fabs(dot(su.ng, wo)), opts.mis, &st);
#if defined(GDR_LIGHT_AREA)
  if (su.light >= 0 && bidir_strategy_shown(&st, 0, t + 1)) {
    float3 le = surface_radiance(&s, &su, wo);
    if (max3(le) > 0.0f) {
      float others = mis_surface_emission_others(&s, &su, wo, st.dvcm, st.dvc, opts.mis);
      film_add(film, st.index, beta * le * bdpt_emission_weight(&opts, &st, others), nonfinite);
    }
  }
#endif
  if (!segments_allowed(params.max_depth, t + 1)) return;

  Bsdf b = surface_bsdf(&s, &su);
  Frame frame = frame_from_normal(su.ns);
  float3 wo_local = frame_to_local(&frame, wo);
  PathSampler ps = path_sampler_bound(params.seed, st.index, st.sample, PRIMARY_SAMPLE_NAMES);
  int delta = bsdf_is_delta(&b);

  // Connection to a light point (s = 1).
  int light;
  LightSample ls;
  float3 wi_local;
  int connects = bidir_connects(&opts), merges = bidir_merges(&opts);
  if (connects && bidir_strategy_shown(&st, 1, t + 1) && nee_applies(&s, &b) &&
      nee_sample(&s, &ps, st.depth, &su, &frame, &light, &ls, &wi_local)) {
    float others = mis_light_point_others(&s, &b, wo_local, wi_local, su.ng, light, &ls, st.dvcm, st.dvc, &opts);
    float w = bidir_weight(&opts, mis_weight(others));
    float3 c = beta * bsdf_eval(&b, wo_local, wi_local) * ls.radiance * (w / ls.pdf);
    if (max3(c) > 0.0f && finite_or_count(c, nonfinite)) {
      atomic_inc(&stats[BIDIR_COUNTER_NEE]);
      out->shadow = 1u;
      out->shadow_p = su.p;
      out->shadow_ng = su.ng;
      out->shadow_wi = ls.wi;
      out->shadow_dist = ls.dist;
      out->shadow_to_point = 0;
      out->shadow_id = st.index;
      *shadow_value = c;
    }
  }

  // Open to connections with the light subpath's stored vertices (s >= 2: at least one more
  // segment each side) and to merges with any light subpath's (at least one more).
  if (!delta && ((connects && segments_allowed(params.max_depth, t + 2)) ||
                 (merges && segments_allowed(params.max_depth, t + 1)))) {
    camera_vertices[slot] = bidir_vertex(&rh.hit, wo, beta, &st, t);
    out->connectable = 1u;
  }
  // pm's visible point is the first rough vertex: the subpath ends there.
  if (opts.technique == BIDIR_PM && !delta) return;
  if (!bidir_camera_subpath_grows(&st, t + 1)) return;

  // BSDF sampling continues the subpath.
  bidir_continue(&st, &opts, &ps, RNG_BLOCK_BSDF(st.depth), params.rr_depth, TRANSPORT_RADIANCE, &b, &frame, &su,
                 wo_local, beta, slot, paths, stats, out);
}

__kernel void bdpt_camera_shade(GdrPtParams params, GdrBidirOptions opts, uint count,
                                __global const GdrRayHit* rays_in, __global const uint* queue_in,
                                __global GdrRayHit* rays_out, __global uint* queue_out, __global GdrRay* shadow_rays,
                                __global float4* shadow_values, __global GdrBidirPathState* paths,
                                __global GdrBidirVertex* camera_vertices, __global uint* connectable,
                                __global float4* film, __global uint* counters, PRIMARY_SAMPLE_ARGS,
                                SCENE_DATA_ARGS) {
  __local uint scratch[GROUP_RESERVE_SCRATCH];
  uint q = get_global_id(0);
  BidirAppend out;
  bidir_append_none(&out);
  float3 value;
  if (q < count) {
    bdpt_camera_shade_one(params, opts, q, rays_in, queue_in, paths, camera_vertices, film, counter_shard(counters),
                          &out, &value, PRIMARY_SAMPLE_NAMES, SCENE_DATA_NAMES);
  }
  uint slots[3];
  bidir_append(scratch, counters, &out, shadow_rays, connectable, queue_out, rays_out, slots);
  if (out.shadow) shadow_values[slots[0]] = (float4)(value, 0.0f);
}

// Connects the camera vertices queued in `connectable` to vertex j of their pixel's light subpath
// (s = depth_y + 1 light vertices, t = depth_z + 1 camera vertices): the value and a shadow ray
// between the two surfaces, added by path_shadow_add where unoccluded. j = BIDIR_OWN_STRATEGY:
// the stored vertex of the path's one strategy (multiplexed: a path connects once at most, so one
// launch serves every stored vertex).
// Entry q's connection: 1 with its segment (*cn) and weighted value (*value) where it adds.
__attribute__((always_inline)) inline int bdpt_connect_one(
    GdrPtParams params, GdrBidirOptions opts, uint q, uint j, uint stride, __global const uint* connectable,
    __global const GdrBidirVertex* camera_vertices, __global const GdrBidirPathState* light_paths,
    __global const GdrBidirVertex* store, __global uint* stats, BidirConnection* cn, float3* value, SCENE_DATA_ARGS) {
  uint slot = connectable[q];
  GdrBidirPathState light = light_paths[slot];
  GdrBidirVertex z = camera_vertices[slot];
  if (j == BIDIR_OWN_STRATEGY) {
    if (z.depth + 1 != light.shown_t) return 0;
    for (j = 0; j < (uint)light.stored && store[j * stride + slot].depth + 1 != light.shown_s; ++j) {
    }
  }
  if ((int)j >= light.stored) return 0;
  GdrBidirVertex y = store[j * stride + slot];
  if (!segments_allowed(params.max_depth, z.depth + y.depth + 1) ||
      !bidir_strategy_shown(&light, y.depth + 1, z.depth + 1)) return 0;
  SceneData s = path_scene(&params, SCENE_DATA_NAMES);
  atomic_inc(&stats[BIDIR_COUNTER_CONNECTIONS]);
  if (!bidir_connection(&s, &z, &y, &opts, cn)) return 0;
  float3 c = cn->value;
  if (!(max3(c) > 0.0f)) return 0;
  c *= bidir_weight(&opts, mis_weight(cn->others));
  if (!(max3(c) > 0.0f) || !finite_or_count(c, &stats[BIDIR_COUNTER_NONFINITE])) return 0;
  *value = c;
  return 1;
}

__kernel void bdpt_connect(GdrPtParams params, GdrBidirOptions opts, uint count, uint j, uint stride,
                           __global const uint* connectable, __global const GdrBidirVertex* camera_vertices,
                           __global const GdrBidirPathState* light_paths, __global const GdrBidirVertex* store,
                           __global GdrRay* shadow_rays, __global float4* shadow_values, __global uint* counters,
                           SCENE_DATA_ARGS) {
  __local uint scratch[GROUP_RESERVE_SCRATCH];
  uint q = get_global_id(0);
  BidirConnection cn;
  float3 c;
  int connected = q < count && bdpt_connect_one(params, opts, q, j, stride, connectable, camera_vertices, light_paths,
                                                store, counter_shard(counters), &cn, &c, SCENE_DATA_NAMES);
  const uint which[1] = {BIDIR_COUNTER_SHADOW_RAYS};
  uint k = (uint)connected;
  group_reserve(scratch, counters, which, 1, &k);
  if (!connected) return;
  write_segment_ray(&shadow_rays[k], cn.from, cn.from_ng, cn.to, params.first_pixel + connectable[q]);
  shadow_values[k] = (float4)(c, 0.0f);
}

// Merging: the light vertices of the chunk's light subpaths within the radius of the camera
// vertices queued in `connectable` (a density estimate, SmallVCM's RangeQuery), added to their
// pixels. The grid (bidir/hash_grid.h) lists the store's entries by cell.
__kernel void vcm_merge(GdrPtParams params, GdrBidirOptions opts, uint count, uint stride,
                        __global const uint* connectable, __global const GdrBidirVertex* camera_vertices,
                        __global const GdrBidirVertex* store, __global const float4* store_points,
                        __global const uint* starts, __global const uint* sorted, uint buckets,
                        __global float4* film, __global uint* counters, SCENE_DATA_ARGS) {
  uint q = get_global_id(0);
  if (q >= count) return;
  uint slot = connectable[q];
  GdrBidirVertex z = camera_vertices[slot];
  SceneData s = path_scene(&params, SCENE_DATA_NAMES);
  Surface sz = surface_at(&s, z.prim, z.u, z.v);
  Bsdf bz = surface_bsdf(&s, &sz);
  Frame fz = frame_from_normal(sz.ns);
  float3 wo_z = vload3(0, z.wo), wo_z_local = frame_to_local(&fz, wo_z);
  PhotonQuery pq = photon_query(sz.p, opts.radius, buckets);
  float3 sum = (float3)(0.0f);
  uint merged = 0, e;
  while (photon_query_next(&pq, starts, sorted, store_points, &e)) {
    GdrBidirVertex y = store[e];
    if (!segments_allowed(params.max_depth, y.depth + z.depth)) continue;
    float3 wi = vload3(0, y.wo);
    float3 f = photon_merge_value(&bz, &fz, sz.ng, wo_z_local, wi);
    if (!(max3(f) > 0.0f)) continue;
    float w = 1.0f;
    if (opts.technique == BIDIR_VCM) {
      float3 wi_local = frame_to_local(&fz, wi);
      float pdf_fwd = bsdf_pdf(&bz, wo_z_local, wi_local), pdf_rev = bsdf_pdf(&bz, wi_local, wo_z_local);
      w = bidir_weight(&opts, mis_weight(mis_merge_side(y.dvcm, y.dvm, pdf_fwd, &opts) +
                                         mis_merge_side(z.dvcm, z.dvm, pdf_rev, &opts)));
    }
    sum += f * vload3(0, y.throughput) * w;
    ++merged;
  }
  if (merged == 0) return;
  __global uint* stats = counter_shard(counters);
  atomic_add(&stats[BIDIR_COUNTER_MERGES], merged);
  film_add(film, params.first_pixel + slot, vload3(0, z.throughput) * sum * opts.vm_normalization,
           &stats[BIDIR_COUNTER_NONFINITE]);
}

// The grid's keys: each light vertex of the store (entry j * stride + slot, j < the subpath's
// stored count) gets its cell's bucket and its point; the other entries a key past the buckets.
__kernel void vcm_grid_keys(GdrPtParams params, GdrBidirOptions opts, uint stride, uint entries,
                            __global const GdrBidirPathState* light_paths, __global const GdrBidirVertex* store,
                            uint buckets, __global uint* keys, __global float4* store_points, SCENE_DATA_ARGS) {
  uint e = get_global_id(0);
  if (e >= entries) return;
  uint j = e / stride, slot = e % stride;
  if (slot >= params.pixel_count || (int)j >= light_paths[slot].stored) {
    keys[e] = 0xFFFFFFFFu;
    return;
  }
  SceneData s = path_scene(&params, SCENE_DATA_NAMES);
  GdrBidirVertex y = store[e];
  float3 p = surface_at(&s, y.prim, y.u, y.v).p;
  store_points[e] = (float4)(p, 0.0f);
  keys[e] = hash_grid_bucket(hash_grid_cell(p, opts.radius), buckets);
}
