// The plastics' coating tables (kernels/shared/coating_table.h): each plastic material gets its
// block in the scene's coating_tables buffer, filled on the device by
// kernels/bsdf/coating_tables.cl from the kernels' own microfacet and Fresnel functions.
#pragma once
#include <array>
#include <cstdint>
#include <vector>

#include "device/context.h"
#include "shared/scene_types.h"

namespace gdr {

// What a material's coating table depends on: its type, distribution, roughness and IOR (not
// its colours or `nonlinear`), as bit patterns.
std::array<uint32_t, 5> coating_key(const GdrMaterial& m);

// Sets every material's coating_table (its offset in `tables`, or -1 when it has no coating or
// `needed` is given and says it is not used), sizes `tables` and fills it. Materials with the
// same coating_key share one block. Without a plastic material to tabulate nothing is built or
// launched.
void build_coating_tables(Context& context, std::vector<GdrMaterial>& materials,
                          std::vector<float>& tables, const std::vector<bool>& needed = {});

}  // namespace gdr
