// The gaussian filter's common case in eight lanes: sample_filter_axis (camera/camera.h) for
// pixels the image does not cut, where gaussian_inverse_guess takes erfinv's central branch and
// gaussian_halley_step applies (samples within r / 2 of the centre, about 95% of them), by the
// same operations. The other lanes, and the other filters, take sample_filter_axis.
#pragma once
#include "camera/camera.h"
#include "core/lanes.h"

// Offsets drawn with u for uncut pixels; *served marks the lanes whose offset this is.
inline float8 gaussian_uncut_offset_lanes(float r, float8 u, int8* served) {
  // sample_filter_axis's target over the uncut range [-r, r].
  float8 target = mix((float8)(filter_cdf(FILTER_GAUSSIAN, r, -r)), (float8)(filter_cdf(FILTER_GAUSSIAN, r, r)), u);
  float8 y = GAUSSIAN_ERFINV_ARGUMENT(r, target);
  float8 w = ERFINV_W(y), p;
  int8 central = w < 5.0f;
  ERFINV_CENTRAL(p, w)
  float sigma = 0.25f * r;
  float8 x = (sigma * M_SQRT2_F * (p * y)) / sigma;
  *served = central & (fabs(x) <= 2.0f);
  GAUSSIAN_HALLEY(float8, x)
  return clamp(sigma * x, -r, r);
}
