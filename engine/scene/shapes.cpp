// Shapes: mesh files and analytic shapes become triangles in world space, with their material,
// attached area emitter and flags.
#include <cfloat>
#include <cmath>

#include "scene/load_context.h"
#include "scene/mesh.h"
#include "util/error.h"

namespace gdr {
namespace {

std::string shape_name(const XmlNode& node) {
  if (const std::string* id = node.attr("id")) return *id;
  return node.type() + " at " + node.file + ":" + std::to_string(node.line);
}

std::string mesh_path(LoadContext& ctx, const Props& p) {
  const XmlNode* fn = p.find("filename");
  if (!fn) throw InputError(p.node().file, p.node().line, "<shape type=\"" + p.type() + "\"> needs a filename");
  return ctx.doc.resolve(p.get_string("filename", ""), *fn);
}

// Reads the mesh of a shape in object space, plus the transform that places it; false when the
// shape type is not supported.
bool read_mesh(LoadContext& ctx, const Props& p, MeshData* mesh, Mat4d* to_world) {
  std::string type = p.type();
  *to_world = p.get_transform("to_world");
  if (type == "obj") {
    *mesh = read_obj(mesh_path(ctx, p), p.get_bool("flip_tex_coords", true));
  } else if (type == "ply") {
    *mesh = read_ply(mesh_path(ctx, p));
    // Mitsuba 3's PLY reader flips v only when asked (its OBJ reader does by default).
    if (p.get_bool("flip_tex_coords", false))
      for (size_t i = 1; i < mesh->uvs.size(); i += 2) mesh->uvs[i] = 1.0f - mesh->uvs[i];
  } else if (type == "serialized") {
    *mesh = read_serialized(mesh_path(ctx, p), p.get_int("shape_index", 0));
  } else if (type == "rectangle") {
    *mesh = make_rectangle();
  } else if (type == "cube") {
    *mesh = make_cube();
  } else if (type == "disk") {
    *mesh = make_disk();
  } else if (type == "sphere") {
    Vec3d center = p.get_vec3("center", {0, 0, 0});
    double radius = p.get_float("radius", 1.0);
    if (!(radius > 0)) throw InputError(p.node().file, p.node().line, "sphere radius must be positive");
    *mesh = make_sphere();
    *to_world = *to_world * Mat4d::translate(center) * Mat4d::scale({radius, radius, radius});
  } else {
    return false;
  }
  return true;
}

}  // namespace

void load_shape(LoadContext& ctx, const XmlNode& node) {
  Props p = ctx.props(node);
  MeshData mesh;
  Mat4d to_world;
  if (!read_mesh(ctx, p, &mesh, &to_world)) {
    ctx.unsupported(node, "shape type not supported: ignored");
    return;
  }
  validate_mesh(mesh, node.file);
  if (mesh.triangle_count() == 0) ctx.warn(node.describe() + ": the mesh has no triangles: nothing to render");
  if (std::fabs(to_world.det3()) < 1e-30) throw InputError(node.file, node.line, "shape to_world is singular");
  if (p.get_bool("face_normals", false)) mesh.normals.clear();
  for (const char* medium : {"interior", "exterior"}) {
    if (const XmlNode* m = p.find(medium)) ctx.unsupported(*m, "participating media not supported: ignored");
  }
  for (const XmlNode* m : p.nested("medium")) ctx.unsupported(*m, "participating media not supported: ignored");

  Scene& s = ctx.scene;
  GdrShape shape{};
  int shape_index = static_cast<int>(s.shapes.size());
  int base = static_cast<int>(s.positions.size());
  shape.first_triangle = static_cast<int>(s.triangles.size());
  shape.triangle_count = static_cast<int>(mesh.triangle_count());
  shape.first_light = -1;
  bool has_normals = !mesh.normals.empty(), has_uvs = !mesh.uvs.empty();
  shape.flags = (has_normals ? SHAPE_HAS_NORMALS : 0) | (has_uvs ? SHAPE_HAS_UVS : 0) |
                (p.get_bool("flip_normals", false) ? SHAPE_FLIP_NORMALS : 0);

  Mat4d inv = to_world.inverse();
  for (size_t v = 0; v < mesh.vertex_count(); ++v) {
    Vec3d q = to_world.point({mesh.positions[3 * v], mesh.positions[3 * v + 1], mesh.positions[3 * v + 2]});
    // Checked in double: converting a value beyond float's range to float is undefined.
    if (!(std::fabs(q.x) <= FLT_MAX && std::fabs(q.y) <= FLT_MAX && std::fabs(q.z) <= FLT_MAX)) {
      throw InputError(node.file, node.line, "shape vertex " + std::to_string(v) +
                                                 " is not finite or beyond float range after to_world");
    }
    s.positions.push_back({static_cast<float>(q.x), static_cast<float>(q.y), static_cast<float>(q.z), 0});
    Vec4 n{};
    if (has_normals) {
      Vec3d a{mesh.normals[3 * v], mesh.normals[3 * v + 1], mesh.normals[3 * v + 2]};
      // Inverse transpose of the linear part.
      Vec3d r = normalize({inv.m[0][0] * a.x + inv.m[1][0] * a.y + inv.m[2][0] * a.z,
                           inv.m[0][1] * a.x + inv.m[1][1] * a.y + inv.m[2][1] * a.z,
                           inv.m[0][2] * a.x + inv.m[1][2] * a.y + inv.m[2][2] * a.z});
      n = {static_cast<float>(r.x), static_cast<float>(r.y), static_cast<float>(r.z), 0};
    }
    s.normals.push_back(n);
    s.uvs.push_back(has_uvs ? mesh.uvs[2 * v] : 0.0f);
    s.uvs.push_back(has_uvs ? mesh.uvs[2 * v + 1] : 0.0f);
  }
  for (size_t t = 0; t < mesh.triangle_count(); ++t) {
    GdrTriangle tri{};
    for (int k = 0; k < 3; ++k) tri.v[k] = base + mesh.indices[3 * t + k];
    tri.shape = shape_index;
    const Vec4& a = s.positions[tri.v[0]];
    const Vec4& b = s.positions[tri.v[1]];
    const Vec4& c = s.positions[tri.v[2]];
    Vec3d e1{b.x - a.x, b.y - a.y, b.z - a.z}, e2{c.x - a.x, c.y - a.y, c.z - a.z};
    if (!(length(cross(e1, e2)) > 0)) ++ctx.degenerate_triangles;
    s.triangles.push_back(tri);
  }

  // The area emitter first: a shape that emits and has no BSDF is black (Mitsuba 0.x and 3).
  const XmlNode* area = nullptr;
  for (const XmlNode* e : p.nested("emitter")) {
    if (e->type() != "area") {
      ctx.unsupported(*e, "only area emitters can be attached to a shape: ignored");
    } else if (area) {
      ctx.unsupported(*e, "a shape takes one area emitter: ignored");
    } else {
      area = e;
    }
  }
  std::vector<const XmlNode*> bsdfs = p.nested("bsdf");
  if (bsdfs.size() > 1) ctx.unsupported(*bsdfs[1], "a shape takes one BSDF: only the first is used");
  shape.material = !bsdfs.empty() ? load_material(ctx, *bsdfs.front())
                   : area         ? black_material(ctx)
                                  : default_material(ctx);
  s.shapes.push_back(shape);
  s.shape_names.push_back(shape_name(node));
  if (area) {
    ctx.attached_emitters.insert(area);
    add_area_lights(ctx, *area, shape_index);
  }
}

}  // namespace gdr
