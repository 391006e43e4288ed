// Sampling tables for environment maps: a piecewise-constant 2D distribution over the lat-long
// texels, proportional to luminance * sin(theta), so next-event estimation aims at bright parts
// of the sky. The kernels read them (kernels/light/lights.h: environment_sample / _pdf).
#pragma once
#include <vector>

#include "scene/scene.h"

namespace gdr {

// Appends the tables of every LIGHT_ENVMAP light of `lights` to `tables` and sets the light's
// distribution_offset. Layout per map: kernels/shared/environment_table.h.
void build_environment_tables(const Scene& scene, std::vector<GdrLight>& lights, std::vector<float>& tables);

}  // namespace gdr
