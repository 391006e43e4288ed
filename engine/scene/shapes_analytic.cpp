// Mitsuba's analytic shapes as triangle meshes. Winding is counter-clockwise seen from the side
// the normal points to, so the geometric normal (e1 x e2) agrees with the shading normal.
#include <cmath>

#include "scene/mesh.h"
#include "util/error.h"

namespace gdr {
namespace {

void add_vertex(MeshData& m, float x, float y, float z, float nx, float ny, float nz, float u, float v) {
  m.positions.insert(m.positions.end(), {x, y, z});
  m.normals.insert(m.normals.end(), {nx, ny, nz});
  m.uvs.insert(m.uvs.end(), {u, v});
}

void add_triangle(MeshData& m, int a, int b, int c) { m.indices.insert(m.indices.end(), {a, b, c}); }

}  // namespace

void validate_mesh(const MeshData& mesh, const std::string& path) {
  for (size_t i = 0; i < mesh.positions.size(); ++i)
    if (!std::isfinite(mesh.positions[i]))
      throw InputError(path, 0, "vertex " + std::to_string(i / 3) + " has a non-finite coordinate");
  long n = static_cast<long>(mesh.vertex_count());
  for (size_t i = 0; i < mesh.indices.size(); ++i)
    if (mesh.indices[i] < 0 || mesh.indices[i] >= n)
      throw InputError(path, 0, "triangle " + std::to_string(i / 3) + " refers to vertex " +
                                    std::to_string(mesh.indices[i]) + " of " + std::to_string(n));
}

MeshData make_rectangle() {
  MeshData m;
  add_vertex(m, -1, -1, 0, 0, 0, 1, 0, 0);
  add_vertex(m, 1, -1, 0, 0, 0, 1, 1, 0);
  add_vertex(m, 1, 1, 0, 0, 0, 1, 1, 1);
  add_vertex(m, -1, 1, 0, 0, 0, 1, 0, 1);
  add_triangle(m, 0, 1, 2);
  add_triangle(m, 2, 3, 0);
  return m;
}

MeshData make_cube() {
  MeshData m;
  for (int axis = 0; axis < 3; ++axis) {
    for (int sign = -1; sign <= 1; sign += 2) {
      // Tangents u, v with u x v = the outward normal.
      float n[3] = {0, 0, 0}, u[3] = {0, 0, 0}, v[3] = {0, 0, 0};
      n[axis] = static_cast<float>(sign);
      u[(axis + (sign > 0 ? 1 : 2)) % 3] = 1;
      v[(axis + (sign > 0 ? 2 : 1)) % 3] = 1;
      int base = static_cast<int>(m.vertex_count());
      const float corners[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
      for (const auto& c : corners) {
        float p[3];
        for (int k = 0; k < 3; ++k) p[k] = n[k] + c[0] * u[k] + c[1] * v[k];
        add_vertex(m, p[0], p[1], p[2], n[0], n[1], n[2], (c[0] + 1) * 0.5f, (c[1] + 1) * 0.5f);
      }
      add_triangle(m, base, base + 1, base + 2);
      add_triangle(m, base + 2, base + 3, base);
    }
  }
  return m;
}

MeshData make_disk(int segments) {
  MeshData m;
  add_vertex(m, 0, 0, 0, 0, 0, 1, 0, 0);
  for (int j = 0; j <= segments; ++j) {
    double phi = 2.0 * M_PI * j / segments;
    add_vertex(m, static_cast<float>(std::cos(phi)), static_cast<float>(std::sin(phi)), 0, 0, 0, 1, 1.0f,
               static_cast<float>(j) / segments);
  }
  for (int j = 0; j < segments; ++j) add_triangle(m, 0, 1 + j, 2 + j);
  return m;
}

MeshData make_sphere(int rings, int segments) {
  MeshData m;
  for (int i = 0; i <= rings; ++i) {
    double theta = M_PI * i / rings;
    for (int j = 0; j <= segments; ++j) {
      double phi = 2.0 * M_PI * j / segments;
      float x = static_cast<float>(std::sin(theta) * std::cos(phi));
      float y = static_cast<float>(std::sin(theta) * std::sin(phi));
      float z = static_cast<float>(std::cos(theta));
      if (i == 0 || i == rings) x = y = 0;  // exact poles
      add_vertex(m, x, y, z, x, y, z, static_cast<float>(j) / segments, static_cast<float>(i) / rings);
    }
  }
  int row = segments + 1;
  for (int i = 0; i < rings; ++i) {
    for (int j = 0; j < segments; ++j) {
      int p00 = i * row + j, p01 = p00 + 1, p10 = p00 + row, p11 = p10 + 1;
      // The triangle touching a pole would have two coincident corners: leave it out.
      if (i + 1 < rings) add_triangle(m, p00, p10, p11);
      if (i > 0) add_triangle(m, p00, p11, p01);
    }
  }
  return m;
}

}  // namespace gdr
