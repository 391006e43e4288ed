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

// The gaussian filter in units of sigma = r / 4 is exp(-x^2 / 2) less its value at the cut x = 4,
// the offset exp(-8); sqrt(pi / 2) is the integral of exp(-x^2 / 2) over x >= 0, and erfc(2 sqrt 2)
// the share of that integral past the cut.
#define GAUSSIAN_OFFSET exp(-8.0f)
#define GAUSSIAN_SQRT_HALF_PI 1.2533141f
#define GAUSSIAN_ERFC_CUT 6.3342484e-5f

inline float gaussian_tail(float r, float t) {  // integral over [t, r], 0 <= t <= r
  float sigma = 0.25f * r, k = M_SQRT1_2_F / sigma;
  // erfc(r k) = erfc(2 sqrt 2) at the cut r = 4 sigma, whatever r.
  float erfc_t = t > 0.0f ? filter_erfc(t * k) : 1.0f;
  return fmax(sigma * GAUSSIAN_SQRT_HALF_PI * (erfc_t - GAUSSIAN_ERFC_CUT) - GAUSSIAN_OFFSET * (r - t), 0.0f);
}

// Where the gaussian filter's cdf (from -r) reaches `target`, to first order. In units of sigma
// the cdf is F(x) = sqrt(pi/2) (erf(x / sqrt 2) + erf(2 sqrt 2)) - e (x + 4), e the offset;
// x0 = sqrt 2 erfinv((T + 4 e) / sqrt(pi/2) - erf(2 sqrt 2)) leaves the residual
// F(x0) - T = -e x0, below 4e-4 of the peak, which gaussian_halley_step removes in closed form.
// GAUSSIAN_ERFINV_ARGUMENT is the argument of erfinv, also for lanes.
#define GAUSSIAN_ERFINV_ARGUMENT(r, target)                                                               \
  clamp(((target) / (0.25f * (r)) + 4.0f * GAUSSIAN_OFFSET) / GAUSSIAN_SQRT_HALF_PI - (1.0f - GAUSSIAN_ERFC_CUT), \
        -0.9999999f, 0.9999999f)
inline float gaussian_inverse_guess(float r, float target) {
  return 0.25f * r * M_SQRT2_F * erfinv_approx(GAUSSIAN_ERFINV_ARGUMENT(r, target));
}

// One Halley step from the guess t0 (gaussian_inverse_guess) of a pixel the image does not cut,
// where it lies within r / 2 of the centre (95% of the filter's mass); 0 elsewhere. The residual
// -e x0 is known, and the filter f = exp(-x^2 / 2) - e and its slope come from one exp: the step
// is as close to the root as the bracketed Newton steps get (tests/camera/
// test_camera_importance.cpp), which take three exps where this takes one.
// GAUSSIAN_HALLEY(F, x) is the step on x = t0 / sigma in values of type F (float, or lanes).
#define GAUSSIAN_HALLEY(F, x)                                                                         \
  {                                                                                                  \
    F g = exp(-0.5f * x * x), f = g - GAUSSIAN_OFFSET, residual = -GAUSSIAN_OFFSET * x, slope = -x * g; \
    x -= 2.0f * residual * f / (2.0f * f * f - residual * slope);                                    \
  }
inline int gaussian_halley_step(float r, float t0, float* t) {
  float sigma = 0.25f * r, x = t0 / sigma;
  if (!(fabs(x) <= 2.0f)) return 0;
  GAUSSIAN_HALLEY(float, x)
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
    return fmax(exp(-t * t / (2.0f * sigma * sigma)) - GAUSSIAN_OFFSET, 0.0f);
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
    float guess = gaussian_inverse_guess(r, target);
    if (lo == -r && hi == r && gaussian_halley_step(r, guess, &t)) return t;
    t = clamp(guess, lo, hi);
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
