// Scenes built in code for tests whose answer is known analytically.
#pragma once
#include <array>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "bsdf/bsdf_harness.h"
#include "scene/mesh.h"
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

// Builds small scenes triangle by triangle: shapes with a material and optionally an area
// emitter on every triangle. finish() sets the camera, the bounds and the features.
class SceneBuilder {
 public:
  explicit SceneBuilder(Scene base = {}) : scene_(std::move(base)) {}

  int material(const GdrMaterial& m, const std::string& name = "material") {
    scene_.materials.push_back(m);
    scene_.material_names.push_back(name);
    return int(scene_.materials.size()) - 1;
  }

  // A shape of `mesh` (object space, already placed) with material `mat`; `le` > 0 makes every
  // triangle an area light of that grey radiance. Returns the shape index.
  int shape(const MeshData& mesh, int mat, float le = 0.0f, const std::string& name = "shape") {
    int base = int(scene_.positions.size());
    bool has_normals = !mesh.normals.empty();
    for (size_t v = 0; v < mesh.vertex_count(); ++v) {
      const float* p = &mesh.positions[3 * v];
      scene_.positions.push_back(Vec4{p[0], p[1], p[2], 0});
      scene_.normals.push_back(has_normals ? Vec4{mesh.normals[3 * v], mesh.normals[3 * v + 1],
                                                  mesh.normals[3 * v + 2], 0}
                                           : Vec4{});
      scene_.uvs.push_back(0.0f);
      scene_.uvs.push_back(0.0f);
    }
    GdrShape shape{};
    shape.material = mat;
    shape.first_triangle = int(scene_.triangles.size());
    shape.triangle_count = int(mesh.triangle_count());
    shape.first_light = le > 0 ? int(scene_.lights.size()) : -1;
    shape.flags = has_normals ? SHAPE_HAS_NORMALS : 0;
    int index = int(scene_.shapes.size());
    for (size_t t = 0; t < mesh.triangle_count(); ++t) {
      GdrTriangle tri{{base + mesh.indices[3 * t], base + mesh.indices[3 * t + 1],
                       base + mesh.indices[3 * t + 2]},
                      index};
      if (le > 0) {
        GdrLight l{};
        l.type = LIGHT_AREA;
        l.triangle = int(scene_.triangles.size());
        l.texture = -1;
        l.radiance[0] = l.radiance[1] = l.radiance[2] = le;
        scene_.lights.push_back(l);
      }
      scene_.triangles.push_back(tri);
    }
    scene_.shapes.push_back(shape);
    scene_.shape_names.push_back(name);
    return index;
  }

  Scene finish(const GdrCamera& camera) {
    scene_.camera = camera;
    for (int a = 0; a < 3; ++a) {
      scene_.bounds_min[a] = INFINITY;
      scene_.bounds_max[a] = -INFINITY;
    }
    for (const Vec4& p : scene_.positions) {
      const float v[3] = {p.x, p.y, p.z};
      for (int a = 0; a < 3; ++a) {
        scene_.bounds_min[a] = std::min(scene_.bounds_min[a], v[a]);
        scene_.bounds_max[a] = std::max(scene_.bounds_max[a], v[a]);
      }
    }
    scene_.features = compute_scene_features(scene_);
    return scene_;
  }

  Scene& scene() { return scene_; }

 private:
  Scene scene_;
};

// One triangle (a, b, c), normal along (b - a) x (c - a).
inline MeshData triangle_mesh(std::array<float, 3> a, std::array<float, 3> b, std::array<float, 3> c) {
  MeshData m;
  m.positions = {a[0], a[1], a[2], b[0], b[1], b[2], c[0], c[1], c[2]};
  m.indices = {0, 1, 2};
  return m;
}

// The quad a, b, c, d (in order around it) as two triangles, normal along (b - a) x (c - a).
inline MeshData quad_mesh(std::array<float, 3> a, std::array<float, 3> b, std::array<float, 3> c,
                          std::array<float, 3> d) {
  MeshData m;
  m.positions = {a[0], a[1], a[2], b[0], b[1], b[2], c[0], c[1], c[2], d[0], d[1], d[2]};
  m.indices = {0, 1, 2, 0, 2, 3};
  return m;
}

// The box [lo, hi] with outward normals (make_cube() placed by scale and offset).
inline MeshData box_mesh(std::array<float, 3> lo, std::array<float, 3> hi) {
  MeshData m = make_cube();
  for (size_t v = 0; v < m.vertex_count(); ++v) {
    for (int a = 0; a < 3; ++a) {
      m.positions[3 * v + a] = lo[a] + (m.positions[3 * v + a] + 1.0f) * 0.5f * (hi[a] - lo[a]);
    }
  }
  m.normals.clear();  // flat faces: the geometric normal is exact
  return m;
}

// A faceted sphere of `radius` around `c` (flat facets: no shading normals, so a closed object
// whose geometric and shading normals agree exactly).
inline MeshData sphere_mesh(std::array<float, 3> c, float radius) {
  MeshData m = make_sphere(32, 64);
  m.normals.clear();
  for (size_t v = 0; v < m.vertex_count(); ++v) {
    for (int a = 0; a < 3; ++a) m.positions[3 * v + a] = c[a] + radius * m.positions[3 * v + a];
  }
  return m;
}

// Scales every position, the camera's position and its clip distances by `s` about the origin:
// radiance does not depend on the unit of length, so the image must not change.
inline void scale_scene(Scene& scene, float s) {
  for (Vec4& p : scene.positions) {
    p.x *= s;
    p.y *= s;
    p.z *= s;
  }
  for (int r = 0; r < 3; ++r) scene.camera.to_world[4 * r + 3] *= s;
  scene.camera.near_clip *= s;
  scene.camera.far_clip *= s;
  for (int a = 0; a < 3; ++a) {
    scene.bounds_min[a] *= s;
    scene.bounds_max[a] *= s;
  }
  for (GdrLight& l : scene.lights) {
    for (int a = 0; a < 3; ++a) l.position[a] *= s;
    l.scene_radius *= s;
  }
}

// A coarse diffuse sphere (4 x 8 facets) with smooth vertex normals on a floor before a wall,
// under a small area light, 24 pixels wide: its shading normals differ from its facets' by up to
// ~40 degrees (what light subpaths need the shading-normal correction for).
inline Scene coarse_smooth_sphere_scene() {
  SceneBuilder b;
  int white = b.material(diffuse_material(0.7f), "white");
  MeshData sphere = make_sphere(4, 8);
  for (size_t v = 0; v < sphere.vertex_count(); ++v) sphere.positions[3 * v + 2] += 3.0f;
  b.shape(sphere, white, 0.0f, "sphere");
  b.shape(quad_mesh({-3, -1, 0}, {-3, -1, 6}, {3, -1, 6}, {3, -1, 0}), white, 0.0f, "floor");
  b.shape(quad_mesh({-3, -1, 6}, {-3, 3, 6}, {3, 3, 6}, {3, -1, 6}), white, 0.0f, "wall");
  b.shape(quad_mesh({-0.75f, 2.5f, 2.25f}, {0.75f, 2.5f, 2.25f}, {0.75f, 2.5f, 3.75f}, {-0.75f, 2.5f, 3.75f}),
          white, 5.0f, "light");
  return b.finish(camera_looking_z(0.0f, 0.3f, 0.5f, 45.0f, 24));
}

// A caustic: an area light above the camera's view shines through a glass sphere (IOR 1.5,
// smooth normals) onto a diffuse wall that the camera faces, 24 pixels wide. The caustic's light
// reaches the wall only along specular chains (wall -> sphere -> sphere -> light), whose
// gradients the manifold shift builds.
inline Scene glass_caustic_scene() {
  SceneBuilder b;
  int white = b.material(diffuse_material(0.8f), "white");
  int glass = b.material(dielectric_material(BSDF_DIELECTRIC, 1.5f), "glass");
  MeshData sphere = make_sphere(24, 48);
  for (size_t v = 0; v < sphere.vertex_count(); ++v) {
    for (int a = 0; a < 3; ++a) sphere.positions[3 * v + a] *= 0.9f;
    sphere.positions[3 * v + 1] += 0.3f;
    sphere.positions[3 * v + 2] += 3.0f;
  }
  b.shape(sphere, glass, 0.0f, "sphere");
  b.shape(quad_mesh({-3, -3, 4}, {-3, 3, 4}, {3, 3, 4}, {3, -3, 4}), white, 0.0f, "wall");
  b.shape(quad_mesh({-0.6f, 0.8f, 1.5f}, {0.6f, 0.8f, 1.5f}, {0.6f, 2.0f, 1.5f}, {-0.6f, 2.0f, 1.5f}), white, 6.0f,
          "light");
  return b.finish(camera_looking_z(0.0f, 0.0f, 0.0f, 45.0f, 24));
}

}  // namespace gdr::test
