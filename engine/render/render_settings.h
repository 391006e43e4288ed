// What every integrator is asked to do, and what it returns. Settings of one integrator only
// (strategies, shifts, reconstruction) are its own: IntegratorParams.
#pragma once
#include <cstdint>
#include <optional>

#include "image/image.h"

namespace gdr {

struct RenderSettings {
  int spp = 16;                        // samples per pixel; 0: until the time budget runs out
  std::optional<double> time_budget;   // seconds; stops after the pass that crosses it
  uint32_t seed = 0;
  int max_depth = 16;                  // Mitsuba's convention: path segments; < 0 unbounded, 0 nothing
  int rr_depth = 5;                    // bounces before Russian roulette
  bool progress = false;               // progress line on stderr
};

struct RenderResult {
  Image image;       // R,G,B (and integrator-specific layers)
  int samples = 0;   // samples per pixel actually taken
  double seconds = 0;
};

}  // namespace gdr
