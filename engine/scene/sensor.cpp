// The perspective sensor with its film, reconstruction filter and sampler -> GdrCamera.
// Camera frame (Mitsuba's): looks along local +z, +x is left, +y is up.
#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "scene/load_context.h"
#include "util/error.h"

namespace gdr {
namespace {

void set_to_world(GdrCamera& cam, const Mat4d& m) {
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 4; ++c) cam.to_world[4 * r + c] = static_cast<float>(m.m[r][c]);
}

// Field of view in degrees and its axis; focal_length refers to the diagonal of a 36x24 mm film,
// as in Mitsuba, and a sensor with neither fov nor focal_length has Mitsuba's 50mm.
void read_fov(const Props& p, double* fov, std::string* axis) {
  *axis = p.get_string("fov_axis", "x");
  if (!p.has("fov")) {
    const XmlNode* n = p.find("focal_length");
    std::string text = p.get_string("focal_length", "50mm");
    char* end = nullptr;
    double f = std::strtod(text.c_str(), &end);
    std::string unit = end ? std::string(end) : "";
    if (end == text.c_str() || !(unit.empty() || unit == "mm") || !(f > 0)) {
      const XmlNode& where = n ? *n : p.node();
      throw InputError(where.file, where.line, "focal_length '" + text + "' is not a length in mm");
    }
    *fov = 2.0 * std::atan(std::sqrt(36.0 * 36.0 + 24.0 * 24.0) / (2.0 * f)) * 180.0 / M_PI;
    *axis = "diagonal";
  } else {
    *fov = p.get_float("fov", 45.0);
  }
  if (!(*fov > 0 && *fov < 180)) {
    throw InputError(p.node().file, p.node().line, "fov must be between 0 and 180 degrees");
  }
}

void set_fov(GdrCamera& cam, double fov, const std::string& axis_in, const XmlNode& node) {
  double t = std::tan(0.5 * fov * M_PI / 180.0);
  double w = cam.width, h = cam.height;
  std::string axis = axis_in;
  if (axis == "smaller") axis = w <= h ? "x" : "y";
  if (axis == "larger") axis = w >= h ? "x" : "y";
  double tx, ty;
  if (axis == "x") {
    tx = t;
    ty = t * h / w;
  } else if (axis == "y") {
    ty = t;
    tx = t * w / h;
  } else if (axis == "diagonal") {
    double d = std::sqrt(w * w + h * h);
    tx = t * w / d;
    ty = t * h / d;
  } else {
    throw InputError(node.file, node.line, "unknown fov_axis '" + axis_in + "' (x, y, diagonal, smaller, larger)");
  }
  cam.tan_half_fov_x = static_cast<float>(tx);
  cam.tan_half_fov_y = static_cast<float>(ty);
}

void read_filter(LoadContext& ctx, const XmlNode& film, GdrCamera& cam) {
  std::vector<const XmlNode*> filters = ctx.props(film).nested("rfilter");
  cam.filter = FILTER_GAUSSIAN;  // Mitsuba's default
  double radius = 2.0;           // 4 standard deviations of 0.5 px
  if (!filters.empty()) {
    Props f = ctx.props(*filters.front());
    std::string type = f.type();
    if (type == "box") {
      cam.filter = FILTER_BOX;
      radius = f.get_float("radius", 0.5);
    } else if (type == "tent") {
      cam.filter = FILTER_TENT;
      radius = f.get_float("radius", 1.0);
    } else if (type == "gaussian") {
      radius = 4.0 * f.get_float("stddev", 0.5);
    } else {
      ctx.unsupported(*filters.front(), "reconstruction filter not supported: using a gaussian (stddev 0.5)");
    }
  }
  if (!(radius > 0)) throw InputError(film.file, film.line, "filter radius must be positive");
  cam.filter_radius = static_cast<float>(radius);
}

// The command line's film size replaces the file's; a width alone keeps the file's aspect ratio.
void apply_resolution(const LoadOptions& o, GdrCamera& cam) {
  if (o.width <= 0) return;
  int height = o.height > 0 ? o.height
                            : std::max(1, static_cast<int>(std::lround(double(o.width) * cam.height / cam.width)));
  cam.width = o.width;
  cam.height = height;
}

}  // namespace

void load_sensor(LoadContext& ctx, const XmlNode& node) {
  if (ctx.has_sensor) {
    ctx.unsupported(node, "only the first sensor is used: ignored");
    return;
  }
  ctx.has_sensor = true;
  Props p = ctx.props(node);
  // A pinhole camera is in focus at every distance.
  p.known({"focus_distance"});
  std::string type = p.type();
  if (type != "perspective") {
    ctx.unsupported(node, "sensor type not supported: rendered as a pinhole perspective camera");
  }
  // Thin-lens depth of field is not modelled (focus_distance alone changes nothing).
  if (p.has("aperture_radius")) ctx.unsupported(node, "depth of field not supported: pinhole camera");
  GdrCamera& cam = ctx.scene.camera;
  cam = GdrCamera{};
  cam.width = 768;
  cam.height = 576;
  std::vector<const XmlNode*> films = p.nested("film");
  if (!films.empty()) {
    Props f = ctx.props(*films.front());
    // The output file's format is gdrender's own (EXR of 32-bit floats, PNG beside it).
    f.known({"file_format", "pixel_format", "component_format", "banner", "attach_log"});
    cam.width = f.get_int("width", 768);
    cam.height = f.get_int("height", 576);
    if (cam.width <= 0 || cam.height <= 0 || cam.width > 65536 || cam.height > 65536) {
      throw InputError(films.front()->file, films.front()->line, "film size must be between 1 and 65536 pixels");
    }
    read_filter(ctx, *films.front(), cam);
    // Mitsuba 3's sample_border, Mitsuba 0.6's highQualityEdges; false in both.
    cam.sample_border = f.get_bool("sample_border", f.get_bool("high_quality_edges", false)) ? 1 : 0;
  } else {
    cam.filter = FILTER_GAUSSIAN;
    cam.filter_radius = 2.0f;
  }
  apply_resolution(ctx.options, cam);
  std::vector<const XmlNode*> samplers = p.nested("sampler");
  if (!samplers.empty()) {
    Props sampler = ctx.props(*samplers.front());
    sampler.known({"seed"});  // gdrender's --seed decides the noise
    int spp = sampler.get_int("sample_count", 4);
    if (spp <= 0) throw InputError(samplers.front()->file, samplers.front()->line, "sample_count must be positive");
    ctx.scene.spp = spp;
  }
  double fov;
  std::string axis;
  read_fov(p, &fov, &axis);
  set_fov(cam, fov, axis, node);
  cam.near_clip = static_cast<float>(p.get_float("near_clip", 0.01));
  cam.far_clip = static_cast<float>(p.get_float("far_clip", 10000.0));
  if (!(cam.near_clip > 0) || !(cam.far_clip > cam.near_clip)) {
    throw InputError(node.file, node.line, "need 0 < near_clip < far_clip");
  }
  Mat4d to_world = p.get_transform("to_world");
  if (std::fabs(to_world.det3()) < 1e-12) throw InputError(node.file, node.line, "sensor to_world is singular");
  set_to_world(cam, to_world);
}

void default_camera(LoadContext& ctx) {
  // Mitsuba places a default camera that sees the whole scene; this one looks along +z at the
  // bounding box from in front of it.
  const Scene& s = ctx.scene;
  Vec3d lo{s.bounds_min[0], s.bounds_min[1], s.bounds_min[2]};
  Vec3d hi{s.bounds_max[0], s.bounds_max[1], s.bounds_max[2]};
  Vec3d center = (lo + hi) * 0.5;
  double radius = std::max(s.bounding_radius(), 1e-3);
  double distance = radius / std::tan(0.5 * 45.0 * M_PI / 180.0) + radius;
  GdrCamera& cam = ctx.scene.camera;
  cam = GdrCamera{};
  cam.width = 768;
  cam.height = 576;
  cam.filter = FILTER_GAUSSIAN;
  cam.filter_radius = 2.0f;
  apply_resolution(ctx.options, cam);
  cam.near_clip = static_cast<float>(std::max(distance - 2 * radius, 1e-3 * distance));
  cam.far_clip = static_cast<float>(distance + 4 * radius);
  set_fov(cam, 45.0, "x", *ctx.doc.root);
  Vec3d origin = center - Vec3d{0, 0, distance};
  set_to_world(cam, Mat4d::look_at(origin, center, {0, 1, 0}));
  ctx.warn(ctx.doc.path + ": the scene has no sensor: a default camera (fov 45, 768x576) looks at the scene along +z");
}

}  // namespace gdr
