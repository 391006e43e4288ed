// Local shading frames: z is the shading normal, x the tangent (alpha_u), y the bitangent.
// Trigonometry in that frame, reflection, and an orthonormal basis around a normal.
#pragma once
#include "core/math.h"

inline float cos_theta(float3 w) { return w.z; }
inline float cos2_theta(float3 w) { return w.z * w.z; }
inline float sin2_theta(float3 w) { return fmax(0.0f, 1.0f - w.z * w.z); }

// Mirror of w about the frame normal (0, 0, 1).
inline float3 reflect_local(float3 w) { return (float3)(-w.x, -w.y, w.z); }

// Mirror of w about the unit vector m.
inline float3 reflect_about(float3 w, float3 m) { return 2.0f * dot(w, m) * m - w; }

// (sin phi, cos phi) of w's projection on the tangent plane; (0, 1) at the pole.
inline float2 sincos_phi(float3 w) {
  float r2 = w.x * w.x + w.y * w.y;
  if (!(r2 > 1e-30f)) return (float2)(0.0f, 1.0f);
  float inv_r = rsqrt(r2);
  return (float2)(clamp(w.y * inv_r, -1.0f, 1.0f), clamp(w.x * inv_r, -1.0f, 1.0f));
}

typedef struct Frame {
  float3 s, t, n;
} Frame;

// Orthonormal basis around the unit normal n (Duff et al. 2017, branchless and continuous).
inline Frame frame_from_normal(float3 n) {
  float sign = n.z >= 0.0f ? 1.0f : -1.0f;
  float a = -1.0f / (sign + n.z);
  float b = n.x * n.y * a;
  Frame f;
  f.s = (float3)(1.0f + sign * n.x * n.x * a, sign * b, -sign * n.x);
  f.t = (float3)(b, sign + n.y * n.y * a, -n.y);
  f.n = n;
  return f;
}

inline float3 frame_to_local(const Frame* f, float3 v) {
  return (float3)(dot(v, f->s), dot(v, f->t), dot(v, f->n));
}

inline float3 frame_to_world(const Frame* f, float3 v) {
  return f->s * v.x + f->t * v.y + f->n * v.z;
}
