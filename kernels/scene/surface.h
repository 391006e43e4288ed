// What shading needs at a ray hit, rebuilt from the triangle index and barycentrics Embree found.
#pragma once
#include "core/geometry.h"
#include "scene/scene_data.h"
#include "scene/texture.h"

typedef struct Surface {
  float3 p;   // position (interpolated, more precise than origin + t * dir)
  float3 ng;  // geometric normal, on the side of the shading normal
  float3 ns;  // shading normal
  float2 uv;
  float area; // of the triangle
  int material;
  int light;  // area light of this triangle, or -1
} Surface;

__attribute__((always_inline)) inline Surface surface_at(const SceneData* s, uint prim, float b1, float b2) {
  GdrTriangle tri = s->triangles[prim];
  GdrShape shape = s->shapes[tri.shape];
  float b0 = 1.0f - b1 - b2;
  float3 p0 = s->positions[tri.v[0]].xyz, p1 = s->positions[tri.v[1]].xyz, p2 = s->positions[tri.v[2]].xyz;
  Surface su;
  su.p = b0 * p0 + b1 * p1 + b2 * p2;
  float3 c = cross(p1 - p0, p2 - p0);
  float len = length(c);
  su.area = 0.5f * len;
  // Degenerate triangles have no normal; any unit vector keeps the arithmetic finite.
  su.ng = len > 0.0f ? c / len : (float3)(0.0f, 0.0f, 1.0f);
  su.ns = su.ng;
  if (shape.flags & SHAPE_HAS_NORMALS) {
    float3 n = b0 * s->normals[tri.v[0]].xyz + b1 * s->normals[tri.v[1]].xyz + b2 * s->normals[tri.v[2]].xyz;
    float nl = length(n);
    if (nl > 0.0f && isfinite(nl)) su.ns = n / nl;
  }
  if (shape.flags & SHAPE_FLIP_NORMALS) su.ns = -su.ns;
  if (dot(su.ng, su.ns) < 0.0f) su.ng = -su.ng;
  su.uv = (float2)(0.0f);
  if (shape.flags & SHAPE_HAS_UVS) su.uv = b0 * s->uvs[tri.v[0]] + b1 * s->uvs[tri.v[1]] + b2 * s->uvs[tri.v[2]];
  su.material = shape.material;
  su.light = shape.first_light >= 0 ? shape.first_light + (int)(prim - (uint)shape.first_triangle) : -1;
  return su;
}

// The material's diffuse reflectance at the surface, textured or constant.
// Scene builds (GDR_TEXTURES_SELECTED) compile the texture lookup only when GDR_TEXTURES is set.
inline float3 surface_reflectance(const SceneData* s, const Surface* su) {
  __global const GdrMaterial* m = &s->materials[su->material];
#if !defined(GDR_TEXTURES_SELECTED) || defined(GDR_TEXTURES)
  if (m->reflectance_texture >= 0) return texture_eval(s, m->reflectance_texture, su->uv);
#endif
  return vload3(0, m->reflectance);
}
