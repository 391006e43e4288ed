// Error of an image against a reference, in the forms the rendering literature reports, and a
// false-colour picture of where the error is.
#pragma once
#include <string>
#include <vector>

#include "image/image.h"

namespace gdr {

struct ImageError {
  double rel_mse = 0;  // mean over pixels and channels of (a - b)^2 / (b^2 + 1e-2)
  double mse = 0;      // mean of (a - b)^2
  double mape = 0;     // mean of |a - b| / (|b| + 1e-2)
  double brightness = 0;  // mean of a over mean of b (1: as bright as the reference; 0 when b's mean is 0)
  size_t values = 0;   // values compared (non-finite ones in either image are skipped)
  size_t skipped = 0;
};

// The R,G,B channels of one or several renders of one image (independent seeds) against a
// reference: the mean of their
// errors, and the relMSE split into bias^2 and variance. Per value (pixel and channel) with
// mean m and unbiased sample variance s^2 over the K runs, the mean relMSE is
// (m - ref)^2 + (K-1)/K s^2 (over ref^2 + 1e-2), whose expectation is bias^2 + variance:
// `variance` estimates the second part by s^2, `bias2` the first as the rest (so it can come out
// slightly below 0 by chance; it also holds the reference's own error, fixed across the runs).
struct ImageSetError {
  ImageError mean;        // the runs' rel_mse, mse, mape and brightness averaged; values compared
  double bias2 = 0;       // relMSE share of the runs' common error
  double variance = 0;    // relMSE share of their spread (0 for one run)
  size_t runs = 0;
};
// Throws gdr::Error for no runs or when a size differs. Values non-finite in any image are skipped.
ImageSetError compare_image_set(const std::vector<Image>& runs, const Image& reference);

// Per-pixel relMSE (averaged over RGB) mapped through a perceptual colour ramp on a log scale
// from 1e-4 (dark blue) to 1 (yellow); R,G,B channels only.
Image error_image(const Image& a, const Image& b);

}  // namespace gdr
