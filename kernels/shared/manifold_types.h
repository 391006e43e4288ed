// Manifold walks (Jakob & Marschner 2012), shared by their kernels (kernels/manifold) and the
// host stage that drives them (engine/render/manifold_walks): a chain x_0 -> s_1 .. s_m -> x_e of
// specular (or near-specular) vertices between two fixed rough ends. A walk starts from the
// vertices of another chain (the base path's) and moves them, through Newton steps on the
// specular constraints and Embree re-traces of the chain, until the chain from its own start
// x_0 ends at the fixed x_e. Then a second walk from the base chain's start, seeded with the
// solution, must lead back to the base chain (the shift is its own reverse).
#pragma once
#include "shared/counters.h"

#define MANIFOLD_MAX_CHAIN 4  // specular vertices between the two ends (compiled maximum)

#define MANIFOLD_VERTEX_DELTA 1     // a delta lobe: the generalized half vector is the shading normal
#define MANIFOLD_VERTEX_TRANSMIT 2  // the lobe transmits (refracts, or passes straight through)

// A point on a triangle, as Embree reports it.
typedef struct GdrManifoldPoint {
  unsigned int prim;
  float b1, b2;
} GdrManifoldPoint;

// A specular vertex of a chain, and the constraint it keeps.
typedef struct GdrManifoldVertex {
  GdrManifoldPoint at;
  int flags;    // MANIFOLD_VERTEX_*
  float h[3];   // not delta: the micro-normal (normalized generalized half vector) the chain keeps,
                // in the vertex's manifold frame (kernels/manifold/differential.h)
  float pad0;
} GdrManifoldVertex;

// One walk to solve.
typedef struct GdrManifoldWalk {
  GdrManifoldPoint start;   // x_0 of the new chain (fixed)
  GdrManifoldPoint end;     // x_e (fixed, shared with the base chain)
  GdrManifoldPoint origin;  // x_0 of the base chain (where the reverse walk starts)
  int count;                // specular vertices, 1 .. MANIFOLD_MAX_CHAIN
  unsigned int owner;       // the caller's id (G-PT: group * 4 + offset)
  int pad0;
  GdrManifoldVertex v[MANIFOLD_MAX_CHAIN];  // the base chain: first guess and constraints
} GdrManifoldWalk;

// Its outcome.
typedef struct GdrManifoldResult {
  int status;      // 0: solved and reversible; else the MANIFOLD_COUNTER_FAIL_* reason
  int iterations;  // Newton iterations of both walks
  float g_walk;    // generalized geometry term |d omega_0 / dA(x_e)| of the new chain
  float g_origin;  // the same of the base chain: |J| of the shift is g_walk / g_origin
  float g_walk_at_end;    // |d omega_e / dA(x_0)| of the new chain (x_e fixed)
  float g_origin_at_end;  // the same of the base chain
  GdrManifoldPoint v[MANIFOLD_MAX_CHAIN];  // the new chain's specular vertices
} GdrManifoldResult;

// Per-walk iteration state, as structure of arrays: word f of walk w lies at state[f * capacity + w],
// so neighbouring work items read each field from one contiguous run (kernels/manifold/walk_state.h
// gathers and scatters it). Points take three words (prim, b1, b2), positions three floats.
enum {
  MANIFOLD_STATE_PHASE,             // 0: the walk from start; 1: the reverse walk from origin
  MANIFOLD_STATE_ITERATIONS,        // of this phase
  MANIFOLD_STATE_BETA,              // step size: starts at 1, halved on a rejected step, doubled
                                    // on an accepted one (capped at 1)
  MANIFOLD_STATE_ERROR,             // the accepted chain's distance from x_e
  MANIFOLD_STATE_ACCEPTED,          // a traced chain has been accepted in this phase
  MANIFOLD_STATE_CHAIN_REACHES,     // the accepted chain's last segment hit x_e's shape
  MANIFOLD_STATE_TRACED,            // vertices of the proposal traced so far
  MANIFOLD_STATE_TRACE_STATUS,      // 0, or why the proposal could not be traced (MANIFOLD_COUNTER_FAIL_*)
  MANIFOLD_STATE_PROPOSAL_REACHES,  // the proposal's last segment hit x_e's shape (else it ends on x_e's tangent plane)
  MANIFOLD_STATE_CHAIN_END,         // where the accepted chain's last segment meets x_e's surface or tangent plane
  MANIFOLD_STATE_PROPOSAL_END = MANIFOLD_STATE_CHAIN_END + 3,
  MANIFOLD_STATE_CHAIN = MANIFOLD_STATE_PROPOSAL_END + 3,      // the accepted chain's specular vertices
  MANIFOLD_STATE_PROPOSAL = MANIFOLD_STATE_CHAIN + 3 * MANIFOLD_MAX_CHAIN,  // the chain being traced
  MANIFOLD_STATE_WORDS = MANIFOLD_STATE_PROPOSAL + 3 * MANIFOLD_MAX_CHAIN
};

typedef struct GdrManifoldParams {
  float tolerance;          // world distance from x_e at which a walk has converged
  int max_iterations;       // per walk (--manifold-iterations)
  float reverse_tolerance;  // how far from the base chain's vertices the walk back may end
  float ray_epsilon;        // chain segments start this far from their vertex (skips its own surface)
} GdrManifoldParams;

// Counters (atomic_inc): queue sizes, then the walks' outcomes by reason.
#define MANIFOLD_COUNTERS(X)                                                                        \
  X(MANIFOLD_COUNTER_ACTIVE, "")                                                                    \
  X(MANIFOLD_COUNTER_TRACING, "")                                                                   \
  X(MANIFOLD_COUNTER_WALKS, "manifold/walks")                                                      \
  X(MANIFOLD_COUNTER_SOLVED, "manifold/solved")                                                    \
  X(MANIFOLD_COUNTER_ITERATIONS, "manifold/iterations")                                            \
  X(MANIFOLD_COUNTER_RAYS, "manifold/rays")                                                        \
  X(MANIFOLD_COUNTER_FAIL_NO_CONVERGENCE, "manifold/fail_no_convergence")                          \
  X(MANIFOLD_COUNTER_FAIL_MISS, "manifold/fail_projection_miss")       /* a chain ray escaped */    \
  X(MANIFOLD_COUNTER_FAIL_OTHER_OBJECT, "manifold/fail_other_object") /* a vertex on another shape */ \
  X(MANIFOLD_COUNTER_FAIL_LOBE, "manifold/fail_lobe_mismatch")        /* reflection vs refraction, TIR */ \
  X(MANIFOLD_COUNTER_FAIL_SINGULAR, "manifold/fail_singular")         /* a singular constraint block */ \
  X(MANIFOLD_COUNTER_FAIL_MERGED, "manifold/fail_merged_vertices")                                 \
  X(MANIFOLD_COUNTER_FAIL_NOT_REVERSIBLE, "manifold/fail_not_reversible")                          \
  X(MANIFOLD_COUNTER_FAIL_OCCLUDED, "manifold/fail_occluded")         /* the last segment is blocked */
enum { MANIFOLD_COUNTERS(GDR_COUNTER_ENUM) MANIFOLD_COUNTER_COUNT };
