#include "scene/load_scene.h"

#include <algorithm>
#include <cmath>

#include "scene/load_context.h"
#include "util/error.h"

namespace gdr {

void LoadContext::unsupported(const XmlNode& node, const std::string& instead) {
  if (!reported.insert(&node).second) return;
  std::string what = node.describe();
  if (options.strict) {
    throw InputError(node.file, node.line, "unsupported <" + node.tag + " type=\"" + node.type() + "\">: " + instead);
  }
  warn(what + ": " + instead);
}

namespace {

void read_integrator(LoadContext& ctx, const XmlNode& node) {
  Props p = ctx.props(node);
  ctx.scene.integrator = p.type();
  ctx.scene.integrator_file = node.file;
  ctx.scene.integrator_line = node.line;
  ctx.scene.max_depth = p.get_int("max_depth", -1);
  if (ctx.scene.max_depth < -1) {
    throw InputError(node.file, node.line, "max_depth must be -1 (unbounded) or >= 0");
  }
  // Mitsuba's direct illumination is path tracing of two segments: emission seen directly and
  // light scattered once.
  if (ctx.scene.integrator == "direct") {
    ctx.scene.integrator = "path";
    ctx.scene.max_depth = 2;
  }
  // Path-tracer parameters of Mitsuba that the render settings cover or that change nothing here.
  p.known({"rr_depth", "samples_per_pass", "emitter_samples", "bsdf_samples"});
}

// A named property of a plugin that the loader never looked up is a parameter gdrender does not
// know: a warning naming its file and line, an error with --strict.
void report_unread_parameters(LoadContext& ctx, const XmlNode& node) {
  for (const auto& child : node.children) {
    // Elements already reported as unsupported are not reported again, nor are their children.
    if (ctx.reported.count(&node) || ctx.reported.count(child.get())) continue;
    if (node.loaded && !child->read && child->attr("name") && child->tag != "default") {
      std::string problem = "<" + child->tag + " name=\"" + child->name() + "\">: " + node.describe() +
                            " has no such parameter in gdrender";
      if (ctx.options.strict) throw InputError(child->file, child->line, problem);
      ctx.warn(child->file + ":" + std::to_string(child->line) + ": " + problem + "; ignored");
    }
    report_unread_parameters(ctx, *child);
  }
}

void compute_bounds(Scene& s) {
  if (s.positions.empty()) return;
  float lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
  for (const Vec4& p : s.positions) {
    const float v[3] = {p.x, p.y, p.z};
    for (int k = 0; k < 3; ++k) {
      lo[k] = std::min(lo[k], v[k]);
      hi[k] = std::max(hi[k], v[k]);
    }
  }
  for (int k = 0; k < 3; ++k) {
    s.bounds_min[k] = lo[k];
    s.bounds_max[k] = hi[k];
  }
}

// Top-level definitions that only matter when something refers to them.
bool is_definition(const std::string& tag) { return tag == "bsdf" || tag == "texture"; }
// A named value at the top level: a property of the scene itself.
bool is_scene_property(const XmlNode& node) {
  const std::string& tag = node.tag;
  return node.attr("name") && (tag == "boolean" || tag == "integer" || tag == "float" || tag == "string" ||
                               tag == "rgb" || tag == "spectrum" || tag == "point" || tag == "vector");
}

}  // namespace

Scene load_scene(const std::string& path, const LoadOptions& options) {
  XmlDocument doc = load_xml_document(path, options.defines);
  Scene scene;
  scene.path = path;
  LoadContext ctx(doc, options, scene);
  for (const std::string& name : doc.unused_defines) {
    // A parameter the scene does not have (say -D res=... on a scene with width and height) would
    // otherwise be ignored without a word.
    std::string has;
    for (const std::string& p : doc.parameters) has += (has.empty() ? "" : ", ") + p;
    std::string problem = "-D " + name + "=...: the scene has no parameter $" + name + " (its parameters: " +
                          (has.empty() ? std::string("none") : has) + ")";
    if (options.strict) throw InputError(path, 0, problem);
    ctx.warn(path + ": " + problem + "; ignored");
  }

  scene.robust_intersections = ctx.props(*doc.root).get_bool("embree_use_robust_intersections", false);
  std::vector<const XmlNode*> emitters;
  for (const auto& child : doc.root->children) {
    const XmlNode& node = *child;
    const std::string& tag = node.tag;
    if (tag == "integrator") {
      read_integrator(ctx, node);
    } else if (tag == "sensor") {
      load_sensor(ctx, node);
    } else if (tag == "shape") {
      load_shape(ctx, node);
    } else if (tag == "emitter") {
      emitters.push_back(&node);
    } else if (is_definition(tag) || is_scene_property(node)) {
      continue;  // properties: read above, or reported as unknown parameters below
    } else if (tag == "medium" || tag == "phase" || tag == "volume") {
      ctx.unsupported(node, "participating media not supported: ignored");
    } else {
      ctx.unsupported(node, "element not supported: ignored");
    }
  }
  compute_bounds(scene);
  for (const XmlNode* e : emitters) {
    // Area emitters defined at the top level are used through a shape's <ref>.
    if (e->type() == "area" && ctx.attached_emitters.count(e)) continue;
    load_emitter(ctx, *e);
  }
  finish_lights(ctx);
  if (scene.lights.empty()) ctx.warn(path + ": the scene has no emitter: the image is black");
  if (!ctx.has_sensor) default_camera(ctx);
  report_unread_parameters(ctx, *doc.root);
  for (const std::string& w : doc.warnings) ctx.warn(w);
  if (ctx.degenerate_triangles) {
    ctx.warn(path + ": " + std::to_string(ctx.degenerate_triangles) + " degenerate (zero-area) triangles kept");
  }
  scene.features = compute_scene_features(scene, options.glossy_threshold);
  return scene;
}

}  // namespace gdr
