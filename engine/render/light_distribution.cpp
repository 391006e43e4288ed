#include "render/light_distribution.h"

#include <cmath>

#include "scene/scene.h"
#include "shared/color.h"

namespace gdr {
namespace {

float triangle_area(const Scene& s, int t) {
  const GdrTriangle& tri = s.triangles[t];
  const Vec4 &a = s.positions[tri.v[0]], &b = s.positions[tri.v[1]], &c = s.positions[tri.v[2]];
  float ux = b.x - a.x, uy = b.y - a.y, uz = b.z - a.z;
  float vx = c.x - a.x, vy = c.y - a.y, vz = c.z - a.z;
  float cx = uy * vz - uz * vy, cy = uz * vx - ux * vz, cz = ux * vy - uy * vx;
  return 0.5f * std::sqrt(cx * cx + cy * cy + cz * cz);
}

// Power up to constant factors shared by all types (pbrt's Light::Phi).
float light_power(const Scene& s, const GdrLight& l) {
  constexpr float pi = 3.14159265f;
  float radius = l.scene_radius > 0 ? l.scene_radius : 1.0f;
  float lum = gdr_luminance(l.radiance[0], l.radiance[1], l.radiance[2]);
  switch (l.type) {
    case LIGHT_AREA: return pi * lum * triangle_area(s, l.triangle);
    case LIGHT_POINT: return 4 * pi * lum;
    case LIGHT_SPOT: return 2 * pi * lum * (1 - 0.5f * (l.cos_falloff + l.cos_cutoff));
    case LIGHT_DIRECTIONAL: return pi * radius * radius * lum;
    case LIGHT_CONSTANT:
    case LIGHT_ENVMAP: return 4 * pi * pi * radius * radius * lum;
  }
  return 0;
}

}  // namespace

std::vector<float> light_selection_cdf(const Scene& scene) {
  size_t n = scene.lights.size();
  if (n == 0) return {};
  std::vector<double> power(n);
  double total = 0;
  for (size_t i = 0; i < n; ++i) {
    double p = light_power(scene, scene.lights[i]);
    power[i] = std::isfinite(p) && p > 0 ? p : 0.0;
    total += power[i];
  }
  std::vector<float> cdf(n + 1, 0.0f);
  double acc = 0;
  for (size_t i = 0; i < n; ++i) {
    // Lights whose power is unknown or zero share the probability evenly.
    acc += total > 0 ? power[i] / total : 1.0 / n;
    cdf[i + 1] = static_cast<float>(acc);
  }
  cdf[n] = 1.0f;
  return cdf;
}

}  // namespace gdr
