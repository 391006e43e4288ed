// A specular chain x_0 -> x_1 .. x_m -> x_e and its tangent space: with x_0 fixed, the constraints
// c_1 .. c_m tie x_1 .. x_m to x_e. Their block-tridiagonal matrix (2x2 blocks A_i, B_i, C_i,
// constraint.h) is solved by block elimination for dx_1/dx_e, which gives both the Newton step
// (how to move x_1 so that the chain's end moves toward its target) and the generalized geometry
// term |d omega_0 / dA(x_e)| of the chain (Jakob & Marschner 2012, section 4).
#pragma once
#include "manifold/constraint.h"

typedef struct ManifoldChain {
  int count;  // m
  ManifoldSurface x[MANIFOLD_MAX_CHAIN + 2];  // x_0, x_1 .. x_m, x_e
  int flags[MANIFOLD_MAX_CHAIN];
  mreal3 kept[MANIFOLD_MAX_CHAIN];            // near-specular vertices' micro-normals
} ManifoldChain;

// The blocks A_i, C_i of the chain's constraint matrix and the inverse pivots of its block
// elimination (U_1 = B_1, U_i = B_i - A_i U_{i-1}^-1 C_{i-1}). Returns 0 or the
// MANIFOLD_COUNTER_FAIL_* reason.
inline int manifold_factor(const SceneData* sd, const ManifoldChain* ch, M2* A, M2* C, M2* Uinv) {
  const int m = ch->count;
  M2 B[MANIFOLD_MAX_CHAIN];
  for (int i = 0; i < m; ++i) {
    mreal2 c;
    int r = manifold_constraint(sd, &ch->x[i], &ch->x[i + 1], &ch->x[i + 2], ch->flags[i], ch->kept[i], &c, &A[i],
                                &B[i], &C[i]);
    if (r) return r;
  }
  M2 U = B[0];
  for (int i = 0; i < m; ++i) {
    if (i > 0) U = m2_sub(B[i], m2_mul(m2_mul(A[i], Uinv[i - 1]), C[i - 1]));
    if (!m2_inverse(U, &Uinv[i])) return MANIFOLD_COUNTER_FAIL_SINGULAR;
  }
  return 0;
}

// dx_1/dx_e (plane coordinates of x_1 per plane coordinates of x_e, x_0 fixed) at a chain whose
// constraints hold: the right-hand side -C_m dx_e sits in the last row only, so back
// substitution gives X_m = -U_m^-1 C_m, X_i = -U_i^-1 C_i X_{i+1}.
inline M2 manifold_end_back_substitution(int m, const M2* C, const M2* Uinv) {
  M2 X = m2_neg(m2_mul(Uinv[m - 1], C[m - 1]));
  for (int i = m - 2; i >= 0; --i) X = m2_neg(m2_mul(Uinv[i], m2_mul(C[i], X)));
  return X;
}

// The same for chain ch. Returns 0 or the MANIFOLD_COUNTER_FAIL_* reason.
inline int manifold_end_derivative(const SceneData* sd, const ManifoldChain* ch, M2* dx1) {
  M2 A[MANIFOLD_MAX_CHAIN], C[MANIFOLD_MAX_CHAIN], Uinv[MANIFOLD_MAX_CHAIN];
  int r = manifold_factor(sd, ch, A, C, Uinv);
  if (r) return r;
  *dx1 = manifold_end_back_substitution(ch->count, C, Uinv);
  return isfinite(m2_det(*dx1)) ? 0 : MANIFOLD_COUNTER_FAIL_SINGULAR;
}

// Where x_1 moves to first order when x_0 moves to `start` (x_e fixed): the right-hand side
// -A_1 dx_0 sits in the first row only. Returns 0 or the MANIFOLD_COUNTER_FAIL_* reason.
inline int manifold_start_move(const SceneData* sd, const ManifoldChain* ch, mreal3 start, mreal3* x1) {
  const int m = ch->count;
  M2 A[MANIFOLD_MAX_CHAIN], C[MANIFOLD_MAX_CHAIN], Uinv[MANIFOLD_MAX_CHAIN];
  int r = manifold_factor(sd, ch, A, C, Uinv);
  if (r) return r;
  mreal3 d = start - ch->x[0].p;
  mreal2 rhs[MANIFOLD_MAX_CHAIN];
  rhs[0] = -m2_apply(A[0], (mreal2)(dot(d, ch->x[0].dpdu), dot(d, ch->x[0].dpdv)));
  for (int i = 1; i < m; ++i) rhs[i] = -m2_apply(A[i], m2_apply(Uinv[i - 1], rhs[i - 1]));
  mreal2 dx = m2_apply(Uinv[m - 1], rhs[m - 1]);
  for (int i = m - 2; i >= 0; --i) dx = m2_apply(Uinv[i], rhs[i] - m2_apply(C[i], dx));
  if (!isfinite(dx.x) || !isfinite(dx.y)) return MANIFOLD_COUNTER_FAIL_SINGULAR;
  *x1 = ch->x[1].p + dx.x * ch->x[1].dpdu + dx.y * ch->x[1].dpdv;
  return 0;
}

// The solid angle per unit area that vertex `to`, moving by dx (plane coordinates per unit area
// of the moved end), sweeps as seen from `from`.
inline mreal manifold_swept(const ManifoldSurface* from, const ManifoldSurface* to, M2 dx) {
  mreal3 d = to->p - from->p;
  mreal r2 = dot(d, d);
  if (!(r2 > (mreal)0)) return 0;
  mreal cos_to = fabs(dot(d, to->ng)) / sqrt(r2);
  return fabs(m2_det(dx)) * cos_to / r2;
}

// |d omega_0 / dA(x_e)| from dx_1/dx_e: the area x_1 sweeps per unit area of x_e, seen from x_0.
inline mreal manifold_geometry(const ManifoldChain* ch, M2 dx1) { return manifold_swept(&ch->x[0], &ch->x[1], dx1); }

// Both generalized geometry terms of a chain whose constraints hold: |d omega_0 / dA(x_e)| (*g,
// x_0 fixed) and |d omega_e / dA(x_0)| (*g_at_end, x_e fixed), the latter from dx_m/dx_0: the
// right-hand side -A_1 dx_0 sits in the first row only, so forward elimination alone gives it,
// X_m = U_m^-1 (-A_m U_{m-1}^-1) .. (-A_1). Shading normals that vary over flat triangles make
// the chain's map lose etendue, so the one is not the other turned around by the end cosines
// (a photon's density needs the second: gbidir/photon_chain.h). Returns 0 or the
// MANIFOLD_COUNTER_FAIL_* reason.
inline int manifold_geometries(const SceneData* sd, const ManifoldChain* ch, float* g, float* g_at_end) {
  const int m = ch->count;
  M2 A[MANIFOLD_MAX_CHAIN], C[MANIFOLD_MAX_CHAIN], Uinv[MANIFOLD_MAX_CHAIN];
  int r = manifold_factor(sd, ch, A, C, Uinv);
  if (r) return r;
  M2 X1 = manifold_end_back_substitution(m, C, Uinv), Xm = m2_neg(A[0]);
  for (int i = 1; i < m; ++i) Xm = m2_neg(m2_mul(A[i], m2_mul(Uinv[i - 1], Xm)));
  Xm = m2_mul(Uinv[m - 1], Xm);
  if (!isfinite(m2_det(X1)) || !isfinite(m2_det(Xm))) return MANIFOLD_COUNTER_FAIL_SINGULAR;
  *g = (float)manifold_geometry(ch, X1);
  *g_at_end = (float)manifold_swept(&ch->x[m + 1], &ch->x[m], Xm);
  return 0;
}

// The Newton step: where x_1 goes so that the chain's end moves by beta toward `target`.
inline mreal3 manifold_step(const ManifoldChain* ch, M2 dx1, mreal3 target, mreal beta) {
  const ManifoldSurface* e = &ch->x[ch->count + 1];
  mreal3 d = target - e->p;
  mreal2 de = (mreal2)(dot(d, e->dpdu), dot(d, e->dpdv));
  mreal2 d1 = m2_apply(dx1, de) * beta;
  return ch->x[1].p + d1.x * ch->x[1].dpdu + d1.y * ch->x[1].dpdv;
}

// Scattering at a chain vertex about the (unit) normal or micro-normal nm: the direction w_b with
// eta_a w_a + eta_b w_b parallel to nm. Returns 0 on total internal reflection.
inline int manifold_scatter(mreal3 wa, mreal3 nm, int transmit, mreal2 eta, mreal3* wb) {
  mreal ca = dot(wa, nm);
  if (!transmit) {
    *wb = 2 * ca * nm - wa;
    return 1;
  }
  if (ca < (mreal)0) {
    nm = -nm;
    ca = -ca;
  }
  mreal e = eta.x / eta.y;
  mreal sin2b = e * e * fmax((mreal)0, (mreal)1 - ca * ca);
  if (sin2b >= (mreal)1) return 0;
  *wb = -e * wa + (e * ca - sqrt((mreal)1 - sin2b)) * nm;
  return 1;
}
