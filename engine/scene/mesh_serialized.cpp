// Mitsuba's .serialized meshes: a sequence of meshes, each a header (uint16 0x041C, uint16
// version 3 or 4) and a zlib stream (flags, [v4: name], vertex and triangle counts, positions,
// normals, uvs, colours, uint32 indices), then a table of mesh offsets (uint64 in v4, uint32 in
// v3) and their count (uint32) at the end of the file. Little endian throughout.
#include <zlib.h>

#include <cmath>
#include <cstdint>
#include <algorithm>
#include <cstring>
#include <new>

#include "scene/mesh.h"
#include "util/error.h"
#include "util/input_limits.h"

namespace gdr {
namespace {

constexpr uint16_t kMagic = 0x041C;
constexpr uint32_t kHasNormals = 0x0001, kHasUvs = 0x0002, kHasColors = 0x0008, kFaceNormals = 0x0010,
                   kDouble = 0x2000;

template <class T>
T load_le(const unsigned char* p) {
  T v = 0;
  for (size_t i = 0; i < sizeof(T); ++i) v |= static_cast<T>(static_cast<T>(p[i]) << (8 * i));
  return v;
}

// Inflates the zlib stream that starts at `data` on demand: no size is stored, so the counts are
// read first and only the bytes they call for are inflated (a stream that inflates to gigabytes
// costs no more than its counts allow).
class Inflater {
 public:
  Inflater(const unsigned char* data, size_t size, const std::string& path) : path_(path) {
    if (inflateInit(&zs_) != Z_OK) throw InputError(path, 0, "zlib initialisation failed");
    zs_.next_in = const_cast<unsigned char*>(data);
    zs_.avail_in = static_cast<uInt>(std::min<size_t>(size, 0xFFFFFFFFu));
  }
  ~Inflater() { inflateEnd(&zs_); }
  Inflater(const Inflater&) = delete;
  Inflater& operator=(const Inflater&) = delete;

  const std::vector<unsigned char>& bytes() const { return out_; }

  // Inflates until at least `n` bytes are out (fewer only when the stream ends first).
  void fill(size_t n) {
    if (n <= out_.size() || ended_) return;
    size_t old = out_.size();
    try {
      out_.resize(n);
    } catch (const std::bad_alloc&) {
      throw InputError(path_, 0, "out of memory inflating " + format_bytes(n) + " of mesh data");
    }
    zs_.next_out = out_.data() + old;
    zs_.avail_out = static_cast<uInt>(std::min<size_t>(n - old, 0xFFFFFFFFu));
    while (zs_.avail_out > 0) {
      int ret = inflate(&zs_, Z_NO_FLUSH);
      if (ret == Z_STREAM_END) {
        ended_ = true;
        break;
      }
      if (ret != Z_OK) {
        throw InputError(path_, 0, std::string("corrupt compressed mesh data (zlib: ") + (zs_.msg ? zs_.msg : "error") + ")");
      }
      if (zs_.avail_in == 0 && zs_.avail_out > 0) throw InputError(path_, 0, "truncated compressed mesh data");
    }
    out_.resize(n - zs_.avail_out);
  }

 private:
  z_stream zs_{};
  std::vector<unsigned char> out_;
  bool ended_ = false;
  std::string path_;
};

}  // namespace

MeshData read_serialized(const std::string& path, int shape_index) {
  const std::string bytes = read_input_file(path, ".serialized mesh");
  const auto* data = reinterpret_cast<const unsigned char*>(bytes.data());
  size_t size = bytes.size();
  if (size < 8 || load_le<uint16_t>(data) != kMagic) throw InputError(path, 0, "not a Mitsuba .serialized mesh file");
  uint16_t version = load_le<uint16_t>(data + 2);
  if (version != 3 && version != 4) {
    throw InputError(path, 0, "unsupported .serialized version " + std::to_string(version));
  }
  uint32_t count = load_le<uint32_t>(data + size - 4);
  if (shape_index < 0 || static_cast<uint32_t>(shape_index) >= count) {
    throw InputError(path, 0, "shape_index " + std::to_string(shape_index) + " out of range (the file holds " +
                                  std::to_string(count) + " meshes)");
  }
  size_t entry = version == 4 ? 8 : 4;
  if (size < 4 + entry * count) throw InputError(path, 0, "truncated mesh offset table");
  size_t at = size - 4 - entry * (count - static_cast<size_t>(shape_index));
  uint64_t offset = version == 4 ? load_le<uint64_t>(data + at) : load_le<uint32_t>(data + at);
  // offset + 4 could wrap around for offsets near 2^64; size >= 8 here.
  if (offset > size - 4 || load_le<uint16_t>(data + offset) != kMagic) {
    throw InputError(path, 0, "bad offset for mesh " + std::to_string(shape_index));
  }
  size_t compressed = size - offset - 4;
  Inflater z(data + offset + 4, compressed, path);

  size_t pos = 0;
  auto need = [&](size_t n) {
    z.fill(pos + n);
    if (pos + n > z.bytes().size()) throw InputError(path, 0, "truncated mesh " + std::to_string(shape_index));
  };
  need(4);
  uint32_t flags = load_le<uint32_t>(z.bytes().data());
  pos = 4;
  if (version == 4) {
    // The mesh's name, up to its NUL.
    for (;; ++pos) {
      if (pos > 4 + 65536) throw InputError(path, 0, "mesh " + std::to_string(shape_index) + ": name too long");
      need(1);
      if (z.bytes()[pos] == 0) break;
    }
    ++pos;
  }
  need(16);
  uint64_t nv = load_le<uint64_t>(z.bytes().data() + pos);
  uint64_t nt = load_le<uint64_t>(z.bytes().data() + pos + 8);
  pos += 16;
  size_t scalar = (flags & kDouble) ? 8 : 4;
  if (nv > (1ull << 31) || nt > (1ull << 31)) throw InputError(path, 0, "mesh too large");
  // What the counts call for, checked before it is inflated: against what the compressed stream
  // can hold (deflate compresses at most about 1032:1) and against the input limit.
  uint64_t per_vertex = 3 + ((flags & kHasNormals) ? 3 : 0) + ((flags & kHasUvs) ? 2 : 0) + ((flags & kHasColors) ? 3 : 0);
  uint64_t payload = nv * per_vertex * scalar + 12 * nt;
  std::string claim = "mesh " + std::to_string(shape_index) + " claims " + std::to_string(nv) + " vertices and " +
                      std::to_string(nt) + " triangles";
  check_declared_size(path, static_cast<double>(payload), compressed, 1040.0, claim);
  // The inflated data, and the floats and indices it becomes.
  check_input_allocation(path, payload + nv * per_vertex * 4 + 12 * nt, claim + ", which");
  z.fill(pos + payload);
  const std::vector<unsigned char>& raw = z.bytes();
  auto read_scalars = [&](size_t n, std::vector<float>& dst) {
    need(n * scalar);
    dst.resize(n);
    for (size_t i = 0; i < n; ++i, pos += scalar) {
      if (scalar == 8) {
        uint64_t b = load_le<uint64_t>(raw.data() + pos);
        double d;
        std::memcpy(&d, &b, 8);
        dst[i] = static_cast<float>(d);
      } else {
        uint32_t b = load_le<uint32_t>(raw.data() + pos);
        std::memcpy(&dst[i], &b, 4);
      }
    }
  };
  MeshData mesh;
  read_scalars(3 * nv, mesh.positions);
  if (flags & kHasNormals) read_scalars(3 * nv, mesh.normals);
  if (flags & kHasUvs) read_scalars(2 * nv, mesh.uvs);
  if (flags & kHasColors) {
    std::vector<float> colors;
    read_scalars(3 * nv, colors);
  }
  if (flags & kFaceNormals) mesh.normals.clear();
  need(12 * nt);
  mesh.indices.resize(3 * nt);
  for (size_t i = 0; i < 3 * nt; ++i, pos += 4) {
    uint32_t idx = load_le<uint32_t>(raw.data() + pos);
    if (idx >= nv) {
      throw InputError(path, 0, "mesh " + std::to_string(shape_index) + ": triangle " + std::to_string(i / 3) +
                                    " refers to vertex " + std::to_string(idx) + " of " + std::to_string(nv));
    }
    mesh.indices[i] = static_cast<int>(idx);
  }
  for (size_t i = 0; i < mesh.positions.size(); ++i) {
    if (!std::isfinite(mesh.positions[i])) {
      throw InputError(path, 0, "mesh " + std::to_string(shape_index) + ": vertex " + std::to_string(i / 3) +
                                    " has a non-finite coordinate");
    }
  }
  return mesh;
}

}  // namespace gdr
