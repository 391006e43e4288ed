// A triangle mesh in object space, as the readers (OBJ, PLY, Mitsuba .serialized) and the
// analytic shapes produce it, before the shape's to_world is applied.
#pragma once
#include <string>
#include <vector>

namespace gdr {

struct MeshData {
  std::vector<float> positions;  // 3 per vertex
  std::vector<float> normals;    // 3 per vertex, or empty
  std::vector<float> uvs;        // 2 per vertex, or empty
  std::vector<int> indices;      // 3 per triangle

  size_t vertex_count() const { return positions.size() / 3; }
  size_t triangle_count() const { return indices.size() / 3; }
};

// Readers: each throws InputError naming the mesh file (and its line where the format has lines)
// for unreadable data, non-finite vertices and out-of-range indices. Polygons are fan-triangulated.
MeshData read_obj(const std::string& path, bool flip_tex_coords);
MeshData read_ply(const std::string& path);
MeshData read_serialized(const std::string& path, int shape_index);

// Checks every position is finite and every index names a vertex; InputError naming `path`.
void validate_mesh(const MeshData& mesh, const std::string& path);

// Analytic shapes as Mitsuba defines them, in object space.
MeshData make_rectangle();                    // [-1,1]^2 at z = 0, normal +z
MeshData make_cube();                         // [-1,1]^3, normals outward
MeshData make_disk(int segments = 64);        // unit disk at z = 0, normal +z
MeshData make_sphere(int rings = 64, int segments = 128);  // unit sphere, normals outward

}  // namespace gdr
