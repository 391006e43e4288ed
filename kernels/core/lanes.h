// Arithmetic on eight paths at once, for kernels written eight paths a work item (CPU devices:
// PoCL widens no shading kernel across work items by itself, README "Tests and benchmarks").
// A lane's 3-vector is one component of three float8 values; comparisons give int8 masks (-1
// where true) for select(). Each helper is its float3 namesake's arithmetic, lane by lane.
#pragma once
#include "core/math.h"

#define LANES 8

typedef struct {
  float8 x, y, z;
} Lanes3;

// Per-lane values kept component-major in private memory between the lane and per-lane steps.
typedef struct {
  float x[LANES], y[LANES], z[LANES];
} LaneArray3;

inline void lane_array3_set(LaneArray3* a, int k, float3 v) {
  a->x[k] = v.x;
  a->y[k] = v.y;
  a->z[k] = v.z;
}
inline float3 lane_array3_get(const LaneArray3* a, int k) { return (float3)(a->x[k], a->y[k], a->z[k]); }
inline Lanes3 lanes3_load(const LaneArray3* a) {
  Lanes3 v = {vload8(0, a->x), vload8(0, a->y), vload8(0, a->z)};
  return v;
}
inline void lanes3_store(Lanes3 v, LaneArray3* a) {
  vstore8(v.x, 0, a->x);
  vstore8(v.y, 0, a->y);
  vstore8(v.z, 0, a->z);
}

inline Lanes3 lanes3_sub(Lanes3 a, Lanes3 b) {
  Lanes3 v = {a.x - b.x, a.y - b.y, a.z - b.z};
  return v;
}
inline Lanes3 lanes3_cross(Lanes3 a, Lanes3 b) {
  Lanes3 v = {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
  return v;
}
inline Lanes3 lanes3_mul(Lanes3 a, Lanes3 b) {
  Lanes3 v = {a.x * b.x, a.y * b.y, a.z * b.z};
  return v;
}
inline Lanes3 lanes3_scale(Lanes3 a, float8 s) {
  Lanes3 v = {a.x * s, a.y * s, a.z * s};
  return v;
}
inline float8 lanes3_dot(Lanes3 a, Lanes3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline float8 lanes3_max(Lanes3 a) { return fmax(a.x, fmax(a.y, a.z)); }
inline int8 lanes3_finite(Lanes3 a) { return isfinite(a.x) & isfinite(a.y) & isfinite(a.z); }
// finite_or_zero3, fmax(v, 0), and a lane-wise select (b where take_b).
inline Lanes3 lanes3_finite_or_zero(Lanes3 v) {
  int8 ok = lanes3_finite(v);
  Lanes3 r = {select((float8)(0.0f), v.x, ok), select((float8)(0.0f), v.y, ok), select((float8)(0.0f), v.z, ok)};
  return r;
}

inline Lanes3 lanes3_fmax0(Lanes3 v) {
  Lanes3 r = {fmax(v.x, 0.0f), fmax(v.y, 0.0f), fmax(v.z, 0.0f)};
  return r;
}

inline Lanes3 lanes3_select(Lanes3 a, Lanes3 b, int8 take_b) {
  Lanes3 r = {select(a.x, b.x, take_b), select(a.y, b.y, take_b), select(a.z, b.z, take_b)};
  return r;
}

// frame_from_normal's basis around unit normals n, and the changes of frame.
typedef struct {
  Lanes3 s, t, n;
} FrameLanes;

inline FrameLanes frame_lanes_from_normal(Lanes3 n) {
  float8 sign = select((float8)(-1.0f), (float8)(1.0f), n.z >= 0.0f);
  float8 a = -1.0f / (sign + n.z);
  float8 b = n.x * n.y * a;
  FrameLanes f;
  f.s.x = 1.0f + sign * n.x * n.x * a;
  f.s.y = sign * b;
  f.s.z = -sign * n.x;
  f.t.x = b;
  f.t.y = sign + n.y * n.y * a;
  f.t.z = -n.y;
  f.n = n;
  return f;
}

inline Lanes3 frame_lanes_to_local(const FrameLanes* f, Lanes3 v) {
  Lanes3 l = {lanes3_dot(v, f->s), lanes3_dot(v, f->t), lanes3_dot(v, f->n)};
  return l;
}

inline Lanes3 frame_lanes_to_world(const FrameLanes* f, Lanes3 v) {
  Lanes3 w = {f->s.x * v.x + f->t.x * v.y + f->n.x * v.z, f->s.y * v.x + f->t.y * v.y + f->n.y * v.z,
              f->s.z * v.x + f->t.z * v.y + f->n.z * v.z};
  return w;
}

// xform_vector (core/geometry.h) by the 3x4 matrix m.
inline Lanes3 xform_vector_lanes(__global const float* m, Lanes3 v) {
  Lanes3 r = {m[0] * v.x + m[1] * v.y + m[2] * v.z, m[4] * v.x + m[5] * v.y + m[6] * v.z,
              m[8] * v.x + m[9] * v.y + m[10] * v.z};
  return r;
}

// normalize_or(v, 0).
inline Lanes3 lanes3_normalize_or_zero(Lanes3 v) {
  float8 len2 = lanes3_dot(v, v);
  float8 k = select((float8)(0.0f), rsqrt(len2), (len2 > 1e-30f) & isfinite(len2));
  return lanes3_scale(v, k);
}

// sin(pi y) and cos(pi y) for |y| <= 1/4 by their Taylor series to the ninth power (error below
// 4e-7), in values of type F: PoCL's cospi and sinpi are calls, which no lane code should hold.
#define SINCOSPI_QUARTER(name, F)                                                                        \
  inline void name(F y, F* s, F* c) {                                                                    \
    F x = M_PI_F * y, x2 = x * x;                                                                        \
    *s = x * (1.0f + x2 * (-1.0f / 6.0f + x2 * (1.0f / 120.0f + x2 * (-1.0f / 5040.0f + x2 * (1.0f / 362880.0f))))); \
    *c = 1.0f + x2 * (-0.5f + x2 * (1.0f / 24.0f + x2 * (-1.0f / 720.0f + x2 * (1.0f / 40320.0f))));    \
  }
SINCOSPI_QUARTER(sincospi_quarter, float)
SINCOSPI_QUARTER(sincospi_quarter_lanes, float8)
ATAN2_APPROX(atan2_approx_lanes, float8)

// sin(pi y) and cos(pi y) for any y: the quarter-period polynomial after taking out the nearest
// multiple n of 1/2, then the rotation by n quarter turns.
inline void sincospi_lanes(float8 y, float8* s, float8* c) {
  float8 n = rint(2.0f * y);
  float8 sr, cr;
  sincospi_quarter_lanes(y - 0.5f * n, &sr, &cr);
  int8 q = convert_int8(n) & 3;
  int8 swap = (q & 1) != 0;
  float8 s1 = select(sr, cr, swap), c1 = select(cr, -sr, swap);
  int8 flip = q >= 2;
  *s = select(s1, -s1, flip);
  *c = select(c1, -c1, flip);
}

// square_to_cosine_hemisphere (core/warp.h) of (u0, u1): the concentric disk's branches as selects,
// its angle phi in units of pi within [-1/4, 3/4], folded to |phi| <= 1/4 for the polynomial.
inline Lanes3 square_to_cosine_hemisphere_lanes(float8 u0, float8 u1) {
  float8 x = 2.0f * u0 - 1.0f, y = 2.0f * u1 - 1.0f;
  int8 wide = fabs(x) > fabs(y);
  float8 r = select(y, x, wide);
  float8 ratio = select(x, y, wide) / select(r, (float8)(1.0f), r == 0.0f);
  float8 phi = select(0.5f - 0.25f * ratio, 0.25f * ratio, wide);
  int8 far = phi > 0.25f;
  float8 s, c;
  sincospi_quarter_lanes(select(phi, 0.5f - phi, far), &s, &c);
  Lanes3 w;
  w.x = r * select(c, s, far);
  w.y = r * select(s, c, far);
  w.z = sqrt(fmax(1.0f - w.x * w.x - w.y * w.y, 0.0f));
  return w;
}
