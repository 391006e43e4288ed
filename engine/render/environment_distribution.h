// Sampling tables for environment maps: the weights of the map's sample grid (luminance times
// the mean sine of each row's band of latitudes) and their alias tables, so that next-event
// estimation draws directions from the bilinear interpolation of those weights (about in
// proportion to the map's radiance). The kernels read them (kernels/light/envmap.h).
#pragma once
#include <vector>

#include "scene/scene.h"

namespace gdr {

// Appends the tables of every LIGHT_ENVMAP light of `lights` to `tables` and sets the light's
// distribution_offset. Layout per map: kernels/shared/environment_table.h.
void build_environment_tables(const Scene& scene, std::vector<GdrLight>& lights, std::vector<float>& tables);

}  // namespace gdr
