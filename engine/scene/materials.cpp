// Mitsuba BSDF plugins -> GdrMaterial, with the defaults of the Mitsuba 3 documentation.
#include <algorithm>
#include <cstdlib>

#include "scene/load_context.h"
#include "scene/named_conductors.h"
#include "scene/named_iors.h"
#include "util/error.h"

namespace gdr {
namespace {

GdrMaterial base_material(int type) {
  GdrMaterial m{};
  m.type = type;
  m.reflectance_texture = -1;
  m.distribution = MICROFACET_BECKMANN;
  set4(m.reflectance, Rgb(0.5f));
  set4(m.specular_reflectance, Rgb(1.0f));
  set4(m.specular_transmittance, Rgb(1.0f));
  set4(m.eta, Rgb(1.0f));
  m.alpha_u = m.alpha_v = 0.1f;
  m.coating_table = -1;  // set when the scene is uploaded
  return m;
}

// int_ior / ext_ior: a number or a name from the IOR table.
float read_ior(const Props& p, const std::string& name, const char* fallback_name) {
  const XmlNode* n = p.find(name);
  std::string text;
  if (!n) {
    text = fallback_name;
  } else if (n->tag == "float" || n->tag == "integer") {
    return static_cast<float>(p.get_float(name, 1.0));
  } else if (n->tag == "string") {
    text = n->attr_or("value", "");
  } else {
    throw InputError(n->file, n->line, "'" + name + "' must be a <float> or a named material <string>");
  }
  float ior = 1.0f;
  if (named_ior(text, &ior)) return ior;
  char* end = nullptr;
  double v = std::strtod(text.c_str(), &end);
  if (end != text.c_str() && *end == 0 && v > 0) return static_cast<float>(v);
  throw InputError(n ? n->file : p.node().file, n ? n->line : p.node().line,
                   "unknown IOR name '" + text + "' (known: " + named_ior_list() + ")");
}

void read_eta(const Props& p, GdrMaterial& m, const char* default_int) {
  float int_ior = read_ior(p, "int_ior", default_int);
  float ext_ior = read_ior(p, "ext_ior", "air");
  if (!(int_ior > 0) || !(ext_ior > 0)) {
    throw InputError(p.node().file, p.node().line, "IORs must be positive");
  }
  set4(m.eta, Rgb(int_ior / ext_ior));
}

// A reflectance or transmittance above 1 creates energy (Mitsuba renders it as given): clamped,
// with a warning naming the value's file and line.
Rgb at_most_one(LoadContext& ctx, const Props& p, const std::string& name, Rgb c) {
  if (c.max() <= 1.0f) return c;
  const XmlNode* n = p.find(name);
  ctx.warn(n->file + ":" + std::to_string(n->line) + ": '" + name + "' above 1 would reflect more light than " +
           "arrives: clamped to 1");
  return Rgb(std::min(c.r, 1.0f), std::min(c.g, 1.0f), std::min(c.b, 1.0f));
}

Rgb read_constant(LoadContext& ctx, const Props& p, const std::string& name, Rgb fallback) {
  if (const XmlNode* t = p.texture(name)) {
    ctx.unsupported(*t, "texture for '" + name + "' not supported: using " + std::to_string(fallback.r));
    return fallback;
  }
  return at_most_one(ctx, p, name, p.get_color(name, fallback, SpectrumUse::Reflectance));
}

void read_roughness(LoadContext& ctx, const Props& p, GdrMaterial& m) {
  std::string dist = p.get_string("distribution", "beckmann");
  if (dist == "ggx") {
    m.distribution = MICROFACET_GGX;
  } else if (dist != "beckmann") {
    ctx.unsupported(p.node(), "microfacet distribution '" + dist + "' not supported: using beckmann");
  }
  for (const char* name : {"alpha", "alpha_u", "alpha_v"}) {
    if (const XmlNode* t = p.texture(name)) ctx.unsupported(*t, std::string("textured ") + name + ": using 0.1");
  }
  auto value = [&](const std::string& name, double fallback) {
    const XmlNode* n = p.find(name);
    return n && n->tag != "texture" ? p.get_float(name, fallback) : fallback;
  };
  double alpha = value("alpha", 0.1);
  double au = value("alpha_u", alpha), av = value("alpha_v", alpha);
  if (au < 0 || av < 0) throw InputError(p.node().file, p.node().line, "roughness alpha must not be negative");
  m.alpha_u = static_cast<float>(au);
  m.alpha_v = static_cast<float>(av);
}

// diffuse reflectance: a constant or a texture.
void read_reflectance(LoadContext& ctx, const Props& p, const std::string& name, GdrMaterial& m) {
  if (const XmlNode* t = p.texture(name)) {
    m.reflectance_texture = load_texture(ctx, *t);
    return;
  }
  set4(m.reflectance, at_most_one(ctx, p, name, p.get_color(name, Rgb(0.5f), SpectrumUse::Reflectance)));
}

void read_conductor(LoadContext& ctx, const Props& p, GdrMaterial& m) {
  const XmlNode& node = p.node();
  ComplexIor ior{};
  if (p.has("eta") || p.has("k")) {
    Rgb eta = p.get_color("eta", Rgb(0.0f), SpectrumUse::Unbounded);
    Rgb k = p.get_color("k", Rgb(1.0f), SpectrumUse::Unbounded);
    ior = {{eta.r, eta.g, eta.b}, {k.r, k.g, k.b}};
  } else {
    // Mitsuba 0.x defaulted to copper, Mitsuba 2/3 to the perfect mirror.
    std::string name = p.get_string("material", node.version_major < 2 ? "Cu" : "none");
    if (!named_conductor(name, &ior)) {
      const XmlNode* n = p.find("material");
      throw InputError(n->file, n->line, "unknown conductor '" + name + "' (known: " + named_conductor_list() + ")");
    }
  }
  float ext = 1.0f;
  if (p.has("ext_eta")) ext = read_ior(p, "ext_eta", "air");
  for (int i = 0; i < 3; ++i) {
    m.eta[i] = ior.eta[i] / ext;
    m.k[i] = ior.k[i] / ext;
  }
  set4(m.specular_reflectance, read_constant(ctx, p, "specular_reflectance", Rgb(1.0f)));
}

GdrMaterial make_material(LoadContext& ctx, const XmlNode& node, int* twosided_out);

// Plugins that wrap another BSDF and change it in ways the renderer does not model.
const XmlNode* wrapped_bsdf(const Props& p) {
  std::vector<const XmlNode*> inner = p.nested("bsdf");
  return inner.empty() ? nullptr : inner.front();
}

GdrMaterial make_material(LoadContext& ctx, const XmlNode& node, int* twosided_out) {
  Props p = ctx.props(node);
  std::string type = p.type();
  if (type == "twosided") {
    std::vector<const XmlNode*> inner = p.nested("bsdf");
    if (inner.empty()) throw InputError(node.file, node.line, "<bsdf type=\"twosided\"> needs a nested BSDF");
    if (inner.size() > 1) ctx.unsupported(node, "a different back-side BSDF is not supported: the front one is used on both sides");
    GdrMaterial m = make_material(ctx, *inner.front(), twosided_out);
    *twosided_out = 1;
    return m;
  }
  if (type == "diffuse") {
    GdrMaterial m = base_material(BSDF_DIFFUSE);
    read_reflectance(ctx, p, "reflectance", m);
    return m;
  }
  if (type == "conductor" || type == "roughconductor") {
    GdrMaterial m = base_material(type == "conductor" ? BSDF_CONDUCTOR : BSDF_ROUGH_CONDUCTOR);
    read_conductor(ctx, p, m);
    if (type == "roughconductor") read_roughness(ctx, p, m);
    else m.alpha_u = m.alpha_v = 0.0f;
    return m;
  }
  if (type == "dielectric" || type == "thindielectric" || type == "roughdielectric") {
    GdrMaterial m = base_material(type == "dielectric" ? BSDF_DIELECTRIC
                                  : type == "thindielectric" ? BSDF_THIN_DIELECTRIC : BSDF_ROUGH_DIELECTRIC);
    read_eta(p, m, "bk7");
    set4(m.specular_reflectance, read_constant(ctx, p, "specular_reflectance", Rgb(1.0f)));
    set4(m.specular_transmittance, read_constant(ctx, p, "specular_transmittance", Rgb(1.0f)));
    if (type == "roughdielectric") read_roughness(ctx, p, m);
    else m.alpha_u = m.alpha_v = 0.0f;
    return m;
  }
  if (type == "plastic" || type == "roughplastic") {
    GdrMaterial m = base_material(type == "plastic" ? BSDF_PLASTIC : BSDF_ROUGH_PLASTIC);
    read_eta(p, m, "polypropylene");
    read_reflectance(ctx, p, "diffuse_reflectance", m);
    set4(m.specular_reflectance, read_constant(ctx, p, "specular_reflectance", Rgb(1.0f)));
    m.nonlinear = p.get_bool("nonlinear", false) ? 1 : 0;
    if (type == "roughplastic") {
      read_roughness(ctx, p, m);
      // Its coating is tabulated over cos(theta) only (render/coating_tables.h), as in Mitsuba 3,
      // which refuses anisotropic roughplastic too.
      if (m.alpha_u != m.alpha_v) {
        const XmlNode* n = p.find("alpha_u") ? p.find("alpha_u") : &p.node();
        throw InputError(n->file, n->line, "roughplastic does not support anisotropic roughness "
                                           "(alpha_u != alpha_v): give one 'alpha'");
      }
    } else {
      m.alpha_u = m.alpha_v = 0.0f;
    }
    return m;
  }
  if (type == "bumpmap" || type == "normalmap" || type == "mask" || type == "coating" ||
      type == "roughcoating" || type == "blendbsdf") {
    if (const XmlNode* inner = wrapped_bsdf(p)) {
      ctx.unsupported(node, "not supported: using its (first) nested BSDF");
      return make_material(ctx, *inner, twosided_out);
    }
  }
  ctx.unsupported(node, "BSDF not supported: using a 50% grey diffuse");
  return base_material(BSDF_DIFFUSE);
}

std::string element_name(const XmlNode& node) {
  if (const std::string* id = node.attr("id")) return *id;
  return node.type() + " at " + node.file + ":" + std::to_string(node.line);
}

}  // namespace

int load_material(LoadContext& ctx, const XmlNode& bsdf) {
  auto it = ctx.material_of.find(&bsdf);
  if (it != ctx.material_of.end()) return it->second;
  int twosided = 0;
  GdrMaterial m = make_material(ctx, bsdf, &twosided);
  m.twosided = twosided;
  int index = static_cast<int>(ctx.scene.materials.size());
  ctx.scene.materials.push_back(m);
  ctx.scene.material_names.push_back(element_name(bsdf));
  ctx.material_of[&bsdf] = index;
  return index;
}

int default_material(LoadContext& ctx) {
  if (ctx.default_material < 0) {
    ctx.default_material = static_cast<int>(ctx.scene.materials.size());
    ctx.scene.materials.push_back(base_material(BSDF_DIFFUSE));
    ctx.scene.material_names.push_back("default diffuse");
  }
  return ctx.default_material;
}

int black_material(LoadContext& ctx) {
  if (ctx.black_material < 0) {
    ctx.black_material = static_cast<int>(ctx.scene.materials.size());
    GdrMaterial m = base_material(BSDF_DIFFUSE);
    set4(m.reflectance, Rgb(0.0f));
    ctx.scene.materials.push_back(m);
    ctx.scene.material_names.push_back("default black diffuse (emitter without a BSDF)");
  }
  return ctx.black_material;
}

}  // namespace gdr
