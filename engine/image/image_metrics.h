// Error of an image against a reference, in the forms the rendering literature reports, and a
// false-colour picture of where the error is.
#pragma once
#include <string>

#include "image/image.h"

namespace gdr {

struct ImageError {
  double rel_mse = 0;  // mean over pixels and channels of (a - b)^2 / (b^2 + 1e-2)
  double mse = 0;      // mean of (a - b)^2
  double mape = 0;     // mean of |a - b| / (|b| + 1e-2)
  size_t values = 0;   // values compared (non-finite ones in either image are skipped)
  size_t skipped = 0;
};

// Compares the R,G,B channels of `a` against reference `b`; throws gdr::Error when the sizes differ.
ImageError compare_images(const Image& a, const Image& b);

// Per-pixel relMSE (averaged over RGB) mapped through a perceptual colour ramp on a log scale
// from 1e-4 (dark blue) to 1 (yellow); R,G,B channels only.
Image error_image(const Image& a, const Image& b);

}  // namespace gdr
