#include "scene/xml_spectrum.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include "scene/xml_values.h"
#include "util/error.h"

namespace gdr {
namespace {

using Samples = std::vector<std::pair<double, double>>;

// Mitsuba's rules for a sampled spectrum (Properties::Spectrum), and gdrender's for any value.
Samples checked(const XmlNode& node, const std::string& what, const std::vector<double>& nm,
                const std::vector<double>& values) {
  if (nm.size() != values.size()) {
    node_error(node, what + ": " + std::to_string(nm.size()) + " wavelengths but " + std::to_string(values.size()) +
                         " values");
  }
  if (nm.size() < 2)
    node_error(node, what + ": a sampled spectrum needs at least two wavelengths (or one value alone)");
  Samples s;
  for (size_t i = 0; i < nm.size(); ++i) {
    if (!std::isfinite(nm[i])) node_error(node, what + ": wavelengths must be finite");
    if (!std::isfinite(values[i])) node_error(node, what + ": values must be finite");
    if (values[i] < 0) node_error(node, what + ": values must not be negative");
    if (i > 0 && !(nm[i] > nm[i - 1])) node_error(node, what + ": wavelengths must increase");
    s.emplace_back(nm[i], values[i]);
  }
  return s;
}

// value="nm:v, nm:v, ..."
Samples inline_samples(const XmlNode& node) {
  std::vector<double> nm, values;
  for (const std::string& tok : split_number_list(required_attr(node, "value"))) {
    size_t colon = tok.find(':');
    if (colon == std::string::npos) {
      node_error(node, describe_attr(node, "value") + ": '" + tok + "' is not wavelength:value");
    }
    nm.push_back(parse_number_text(node, "value", tok.substr(0, colon)));
    values.push_back(parse_number_text(node, "value", tok.substr(colon + 1)));
  }
  return checked(node, describe_attr(node, "value"), nm, values);
}

std::vector<double> number_list(const Props& p, const std::string& name) {
  const XmlNode* n = p.find(name);
  if (!n) node_error(p.node(), "<spectrum type=\"" + p.type() + "\"> needs '" + name + "'");
  return parse_number_list(*n, "value");
}

double required_float(const Props& p, const std::string& name) {
  if (!p.has(name)) node_error(p.node(), "<spectrum type=\"" + p.type() + "\"> needs '" + name + "'");
  return p.get_float(name, 0.0);
}

std::string where(const XmlNode& node) {
  return "<spectrum type=\"" + node.type() + "\" name=\"" + node.name() + "\">";
}

// Properties::Spectrum(values, wavelength_min, wavelength_max): evenly spaced samples.
Samples regular_samples(const Props& p) {
  double lo = required_float(p, "wavelength_min"), hi = required_float(p, "wavelength_max");
  std::vector<double> values = number_list(p, "values");
  if (values.size() < 2) node_error(p.node(), where(p.node()) + ": a regular spectrum needs at least two values");
  std::vector<double> nm(values.size());
  double step = (hi - lo) / static_cast<double>(values.size() - 1);
  for (size_t i = 0; i < nm.size(); ++i) nm[i] = lo + step * static_cast<double>(i);
  return checked(p.node(), where(p.node()), nm, values);
}

std::string format_rgb(const double c[3]) {
  char buf[96];
  std::snprintf(buf, sizeof buf, "(%.6g, %.6g, %.6g)", c[0], c[1], c[2]);
  return buf;
}

// The clamp is Mitsuba's; the warning names what was clamped and where.
Rgb report_clamp(const XmlNode& node, const XmlDocument& doc, SpectrumUse use, const SpectrumRgb& c) {
  if (!c.clamped) return c.rgb;
  const double after[3] = {c.rgb.r, c.rgb.g, c.rgb.b};
  std::string range = use == SpectrumUse::Reflectance ? "[0, 1] (a reflectance)" : "[0, inf) (outside the sRGB gamut)";
  std::string msg = node.file + ":" + std::to_string(node.line) + ": <" + node.tag + " name=\"" + node.name() +
                    "\">: the spectrum's sRGB colour " + format_rgb(c.unclamped) + " lies outside " + range +
                    ": clamped to " + format_rgb(after) + ", as Mitsuba 3 does";
  if (std::find(doc.warnings.begin(), doc.warnings.end(), msg) == doc.warnings.end()) doc.warnings.push_back(msg);
  return c.rgb;
}

Rgb spectrum_plugin(const XmlNode& node, const XmlDocument& doc, SpectrumUse use) {
  Props p(node, doc);
  std::string type = p.type();
  if (type == "irregular") {
    Samples s = checked(node, where(node), number_list(p, "wavelengths"), number_list(p, "values"));
    return report_clamp(node, doc, use, spectrum_to_rgb(s, use));
  }
  if (type == "regular") return report_clamp(node, doc, use, spectrum_to_rgb(regular_samples(p), use));
  if (type == "blackbody") {
    double kelvin = required_float(p, "temperature");
    if (!(kelvin > 0)) node_error(node, where(node) + ": the temperature must be positive (kelvin)");
    double lo = p.get_float("wavelength_min", 360.0), hi = p.get_float("wavelength_max", 830.0);
    return report_clamp(node, doc, use, blackbody_spectrum_to_rgb(kelvin, lo, hi, use));
  }
  node_error(node, "<spectrum type=\"" + type +
                       "\"> is not supported (gdrender reads the spectrum plugins irregular, "
                       "regular and blackbody, and value=\"...\")");
}

// Mitsuba 0.x: <blackbody temperature="5000K" scale="1"/>.
Rgb legacy_blackbody(const XmlNode& node) {
  std::string temp = required_attr(node, "temperature");
  if (!temp.empty() && (temp.back() == 'K' || temp.back() == 'k')) temp.pop_back();
  double kelvin = parse_number_text(node, "temperature", temp);
  if (!(kelvin > 0) || !std::isfinite(kelvin))
    node_error(node, describe_attr(node, "temperature") + ": must be positive");
  double scale = node.attr("scale") ? parse_number(node, "scale") : 1.0;
  Rgb c = blackbody_to_rgb(kelvin);
  return {static_cast<float>(c.r * scale), static_cast<float>(c.g * scale), static_cast<float>(c.b * scale)};
}

}  // namespace

Rgb parse_spectrum(const XmlNode& node, const XmlDocument& doc, SpectrumUse use) {
  if (node.tag == "blackbody") return legacy_blackbody(node);
  if (node.attr("type")) return spectrum_plugin(node, doc, use);
  if (node.attr("filename")) node_error(node, "<spectrum filename=...> (spectral data files) is not supported");
  const std::string& text = required_attr(node, "value");
  if (text.find(':') == std::string::npos) {
    std::vector<double> v = parse_number_list(node, "value");
    if (v.size() != 1)
      node_error(node, describe_attr(node, "value") + ": expected one value or wavelength:value pairs");
    return uniform_spectrum_to_rgb(v[0], use);
  }
  return report_clamp(node, doc, use, spectrum_to_rgb(inline_samples(node), use));
}

}  // namespace gdr
