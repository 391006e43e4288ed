// The BSDF interface types: a material resolved at a hit point, and one sampled direction.
// Directions live in the local shading frame (z = shading normal), are unit length; wo points
// toward the previous vertex (camera side), wi toward the next one.
#pragma once

typedef struct Bsdf {
  int type;          // BSDF_*
  int twosided;      // opaque types: the back side shades like the front
  int distribution;  // MICROFACET_*
  int nonlinear;     // plastics: colour shift from internal scattering
  float3 diffuse;    // diffuse reflectance (textured value)
  float3 specular_r, specular_t, eta, k;
  float alpha_u, alpha_v;  // clamped to >= GDR_MIN_ALPHA
  // Derived by bsdf_from_material (plastics): probability weight of the specular lobe, the
  // material's coating table (shared/coating_table.h; 0 without one) and the diffuse
  // reflectance of the coating seen from inside, read from it.
  float specular_weight;
  __global const float* coating;
  float internal_reflectance;
} Bsdf;

typedef struct BsdfSample {
  float3 wi;
  float3 weight;    // f(wo, wi) |cos wi| / pdf; delta lobes: the lobe's throughput weight
  float pdf;        // solid-angle pdf; delta lobes: the discrete selection probability
  int delta;        // 1 if a delta (specular) lobe was sampled
  int transmitted;  // 1 if wi is on the other side of the surface
  float eta;        // relative IOR crossed (IOR on wi's side / IOR on wo's side); 1 for reflection
} BsdfSample;
