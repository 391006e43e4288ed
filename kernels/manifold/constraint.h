// The specular constraint of a chain vertex x_i between x_{i-1} and x_{i+1}: the generalized half
// vector H = eta_a w_a + eta_b w_b (w toward the neighbours, eta the IOR on each one's side) is
// parallel to the shading normal at a delta vertex, and equals the kept micro-normal at a
// near-specular one. In the manifold frame (s, t): c_i = (H.s, H.t) for a delta vertex (H not
// normalized, so that an index-matched interface, where H vanishes at the solution, needs no
// division by |H|), and c_i = (h.s, h.t) - h_kept.xy with h = H / |H| otherwise. The derivatives
// of c_i with respect to the plane coordinates of x_{i-1}, x_i and x_{i+1} are the blocks A_i,
// B_i, C_i of the chain's block-tridiagonal constraint matrix.
#pragma once
#include "manifold/differential.h"
#include "shared/material_class.h"

// IOR on the side of w_a and on the far side: 1 and 1 for a reflection; a transmission through a
// dielectric of relative IOR eta (int / ext) is entered from the side of w_a (the shading normal's
// side is outside, as the BSDFs have it). Thin sheets and index-matched interfaces pass light
// straight: 1 and 1.
inline mreal2 manifold_etas(const SceneData* sd, const ManifoldSurface* m, int flags, mreal3 wa) {
  if (!(flags & MANIFOLD_VERTEX_TRANSMIT)) return (mreal2)(1, 1);
  __global const GdrMaterial* mat = &sd->materials[m->material];
  mreal eta = mat->eta[0];
  if (mat->type == BSDF_THIN_DIELECTRIC || material_index_matched(mat->type, mat->eta[0]) || !(eta > (mreal)0)) {
    return (mreal2)(1, 1);
  }
  return dot(wa, m->n) > (mreal)0 ? (mreal2)(1, eta) : (mreal2)(eta, 1);
}

// The half vector the constraint compares (H, or h = H / |H| for a near-specular vertex) in the
// manifold frame; 0 where a near-specular vertex's H vanishes.
inline int manifold_half_vector(const ManifoldSurface* m, int flags, mreal2 eta, mreal3 wa, mreal3 wb, mreal3* h) {
  mreal3 H = eta.x * wa + eta.y * wb;
  if (!(flags & MANIFOLD_VERTEX_DELTA)) {
    mreal len = length(H);
    if (!(len > (mreal)1e-6)) return 0;
    H /= len;
  }
  *h = (mreal3)(dot(H, m->s), dot(H, m->t), dot(H, m->n));
  return 1;
}

// The constraint of vertex m between a and b (positions) and its derivative blocks with respect to
// a's, m's and b's plane coordinates. Returns 0 or the MANIFOLD_COUNTER_FAIL_* reason.
inline int manifold_constraint(const SceneData* sd, const ManifoldSurface* a, const ManifoldSurface* m,
                               const ManifoldSurface* b, int flags, mreal3 kept, mreal2* c, M2* A, M2* B, M2* C) {
  mreal3 wa = a->p - m->p, wb = b->p - m->p;
  mreal la = length(wa), lb = length(wb);
  if (!(la > (mreal)0) || !(lb > (mreal)0)) return MANIFOLD_COUNTER_FAIL_MERGED;
  wa /= la;
  wb /= lb;
  if (!(m->s_len > (mreal)1e-6)) return MANIFOLD_COUNTER_FAIL_SINGULAR;
  mreal2 eta = manifold_etas(sd, m, flags, wa);
  mreal3 H = eta.x * wa + eta.y * wb;
  int delta = (flags & MANIFOLD_VERTEX_DELTA) != 0;
  mreal hl = length(H);
  if (!delta && !(hl > (mreal)1e-6)) return MANIFOLD_COUNTER_FAIL_SINGULAR;
  mreal3 V = delta ? H : H / hl;
  *c = (mreal2)(dot(V, m->s), dot(V, m->t));
  if (!delta) *c -= kept.xy;

  // d w / d x for a unit vector w = (q - x) / |q - x| moved along T at its far end (q) or near end (x).
  mreal3 dirs[6] = {a->dpdu, a->dpdv, m->dpdu, m->dpdv, b->dpdu, b->dpdv};
  mreal2 cols[6];
  for (int j = 0; j < 6; ++j) {
    mreal3 T = dirs[j];
    mreal3 dwa = (mreal3)(0), dwb = (mreal3)(0);
    if (j < 2) dwa = (T - wa * dot(wa, T)) / la;
    if (j >= 4) dwb = (T - wb * dot(wb, T)) / lb;
    if (j == 2 || j == 3) {
      dwa = -(T - wa * dot(wa, T)) / la;
      dwb = -(T - wb * dot(wb, T)) / lb;
    }
    mreal3 dH = eta.x * dwa + eta.y * dwb;
    mreal3 dV = delta ? dH : (dH - V * dot(V, dH)) / hl;
    mreal2 d = (mreal2)(dot(dV, m->s), dot(dV, m->t));
    if (j == 2 || j == 3) {
      mreal3 ds, dt;
      manifold_frame_derivative(m, j == 2 ? m->dndu : m->dndv, &ds, &dt);
      d += (mreal2)(dot(V, ds), dot(V, dt));
    }
    cols[j] = d;
  }
  *A = m2_cols(cols[0], cols[1]);
  *B = m2_cols(cols[2], cols[3]);
  *C = m2_cols(cols[4], cols[5]);
  return 0;
}
