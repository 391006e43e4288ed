// Layout of a plastic material's coating table, at the material's coating_table offset in the
// scene's coating_tables buffer. Filled once per scene by kernels/bsdf/coating_tables.cl
// (launched by engine/render/coating_tables.cpp), read by kernels/bsdf/plastic.h. As Mitsuba 3
// (plastic.cpp, roughplastic.cpp) computes them when a material is loaded:
//   [0]        the diffuse reflectance of the coating seen from inside (R_int);
//   [1 .. 64]  rough coating only: the external transmittance t(mu) at mu_i = max(1e-6, i / 63),
//              read by linear interpolation.
#pragma once
#include "shared/scene_types.h"

#define GDR_COATING_NODES 64                // MI_ROUGH_TRANSMITTANCE_RES
#define GDR_COATING_INTERNAL_REFLECTANCE 0  // offset of R_int in a material's table
#define GDR_COATING_TRANSMITTANCE 1         // offset of t(mu_0)

// The cosine of node i (the first is kept off the horizon, where the integrands are 0 / 0).
inline float coating_node_cos(int i) {
  float mu = (float)i / (float)(GDR_COATING_NODES - 1);
  return mu > 1e-6f ? mu : 1e-6f;
}

// Floats a material of `type` takes in the table (0: none).
inline int coating_table_size(int type) {
  return type == BSDF_ROUGH_PLASTIC ? 1 + GDR_COATING_NODES : type == BSDF_PLASTIC ? 1 : 0;
}
