// Mitsuba 3's latitude-longitude environment map (src/emitters/envmap.cpp): its lookup and an
// importance sampler whose pdf is exactly the density it samples.
//
// The map's texels are samples on a grid: column c at u = (c + 1/2) / W, wrapping around in phi;
// row r at v = r / (H - 1), so the first and last rows lie on the poles. Radiance is the bilinear
// interpolation of the four samples around (u, v). The sampler draws from the same bilinear
// interpolation of the sampling weights (the texels' fourth channel, shared/environment_table.h):
// a band between two rows by its mass, v inside it from the linear marginal, one of the band's two
// rows by its share at that v, a column interval from that row's alias table and u inside it from
// the linear density there.
#pragma once
#include "core/math.h"
#include "scene/scene_data.h"
#include "shared/environment_table.h"

// u from atan2(x, -z), v = theta / pi measured from +y (local frame). Written once for values
// of type F with their atan2 (float here, float8 in light/envmap_lanes.h).
#define ENVMAP_UV(name, F, ATAN2)                       \
  inline void name(F x, F y, F z, F* u, F* v) {         \
    F a = ATAN2(x, -z) * (0.5f * M_1_PI_F);             \
    *u = a - floor(a);                                  \
    *v = acos(clamp(y, -1.0f, 1.0f)) * M_1_PI_F;        \
  }
ENVMAP_UV(envmap_uv_of, float, atan2_approx)
inline float2 envmap_uv(float3 d) {
  float u, v;
  envmap_uv_of(d.x, d.y, d.z, &u, &v);
  return (float2)(u, v);
}
// The local direction's components at polar angle theta (from +y) and azimuth phi, from their
// sines and cosines: envmap_uv's inverse, written once for floats and lanes (light/envmap_lanes.h).
#define ENVMAP_DIRECTION_COMPONENTS(sin_theta, cos_theta, sin_phi, cos_phi) \
  (sin_theta) * (sin_phi), (cos_theta), -(sin_theta) * (cos_phi)

// theta = pi v, phi = 2 pi u, by sinpi and cospi (no argument reduction by pi).
inline float3 envmap_direction(float2 uv) {
  float sin_theta = sinpi(uv.y), phi = 2.0f * uv.x;
  return (float3)(ENVMAP_DIRECTION_COMPONENTS(sin_theta, cospi(uv.y), sinpi(phi), cospi(phi)));
}

// The four grid samples around (u, v): columns c0, c1 = c0 + 1 (wrapped) with weight fc on c1,
// rows r0, r0 + 1 with weight fr on r0 + 1. Needs w >= 1, h >= 2 (the loader pads smaller maps).
// Written once for values of type F and I with their conversions (float and int here, float8 and
// int8 in light/envmap_lanes.h).
#define ENVMAP_CELL(name, F, I, TO_I, TO_F)                                           \
  inline void name(F u, F v, int w, int h, I* c0, I* c1, I* r0, F* fc, F* fr) {       \
    F x = u * (float)w - 0.5f;                                                        \
    x -= floor(x / (float)w) * (float)w; /* [0, w) */                                 \
    *c0 = min(TO_I(x), w - 1);                                                        \
    *fc = clamp(x - TO_F(*c0), 0.0f, 1.0f);                                           \
    *c1 = select(*c0 + 1, (I)(0), *c0 + 1 == w);                                      \
    F y = clamp(v, 0.0f, 1.0f) * (float)(h - 1);                                      \
    *r0 = min(TO_I(y), h - 2);                                                        \
    *fr = clamp(y - TO_F(*r0), 0.0f, 1.0f);                                           \
  }
ENVMAP_CELL(envmap_cell_of, float, int, convert_int, convert_float)

typedef struct EnvGridCell {
  int c0, c1, r0;
  float fc, fr;
} EnvGridCell;

inline EnvGridCell envmap_cell(float2 uv, int w, int h) {
  EnvGridCell g;
  envmap_cell_of(uv.x, uv.y, w, h, &g.c0, &g.c1, &g.r0, &g.fc, &g.fr);
  return g;
}

// Grid sample (c, r): its radiance in xyz, its sampling weight in w.
inline float4 envmap_texel(const SceneData* s, __global const GdrTexture* t, int c, int r) {
  return s->texels[t->offset + r * t->width + c];
}

// Radiance of the map (before its scale) at lat-long position uv, and in *p_uv the sampler's
// density there per unit u and v: both the bilinear interpolation of the same four texels.
inline float3 envmap_lookup_pdf(const SceneData* s, __global const GdrTexture* t, float2 uv, float* p_uv) {
  *p_uv = 0.0f;
  if (!isfinite(uv.x) || !isfinite(uv.y)) return (float3)(0.0f);
  EnvGridCell g = envmap_cell(uv, t->width, t->height);
  float4 top = mix(envmap_texel(s, t, g.c0, g.r0), envmap_texel(s, t, g.c1, g.r0), g.fc);
  float4 bottom = mix(envmap_texel(s, t, g.c0, g.r0 + 1), envmap_texel(s, t, g.c1, g.r0 + 1), g.fc);
  float4 v = mix(top, bottom, g.fr);
  *p_uv = v.w * (float)t->width * (float)(t->height - 1);
  return v.xyz;
}

inline float3 envmap_lookup(const SceneData* s, __global const GdrTexture* t, float2 uv) {
  float p_uv;
  return envmap_lookup_pdf(s, t, uv, &p_uv);
}

inline float envmap_uv_pdf(const SceneData* s, __global const GdrTexture* t, float2 uv) {
  float p_uv;
  envmap_lookup_pdf(s, t, uv, &p_uv);
  return p_uv;
}

// A sample of the density proportional to (1 - t) a + t b on [0, 1) (a, b >= 0), by its
// inverse cdf in a form without cancellation (pbrt-v4's SampleLinear).
// Written once for values of type F (float, and float8 for light/envmap_lanes.h): where a + b is
// not positive, u itself; where u and a are zero, 0.
#define SAMPLE_LINEAR(name, F)                                                                   \
  inline F name(F u, F a, F b) {                                                                 \
    F x = fmin(u * (a + b) / (a + sqrt(mix(a * a, b * b, u))), 0x1.fffffep-1f);                  \
    return select(u, select(x, (F)(0.0f), (u == 0.0f) & (a == 0.0f)), a + b > 0.0f);             \
  }
SAMPLE_LINEAR(sample_linear, float)

// u rescaled to [0, 1) inside the interval an alias bucket gave, from f, u's place in the bucket,
// and keep, the bucket's probability of keeping its own interval: it is uniform there, whichever
// bucket gave it. Written once for values of type F (float, float8 in light/envmap_lanes.h).
#define ALIAS_RESCALED(name, F)                                                                     \
  inline F name(F f, F keep) {                                                                      \
    return select(clamp((f - keep) / (1.0f - keep), 0.0f, 0x1.fffffep-1f), f / keep, f < keep);     \
  }
ALIAS_RESCALED(alias_rescaled, float)

// An interval of n drawn with the alias table `table` (entry j: the probability of keeping j, then
// the interval taken otherwise), and u rescaled to [0, 1) inside the drawn interval.
inline int sample_alias(__global const float* table, int n, float u, float* rescaled) {
  float x = u * (float)n;
  int j = min((int)x, n - 1);
  float f = fmin(x - (float)j, 0x1.fffffep-1f);
  float keep = table[2 * j];
  *rescaled = alias_rescaled(f, keep);
  return f < keep ? j : (int)table[2 * j + 1];
}

// At v = fr inside a band whose rows' sums are a and b, the band's density is
// (1 - fr) a g_0(u) + fr b g_1(u), g_i the rows' own normalised densities: the first row's share,
// in which it gives u. Written once for values of type F (float, float8 in light/envmap_lanes.h).
#define ENVMAP_FIRST_ROW_SHARE(name, F)                                                \
  inline F name(F fr, F a, F b) {                                                      \
    F share = (1.0f - fr) * a, total = share + fr * b;                                 \
    return select(select((F)(0.0f), (F)(1.0f), a > 0.0f), share / total, total > 0.0f); \
  }
ENVMAP_FIRST_ROW_SHARE(envmap_first_row_share, float)

// A lat-long position drawn in proportion to the bilinear interpolation of the weights:
// a band by its mass and v inside it, one of its rows by its share there, a column interval from
// that row's alias table, and u inside it from the weights at its ends.
inline float2 envmap_sample_uv(const SceneData* s, __global const GdrTexture* t, __global const float* table,
                               float2 u) {
  int w = t->width, h = t->height;
  __global const float* sums = table + env_table_row_sums_offset(h);
  float ub;
  int band = sample_alias(table, h - 1, u.y, &ub);
  float a = sums[band], b = sums[band + 1];
  float fr = sample_linear(ub, a, b);
  float p0 = envmap_first_row_share(fr, a, b);
  int first = u.x < p0, row = first ? band : band + 1;
  float du = clamp(first ? u.x / p0 : (u.x - p0) / (1.0f - p0), 0.0f, 0x1.fffffep-1f);
  float dc;
  int c = sample_alias(table + env_table_aliases_offset(w, h, row), w, du, &dc);
  float fa = envmap_texel(s, t, c, row).w, fb = envmap_texel(s, t, c + 1 == w ? 0 : c + 1, row).w;
  float x = ((float)c + sample_linear(dc, fa, fb) + 0.5f) / (float)w;
  return (float2)(x >= 1.0f ? x - 1.0f : x, ((float)band + fr) / (float)(h - 1));
}
