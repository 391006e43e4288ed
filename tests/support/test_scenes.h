// Scenes built in code for tests whose answer is known analytically.
#pragma once
#include <array>

#include "scene/scene.h"
#include "scene/scene_features.h"

namespace gdr::test {

// A camera at `eye` looking along +z (Mitsuba's frame: +x left, +y up), square film.
inline GdrCamera camera_looking_z(float ex, float ey, float ez, float fov_deg, int res) {
  GdrCamera c{};
  const float m[12] = {1, 0, 0, ex, 0, 1, 0, ey, 0, 0, 1, ez};
  for (int i = 0; i < 12; ++i) c.to_world[i] = m[i];
  c.tan_half_fov_x = c.tan_half_fov_y = std::tan(fov_deg * 0.5f * 3.14159265f / 180.0f);
  c.near_clip = 1e-4f;
  c.far_clip = 1e6f;
  c.width = c.height = res;
  c.filter = FILTER_BOX;
  c.filter_radius = 0.5f;
  return c;
}

// A closed cube [-s, s]^3 whose inner faces are diffuse with albedo `albedo` and emit `le`:
// the white furnace. Every point sees radiance le / (1 - albedo).
inline Scene furnace_scene(float albedo, float le, int res, float s = 1.0f) {
  Scene scene;
  const float p[8][3] = {{-s, -s, -s}, {s, -s, -s}, {s, s, -s}, {-s, s, -s},
                         {-s, -s, s},  {s, -s, s},  {s, s, s},  {-s, s, s}};
  for (const auto& v : p) scene.positions.push_back(Vec4{v[0], v[1], v[2], 0});
  scene.normals.assign(8, Vec4{});
  scene.uvs.assign(16, 0.0f);
  // Faces wound so that their normals point into the cube.
  const int quads[6][4] = {{0, 1, 2, 3}, {4, 7, 6, 5}, {0, 4, 5, 1}, {3, 2, 6, 7}, {0, 3, 7, 4}, {1, 5, 6, 2}};
  for (const auto& q : quads) {
    scene.triangles.push_back(GdrTriangle{{q[0], q[1], q[2]}, 0});
    scene.triangles.push_back(GdrTriangle{{q[0], q[2], q[3]}, 0});
  }
  GdrShape shape{};
  shape.material = 0;
  shape.first_triangle = 0;
  shape.triangle_count = 12;
  shape.first_light = 0;
  scene.shapes.push_back(shape);
  scene.shape_names.push_back("furnace");
  GdrMaterial m{};
  m.type = BSDF_DIFFUSE;
  m.reflectance_texture = -1;
  m.reflectance[0] = m.reflectance[1] = m.reflectance[2] = albedo;
  scene.materials.push_back(m);
  scene.material_names.push_back("walls");
  for (int t = 0; t < 12; ++t) {
    GdrLight l{};
    l.type = LIGHT_AREA;
    l.triangle = t;
    l.texture = -1;
    l.radiance[0] = l.radiance[1] = l.radiance[2] = le;
    scene.lights.push_back(l);
  }
  scene.camera = camera_looking_z(0.1f * s, -0.2f * s, 0.05f * s, 90.0f, res);
  for (int a = 0; a < 3; ++a) {
    scene.bounds_min[a] = -s;
    scene.bounds_max[a] = s;
  }
  scene.features = compute_scene_features(scene);
  return scene;
}

}  // namespace gdr::test
