// Camera rays: Mitsuba's perspective camera (looks along +z, +x left, +y up) with the pixel
// filter importance-sampled, so every sample has weight 1 and lands in its own pixel only.
// Sampling the filter cut to the image converges to what Mitsuba's splatting gives: its samples
// lie uniformly on the sampled region and each pixel divides its filter-weighted sum by the sum
// of its weights, so both tend to the filter-weighted mean over the region.
#pragma once
#include "core/geometry.h"
#include "shared/scene_types.h"

// Pixel filters as Mitsuba defines them, one axis at a time (the 2D filter is the product of
// its two axes): box 1, tent 1 - |t| / r, gaussian exp(-t^2 / 2 s^2) - exp(-r^2 / 2 s^2) with
// r = 4 s, all on [-r, r]. filter_cdf is the filter's integral from -r to t.
// erfc(x) for x >= 0 (Abramowitz & Stegun 7.1.26, absolute error below 1.5e-7): the library's
// erfc costs tens of nanoseconds a call on PoCL, enough to make sampling the gaussian filter
// outweigh a bounce's shading.
inline float filter_erfc(float x) {
  float t = 1.0f / (1.0f + 0.3275911f * x);
  float poly = t * (0.254829592f + t * (-0.284496736f + t * (1.421413741f + t * (-1.453152027f + t * 1.061405429f))));
  return poly * exp(-x * x);
}

inline float gaussian_tail(float r, float t) {  // integral over [t, r], 0 <= t <= r
  float sigma = 0.25f * r, k = M_SQRT1_2_F / sigma;
  // erfc(r k) = erfc(2 sqrt 2) at the cut r = 4 sigma, whatever r.
  const float sqrt_half_pi = 1.2533141f, bias = exp(-8.0f), erfc_cut = 6.3342484e-5f;
  float erfc_t = t > 0.0f ? filter_erfc(t * k) : 1.0f;
  return fmax(sigma * sqrt_half_pi * (erfc_t - erfc_cut) - bias * (r - t), 0.0f);
}

// Where the gaussian filter's cdf reaches `target`, ignoring its cut at r and its offset (both
// below 4e-4 of its peak): the start of the Newton steps that invert the filter's own cdf, which
// then take one or two steps instead of five or more from the centre.
inline float gaussian_inverse_guess(float r, float target) {
  float sigma = 0.25f * r;
  const float sqrt_half_pi = 1.2533141f;
  float x = clamp(target / (sigma * sqrt_half_pi) - 1.0f, -0.9999999f, 0.9999999f);
  return sigma * M_SQRT2_F * erfinv_approx(x);
}

// The gaussian's inverse cdf over its whole support (a pixel the image does not cut) at `target`,
// in one step where it lies within r / 2 of the centre (95% of the filter's mass); 0 elsewhere.
// In units of sigma the cdf is F(x) = sqrt(pi/2) (erf(x / sqrt 2) + erf(2 sqrt 2)) - e (x + 4),
// e = exp(-8) the offset. x0 = sqrt 2 erfinv((T + 4 e) / sqrt(pi/2) - erf(2 sqrt 2)) leaves the
// residual F(x0) - T = -e x0 in closed form, and one Halley step from there (the filter
// f = exp(-x^2 / 2) - e and its slope known from one exp) is as close to the root as the
// bracketed Newton steps get for |x0| <= 2 (tests/camera/test_camera_importance.cpp). Those took a
// log and three exps an axis, this a log and one.
inline int gaussian_central_inverse(float r, float target, float* t) {
  float sigma = 0.25f * r;
  const float sqrt_half_pi = 1.2533141f, e = exp(-8.0f), erf_cut = 1.0f - 6.3342484e-5f;
  float y = (target / sigma + 4.0f * e) / sqrt_half_pi - erf_cut;
  if (!(fabs(y) <= 0.95449974f)) return 0;  // erf(sqrt 2): |x0| <= 2
  float x = M_SQRT2_F * erfinv_approx(y);
  float g = exp(-0.5f * x * x), f = g - e, residual = -e * x, slope = -x * g;
  x -= 2.0f * residual * f / (2.0f * f * f - residual * slope);
  *t = clamp(sigma * x, -r, r);
  return 1;
}

inline float filter_cdf(int filter, float r, float t) {
  t = clamp(t, -r, r);
  if (filter == FILTER_TENT) return t <= 0.0f ? (t + r) * (t + r) / (2.0f * r) : r - (r - t) * (r - t) / (2.0f * r);
  if (filter == FILTER_GAUSSIAN) {
    // The ends of the support, where every range the image does not cut starts and ends, in
    // closed form: the tail past the cut is 0 there by construction (no erfc: sampling an uncut
    // pixel's filter took two of them an axis).
    if (t == -r) return 0.0f;
    if (t == r) return 2.0f * gaussian_tail(r, 0.0f);
    // erfc keeps the tails accurate where erf would cancel.
    return t <= 0.0f ? gaussian_tail(r, -t) : 2.0f * gaussian_tail(r, 0.0f) - gaussian_tail(r, t);
  }
  return t + r;
}

inline float filter_eval(int filter, float r, float t) {
  if (fabs(t) > r) return 0.0f;
  if (filter == FILTER_TENT) return 1.0f - fabs(t) / r;
  if (filter == FILTER_GAUSSIAN) {
    float sigma = 0.25f * r;
    return fmax(exp(-t * t / (2.0f * sigma * sigma)) - exp(-8.0f), 0.0f);
  }
  return 1.0f;
}

// The filter's mass over the offsets [range.x, range.y] a pixel may sample.
inline float filter_mass(int filter, float r, float2 range) {
  return filter_cdf(filter, r, range.y) - filter_cdf(filter, r, range.x);
}

// An offset drawn from the filter restricted to [range.x, range.y] (inside [-r, r]), by
// inverting its cdf: closed forms for box and tent, bracketed Newton steps for the gaussian.
inline float sample_filter_axis(int filter, float r, float2 range, float u) {
  float lo = range.x, hi = range.y;
  if (filter == FILTER_BOX) return clamp(mix(lo, hi, u), lo, hi);
  float target = mix(filter_cdf(filter, r, lo), filter_cdf(filter, r, hi), u);
  float t;
  if (filter == FILTER_TENT) {
    t = target <= 0.5f * r ? -r + sqrt(2.0f * r * target) : r - sqrt(fmax(2.0f * r * (r - target), 0.0f));
  } else {
    if (lo == -r && hi == r && gaussian_central_inverse(r, target, &t)) return t;
    t = clamp(gaussian_inverse_guess(r, target), lo, hi);
    for (int i = 0; i < 32; ++i) {
      float e = filter_cdf(filter, r, t) - target;
      // Within a few float steps of the cdf (at most 0.63 r): in the tails, where the filter is
      // small, Newton's step size alone would not get there before the bracket closes.
      if (fabs(e) <= 1.5e-7f * r) break;
      if (e > 0.0f) hi = t;
      else lo = t;
      float d = filter_eval(filter, r, t), next = t - e / d;
      if (!(d > 0.0f) || !(next >= lo && next <= hi)) next = 0.5f * (lo + hi);
      float step = fabs(next - t);
      t = next;
      if (step <= 1e-6f * r) break;
    }
  }
  return clamp(t, range.x, range.y);
}

// The film offsets, from the centre of pixel p of an axis of `size` pixels, that its filter
// sample may take: the filter's support, cut at the image's edges unless the film samples its
// border (Mitsuba's sample_border, default false: no sample is taken outside the image, and
// a border pixel is the filter-weighted mean over the part of its footprint inside it).
inline float2 filter_range(const GdrCamera* cam, int p, int size) {
  float r = cam->filter_radius;
  if (cam->sample_border) return (float2)(-r, r);
  float centre = (float)p + 0.5f;
  return (float2)(fmax(-r, -centre), fmin(r, (float)size - centre));
}

// The ray through film position (fx, fy) in pixels from the top-left corner.
inline void camera_ray(const GdrCamera* cam, float fx, float fy, float3* origin, float3* dir, float* tnear, float* tfar) {
  float3 d = (float3)((1.0f - 2.0f * fx / (float)cam->width) * cam->tan_half_fov_x,
                          (1.0f - 2.0f * fy / (float)cam->height) * cam->tan_half_fov_y, 1.0f);
  d = normalize(d);
  *origin = xform_point(cam->to_world, (float3)(0.0f, 0.0f, 0.0f));
  *dir = normalize(xform_vector(cam->to_world, d));
  *tnear = cam->near_clip / d.z;
  *tfar = cam->far_clip / d.z;
}
