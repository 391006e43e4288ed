// A Mitsuba XML scene as a tree, after the document-level steps: <include> fragments spliced in,
// <default> and $name substitution applied to every attribute, <path> folders collected, ids
// indexed, and property names in Mitsuba 0.6 camelCase turned into snake_case (toWorld ->
// to_world, intIOR -> int_ior), so the rest of the loader reads one dialect.
#pragma once
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace gdr {

struct XmlNode {
  std::string tag;
  std::vector<std::pair<std::string, std::string>> attrs;
  std::vector<std::unique_ptr<XmlNode>> children;
  std::string file;  // the file the element was written in
  int line = 0;
  int version_major = 3;  // from that file's <scene version="...">
  // Set by the loader: the element was read as a plugin (its properties were looked up), and the
  // element was looked up as a property. A plugin's named child that was never looked up is a
  // parameter gdrender does not know (a typo, or one it does not reproduce).
  mutable bool loaded = false;
  mutable bool read = false;

  // The attribute's value, or nullptr.
  const std::string* attr(const std::string& name) const;
  std::string attr_or(const std::string& name, const std::string& fallback) const;
  std::string type() const { return attr_or("type", ""); }
  std::string name() const { return attr_or("name", ""); }
  // "<shape type="obj"> at FILE:LINE" for messages.
  std::string describe() const;
};

struct XmlDocument {
  std::string path;  // the top-level file
  std::unique_ptr<XmlNode> root;
  std::vector<std::string> search_paths;  // <path> folders (last declared first), then the scene's
  std::map<std::string, const XmlNode*> ids;
  std::vector<std::string> parameters;      // names of the scene's <default>s
  std::vector<std::string> unused_defines;  // caller's defines the scene neither declares nor uses
  // Things worth a warning found while reading the document (an unknown version, a <lookat>
  // whose up vector had to be replaced), each naming file and line.
  mutable std::vector<std::string> warnings;

  // The element `id` refers to; InputError naming `from` when there is none.
  const XmlNode& lookup(const std::string& id, const XmlNode& from) const;
  // A file named in the scene: absolute, or found in the search paths (then next to the file
  // that names it). InputError naming `from` when it does not exist.
  std::string resolve(const std::string& filename, const XmlNode& from) const;
};

// Parses `path`; `defines` override the scene's <default> values. Throws InputError (malformed
// XML with its line, missing include, undefined $name, duplicate id, include cycle).
XmlDocument load_xml_document(const std::string& path,
                              const std::map<std::string, std::string>& defines);

// "toWorld" -> "to_world", "intIOR" -> "int_ior"; snake_case names are returned unchanged.
std::string snake_case(const std::string& name);

}  // namespace gdr
