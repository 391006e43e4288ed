// The probabilities with which next-event estimation picks each light: proportional to an
// estimate of its emitted power, so bright and large lights get more shadow rays.
#pragma once
#include <vector>

namespace gdr {

struct Scene;

// cdf[0] = 0 ... cdf[n] = 1 over scene.lights (empty when there is no light).
std::vector<float> light_selection_cdf(const Scene& scene);

}  // namespace gdr
