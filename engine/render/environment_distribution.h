// Sampling tables for environment maps: the weights of the map's sample grid (luminance times
// the mean sine of each row's band of latitudes, in its texels' fourth channel) and their alias
// tables, so that next-event estimation draws directions from the bilinear interpolation of those
// weights (about in proportion to the map's radiance). The kernels read them
// (kernels/light/envmap.h).
#pragma once
#include <vector>

#include "scene/scene.h"

namespace gdr {

// Appends the tables of every LIGHT_ENVMAP light of `lights` to `tables`, sets the light's
// distribution_offset and writes the weights into the fourth channel of its map's texels in
// `texels` (the scene's, as the device holds them). Layout: kernels/shared/environment_table.h.
void build_environment_tables(const Scene& scene, std::vector<GdrLight>& lights, std::vector<float>& tables,
                              std::vector<Vec4>& texels);

}  // namespace gdr
