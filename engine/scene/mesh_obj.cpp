// Wavefront OBJ through tinyobjloader. All objects and groups of the file form one mesh (as in
// Mitsuba); polygons are fan-triangulated; corners are de-duplicated by (position, normal, uv).
#include <tiny_obj_loader.h>

#include <cmath>
#include <cstdlib>
#include <sstream>
#include <unordered_map>

#include "scene/mesh.h"
#include "util/error.h"
#include "util/input_limits.h"

namespace gdr {
namespace {

// tinyobjloader reads "nan" or a malformed coordinate as 0 without a word, so the vertex lines
// are checked here first, with their line numbers.
void check_vertex_lines(const std::string& text, const std::string& path) {
  std::istringstream in(text);
  std::string line;
  for (int number = 1; std::getline(in, line); ++number) {
    if (line.size() < 2 || line[0] != 'v' || (line[1] != ' ' && line[1] != '\t')) continue;
    const char* s = line.c_str() + 1;
    for (int i = 0; i < 3; ++i) {
      char* end = nullptr;
      double v = std::strtod(s, &end);
      if (end == s) throw InputError(path, number, "vertex line with fewer than 3 numbers");
      if (!std::isfinite(v)) throw InputError(path, number, "vertex coordinate is not finite");
      s = end;
    }
  }
}

// tinyobjloader stores each polygon's vertex count in one byte, so a face of 256 or more vertices
// would be cut without a word: such faces are refused here, with their line numbers.
constexpr long kMaxFaceVertices = 255;

void check_face_lines(const std::string& text, const std::string& path) {
  std::istringstream in(text);
  std::string line;
  for (int number = 1; std::getline(in, line); ++number) {
    if (line.size() < 2 || line[0] != 'f' || (line[1] != ' ' && line[1] != '\t')) continue;
    std::istringstream tokens(line.substr(1));
    std::string tok;
    long count = 0;
    while (tokens >> tok) ++count;
    if (count > kMaxFaceVertices) {
      throw InputError(path, number, "a face with " + std::to_string(count) + " vertices (at most " +
                                         std::to_string(kMaxFaceVertices) + " are supported: triangulate it)");
    }
  }
}

// The line of the first face that names a vertex outside 1..count (or -count..-1).
int find_bad_face_line(const std::string& text, long count) {
  std::istringstream in(text);
  std::string line;
  long seen = 0;
  for (int number = 1; std::getline(in, line); ++number) {
    if (line.size() > 1 && line[0] == 'v' && (line[1] == ' ' || line[1] == '\t')) ++seen;
    if (line.size() < 2 || line[0] != 'f' || (line[1] != ' ' && line[1] != '\t')) continue;
    std::istringstream tokens(line.substr(1));
    std::string tok;
    while (tokens >> tok) {
      long idx = std::strtol(tok.c_str(), nullptr, 10);
      long resolved = idx > 0 ? idx - 1 : seen + idx;
      if (resolved < 0 || resolved >= count) return number;
    }
  }
  return 0;
}

struct CornerHash {
  size_t operator()(const tinyobj::index_t& i) const {
    return (static_cast<size_t>(i.vertex_index) * 73856093u) ^
           (static_cast<size_t>(i.normal_index) * 19349663u) ^ (static_cast<size_t>(i.texcoord_index) * 83492791u);
  }
};
struct CornerEq {
  bool operator()(const tinyobj::index_t& a, const tinyobj::index_t& b) const {
    return a.vertex_index == b.vertex_index && a.normal_index == b.normal_index &&
           a.texcoord_index == b.texcoord_index;
  }
};

}  // namespace

MeshData read_obj(const std::string& path, bool flip_tex_coords) {
  std::string text = read_input_file(path, "OBJ mesh");
  check_vertex_lines(text, path);
  check_face_lines(text, path);

  tinyobj::attrib_t attrib;
  std::vector<tinyobj::shape_t> shapes;
  std::vector<tinyobj::material_t> materials;
  std::string warn, err;
  std::istringstream in(text);
  tinyobj::MaterialReader* no_materials = nullptr;
  if (!tinyobj::LoadObj(&attrib, &shapes, &materials, &warn, &err, &in, no_materials, false)) {
    throw InputError(path, 0, "malformed OBJ: " + err);
  }
  long nv = static_cast<long>(attrib.vertices.size() / 3);
  long nn = static_cast<long>(attrib.normals.size() / 3);
  long nt = static_cast<long>(attrib.texcoords.size() / 2);

  bool has_normals = nn > 0, has_uvs = nt > 0;
  for (const auto& shape : shapes) {
    for (const auto& idx : shape.mesh.indices) {
      if (idx.vertex_index < 0 || idx.vertex_index >= nv) {
        throw InputError(path, find_bad_face_line(text, nv),
                         "face refers to vertex " + std::to_string(idx.vertex_index + 1) + " but the file has " +
                             std::to_string(nv) + " vertices");
      }
      if (idx.normal_index < 0 || idx.normal_index >= nn) has_normals = false;
      if (idx.texcoord_index < 0 || idx.texcoord_index >= nt) has_uvs = false;
    }
  }

  MeshData mesh;
  std::unordered_map<tinyobj::index_t, int, CornerHash, CornerEq> corners;
  auto corner = [&](tinyobj::index_t idx) {
    if (!has_normals) idx.normal_index = -1;
    if (!has_uvs) idx.texcoord_index = -1;
    auto [it, fresh] = corners.emplace(idx, static_cast<int>(mesh.vertex_count()));
    if (fresh) {
      for (int k = 0; k < 3; ++k) mesh.positions.push_back(attrib.vertices[3 * idx.vertex_index + k]);
      if (has_normals)
        for (int k = 0; k < 3; ++k) mesh.normals.push_back(attrib.normals[3 * idx.normal_index + k]);
      if (has_uvs) {
        float u = attrib.texcoords[2 * idx.texcoord_index], v = attrib.texcoords[2 * idx.texcoord_index + 1];
        mesh.uvs.push_back(u);
        mesh.uvs.push_back(flip_tex_coords ? 1.0f - v : v);
      }
    }
    return it->second;
  };
  for (const auto& shape : shapes) {
    size_t offset = 0;
    for (unsigned char count : shape.mesh.num_face_vertices) {
      // tinyobjloader stores the count of each polygon in an unsigned char.
      if (count >= 3) {
        int first = corner(shape.mesh.indices[offset]);
        for (unsigned k = 1; k + 1 < count; ++k) {
          mesh.indices.push_back(first);
          mesh.indices.push_back(corner(shape.mesh.indices[offset + k]));
          mesh.indices.push_back(corner(shape.mesh.indices[offset + k + 1]));
        }
      }
      offset += count;
    }
  }
  for (float v : mesh.normals)
    if (!std::isfinite(v)) throw InputError(path, 0, "a vertex normal is not finite");
  return mesh;
}

}  // namespace gdr
