// Emitters -> GdrLight: area (one light per triangle of its shape), point, spot, directional,
// constant and envmap. Mitsuba 0.x names (intensity, radiance, irradiance, toWorld, cutoffAngle,
// beamWidth) arrive here already in snake_case.
#include <cmath>

#include "scene/load_context.h"
#include "util/error.h"

namespace gdr {
namespace {

void set4(float* dst, Vec3d v) {
  dst[0] = static_cast<float>(v.x);
  dst[1] = static_cast<float>(v.y);
  dst[2] = static_cast<float>(v.z);
  dst[3] = 0;
}

void set3x4(float* dst, const Mat4d& m) {
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 4; ++c) dst[4 * r + c] = static_cast<float>(m.m[r][c]);
}

GdrLight base_light(int type) {
  GdrLight l{};
  l.type = type;
  l.triangle = -1;
  l.texture = -1;
  l.distribution_offset = -1;
  set3x4(l.to_world, Mat4d{});
  set3x4(l.to_local, Mat4d{});
  return l;
}

Rgb emission(const Props& p, const std::string& name, Rgb fallback) {
  if (const XmlNode* t = p.texture(name)) {
    throw InputError(t->file, t->line, "textured '" + name + "' is not supported");
  }
  Rgb c = p.get_color(name, fallback, SpectrumUse::Emission);
  if (!std::isfinite(c.r) || !std::isfinite(c.g) || !std::isfinite(c.b)) {
    throw InputError(p.node().file, p.node().line, "'" + name + "' is not finite");
  }
  return c;
}

}  // namespace

void add_area_lights(LoadContext& ctx, const XmlNode& node, int shape_index) {
  Props p = ctx.props(node);
  Rgb radiance = emission(p, "radiance", Rgb(1.0f));
  GdrShape& shape = ctx.scene.shapes[shape_index];
  shape.first_light = static_cast<int>(ctx.scene.lights.size());
  for (int t = 0; t < shape.triangle_count; ++t) {
    GdrLight l = base_light(LIGHT_AREA);
    l.triangle = shape.first_triangle + t;
    set4(l.radiance, radiance);
    ctx.scene.lights.push_back(l);
  }
}

void load_emitter(LoadContext& ctx, const XmlNode& node) {
  Props p = ctx.props(node);
  std::string type = p.type();
  if (type == "constant" || type == "envmap") {
    // The integrators look up what escaping rays see in a single environment (as Mitsuba does).
    for (const GdrLight& l : ctx.scene.lights) {
      if (l.type == LIGHT_CONSTANT || l.type == LIGHT_ENVMAP) {
        throw InputError(node.file, node.line, "a second environment emitter (only one constant or envmap is allowed)");
      }
    }
  }
  Mat4d to_world = p.get_transform("to_world");
  if (type == "point") {
    GdrLight l = base_light(LIGHT_POINT);
    set4(l.radiance, emission(p, "intensity", Rgb(1.0f)));
    set4(l.position, p.has("position") ? p.get_vec3("position", {}) : to_world.translation());
    ctx.scene.lights.push_back(l);
  } else if (type == "spot") {
    GdrLight l = base_light(LIGHT_SPOT);
    set4(l.radiance, emission(p, "intensity", Rgb(1.0f)));
    set4(l.position, to_world.translation());
    set4(l.direction, normalize(to_world.vector({0, 0, 1})));
    double cutoff = p.get_float("cutoff_angle", 20.0);
    double beam = p.get_float("beam_width", cutoff * 0.75);
    if (!(cutoff > 0 && cutoff <= 180) || !(beam > 0) || beam > cutoff) {
      throw InputError(node.file, node.line, "spot light needs 0 < beam_width <= cutoff_angle <= 180");
    }
    l.cos_cutoff = static_cast<float>(std::cos(cutoff * M_PI / 180.0));
    l.cos_falloff = static_cast<float>(std::cos(beam * M_PI / 180.0));
    if (p.has("texture")) ctx.unsupported(node, "projected texture not supported: ignored");
    ctx.scene.lights.push_back(l);
  } else if (type == "directional") {
    GdrLight l = base_light(LIGHT_DIRECTIONAL);
    set4(l.radiance, emission(p, "irradiance", Rgb(1.0f)));
    Vec3d dir = p.has("direction") ? p.get_vec3("direction", {}) : to_world.vector({0, 0, 1});
    if (length(dir) == 0) throw InputError(node.file, node.line, "directional light with a zero direction");
    set4(l.direction, normalize(dir));
    ctx.scene.lights.push_back(l);
  } else if (type == "constant") {
    GdrLight l = base_light(LIGHT_CONSTANT);
    set4(l.radiance, emission(p, "radiance", Rgb(1.0f)));
    ctx.scene.lights.push_back(l);
  } else if (type == "envmap") {
    const XmlNode* fn = p.find("filename");
    if (!fn) throw InputError(node.file, node.line, "<emitter type=\"envmap\"> needs a filename");
    double scale = p.get_float("scale", 1.0);
    if (scale < 0) {
      const XmlNode* n = p.find("scale");
      throw InputError(n->file, n->line, "envmap 'scale' must not be negative");
    }
    std::string path = ctx.doc.resolve(p.get_string("filename", ""), *fn);
    GdrLight l = base_light(LIGHT_ENVMAP);
    // Mitsuba pads maps to at least 2 x 3 texels, so that a row lies between the poles.
    l.texture = load_image_texture(ctx, path, *fn, false, true, 2, 3);
    set4(l.radiance, Rgb(static_cast<float>(scale)));
    // Only the rotation matters for a distant light: drop the translation.
    Mat4d rot = to_world;
    rot.m[0][3] = rot.m[1][3] = rot.m[2][3] = 0;
    set3x4(l.to_world, rot);
    set3x4(l.to_local, rot.inverse());
    ctx.scene.lights.push_back(l);
  } else if (type == "area") {
    // Reached only when no shape refers to it.
    ctx.unsupported(node, "area emitter not attached to any shape: ignored");
  } else {
    ctx.unsupported(node, "emitter type not supported: ignored");
  }
}

void finish_lights(LoadContext& ctx) {
  const Scene& s = ctx.scene;
  Vec3d lo{s.bounds_min[0], s.bounds_min[1], s.bounds_min[2]};
  Vec3d hi{s.bounds_max[0], s.bounds_max[1], s.bounds_max[2]};
  Vec3d center = (lo + hi) * 0.5;
  double radius = s.bounding_radius();
  if (!(radius > 0)) radius = 1.0;
  for (GdrLight& l : ctx.scene.lights) {
    if (l.type == LIGHT_DIRECTIONAL || l.type == LIGHT_CONSTANT || l.type == LIGHT_ENVMAP) {
      l.scene_radius = static_cast<float>(radius);
      set4(l.position, center);
    }
  }
}

}  // namespace gdr
