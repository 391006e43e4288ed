#include "scene/xml_document.h"

#include <pugixml.hpp>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include "util/error.h"

namespace fs = std::filesystem;

namespace gdr {

const std::string* XmlNode::attr(const std::string& name) const {
  for (const auto& [key, value] : attrs)
    if (key == name) return &value;
  return nullptr;
}

std::string XmlNode::attr_or(const std::string& name, const std::string& fallback) const {
  const std::string* v = attr(name);
  return v ? *v : fallback;
}

std::string XmlNode::describe() const {
  std::string s = "<" + tag;
  if (const std::string* t = attr("type")) s += " type=\"" + *t + "\"";
  if (const std::string* n = attr("name")) s += " name=\"" + *n + "\"";
  return s + "> at " + file + ":" + std::to_string(line);
}

const XmlNode& XmlDocument::lookup(const std::string& id, const XmlNode& from) const {
  auto it = ids.find(id);
  if (it == ids.end()) throw InputError(from.file, from.line, "unknown reference id '" + id + "'");
  return *it->second;
}

namespace {

// exists() without the exception: a name the OS rejects (too long, say) is a missing file.
bool file_exists(const fs::path& p) {
  std::error_code ec;
  return fs::exists(p, ec);
}

}  // namespace

std::string XmlDocument::resolve(const std::string& filename, const XmlNode& from) const {
  fs::path p(filename);
  if (p.is_absolute()) {
    if (file_exists(p)) return p.string();
  } else {
    for (const std::string& dir : search_paths) {
      fs::path candidate = fs::path(dir) / p;
      if (file_exists(candidate)) return candidate.lexically_normal().string();
    }
    fs::path beside = fs::path(from.file).parent_path() / p;
    if (file_exists(beside)) return beside.lexically_normal().string();
  }
  std::string searched;
  for (const std::string& dir : search_paths) searched += (searched.empty() ? "" : ", ") + dir;
  throw InputError(from.file, from.line,
                   "missing file '" + filename + "' (searched: " + searched + ")");
}

std::string snake_case(const std::string& name) {
  std::string out;
  for (size_t i = 0; i < name.size(); ++i) {
    char c = name[i];
    if (std::isupper(static_cast<unsigned char>(c))) {
      if (i > 0 && std::islower(static_cast<unsigned char>(name[i - 1]))) out += '_';
      out += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    } else {
      out += c;
    }
  }
  return out;
}

namespace {

// One parsed file: its text is kept to turn pugixml's byte offsets into line numbers.
struct SourceFile {
  std::string path;
  std::string text;
  std::vector<size_t> line_starts;

  int line_of(ptrdiff_t offset) const {
    if (offset < 0) return 0;
    auto it = std::upper_bound(line_starts.begin(), line_starts.end(), static_cast<size_t>(offset));
    return static_cast<int>(it - line_starts.begin());
  }
};

class Builder {
 public:
  Builder(XmlDocument& doc, const std::map<std::string, std::string>& defines)
      : doc_(doc), params_(defines) {}

  // Parses `path` and appends its elements to `parent` (the root <scene>'s children are spliced).
  void load(const std::string& path, XmlNode& parent, const XmlNode* included_from, bool top) {
    if (std::find(stack_.begin(), stack_.end(), path) != stack_.end()) {
      throw InputError(included_from->file, included_from->line, "include cycle: '" + path + "'");
    }
    if (stack_.size() > 32) throw InputError(path, 0, "includes nested too deeply");
    auto src = std::make_unique<SourceFile>();
    src->path = path;
    if (std::error_code ec; fs::is_directory(path, ec)) {
      if (included_from) {
        throw InputError(included_from->file, included_from->line, "'" + path + "' is a folder, not a file");
      }
      throw InputError(path, 0, "a folder, not a scene file");
    }
    std::ifstream in(path, std::ios::binary);
    if (!in) {
      if (included_from) throw InputError(included_from->file, included_from->line, "cannot read '" + path + "'");
      throw InputError(path, 0, "cannot read the scene file");
    }
    std::ostringstream ss;
    ss << in.rdbuf();
    src->text = ss.str();
    src->line_starts.push_back(0);
    for (size_t i = 0; i < src->text.size(); ++i)
      if (src->text[i] == '\n') src->line_starts.push_back(i + 1);

    pugi::xml_document xml;
    pugi::xml_parse_result result = xml.load_buffer(src->text.data(), src->text.size());
    if (!result) {
      throw InputError(path, src->line_of(result.offset),
                       std::string("malformed XML: ") + result.description());
    }
    pugi::xml_node root = xml.document_element();
    if (!root) throw InputError(path, 0, "no root element");
    stack_.push_back(path);
    const SourceFile& file = *src;
    files_.push_back(std::move(src));
    int version = 3;
    if (std::string(root.name()) == "scene") {
      std::string v = root.attribute("version").value();
      if (!v.empty() && std::isdigit(static_cast<unsigned char>(v[0]))) version = std::atoi(v.c_str());
      if (top) {
        parent.file = path;
        parent.line = file.line_of(root.offset_debug());
        parent.version_major = version;
      }
      for (pugi::xml_node child : root.children()) visit(child, parent, file, version);
    } else {
      if (top) throw InputError(path, file.line_of(root.offset_debug()), "the root element must be <scene>");
      visit(root, parent, file, version);
    }
    stack_.pop_back();
  }

 private:
  std::string substitute(const std::string& value, const SourceFile& file, int line) {
    if (value.find('$') == std::string::npos) return value;
    std::string out;
    for (size_t i = 0; i < value.size();) {
      if (value[i] != '$') {
        out += value[i++];
        continue;
      }
      size_t j = i + 1;
      while (j < value.size() && (std::isalnum(static_cast<unsigned char>(value[j])) || value[j] == '_')) ++j;
      std::string key = value.substr(i + 1, j - i - 1);
      if (key.empty()) {
        out += value[i++];
        continue;
      }
      used_.insert(key);
      auto it = params_.find(key);
      if (it == params_.end()) {
        throw InputError(file.path, line, "undefined parameter $" + key + " (no <default> and no -D " + key + "=...)");
      }
      out += it->second;
      i = j;
    }
    return out;
  }

  void visit(pugi::xml_node xml, XmlNode& parent, const SourceFile& file, int version) {
    if (xml.type() != pugi::node_element) return;
    int line = file.line_of(xml.offset_debug());
    std::string tag = xml.name();
    if (tag == "default") {
      std::string name = xml.attribute("name").value();
      if (name.empty()) throw InputError(file.path, line, "<default> without a name");
      if (!xml.attribute("value")) throw InputError(file.path, line, "<default name=\"" + name + "\"> without a value");
      std::string value = substitute(xml.attribute("value").value(), file, line);
      params_.emplace(name, value);  // the first definition (or the caller's) wins
      declared_.insert(name);
      return;
    }
    auto node = std::make_unique<XmlNode>();
    node->tag = tag;
    node->file = file.path;
    node->line = line;
    node->version_major = version;
    for (pugi::xml_attribute a : xml.attributes()) {
      std::string key = a.name();
      std::string value = substitute(a.value(), file, line);
      if (key == "name") value = snake_case(value);
      node->attrs.emplace_back(key, value);
    }
    if (tag == "include") {
      const std::string* filename = node->attr("filename");
      if (!filename) throw InputError(file.path, line, "<include> without a filename");
      std::string resolved = doc_.resolve(*filename, *node);
      load(resolved, parent, node.get(), false);
      return;
    }
    if (tag == "path") {
      const std::string* value = node->attr("value");
      if (!value) throw InputError(file.path, line, "<path> without a value");
      fs::path p(*value);
      if (!p.is_absolute()) p = fs::path(file.path).parent_path() / p;
      doc_.search_paths.insert(doc_.search_paths.begin(), p.lexically_normal().string());
      return;
    }
    for (pugi::xml_node child : xml.children()) visit(child, *node, file, version);
    if (const std::string* id = node->attr("id"); id && tag != "ref") {
      auto [it, fresh] = doc_.ids.emplace(*id, node.get());
      if (!fresh) {
        throw InputError(file.path, line, "duplicate id '" + *id + "' (first at " + it->second->file + ":" +
                                              std::to_string(it->second->line) + ")");
      }
    }
    parent.children.push_back(std::move(node));
  }

  XmlDocument& doc_;
  std::map<std::string, std::string> params_;

 public:
  std::set<std::string> used_;      // $names the document refers to
  std::set<std::string> declared_;  // <default> names
  std::vector<std::string> stack_;
  std::vector<std::unique_ptr<SourceFile>> files_;
};

}  // namespace

XmlDocument load_xml_document(const std::string& path,
                              const std::map<std::string, std::string>& defines) {
  XmlDocument doc;
  doc.path = path;
  doc.root = std::make_unique<XmlNode>();
  doc.root->tag = "scene";
  doc.root->file = path;
  fs::path folder = fs::path(path).parent_path();
  doc.search_paths.push_back(folder.empty() ? std::string(".") : folder.string());
  Builder builder(doc, defines);
  builder.load(path, *doc.root, nullptr, true);
  for (const auto& [name, value] : defines) {
    if (!builder.used_.count(name) && !builder.declared_.count(name)) doc.unused_defines.push_back(name);
  }
  doc.parameters.assign(builder.declared_.begin(), builder.declared_.end());
  return doc;
}

}  // namespace gdr
