// The manifold walk as an iterative wavefront stage (engine/render/manifold_walks drives it):
//   manifold_begin    every walk starts from the base chain's vertices;
//   manifold_propose  from the accepted chain, a Newton step on the constraints moves x_1 so that
//                     the chain's end moves toward x_e (the first proposal aims at the base's x_1);
//                     a ray leaves x_0 toward the new x_1;
//   host              Embree traces the chain, one segment per round: manifold_retrace scatters
//                     each hit by its vertex's constraint (the kept normal or micro-normal) into
//                     the next segment, until the chain's last segment reaches x_e's shape;
//   manifold_accept   a proposal closer to x_e is accepted (the step grows), a farther or broken
//                     one is rejected (the step halves); converged and failed walks leave the
//                     active list. A converged walk is walked back from the base chain's start,
//                     seeded with its solution, and must arrive at the base chain.
#pragma once
#include "core/ray_queue.h"
#include "manifold/chain.h"
#include "manifold/walk_state.h"
#include "path/scene.h"

// The chain from `start` through the given specular vertices to `end`, with the walk's constraints.
inline void manifold_load_chain(const SceneData* sd, const GdrManifoldWalk* w, GdrManifoldPoint start,
                                const GdrManifoldPoint* verts, GdrManifoldPoint end, ManifoldChain* ch) {
  ch->count = w->count;
  ch->x[0] = manifold_surface(sd, start);
  for (int i = 0; i < w->count; ++i) {
    ch->x[i + 1] = manifold_surface(sd, verts[i]);
    ch->flags[i] = w->v[i].flags;
    ch->kept[i] = (mreal3)(w->v[i].h[0], w->v[i].h[1], w->v[i].h[2]);
  }
  ch->x[w->count + 1] = manifold_surface(sd, end);
}

inline GdrManifoldPoint walk_start(const GdrManifoldWalk* w, const ManifoldState* st) {
  return st->phase ? w->origin : w->start;
}

inline void walk_fail(__global GdrManifoldResult* r, __global uint* counters, int reason) {
  r->status = reason;
  atomic_inc(&counters[reason]);
}

// A chain segment leaves its vertex p itself, not an origin moved off the surface: the walk aims
// through points, and a moved origin would shift every segment. `tnear` skips the surface it
// leaves.
inline void write_chain_ray(__global GdrRayHit* rays, __global uint* counters, mreal3 p, mreal3 d, float tnear,
                            uint id) {
  uint slot = atomic_inc(&counters[MANIFOLD_COUNTER_TRACING]);
  atomic_inc(&counters[MANIFOLD_COUNTER_RAYS]);
  write_ray_hit(&rays[slot], to_float3(p), to_float3(d), tnear, INFINITY, id);
}

__kernel void manifold_begin(uint count, __global uint* states, uint capacity, __global GdrManifoldResult* results,
                             __global uint* active, __global uint* counters) {
  uint w = get_global_id(0);
  if (w >= count) return;
  ManifoldStateRef s = manifold_state_ref(states, capacity, w);
  set_state_int(s, MANIFOLD_STATE_PHASE, 0);
  set_state_int(s, MANIFOLD_STATE_ITERATIONS, 0);
  set_state_float(s, MANIFOLD_STATE_BETA, 1.0f);
  set_state_float(s, MANIFOLD_STATE_ERROR, INFINITY);
  set_state_int(s, MANIFOLD_STATE_ACCEPTED, 0);
  results[w].status = 0;
  results[w].iterations = 0;
  results[w].g_walk = results[w].g_origin = results[w].g_walk_at_end = results[w].g_origin_at_end = 0.0f;
  active[w] = w;
  atomic_inc(&counters[MANIFOLD_COUNTER_WALKS]);
}

__kernel void manifold_propose(GdrManifoldParams params, uint count, __global const uint* active,
                               __global const GdrManifoldWalk* walks, __global uint* states, uint capacity,
                               __global const GdrManifoldResult* results, __global GdrRayHit* rays,
                               __global uint* counters, GdrPtParams scene_params, SCENE_DATA_ARGS) {
  uint i = get_global_id(0);
  if (i >= count) return;
  SceneData sd = path_scene(&scene_params, SCENE_DATA_NAMES);
  uint w = active[i];
  GdrManifoldWalk W = walks[w];
  ManifoldStateRef s = manifold_state_ref(states, capacity, w);
  ManifoldState st;
  load_state(s, W.count, 0, &st);
  ManifoldSurface x0 = manifold_surface(&sd, walk_start(&W, &st));
  ManifoldChain ch;
  mreal3 x1;
  st.traced = 0;
  st.trace_status = 0;
  st.proposal_reaches = 0;
  if (!st.accepted) {
    // First proposal: the known chain (the base's; for the walk back, the solution) with its
    // start moved to this walk's, to first order.
    GdrManifoldPoint verts[MANIFOLD_MAX_CHAIN];
    for (int k = 0; k < W.count; ++k) verts[k] = st.phase ? results[w].v[k] : W.v[k].at;
    manifold_load_chain(&sd, &W, st.phase ? W.start : W.origin, verts, W.end, &ch);
    // Where a far move's first-order guess is traced into a miss, it is shortened (beta).
    if (manifold_start_move(&sd, &ch, x0.p, &x1)) x1 = ch.x[1].p;
    x1 = ch.x[1].p + (mreal)st.beta * (x1 - ch.x[1].p);
  } else {
    // Newton step: the chain's end moves toward x_e.
    manifold_load_chain(&sd, &W, walk_start(&W, &st), st.chain, W.end, &ch);
    ch.x[W.count + 1].p = (mreal3)(st.chain_end[0], st.chain_end[1], st.chain_end[2]);
    M2 dx1;
    st.trace_status = manifold_end_derivative(&sd, &ch, &dx1);
    if (!st.trace_status) x1 = manifold_step(&ch, dx1, manifold_position(&sd, W.end), st.beta);
  }
  if (!st.trace_status) {
    mreal3 d = x1 - x0.p;
    mreal len = length(d);
    if (!(len > (mreal)0)) st.trace_status = MANIFOLD_COUNTER_FAIL_MERGED;
    else write_chain_ray(rays, counters, x0.p, d / len, params.ray_epsilon, w);
  }
  store_trace(s, &st);
}

// One segment of every proposal being traced: Embree's hit becomes the next chain vertex.
__kernel void manifold_retrace(GdrManifoldParams params, uint count, __global const GdrRayHit* rays_in, __global GdrRayHit* rays_out,
                               __global const GdrManifoldWalk* walks, __global uint* states, uint capacity,
                               __global uint* counters, GdrPtParams scene_params, SCENE_DATA_ARGS) {
  uint i = get_global_id(0);
  if (i >= count) return;
  SceneData sd = path_scene(&scene_params, SCENE_DATA_NAMES);
  GdrRayHit rh = rays_in[i];
  uint w = rh.ray.id;
  ManifoldStateRef s = manifold_state_ref(states, capacity, w);
  __global const GdrManifoldWalk* W = &walks[w];
  int j = state_int(s, MANIFOLD_STATE_TRACED), m = W->count;
  int hit = rh.hit.geomID != GDR_INVALID_ID;
  float3 o = (float3)(rh.ray.org_x, rh.ray.org_y, rh.ray.org_z), d = (float3)(rh.ray.dir_x, rh.ray.dir_y, rh.ray.dir_z);
  GdrManifoldPoint q = {rh.hit.primID, rh.hit.u, rh.hit.v};
  if (hit) q = manifold_refine_hit(&sd, rh.hit.primID, o, d);
  if (j == m) {
    // The last segment: where it meets x_e's surface, or else x_e's tangent plane (the walk
    // still converges there; only the converged chain must reach x_e unblocked).
    set_state_int(s, MANIFOLD_STATE_TRACED, j + 1);
    if (hit && manifold_shape(&sd, q) == manifold_shape(&sd, W->end)) {
      set_state_float3(s, MANIFOLD_STATE_PROPOSAL_END, manifold_point_on(&sd, q));
      set_state_int(s, MANIFOLD_STATE_PROPOSAL_REACHES, 1);
      return;
    }
    ManifoldSurface e = manifold_surface(&sd, W->end);
    float3 ng = to_float3(e.ng);
    float t = dot(to_float3(e.p) - o, ng) / dot(d, ng);
    if (!(t > 0.0f) || !isfinite(t)) {
      set_state_int(s, MANIFOLD_STATE_TRACE_STATUS, MANIFOLD_COUNTER_FAIL_MISS);
      return;
    }
    set_state_float3(s, MANIFOLD_STATE_PROPOSAL_END, o + t * d);
    return;
  }
  if (!hit) {
    set_state_int(s, MANIFOLD_STATE_TRACE_STATUS, MANIFOLD_COUNTER_FAIL_MISS);
    return;
  }
  set_state_point(s, MANIFOLD_STATE_PROPOSAL + 3 * j, q);
  set_state_int(s, MANIFOLD_STATE_TRACED, j + 1);
  if (manifold_shape(&sd, q) != manifold_shape(&sd, W->v[j].at)) {
    set_state_int(s, MANIFOLD_STATE_TRACE_STATUS, MANIFOLD_COUNTER_FAIL_OTHER_OBJECT);
    return;
  }
  ManifoldSurface x = manifold_surface(&sd, q);
  int flags = W->v[j].flags, transmit = (flags & MANIFOLD_VERTEX_TRANSMIT) != 0;
  mreal3 wa = -normalize(to_mreal3(d));
  mreal3 nm = x.n;
  if (!(flags & MANIFOLD_VERTEX_DELTA)) {
    nm = manifold_to_world(&x, (mreal3)(W->v[j].h[0], W->v[j].h[1], W->v[j].h[2]));
    nm = normalize(nm);
  }
  mreal3 wb;
  int ok = manifold_scatter(wa, nm, transmit, manifold_etas(&sd, &x, flags, wa), &wb);
  // The lobe must leave on the side it did on the base chain.
  ok = ok && (dot(wa, x.ng) * dot(wb, x.ng) > (mreal)0) == !transmit;
  if (!ok) {
    set_state_int(s, MANIFOLD_STATE_TRACE_STATUS, MANIFOLD_COUNTER_FAIL_LOBE);
    return;
  }
  write_chain_ray(rays_out, counters, x.p, normalize(wb), params.ray_epsilon, w);
}

__kernel void manifold_accept(GdrManifoldParams params, uint count, __global const uint* active,
                              __global uint* next_active, __global const GdrManifoldWalk* walks,
                              __global uint* states, uint capacity, __global GdrManifoldResult* results,
                              __global uint* counters, GdrPtParams scene_params, SCENE_DATA_ARGS) {
  uint i = get_global_id(0);
  if (i >= count) return;
  SceneData sd = path_scene(&scene_params, SCENE_DATA_NAMES);
  uint w = active[i];
  GdrManifoldWalk W = walks[w];
  const int m = W.count;
  ManifoldStateRef s = manifold_state_ref(states, capacity, w);
  ManifoldState st;
  load_state(s, m, 1, &st);
  __global GdrManifoldResult* res = &results[w];
  st.iterations += 1;
  res->iterations += 1;
  atomic_inc(&counters[MANIFOLD_COUNTER_ITERATIONS]);
  mreal3 target = manifold_position(&sd, W.end);
  if (st.trace_status || st.traced != m + 1) {
    if (!st.accepted) {
      // The first guess cannot be traced: a shorter first-order move, down to none at all.
      if (!(st.beta > 0.0f)) {
        walk_fail(res, counters, st.trace_status ? st.trace_status : MANIFOLD_COUNTER_FAIL_MISS);
        return;
      }
      st.beta = st.beta > 0.1f ? 0.25f * st.beta : 0.0f;
    } else {
      st.beta *= 0.5f;
    }
  } else {
    float error = (float)length(to_mreal3(vload3(0, st.proposal_end)) - target);
    if (!st.accepted || error < st.error) {
      for (int k = 0; k < m; ++k) st.chain[k] = st.proposal[k];
      for (int k = 0; k < 3; ++k) st.chain_end[k] = st.proposal_end[k];
      st.chain_reaches = st.proposal_reaches;
      st.beta = st.accepted ? fmin(1.0f, 2.0f * st.beta) : 1.0f;
      st.accepted = 1;
      st.error = error;
    } else {
      st.beta *= 0.5f;
    }
  }
  if (st.accepted && st.error < params.tolerance && !st.chain_reaches) {
    walk_fail(res, counters, MANIFOLD_COUNTER_FAIL_OCCLUDED);
    return;
  }
  if (st.accepted && st.error < params.tolerance) {
    // Converged: the chain ends at x_e itself.
    ManifoldChain ch;
    manifold_load_chain(&sd, &W, walk_start(&W, &st), st.chain, W.end, &ch);
    float g, g_at_end;
    int r = manifold_geometries(&sd, &ch, &g, &g_at_end);
    if (r) {
      walk_fail(res, counters, r);
      return;
    }
    if (st.phase == 0) {
      for (int k = 0; k < m; ++k) res->v[k] = st.chain[k];
      res->g_walk = g;
      res->g_walk_at_end = g_at_end;
      st.phase = 1;
      st.iterations = 0;
      st.accepted = 0;
      st.beta = 1.0f;
      st.error = INFINITY;
    } else {
      // Reversible: the walk back arrived at the base chain's own vertices.
      float far = 0.0f;
      for (int k = 0; k < m; ++k) {
        far = fmax(far, (float)length(manifold_position(&sd, st.chain[k]) - manifold_position(&sd, W.v[k].at)));
      }
      if (!(far < params.reverse_tolerance)) {
        walk_fail(res, counters, MANIFOLD_COUNTER_FAIL_NOT_REVERSIBLE);
      } else {
        GdrManifoldPoint base[MANIFOLD_MAX_CHAIN];
        for (int k = 0; k < m; ++k) base[k] = W.v[k].at;
        manifold_load_chain(&sd, &W, W.origin, base, W.end, &ch);
        r = manifold_geometries(&sd, &ch, &g, &g_at_end);
        if (r) {
          walk_fail(res, counters, r);
        } else {
          res->g_origin = g;
          res->g_origin_at_end = g_at_end;
          atomic_inc(&counters[MANIFOLD_COUNTER_SOLVED]);
        }
      }
      return;
    }
  } else if (st.iterations >= params.max_iterations || (st.accepted && st.beta < 1.0f / 1024.0f)) {
    walk_fail(res, counters, MANIFOLD_COUNTER_FAIL_NO_CONVERGENCE);
    return;
  }
  // Only a walk that goes on keeps its state: an ended walk's is never read again.
  store_state(s, m, &st);
  next_active[atomic_inc(&counters[MANIFOLD_COUNTER_ACTIVE])] = w;
}
