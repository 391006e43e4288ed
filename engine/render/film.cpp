#include "render/film.h"

#include <algorithm>

#include "util/error.h"

namespace gdr {

Film::Film(Context& ctx, int width, int height, const std::vector<std::string>& layers)
    : width_(width), height_(height) {
  for (const std::string& name : layers) layers_.emplace(name, Buffer<Vec4>(ctx, pixels()));
}

Buffer<Vec4>& Film::operator[](const std::string& layer) {
  auto it = layers_.find(layer);
  if (it == layers_.end()) throw Error("film has no layer '" + layer + "'");
  return it->second;
}

const Buffer<Vec4>& Film::operator[](const std::string& layer) const {
  return const_cast<Film&>(*this)[layer];
}

void Film::clear() {
  for (auto& [name, buffer] : layers_) buffer.fill(Vec4{});
}

std::vector<float> Film::mean_rgb(const std::string& layer, int samples) const {
  return film_rgb((*this)[layer], mean_scale(samples));
}

std::vector<float> film_rgb(const Buffer<Vec4>& sums, float scale) {
  std::vector<Vec4> v = sums.read();
  std::vector<float> rgb(v.size() * 3);
  for (size_t i = 0; i < v.size(); ++i) {
    rgb[3 * i + 0] = v[i].x * scale;
    rgb[3 * i + 1] = v[i].y * scale;
    rgb[3 * i + 2] = v[i].z * scale;
  }
  return rgb;
}

std::vector<float> variance_of_mean(const std::vector<float>& mean, const std::vector<float>& mean_square,
                                    int samples) {
  std::vector<float> variance(mean.size());
  for (size_t i = 0; i < mean.size(); ++i) {
    double var = std::max(0.0, double(mean_square[i]) - double(mean[i]) * mean[i]);
    variance[i] = samples > 1 ? float(var / (samples - 1)) : 0.0f;
  }
  return variance;
}

}  // namespace gdr
