// How a material is classified, for the kernels' BSDF queries (kernels/bsdf/bsdf.h), the shifts'
// choice between reconnection and half-vector copy, and the host's SceneFeatures (which effects
// a scene calls for): one rule, written once. Plain arithmetic only, so that it compiles as
// OpenCL C and C++ alike and gives the same answer on both sides.
#pragma once
#include "shared/scene_types.h"

#define GDR_MIN_ALPHA 1e-4f            // smallest microfacet roughness: below it D overflows float
#define GDR_INDEX_MATCHED_EPS 1e-4f    // |eta - 1| below which a rough dielectric is index-matched
#define GDR_GLOSSY_THRESHOLD 0.001f    // default roughness at or below which a vertex is glossy

// The roughness a BSDF works with (NaN and values below the minimum become the minimum).
inline float material_alpha(float alpha) { return alpha >= GDR_MIN_ALPHA ? alpha : GDR_MIN_ALPHA; }

// A rough dielectric of relative IOR 1 passes light straight through: a delta transmission.
inline int material_index_matched(int type, float eta) {
  return type == BSDF_ROUGH_DIELECTRIC && eta - 1.0f < GDR_INDEX_MATCHED_EPS && 1.0f - eta < GDR_INDEX_MATCHED_EPS;
}

// All components are delta.
inline int material_is_delta(int type, float eta) {
  return type == BSDF_CONDUCTOR || type == BSDF_DIELECTRIC || type == BSDF_THIN_DIELECTRIC ||
         material_index_matched(type, eta);
}

// Some component is delta (smooth plastic's coating reflection, besides the pure delta types).
inline int material_has_delta_lobe(int type, float eta) {
  return material_is_delta(type, eta) || type == BSDF_PLASTIC;
}

inline int material_has_diffuse_lobe(int type) {
  return type == BSDF_DIFFUSE || type == BSDF_PLASTIC || type == BSDF_ROUGH_PLASTIC;
}

// Roughness that decides how gradient-domain shifts treat the vertex: 0 for a delta lobe, the
// smaller alpha of a microfacet lobe, 1 for diffuse; the minimum over a material's lobes.
// Alphas as material_alpha() returns them.
inline float material_roughness(int type, float eta, float alpha_u, float alpha_v) {
  float alpha = alpha_u < alpha_v ? alpha_u : alpha_v;
  switch (type) {
    case BSDF_DIFFUSE: return 1.0f;
    case BSDF_ROUGH_CONDUCTOR:
    case BSDF_ROUGH_PLASTIC: return alpha;
    case BSDF_ROUGH_DIELECTRIC: return material_index_matched(type, eta) ? 0.0f : alpha;
    default: return 0.0f;  // conductor, dielectric, thin dielectric, plastic
  }
}

// A vertex rougher than `threshold` is diffuse for the shifts (reconnectable); others are glossy.
inline int material_is_diffuse(float roughness, float threshold) { return roughness > threshold; }
