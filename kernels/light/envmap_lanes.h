// envmap_sample_uv, envmap_lookup_pdf, envmap_sample_at and environment_eval (light/envmap.h,
// light/lights.h) for eight lanes at once: each table and texel read lane by lane, the arithmetic
// between them (the alias tables' rescaling, sample_linear's roots and divisions, the grid cell,
// the direction's sines and cosines) on float8 lanes, where lane by lane it was a chain of
// divisions waiting one after another. Lanes outside `on` read nothing; their values are unused.
#pragma once
#include "core/lanes.h"
#include "light/lights.h"

#if defined(GDR_LIGHT_ENVMAP)
SAMPLE_LINEAR(sample_linear_lanes, float8)
ENVMAP_FIRST_ROW_SHARE(envmap_first_row_share_lanes, float8)
ALIAS_RESCALED(alias_rescaled_lanes, float8)
ENVMAP_UV(envmap_uv_lanes, float8, atan2_approx_lanes)
ENVMAP_CELL(envmap_cell_lanes, float8, int8, convert_int8, convert_float8)
ENVMAP_SOLID_ANGLE(envmap_solid_angle_lanes, float8, Lanes3)

// sample_alias for each lane: the interval of n drawn by u from the alias table at offset[k] of
// `table`, and u rescaled inside it.
inline int8 sample_alias_lanes(__global const float* table, const int* offset, int8 on, int n, float8 u,
                               float8* rescaled) {
  float8 x = u * (float)n;
  int8 j = min(convert_int8(x), n - 1);
  float8 f = fmin(x - convert_float8(j), 0x1.fffffep-1f);
  int jk[LANES], onk[LANES];
  float keep[LANES], alias[LANES];
  vstore8(j, 0, jk);
  vstore8(on, 0, onk);
  for (int k = 0; k < LANES; ++k) {
    keep[k] = 1.0f;
    alias[k] = 0.0f;
    if (!onk[k]) continue;
    keep[k] = table[offset[k] + 2 * jk[k]];
    alias[k] = table[offset[k] + 2 * jk[k] + 1];
  }
  float8 kp = vload8(0, keep);
  *rescaled = alias_rescaled_lanes(f, kp);
  return select(convert_int8(vload8(0, alias)), j, f < kp);
}

// Two values a lane: values[i0[k]] and values[i1[k]].
inline void envmap_read_pair_lanes(__global const float* values, int8 on, int8 i0, int8 i1, float8* a, float8* b) {
  int ok[LANES], j0[LANES], j1[LANES];
  float va[LANES], vb[LANES];
  vstore8(on, 0, ok);
  vstore8(i0, 0, j0);
  vstore8(i1, 0, j1);
  for (int k = 0; k < LANES; ++k) {
    va[k] = vb[k] = 0.0f;
    if (!ok[k]) continue;
    va[k] = values[j0[k]];
    vb[k] = values[j1[k]];
  }
  *a = vload8(0, va);
  *b = vload8(0, vb);
}

// envmap_sample_uv for each lane in `on`: the lat-long position (*u, *v) drawn by (u1, u2).
inline void envmap_sample_uv_lanes(const SceneData* s, __global const GdrTexture* t, __global const float* table,
                                   int8 on, float8 u1, float8 u2, float8* u, float8* v) {
  int w = t->width, h = t->height;
  int offset[LANES];
  // The band, by the bands' alias table, and v inside it from the linear marginal.
  for (int k = 0; k < LANES; ++k) offset[k] = 0;
  float8 ub;
  int8 band = sample_alias_lanes(table, offset, on, h - 1, u2, &ub);
  float8 a, b;
  envmap_read_pair_lanes(table + env_table_row_sums_offset(h), on, band, band + 1, &a, &b);
  float8 fr = sample_linear_lanes(ub, a, b);
  // One of the band's two rows by its share at v.
  float8 p0 = envmap_first_row_share_lanes(fr, a, b);
  int8 first = u1 < p0;
  int8 row = select(band + 1, band, first);
  float8 du = clamp(select((u1 - p0) / (1.0f - p0), u1 / p0, first), 0.0f, 0x1.fffffep-1f);
  // The row's column interval, and u inside it from the weights at its ends.
  int rows[LANES];
  vstore8(row, 0, rows);
  for (int k = 0; k < LANES; ++k) offset[k] = env_table_aliases_offset(w, h, rows[k]);
  float8 dc;
  int8 c = sample_alias_lanes(table, offset, on, w, du, &dc);
  int ok[LANES], c0[LANES], c1[LANES];
  vstore8(on, 0, ok);
  vstore8(c, 0, c0);
  vstore8(select(c + 1, (int8)(0), c + 1 == w), 0, c1);
  float wa[LANES], wb[LANES];
  for (int k = 0; k < LANES; ++k) {
    wa[k] = wb[k] = 0.0f;
    if (!ok[k]) continue;
    wa[k] = envmap_texel(s, t, c0[k], rows[k]).w;
    wb[k] = envmap_texel(s, t, c1[k], rows[k]).w;
  }
  float8 fa = vload8(0, wa), fb = vload8(0, wb);
  float8 x = (convert_float8(c) + sample_linear_lanes(dc, fa, fb) + 0.5f) / (float)w;
  *u = select(x, x - 1.0f, x >= 1.0f);
  *v = (convert_float8(band) + fr) / (float)(h - 1);
}

// envmap_lookup_pdf at each lane's (u, v) in `on`: the texel *texel and *p_uv.
inline void envmap_lookup_pdf_lanes(const SceneData* s, __global const GdrTexture* t, int8 on, float8 u, float8 v,
                                    Lanes3* texel, float8* p_uv) {
  int w = t->width, h = t->height;
  on &= isfinite(u) & isfinite(v);
  int8 c0, c1, r0;
  float8 fc, fr;
  envmap_cell_lanes(u, v, w, h, &c0, &c1, &r0, &fc, &fr);
  int ok[LANES], k0[LANES], k1[LANES], rk[LANES];
  vstore8(on, 0, ok);
  vstore8(c0, 0, k0);
  vstore8(c1, 0, k1);
  vstore8(r0, 0, rk);
  float t00[4 * LANES], t01[4 * LANES], t10[4 * LANES], t11[4 * LANES];  // lane k's at 4 k
  for (int k = 0; k < LANES; ++k) {
    float4 zero = (float4)(0.0f);
    vstore4(ok[k] ? envmap_texel(s, t, k0[k], rk[k]) : zero, k, t00);
    vstore4(ok[k] ? envmap_texel(s, t, k1[k], rk[k]) : zero, k, t01);
    vstore4(ok[k] ? envmap_texel(s, t, k0[k], rk[k] + 1) : zero, k, t10);
    vstore4(ok[k] ? envmap_texel(s, t, k1[k], rk[k] + 1) : zero, k, t11);
  }
  // Each component i (radiance, then weight) of the lanes' texels, interpolated on lanes.
  float8 m[4];
  for (int i = 0; i < 4; ++i) {
    float a[LANES], b[LANES], c[LANES], d[LANES];
    for (int k = 0; k < LANES; ++k) {
      a[k] = t00[4 * k + i];
      b[k] = t01[4 * k + i];
      c[k] = t10[4 * k + i];
      d[k] = t11[4 * k + i];
    }
    m[i] = mix(mix(vload8(0, a), vload8(0, b), fc), mix(vload8(0, c), vload8(0, d), fc), fr);
  }
  Lanes3 r = {m[0], m[1], m[2]};
  *texel = r;
  *p_uv = select((float8)(0.0f), m[3] * (float)w * (float)(h - 1), on);
}

// A texel of map l times its radiance scale.
inline Lanes3 envmap_scaled_lanes(__global const GdrLight* l, Lanes3 texel) {
  float3 scale = vload3(0, l->radiance);
  Lanes3 r = {texel.x * scale.x, texel.y * scale.y, texel.z * scale.z};
  return r;
}

// envmap_sample_at for each lane: the world direction toward map l at (u, v), with *pdf from p_uv
// and *radiance from the texel.
inline Lanes3 envmap_sample_at_lanes(__global const GdrLight* l, float pmf, float8 u, float8 v, float8 p_uv,
                                     Lanes3 texel, Lanes3* radiance, float8* pdf) {
  float8 sin_theta, cos_theta, sin_phi, cos_phi;
  sincospi_lanes(v, &sin_theta, &cos_theta);
  sincospi_lanes(2.0f * u, &sin_phi, &cos_phi);
  Lanes3 d = {ENVMAP_DIRECTION_COMPONENTS(sin_theta, cos_theta, sin_phi, cos_phi)};
  *pdf = envmap_solid_angle_lanes(pmf, d, p_uv);
  *radiance = envmap_scaled_lanes(l, texel);
  return lanes3_normalize_or_zero(xform_vector_lanes(l->to_world, d));
}

// environment_eval of map l (chosen with probability pmf) for each lane in `on`: the radiance
// arriving along -dir (world, unit) and *pdf, from its position (envmap_uv) in the map.
inline Lanes3 envmap_eval_lanes(const SceneData* s, __global const GdrLight* l, float pmf, int8 on, Lanes3 dir,
                                float8* pdf) {
  Lanes3 d = lanes3_normalize_or_zero(xform_vector_lanes(l->to_local, dir));  // envmap_local_direction
  float8 u, v;
  envmap_uv_lanes(d.x, d.y, d.z, &u, &v);
  __global const GdrTexture* t = &s->textures[l->texture];
  float8 p_uv;
  Lanes3 texel;
  envmap_lookup_pdf_lanes(s, t, on, u, v, &texel, &p_uv);
  *pdf = envmap_solid_angle_lanes(pmf, d, p_uv);
  return envmap_scaled_lanes(l, texel);
}
#endif
