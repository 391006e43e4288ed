// Scalar and vector helpers with the numerical guards every kernel needs: square roots of values
// that rounding pushed below zero, divisions by (near) zero, and NaN/Inf that must never escape.
#pragma once

#define GDR_INV_SQRT_PI 0.56418958354775628f

inline float sqr(float x) { return x * x; }

// sqrt of a value that is mathematically >= 0 but may be slightly negative after rounding.
inline float safe_sqrt(float x) { return sqrt(fmax(x, 0.0f)); }

// a / b, or 0 when b is 0 or the quotient is not finite.
inline float safe_div(float a, float b) {
  float q = (b != 0.0f) ? a / b : 0.0f;
  return isfinite(q) ? q : 0.0f;
}

inline float finite_or_zero(float x) { return isfinite(x) ? x : 0.0f; }

inline float3 finite_or_zero3(float3 v) {
  return (isfinite(v.x) && isfinite(v.y) && isfinite(v.z)) ? v : (float3)(0.0f);
}

inline int is_finite3(float3 v) { return isfinite(v.x) && isfinite(v.y) && isfinite(v.z); }

// a with the sign of b (b == +0 counts as positive).
inline float mulsign(float a, float b) { return b >= 0.0f ? a : -a; }

inline float mean3(float3 v) { return (v.x + v.y + v.z) * (1.0f / 3.0f); }

// Normalizes v, or returns `fallback` when v is (nearly) zero or not finite.
inline float3 normalize_or(float3 v, float3 fallback) {
  float len2 = dot(v, v);
  if (!(len2 > 1e-30f) || !isfinite(len2)) return fallback;
  return v * rsqrt(len2);
}

// Inverse error function (Giles 2010, single precision, |error| ~ 4e-7); x in (-1, 1).
// ERFINV_W and ERFINV_CENTRAL (the branch w < 5, p from w) are also written out for lanes.
#define ERFINV_W(x) (-log(fmax((1.0f - (x)) * (1.0f + (x)), 1e-38f)))
#define ERFINV_CENTRAL(p, w)              \
  w = w - 2.5f;                           \
  p = 2.81022636e-08f;                    \
  p = 3.43273939e-07f + p * w;            \
  p = -3.5233877e-06f + p * w;            \
  p = -4.39150654e-06f + p * w;           \
  p = 0.00021858087f + p * w;             \
  p = -0.00125372503f + p * w;            \
  p = -0.00417768164f + p * w;            \
  p = 0.246640727f + p * w;               \
  p = 1.50140941f + p * w;
inline float erfinv_approx(float x) {
  float w = ERFINV_W(x);
  float p;
  if (w < 5.0f) {
    ERFINV_CENTRAL(p, w)
  } else {
    w = sqrt(w) - 3.0f;
    p = -0.000200214257f;
    p = 0.000100950558f + p * w;
    p = 0.00134934322f + p * w;
    p = -0.00367342844f + p * w;
    p = 0.00573950773f + p * w;
    p = -0.0076224613f + p * w;
    p = 0.00943887047f + p * w;
    p = 1.00167406f + p * w;
    p = 2.83297682f + p * w;
  }
  return p * x;
}

// atan2(y, x) in (-pi, pi], within about 3e-7 of it (atan2_approx(0, 0) = 0 whatever the zeros' signs):
// PoCL's atan2 is an out-of-line call that took 3% of a render of Mitsuba's material-preview
// scene. The angle of the smaller over the larger magnitude, reduced past tan(pi/8) by
// atan(a) = pi/4 + atan((a - 1) / (a + 1)), from Cephes' atanf polynomial.
// Written once for values of type F (float here, float8 in core/lanes.h).
#define ATAN2_APPROX(name, F)                                                                          \
  inline F name(F y, F x) {                                                                            \
    F ax = fabs(x), ay = fabs(y), hi = fmax(ax, ay), lo = fmin(ax, ay);                                \
    F a = select((F)(0.0f), lo / hi, hi > 0.0f);                                                       \
    F t = select(a, (a - 1.0f) / (a + 1.0f), a > 0.41421356f), z = t * t;                              \
    F r = select((F)(0.0f), (F)(M_PI_4_F), a > 0.41421356f) +                                          \
          ((((8.05374449538e-2f * z - 1.38776856032e-1f) * z + 1.99777106478e-1f) * z - 3.33329491539e-1f) * z * t + t); \
    r = select(r, M_PI_2_F - r, ay > ax);                                                              \
    r = select(r, M_PI_F - r, x < 0.0f);                                                               \
    return select(r, -r, y < 0.0f);                                                                    \
  }
ATAN2_APPROX(atan2_approx, float)
