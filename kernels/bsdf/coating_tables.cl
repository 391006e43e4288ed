// The plastics' coating tables (layout: shared/coating_table.h), filled once per scene as
// Mitsuba 3 fills them when it loads a material. For a rough coating, at each of the 64 cosines
// mu_i: the external transmittance t(mu_i) and the reflectance from inside r(mu_i) (relative
// IOR 1 / eta), each the mean of coating.h's integrand over the visible normals, by a tensor
// Gauss-Legendre rule on the unit square of the sampler's uniforms (coating_rule_points per
// axis); then R_int = 2 mean_i(r(mu_i) mu_i), Mitsuba's rule (each node weighs 1/64). A smooth
// coating's R_int is the diffuse Fresnel reflectance fit from inside.
//
// `jobs` lists the plastic materials; `rules` holds the 32-point rule then the 128-point one,
// as (node, weight) on [0, 1] with weights summing to 1.
#include "bsdf/bsdf.h"
#include "bsdf/coating.h"

#define COATING_ROWS 128  // the larger rule: one work item per row of it

inline __global const float2* coating_rule(__global const float2* rules, int points) {
  return points == 32 ? rules : rules + 32;
}

// Item (job, node, row): the row's share of t(mu_node) and r(mu_node), in partial[item].
__kernel void coating_partial_sums(__global const GdrMaterial* materials, __global const int* jobs,
                                   uint job_count, __global const float2* rules,
                                   __global float2* partial) {
  uint item = get_global_id(0);
  if (item >= job_count * GDR_COATING_NODES * COATING_ROWS) return;
  uint row = item % COATING_ROWS, node = (item / COATING_ROWS) % GDR_COATING_NODES;
  __global const GdrMaterial* m = &materials[jobs[item / (COATING_ROWS * GDR_COATING_NODES)]];
  float2 sums = (float2)(0.0f);
  if (m->type == BSDF_ROUGH_PLASTIC) {
    Bsdf b = bsdf_from_material(m, 0, (float3)(0.0f));
    // Isotropic tables: the loader refuses anisotropic roughplastic, as Mitsuba does; a record
    // with alpha_u != alpha_v gets the table of their geometric mean.
    float alpha = b.alpha_u == b.alpha_v ? b.alpha_u : sqrt(b.alpha_u * b.alpha_v);
    float eta = b.eta.x, mu = coating_node_cos((int)node);
    float3 w = (float3)(safe_sqrt(1.0f - mu * mu), 0.0f, mu);
    int nt = coating_rule_points(eta), nr = coating_rule_points(1.0f / eta);
    __global const float2* rt = coating_rule(rules, nt);
    __global const float2* rr = coating_rule(rules, nr);
    if ((int)row < nt) {
      for (int j = 0; j < nt; ++j) {
        float2 u = (float2)(rt[row].x, rt[j].x);
        sums.x +=
            rt[row].y * rt[j].y * coating_transmittance_sample(b.distribution, alpha, eta, w, u);
      }
    }
    if ((int)row < nr) {
      for (int j = 0; j < nr; ++j) {
        float2 u = (float2)(rr[row].x, rr[j].x);
        sums.y += rr[row].y * rr[j].y *
                  coating_reflectance_sample(b.distribution, alpha, 1.0f / eta, w, u);
      }
    }
  }
  partial[item] = sums;
}

// Item job: sums the rows into the material's table.
__kernel void coating_finish(__global const GdrMaterial* materials, __global const int* jobs,
                             uint job_count, __global const float2* partial,
                             __global float* tables) {
  uint job = get_global_id(0);
  if (job >= job_count) return;
  __global const GdrMaterial* m = &materials[jobs[job]];
  __global float* table = tables + m->coating_table;
  Bsdf b = bsdf_from_material(m, 0, (float3)(0.0f));
  if (m->type == BSDF_PLASTIC) {
    table[GDR_COATING_INTERNAL_REFLECTANCE] = fresnel_diffuse_reflectance(1.0f / b.eta.x);
    return;
  }
  float r_sum = 0.0f;
  for (int i = 0; i < GDR_COATING_NODES; ++i) {
    float2 s = (float2)(0.0f);
    __global const float2* rows = partial + ((size_t)job * GDR_COATING_NODES + i) * COATING_ROWS;
    for (int k = 0; k < COATING_ROWS; ++k) s += rows[k];
    table[GDR_COATING_TRANSMITTANCE + i] = clamp(finite_or_zero(s.x), 0.0f, 1.0f);
    r_sum += clamp(finite_or_zero(s.y), 0.0f, 1.0f) * coating_node_cos(i);
  }
  table[GDR_COATING_INTERNAL_REFLECTANCE] =
      clamp(2.0f * r_sum / (float)GDR_COATING_NODES, 0.0f, 1.0f);
}
