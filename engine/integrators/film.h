// Films are device buffers of per-pixel sums (float4, w unused); images want interleaved RGB
// means.
#pragma once
#include <vector>

#include "device/context.h"
#include "scene/scene.h"

namespace gdr {

// The film's RGB times `scale` (1 / samples), interleaved.
inline std::vector<float> film_rgb(const Buffer<Vec4>& film, float scale) {
  std::vector<Vec4> v = film.read();
  std::vector<float> rgb(v.size() * 3);
  for (size_t i = 0; i < v.size(); ++i) {
    rgb[3 * i + 0] = v[i].x * scale;
    rgb[3 * i + 1] = v[i].y * scale;
    rgb[3 * i + 2] = v[i].z * scale;
  }
  return rgb;
}

}  // namespace gdr
