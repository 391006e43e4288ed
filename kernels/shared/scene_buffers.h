// The list of the scene's device buffers, once, for host and kernels. Every use is generated from
// it: the kernels' SceneData struct, their SCENE_DATA_ARGS parameter list and scene_data_make()
// (kernels/scene/scene_data.h), the host's arrays, buffers and argument binding
// (engine/render/device_scene.h). A buffer added here reaches every scene-reading kernel.
//
// X(kernel element type, host element type, name, what it holds). The first entry is given to
// FIRST, the others to NEXT, so that comma-separated lists need no trailing comma.
#pragma once

#define GDR_SCENE_BUFFERS(FIRST, NEXT)                                                            \
  FIRST(GdrTriangle, GdrTriangle, triangles, "vertex indices and shape of each triangle")        \
  NEXT(float4, Vec4, positions, "vertex positions (world space, w unused)")                      \
  NEXT(float4, Vec4, normals, "vertex shading normals (zero without SHAPE_HAS_NORMALS)")          \
  NEXT(float2, float, uvs, "vertex texture coordinates (two host floats each)")                  \
  NEXT(GdrShape, GdrShape, shapes, "material, triangle range, first light and flags per shape")  \
  NEXT(GdrMaterial, GdrMaterial, materials, "BSDF parameters")                                   \
  NEXT(GdrTexture, GdrTexture, textures, "bitmap and checkerboard textures")                     \
  NEXT(float4, Vec4, texels, "linear RGB texels of every bitmap")                                \
  NEXT(GdrLight, GdrLight, lights, "emitters, with their sampling tables' offsets")              \
  NEXT(float, float, light_cdf, "light selection cdf: light_count + 1 entries, 0 ... 1")         \
  NEXT(float, float, env_tables, "environment-map sampling tables (shared/environment_table.h)") \
  NEXT(float, float, coating_tables, "plastics' coating tables, per material (shared/coating_table.h)")
