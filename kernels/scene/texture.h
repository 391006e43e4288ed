// Texture lookups: bitmaps (nearest or bilinear, repeating) and checkerboards, in linear RGB.
#pragma once
#include "scene/scene_data.h"

inline float3 bitmap_texel(const SceneData* s, __global const GdrTexture* t, int x, int y) {
  x = x % t->width;
  y = y % t->height;
  if (x < 0) x += t->width;
  if (y < 0) y += t->height;
  return s->texels[t->offset + y * t->width + x].xyz;
}

inline float3 texture_eval(const SceneData* s, int index, float2 uv) {
  __global const GdrTexture* t = &s->textures[index];
  float u = t->uv_transform[0] * uv.x + t->uv_transform[1] * uv.y + t->uv_transform[2];
  float v = t->uv_transform[3] * uv.x + t->uv_transform[4] * uv.y + t->uv_transform[5];
  if (t->type == TEXTURE_CHECKERBOARD) {
    int cu = (int)floor(2.0f * u), cv = (int)floor(2.0f * v);
    return ((cu + cv) & 1) ? vload3(0, t->color1) : vload3(0, t->color0);
  }
  if (!isfinite(u) || !isfinite(v)) return (float3)(0.0f);
  // Bitmaps: v = 0 is the file's first (top) row, as in Mitsuba (0.x and 3); OBJ meshes flip
  // their v on loading (flip_tex_coords) so that their textures appear upright.
  float x = (u - floor(u)) * t->width;
  float y = (v - floor(v)) * t->height;
  if (!t->bilinear) return bitmap_texel(s, t, (int)x, (int)y);
  x -= 0.5f;
  y -= 0.5f;
  int x0 = (int)floor(x), y0 = (int)floor(y);
  float fx = x - x0, fy = y - y0;
  return (1.0f - fx) * (1.0f - fy) * bitmap_texel(s, t, x0, y0) + fx * (1.0f - fy) * bitmap_texel(s, t, x0 + 1, y0) +
         (1.0f - fx) * fy * bitmap_texel(s, t, x0, y0 + 1) + fx * fy * bitmap_texel(s, t, x0 + 1, y0 + 1);
}
