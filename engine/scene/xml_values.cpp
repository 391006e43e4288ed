#include "scene/xml_values.h"

#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>

#include "scene/xml_spectrum.h"
#include "util/error.h"

namespace gdr {
namespace {

bool is_sep(char c) { return c == ',' || std::isspace(static_cast<unsigned char>(c)); }

Vec3d attr_vec3(const XmlNode& node, const std::string& attr) {
  std::vector<double> v = parse_number_list(node, attr);
  if (v.size() != 3) node_error(node, describe_attr(node, attr) + ": expected 3 numbers");
  return {v[0], v[1], v[2]};
}

// x/y/z attributes with a default for the missing ones, or value="..." (one or three numbers).
Vec3d xyz_or_value(const XmlNode& node, double fallback, bool allow_single) {
  if (node.attr("value")) {
    std::vector<double> v = parse_number_list(node, "value");
    if (v.size() == 1 && allow_single) return {v[0], v[0], v[0]};
    if (v.size() != 3) node_error(node, describe_attr(node, "value") + ": expected 3 numbers");
    return {v[0], v[1], v[2]};
  }
  Vec3d r{fallback, fallback, fallback};
  const char* names[3] = {"x", "y", "z"};
  for (int i = 0; i < 3; ++i)
    if (node.attr(names[i])) r[i] = parse_number(node, names[i]);
  return r;
}

Mat4d transform_op(const XmlNode& op) {
  const std::string& t = op.tag;
  if (t == "translate") return Mat4d::translate(xyz_or_value(op, 0.0, false));
  if (t == "scale") return Mat4d::scale(xyz_or_value(op, 1.0, true));
  if (t == "rotate") {
    Vec3d axis = xyz_or_value(op, 0.0, false);
    if (length(axis) == 0) node_error(op, "<rotate> needs a non-zero axis");
    return Mat4d::rotate(axis, parse_number(op, "angle"));
  }
  if (t == "matrix") {
    std::vector<double> v = parse_number_list(op, "value");
    Mat4d m;
    if (v.size() == 16) {
      for (int i = 0; i < 16; ++i) m.m[i / 4][i % 4] = v[i];
    } else if (v.size() == 9) {
      for (int i = 0; i < 9; ++i) m.m[i / 3][i % 3] = v[i];
    } else {
      node_error(op, describe_attr(op, "value") + ": expected 16 (or 9) numbers, got " + std::to_string(v.size()));
    }
    if (m.m[3][0] != 0 || m.m[3][1] != 0 || m.m[3][2] != 0 || m.m[3][3] != 1) {
      node_error(op, "<matrix>: projective matrices are not supported (last row must be 0 0 0 1)");
    }
    return m;
  }
  if (t == "lookat") {
    Vec3d origin = attr_vec3(op, "origin"), target = attr_vec3(op, "target");
    Vec3d up = op.attr("up") ? attr_vec3(op, "up") : Vec3d{0, 1, 0};
    if (length(target - origin) == 0) node_error(op, "<lookat>: origin and target coincide");
    return Mat4d::look_at(origin, target, up);
  }
  node_error(op, "unknown transform operation <" + t + ">");
}

}  // namespace

void node_error(const XmlNode& node, const std::string& problem) { throw InputError(node.file, node.line, problem); }

std::string describe_attr(const XmlNode& node, const std::string& attr) {
  std::string s = "attribute '" + attr + "' of <" + node.tag;
  if (const std::string* n = node.attr("name")) s += " name=\"" + *n + "\"";
  return s + ">";
}

const std::string& required_attr(const XmlNode& node, const std::string& attr) {
  const std::string* v = node.attr(attr);
  if (!v) node_error(node, "<" + node.tag + "> needs a '" + attr + "' attribute");
  return *v;
}

double parse_number_text(const XmlNode& node, const std::string& attr, const std::string& text) {
  const char* begin = text.c_str();
  char* end = nullptr;
  errno = 0;
  double v = std::strtod(begin, &end);
  while (end && *end && std::isspace(static_cast<unsigned char>(*end))) ++end;
  if (end == begin || (end && *end) || text.empty()) {
    node_error(node, describe_attr(node, attr) + ": '" + text + "' is not a number");
  }
  return v;
}

std::vector<std::string> split_number_list(const std::string& s) {
  std::vector<std::string> out;
  size_t i = 0;
  while (i < s.size()) {
    while (i < s.size() && is_sep(s[i])) ++i;
    size_t j = i;
    while (j < s.size() && !is_sep(s[j])) ++j;
    if (j > i) out.push_back(s.substr(i, j - i));
    i = j;
  }
  return out;
}

double parse_number(const XmlNode& node, const std::string& attr) {
  return parse_number_text(node, attr, required_attr(node, attr));
}

std::vector<double> parse_number_list(const XmlNode& node, const std::string& attr) {
  std::vector<double> out;
  for (const std::string& tok : split_number_list(required_attr(node, attr))) {
    out.push_back(parse_number_text(node, attr, tok));
  }
  return out;
}

Vec3d parse_vec3(const XmlNode& node) { return xyz_or_value(node, 0.0, false); }

Rgb parse_color(const XmlNode& node) {
  const std::string& t = node.tag;
  if (t == "float" || t == "integer") return Rgb(static_cast<float>(parse_number(node, "value")));
  if (t == "rgb" || t == "srgb") {
    std::string text = required_attr(node, "value");
    Rgb c;
    if (t == "srgb" && !text.empty() && text[0] == '#') {
      if (text.size() != 7) node_error(node, describe_attr(node, "value") + ": expected #rrggbb");
      unsigned long v = std::strtoul(text.c_str() + 1, nullptr, 16);
      c = Rgb(((v >> 16) & 255) / 255.0f, ((v >> 8) & 255) / 255.0f, (v & 255) / 255.0f);
    } else {
      std::vector<double> v = parse_number_list(node, "value");
      if (v.size() == 1) c = Rgb(static_cast<float>(v[0]));
      else if (v.size() == 3) c = Rgb(static_cast<float>(v[0]), static_cast<float>(v[1]), static_cast<float>(v[2]));
      else
        node_error(node, describe_attr(node, "value") + ": expected 1 or 3 numbers, got " + std::to_string(v.size()));
    }
    if (t == "srgb") c = Rgb(srgb_to_linear(c.r), srgb_to_linear(c.g), srgb_to_linear(c.b));
    return c;
  }
  node_error(node, "<" + t + "> is not a colour");
}

Mat4d parse_transform(const XmlNode& node) {
  Mat4d m;
  for (const auto& op : node.children) m = transform_op(*op) * m;
  if (!m.finite()) node_error(node, "<transform> is not finite");
  return m;
}

const XmlNode* Props::find(const std::string& name) const {
  for (const auto& child : node_.children) {
    const std::string* n = child->attr("name");
    if (!n || *n != name) continue;
    child->read = true;
    if (child->tag == "ref") return &doc_.lookup(required_attr(*child, "id"), *child);
    return child.get();
  }
  return nullptr;
}

double Props::get_float(const std::string& name, double fallback) const {
  const XmlNode* n = find(name);
  if (!n) return fallback;
  if (n->tag != "float" && n->tag != "integer")
    node_error(*n, "'" + name + "' must be a <float>, not <" + n->tag + ">");
  double v = parse_number(*n, "value");
  if (!std::isfinite(v)) node_error(*n, describe_attr(*n, "value") + " is not finite");
  return v;
}

int Props::get_int(const std::string& name, int fallback) const {
  const XmlNode* n = find(name);
  if (!n) return fallback;
  if (n->tag != "integer" && n->tag != "float")
    node_error(*n, "'" + name + "' must be an <integer>, not <" + n->tag + ">");
  double v = parse_number(*n, "value");
  if (v != std::floor(v) || std::fabs(v) > 2e9) node_error(*n, describe_attr(*n, "value") + ": not an integer");
  return static_cast<int>(v);
}

bool Props::get_bool(const std::string& name, bool fallback) const {
  const XmlNode* n = find(name);
  if (!n) return fallback;
  std::string v = required_attr(*n, "value");
  for (char& c : v) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (v == "true" || v == "1") return true;
  if (v == "false" || v == "0") return false;
  node_error(*n, describe_attr(*n, "value") + ": '" + v + "' is not true or false");
}

std::string Props::get_string(const std::string& name, const std::string& fallback) const {
  const XmlNode* n = find(name);
  return n ? required_attr(*n, "value") : fallback;
}

Vec3d Props::get_vec3(const std::string& name, Vec3d fallback) const {
  const XmlNode* n = find(name);
  return n ? parse_vec3(*n) : fallback;
}

Mat4d Props::get_transform(const std::string& name) const {
  const XmlNode* n = find(name);
  if (!n) return Mat4d{};
  if (n->tag != "transform") node_error(*n, "'" + name + "' must be a <transform>");
  Mat4d m = parse_transform(*n);
  for (const auto& op : n->children) {
    if (op->tag != "lookat") continue;
    Vec3d origin = attr_vec3(*op, "origin"), target = attr_vec3(*op, "target");
    Vec3d up = op->attr("up") ? attr_vec3(*op, "up") : Vec3d{0, 1, 0};
    if (length(cross(up, target - origin)) == 0) {
      doc_.warnings.push_back(op->file + ":" + std::to_string(op->line) +
                              ": <lookat>: the up vector is parallel to the view direction (or zero); another "
                              "perpendicular one is used");
    }
  }
  return m;
}

Rgb Props::get_color(const std::string& name, Rgb fallback, SpectrumUse use) const {
  const XmlNode* n = find(name);
  if (!n || n->tag == "texture") return fallback;
  Rgb c = n->tag == "spectrum" || n->tag == "blackbody" ? parse_spectrum(*n, doc_, use) : parse_color(*n);
  for (float v : {c.r, c.g, c.b}) {
    if (!std::isfinite(v)) node_error(*n, "'" + name + "' is not finite");
    if (v < 0) node_error(*n, "'" + name + "' must not be negative");
  }
  return c;
}

const XmlNode* Props::texture(const std::string& name) const {
  const XmlNode* n = find(name);
  return n && n->tag == "texture" ? n : nullptr;
}

std::vector<const XmlNode*> Props::nested(const std::string& tag) const {
  std::vector<const XmlNode*> out;
  for (const auto& child : node_.children) {
    if (child->tag == tag) {
      out.push_back(child.get());
    } else if (child->tag == "ref") {
      const XmlNode& target = doc_.lookup(required_attr(*child, "id"), *child);
      if (target.tag == tag) {
        out.push_back(&target);
        child->read = true;
      }
    }
  }
  return out;
}

}  // namespace gdr
