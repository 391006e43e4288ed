// State shared by the pieces of the scene loader (materials, textures, emitters, shapes, sensor).
#pragma once
#include <map>
#include <set>
#include <string>

#include "scene/load_scene.h"
#include "scene/xml_values.h"

namespace gdr {

struct LoadContext {
  LoadContext(const XmlDocument& d, const LoadOptions& o, Scene& s) : doc(d), options(o), scene(s) {}

  const XmlDocument& doc;
  const LoadOptions& options;
  Scene& scene;

  std::map<const XmlNode*, int> material_of;  // BSDF element -> material index
  std::map<const XmlNode*, int> texture_of;   // texture element -> texture index
  std::set<const XmlNode*> attached_emitters;  // area emitters used by a shape
  std::set<const XmlNode*> reported;           // elements already warned about
  int default_material = -1;
  int black_material = -1;
  size_t degenerate_triangles = 0;
  bool has_sensor = false;

  Props props(const XmlNode& node) const { return Props(node, doc); }
  // A feature the renderer does not reproduce: a warning naming the element and what is done
  // instead, or an InputError with --strict. Reported once per element.
  void unsupported(const XmlNode& node, const std::string& instead);
  void warn(const std::string& message) { scene.warnings.push_back(message); }
};

// The pieces, one file each.
int load_material(LoadContext& ctx, const XmlNode& bsdf);  // material index (cached per element)
int default_material(LoadContext& ctx);                    // Mitsuba's default: diffuse 0.5
int black_material(LoadContext& ctx);  // an emitting shape's default: diffuse 0 (Mitsuba's)
int load_texture(LoadContext& ctx, const XmlNode& texture);  // texture index, or -1 if unsupported
// A bitmap smaller than min_width x min_height is padded by repeating its last column and row.
int load_image_texture(LoadContext& ctx, const std::string& path, const XmlNode& from, bool raw, bool bilinear,
                       int min_width = 1, int min_height = 1);
// Fills a 4-float slot of the shared layouts (RGB or xyz, then 0).
inline void set4(float* dst, Rgb c) {
  dst[0] = c.r;
  dst[1] = c.g;
  dst[2] = c.b;
  dst[3] = 0;
}

void load_shape(LoadContext& ctx, const XmlNode& shape);
void load_emitter(LoadContext& ctx, const XmlNode& emitter);  // lights not attached to a shape
void add_area_lights(LoadContext& ctx, const XmlNode& emitter, int shape_index);
void finish_lights(LoadContext& ctx);  // scene radius/centre for distant lights
void load_sensor(LoadContext& ctx, const XmlNode& sensor);
void default_camera(LoadContext& ctx);  // when the scene has no sensor

}  // namespace gdr
