// A render's per-pixel sums on the device, as named layers (float4 per pixel, w unused):
// cleared at the start of a render, summed by the kernels pass after pass, and turned into
// interleaved-RGB means at the end. The film knows its layers, so code that sums or saves them
// (all layers of any integrator) needs no integrator of its own. Under MPI the reads below are
// also the reductions (cluster/reduce.h): every rank calls them in the same order, and rank 0
// gets the sums of all ranks' passes; the others get their own.
#pragma once
#include <map>
#include <string>
#include <vector>

#include "device/context.h"
#include "scene/scene.h"

namespace gdr {

class Film {
 public:
  Film(Context& context, int width, int height, const std::vector<std::string>& layers);

  int width() const { return width_; }
  int height() const { return height_; }
  size_t pixels() const { return size_t(width_) * height_; }

  // The layer's sums (the kernels' argument); throws Error for a layer the film lacks.
  Buffer<Vec4>& operator[](const std::string& layer);
  const Buffer<Vec4>& operator[](const std::string& layer) const;

  void clear();
  // The layer's mean over `samples` passes (of all ranks), interleaved RGB.
  std::vector<float> mean_rgb(const std::string& layer, int samples) const;

  Stats* stats() const { return stats_; }

 private:
  int width_, height_;
  Stats* stats_;
  std::map<std::string, Buffer<Vec4>> layers_;
};

// 1 / samples, the factor that turns sums into means (0 before any sample).
inline float mean_scale(int samples) { return samples > 0 ? 1.0f / samples : 0.0f; }

// The buffer's RGB times `scale`, interleaved.
std::vector<float> film_rgb(const Buffer<Vec4>& sums, float scale);
// The same of the buffer's sums over all ranks (on rank 0; the rank's own elsewhere).
std::vector<float> reduced_rgb(const Buffer<Vec4>& sums, float scale, Stats* stats);

// The mean of a set of passes and its per-pixel variance (interleaved RGB). The variance is
// estimated over passes, not over the paths inside one: each pass adds one sample per pixel and
// passes are independent and identically distributed, while inside a pass a gradient-domain
// pixel combines paths it shares with its neighbours. m2 / (passes - 1) is the unbiased variance
// of one pass, and dividing by passes again gives that of their mean, the error the image
// carries. 0 with fewer than 2 passes.
struct PassEstimate {
  int passes = 0;
  std::vector<float> mean, variance;
};

// From a layer of sums and one of summed squared deviations (kernels/path/film.h:
// film_add_moments) over this rank's `held` passes, joined with the other ranks' into the
// estimate of all `passes` (on rank 0; the rank's own elsewhere).
PassEstimate pass_estimate(const Buffer<Vec4>& sum, const Buffer<Vec4>& m2, int held, int passes, Stats* stats);

// Two disjoint sets of passes of the same pixels as one (the pairwise update of Chan, Golub and
// LeVeque, in double).
PassEstimate combine(const PassEstimate& a, const PassEstimate& b);

}  // namespace gdr
