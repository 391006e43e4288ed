// The scene's triangles in an Embree BVH, and the two queries the integrators need: closest hit
// and occlusion, over whole ray queues split across the host threads.
#pragma once
#include <embree3/rtcore.h>

#include <cstddef>

#include "shared/ray_types.h"

namespace gdr {

struct Scene;
class Stats;

enum class BuildQuality { Low, Medium, High };

class EmbreeScene {
 public:
  EmbreeScene(const Scene& scene, BuildQuality quality, Stats* stats = nullptr);
  ~EmbreeScene();
  EmbreeScene(const EmbreeScene&) = delete;
  EmbreeScene& operator=(const EmbreeScene&) = delete;

  // Closest hits of rays[0..count). `coherent`: neighbouring rays start at neighbouring points
  // (Embree's coherent stream mode).
  // Time lands in stats under "embree/intersect", the ray count under "rays/<kind>".
  void intersect(GdrRayHit* rays, size_t count, bool coherent, const char* kind);
  // Occlusion of rays[0..count): blocked rays get tfar = -inf. `coherent` as for intersect.
  void occluded(GdrRay* rays, size_t count, bool coherent, const char* kind);

 private:
  RTCDevice device_ = nullptr;
  RTCScene scene_ = nullptr;
  Stats* stats_;
};

}  // namespace gdr
