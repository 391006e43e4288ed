// Reading plugin properties from the XML tree: <float>, <integer>, <boolean>, <string>, <point>,
// <vector>, <rgb>, <srgb>, <spectrum>, <blackbody>, <transform>, named <ref>s and nested plugins.
// Every malformed value is an InputError naming the file, line and attribute.
#pragma once
#include <initializer_list>
#include <string>
#include <vector>

#include "scene/spectrum.h"
#include "scene/transform.h"
#include "scene/xml_document.h"

namespace gdr {

// Throws InputError naming the node's file and line.
[[noreturn]] void node_error(const XmlNode& node, const std::string& problem);
// "attribute 'value' of <spectrum name="reflectance">" for messages.
std::string describe_attr(const XmlNode& node, const std::string& attr);
// The attribute's value; InputError naming file and line when it is missing.
const std::string& required_attr(const XmlNode& node, const std::string& attr);
// Strict number parsing of attribute `attr` of `node` (the whole value must be a number).
double parse_number(const XmlNode& node, const std::string& attr);
// `text` (part of attribute `attr` of `node`) as a number, parsed as strictly.
double parse_number_text(const XmlNode& node, const std::string& attr, const std::string& text);
// A list of numbers separated by commas and/or white space.
std::vector<double> parse_number_list(const XmlNode& node, const std::string& attr);
// The items of such a list, unparsed.
std::vector<std::string> split_number_list(const std::string& text);
// <point>/<vector>: x/y/z attributes (missing ones 0) or value="x y z".
Vec3d parse_vec3(const XmlNode& node);
// <rgb>/<srgb>/<float>/<integer>: the colour as linear RGB (spectra: scene/xml_spectrum.h).
Rgb parse_color(const XmlNode& node);
// <transform>: its operations composed in order (each later one applied after the earlier ones).
Mat4d parse_transform(const XmlNode& node);

// The properties of one plugin element.
class Props {
 public:
  Props(const XmlNode& node, const XmlDocument& doc) : node_(node), doc_(doc) { node.loaded = true; }
  const XmlNode& node() const { return node_; }
  const XmlDocument& doc() const { return doc_; }
  std::string type() const { return node_.type(); }

  // The child named `name` (a value element, a nested plugin, or the target of a named <ref>).
  const XmlNode* find(const std::string& name) const;
  bool has(const std::string& name) const { return find(name) != nullptr; }

  double get_float(const std::string& name, double fallback) const;
  int get_int(const std::string& name, int fallback) const;
  bool get_bool(const std::string& name, bool fallback) const;
  std::string get_string(const std::string& name, const std::string& fallback) const;
  Vec3d get_vec3(const std::string& name, Vec3d fallback) const;
  Mat4d get_transform(const std::string& name) const;  // identity when absent
  // A colour given as a value (InputError when it is not finite or negative); a spectrum is
  // converted for `use` as Mitsuba 3's RGB variants do (scene/spectrum.h). nullptr from
  // texture() when it is a constant.
  Rgb get_color(const std::string& name, Rgb fallback, SpectrumUse use) const;
  const XmlNode* texture(const std::string& name) const;

  // Marks parameters as known although nothing here reads them (they change nothing in
  // gdrender's output, such as a film's pixel format), so they are not reported as unknown.
  void known(std::initializer_list<const char*> names) const {
    for (const char* n : names) find(n);
  }

  // Nested plugins with this tag, named or not, <ref>s resolved, in document order.
  std::vector<const XmlNode*> nested(const std::string& tag) const;

 private:
  const XmlNode& node_;
  const XmlDocument& doc_;
};

}  // namespace gdr
