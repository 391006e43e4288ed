// Stanford PLY: ASCII and binary (little and big endian). Reads vertex x y z, optional nx ny nz
// and u v / s t / texture_u texture_v; face lists of any integer types (fan-triangulated).
// Other elements and properties are skipped.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <sstream>

#include "scene/mesh.h"
#include "util/error.h"
#include "util/input_limits.h"

namespace gdr {
namespace {

// The longest face list accepted (a polygon of more vertices than this is not a mesh face).
constexpr size_t kMaxPlyListLength = 1u << 20;

// A value read from the file as the message shows it (%g: whole numbers without decimals).
std::string number(double x) {
  std::ostringstream s;
  s << x;
  return s.str();
}

enum class Type { I8, U8, I16, U16, I32, U32, F32, F64 };

struct Property {
  std::string name;
  Type type = Type::F32;
  bool list = false;
  Type count_type = Type::U8;
};

struct Element {
  std::string name;
  size_t count = 0;
  std::vector<Property> props;
};

Type parse_type(const std::string& s, const std::string& path, int line) {
  if (s == "char" || s == "int8") return Type::I8;
  if (s == "uchar" || s == "uint8") return Type::U8;
  if (s == "short" || s == "int16") return Type::I16;
  if (s == "ushort" || s == "uint16") return Type::U16;
  if (s == "int" || s == "int32") return Type::I32;
  if (s == "uint" || s == "uint32") return Type::U32;
  if (s == "float" || s == "float32") return Type::F32;
  if (s == "double" || s == "float64") return Type::F64;
  throw InputError(path, line, "unknown PLY property type '" + s + "'");
}

size_t type_size(Type t) {
  switch (t) {
    case Type::I8: case Type::U8: return 1;
    case Type::I16: case Type::U16: return 2;
    case Type::I32: case Type::U32: case Type::F32: return 4;
    case Type::F64: return 8;
  }
  return 4;
}

// Reads values from the body: binary (either byte order) or ASCII tokens, one element per line.
class BodyReader {
 public:
  BodyReader(std::istream& in, int format, const std::string& path, int line)
      : in_(in), format_(format), path_(path), line_(line) {}

  // Starts the next element instance (ASCII: the next non-empty line).
  void begin_item() {
    if (format_ != 0) return;
    std::string text;
    do {
      if (!std::getline(in_, text)) throw InputError(path_, line_, "unexpected end of PLY data");
      ++line_;
    } while (text.find_first_not_of(" \t\r") == std::string::npos);
    tokens_.clear();
    tokens_.str(text);
  }

  double read(Type t) {
    if (format_ == 0) {
      std::string tok;
      if (!(tokens_ >> tok)) throw InputError(path_, line_, "too few values on the line");
      const char* s = tok.c_str();
      char* end = nullptr;
      double v = std::strtod(s, &end);
      if (end == s || *end) throw InputError(path_, line_, "'" + tok + "' is not a number");
      return v;
    }
    unsigned char b[8];
    size_t n = type_size(t);
    if (!in_.read(reinterpret_cast<char*>(b), static_cast<std::streamsize>(n))) {
      throw InputError(path_, 0, "unexpected end of PLY data");
    }
    bool little_host = [] { uint16_t x = 1; unsigned char c; std::memcpy(&c, &x, 1); return c == 1; }();
    if ((format_ == 1) != little_host)
      for (size_t i = 0; i < n / 2; ++i) std::swap(b[i], b[n - 1 - i]);
    switch (t) {
      case Type::I8: { int8_t v; std::memcpy(&v, b, 1); return v; }
      case Type::U8: return b[0];
      case Type::I16: { int16_t v; std::memcpy(&v, b, 2); return v; }
      case Type::U16: { uint16_t v; std::memcpy(&v, b, 2); return v; }
      case Type::I32: { int32_t v; std::memcpy(&v, b, 4); return v; }
      case Type::U32: { uint32_t v; std::memcpy(&v, b, 4); return v; }
      case Type::F32: { float v; std::memcpy(&v, b, 4); return v; }
      case Type::F64: { double v; std::memcpy(&v, b, 8); return v; }
    }
    return 0;
  }

  int line() const { return format_ == 0 ? line_ : 0; }

 private:
  std::istream& in_;
  int format_;  // 0 ascii, 1 little endian, 2 big endian
  std::string path_;
  int line_;
  std::istringstream tokens_;
};

// The length of item `item`'s list in element `element`, read as a double (a list's count may be
// declared float) and converted only once it is a whole number in range: a cast of anything else
// is undefined.
size_t list_length(BodyReader& body, Type count_type, const std::string& path, const std::string& element,
                   size_t item) {
  double c = body.read(count_type);
  if (!(c >= 0 && c <= double(kMaxPlyListLength) && c == std::floor(c))) {
    throw InputError(path, body.line(), element + " " + std::to_string(item) + ": list length " + number(c) +
                                            " is not a whole number from 0 to " + std::to_string(kMaxPlyListLength));
  }
  return static_cast<size_t>(c);
}

int uv_slot(const std::string& n) {
  if (n == "u" || n == "s" || n == "texture_u" || n == "texture_s") return 0;
  if (n == "v" || n == "t" || n == "texture_v" || n == "texture_t") return 1;
  return -1;
}

}  // namespace

MeshData read_ply(const std::string& path) {
  uint64_t file_size = checked_input_size(path, "PLY mesh");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, 0, "cannot read the PLY file");
  std::string text;
  int line = 0;
  auto next_header_line = [&]() {
    if (!std::getline(in, text)) throw InputError(path, line, "PLY header ends before end_header");
    ++line;
    if (!text.empty() && text.back() == '\r') text.pop_back();
  };
  next_header_line();
  if (text != "ply") throw InputError(path, 1, "not a PLY file (no 'ply' magic)");
  int format = -1;
  std::vector<Element> elements;
  for (;;) {
    next_header_line();
    std::istringstream words(text);
    std::string key;
    words >> key;
    if (key == "end_header") break;
    if (key == "format") {
      std::string f;
      words >> f;
      if (f == "ascii") format = 0;
      else if (f == "binary_little_endian") format = 1;
      else if (f == "binary_big_endian") format = 2;
      else throw InputError(path, line, "unknown PLY format '" + f + "'");
    } else if (key == "element") {
      Element e;
      long long count = -1;
      if (!(words >> e.name >> count) || count < 0) throw InputError(path, line, "bad element count");
      e.count = static_cast<size_t>(count);
      elements.push_back(e);
    } else if (key == "property") {
      if (elements.empty()) throw InputError(path, line, "property before any element");
      Property p;
      std::string type;
      words >> type;
      if (type == "list") {
        std::string count_type, item_type;
        words >> count_type >> item_type >> p.name;
        p.list = true;
        p.count_type = parse_type(count_type, path, line);
        p.type = parse_type(item_type, path, line);
      } else {
        p.type = parse_type(type, path, line);
        words >> p.name;
      }
      elements.back().props.push_back(p);
    } else if (key != "comment" && key != "obj_info" && !key.empty()) {
      throw InputError(path, line, "unknown PLY header line '" + text + "'");
    }
  }
  if (format < 0) throw InputError(path, line, "PLY header without a format line");
  // The counts the header declares, checked against the body's real size (each item takes at
  // least its scalar sizes in binary, a digit and a separator per value in ASCII) and the input
  // limit before anything is allocated.
  {
    std::streamoff header = in.tellg();
    uint64_t body_size = header > 0 && static_cast<uint64_t>(header) <= file_size ? file_size - header : 0;
    double least = 0, memory = 0;
    for (const Element& e : elements) {
      double item = 0;
      for (const Property& p : e.props) item += format == 0 ? 2.0 : static_cast<double>(type_size(p.list ? p.count_type : p.type));
      if (format == 0) item = std::max(item, 2.0);  // an ASCII item is a non-empty line
      least += item * static_cast<double>(e.count);
      if (e.name == "vertex") memory += 8.0 * sizeof(float) * static_cast<double>(e.count);
      if (e.name == "face") memory += 3.0 * sizeof(int) * static_cast<double>(e.count);
    }
    std::string claim = "the header claims";
    for (const Element& e : elements) claim += " " + std::to_string(e.count) + " " + e.name + (elements.size() > 1 && &e != &elements.back() ? "," : "");
    check_declared_size(path, least, body_size, 1.0, claim);
    check_input_allocation(path, memory >= 1.8e19 ? UINT64_MAX : static_cast<uint64_t>(memory), claim + ", which");
  }

  MeshData mesh;
  size_t vertex_count = 0;
  bool has_normals = false, has_uvs = false;
  BodyReader body(in, format, path, line);
  for (const Element& e : elements) {
    if (e.name == "vertex") {
      int slots[32];
      if (e.props.size() > 32) throw InputError(path, 0, "too many vertex properties");
      int found = 0;
      for (size_t i = 0; i < e.props.size(); ++i) {
        const std::string& n = e.props[i].name;
        slots[i] = n == "x" ? 0 : n == "y" ? 1 : n == "z" ? 2 : n == "nx" ? 3 : n == "ny" ? 4 : n == "nz" ? 5
                 : uv_slot(n) >= 0 ? 6 + uv_slot(n) : -1;
        if (slots[i] >= 0) found |= 1 << slots[i];
      }
      if ((found & 7) != 7) throw InputError(path, 0, "PLY vertices lack x, y or z");
      has_normals = (found & 0x38) == 0x38;
      has_uvs = (found & 0xC0) == 0xC0;
      vertex_count = e.count;
      mesh.positions.reserve(3 * e.count);
      for (size_t v = 0; v < e.count; ++v) {
        body.begin_item();
        double vals[8] = {0, 0, 0, 0, 0, 0, 0, 0};
        for (size_t i = 0; i < e.props.size(); ++i) {
          const Property& p = e.props[i];
          if (p.list) {
            size_t n = list_length(body, p.count_type, path, e.name, v);
            for (size_t k = 0; k < n; ++k) body.read(p.type);
          } else {
            double x = body.read(p.type);
            if (slots[i] >= 0) vals[slots[i]] = x;
          }
        }
        for (int k = 0; k < 3; ++k) {
          if (!std::isfinite(vals[k])) {
            throw InputError(path, body.line(), "vertex " + std::to_string(v) + " has a non-finite coordinate");
          }
          mesh.positions.push_back(static_cast<float>(vals[k]));
        }
        if (has_normals)
          for (int k = 3; k < 6; ++k) mesh.normals.push_back(static_cast<float>(vals[k]));
        if (has_uvs)
          for (int k = 6; k < 8; ++k) mesh.uvs.push_back(static_cast<float>(vals[k]));
      }
    } else if (e.name == "face") {
      int list_prop = -1;
      for (size_t i = 0; i < e.props.size(); ++i)
        if (e.props[i].list && (e.props[i].name == "vertex_indices" || e.props[i].name == "vertex_index"))
          list_prop = static_cast<int>(i);
      if (list_prop < 0) throw InputError(path, 0, "PLY faces without a vertex_indices list");
      std::vector<long long> poly;
      for (size_t f = 0; f < e.count; ++f) {
        body.begin_item();
        for (size_t i = 0; i < e.props.size(); ++i) {
          const Property& p = e.props[i];
          size_t n = p.list ? list_length(body, p.count_type, path, e.name, f) : 1;
          if (static_cast<int>(i) == list_prop) poly.clear();
          for (size_t k = 0; k < n; ++k) {
            double x = body.read(p.type);
            if (static_cast<int>(i) != list_prop) continue;
            if (!(x >= 0 && x < double(vertex_count) && x == std::floor(x))) {
              throw InputError(path, body.line(), "face " + std::to_string(f) + " refers to vertex " + number(x) +
                                                      " but the file has " + std::to_string(vertex_count) +
                                                      " vertices");
            }
            poly.push_back(static_cast<long long>(x));
          }
        }
        for (size_t k = 1; k + 1 < poly.size(); ++k) {
          mesh.indices.push_back(static_cast<int>(poly[0]));
          mesh.indices.push_back(static_cast<int>(poly[k]));
          mesh.indices.push_back(static_cast<int>(poly[k + 1]));
        }
      }
    } else if (format == 0 || !e.props.empty()) {  // binary items without properties take no bytes
      for (size_t item = 0; item < e.count; ++item) {
        body.begin_item();
        for (const Property& p : e.props) {
          size_t n = p.list ? list_length(body, p.count_type, path, e.name, item) : 1;
          for (size_t k = 0; k < n; ++k) body.read(p.type);
        }
      }
    }
  }
  if (vertex_count == 0 && mesh.indices.empty()) throw InputError(path, 0, "PLY file without vertices");
  return mesh;
}

}  // namespace gdr
