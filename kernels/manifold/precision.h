// The precision of the manifold solve: double where the device has cl_khr_fp64 and the build
// asks for it (GDR_MANIFOLD_FP64), float elsewhere. Positions come from the scene's float
// buffers and rays are traced in float either way; the constraint derivatives, the block solve
// and the Newton step run in `mreal`.
#pragma once

#if defined(GDR_MANIFOLD_FP64)
#pragma OPENCL EXTENSION cl_khr_fp64 : enable
typedef double mreal;
typedef double2 mreal2;
typedef double3 mreal3;
#define to_mreal3(v) convert_double3(v)
#define to_float3(v) convert_float3(v)
#define MREAL_EPS 1e-12  // relative size of a pivot below which a block is singular
#else
typedef float mreal;
typedef float2 mreal2;
typedef float3 mreal3;
#define to_mreal3(v) (v)
#define to_float3(v) (v)
#define MREAL_EPS 1e-6f
#endif

// A 2x2 matrix [a b; c d].
typedef struct M2 {
  mreal a, b, c, d;
} M2;

inline M2 m2(mreal a, mreal b, mreal c, mreal d) {
  M2 m = {a, b, c, d};
  return m;
}
inline M2 m2_cols(mreal2 c0, mreal2 c1) { return m2(c0.x, c1.x, c0.y, c1.y); }
inline M2 m2_mul(M2 x, M2 y) {
  return m2(x.a * y.a + x.b * y.c, x.a * y.b + x.b * y.d, x.c * y.a + x.d * y.c, x.c * y.b + x.d * y.d);
}
inline M2 m2_sub(M2 x, M2 y) { return m2(x.a - y.a, x.b - y.b, x.c - y.c, x.d - y.d); }
inline M2 m2_neg(M2 x) { return m2(-x.a, -x.b, -x.c, -x.d); }
inline mreal m2_det(M2 x) { return x.a * x.d - x.b * x.c; }
inline mreal2 m2_apply(M2 x, mreal2 v) { return (mreal2)(x.a * v.x + x.b * v.y, x.c * v.x + x.d * v.y); }
inline mreal m2_norm(M2 x) { return fmax(fmax(fabs(x.a), fabs(x.b)), fmax(fabs(x.c), fabs(x.d))); }

// The inverse; 0 where the matrix is singular relative to its own size.
inline int m2_inverse(M2 x, M2* out) {
  mreal det = m2_det(x), n = m2_norm(x);
  if (!(fabs(det) > MREAL_EPS * n * n) || !isfinite(det)) return 0;
  mreal r = (mreal)1 / det;
  *out = m2(x.d * r, -x.b * r, -x.c * r, x.a * r);
  return 1;
}
