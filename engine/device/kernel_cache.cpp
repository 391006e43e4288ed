#include "device/kernel_cache.h"

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <algorithm>
#include <iterator>
#include <string_view>

#include "image/atomic_file.h"
#include "util/hash.h"

namespace gdr {
namespace {

// PoCL caches its own builds (in POCL_CACHE_DIR) and, asked for a program's binary, first compiles
// every kernel of the program for any work-group size, which doubles a first build to shorten a
// warm start a little (README gives the figures): its programs are stored only when asked for.
bool cache_wanted(const DeviceInfo& device) {
  const char* setting = std::getenv("GDR_KERNEL_CACHE");
  const std::string mode = setting ? setting : "";
  if (mode == "off") return false;
  return mode == "on" || !is_pocl(device);
}

std::string cache_dir() {
  namespace fs = std::filesystem;
  if (const char* dir = std::getenv("GDR_KERNEL_CACHE_DIR")) return dir;
  if (const char* xdg = std::getenv("XDG_CACHE_HOME")) return (fs::path(xdg) / "gdrender" / "kernels").string();
  if (const char* home = std::getenv("HOME")) return (fs::path(home) / ".cache" / "gdrender" / "kernels").string();
  return {};
}

}  // namespace

KernelCache::KernelCache(const DeviceInfo& device, const std::string& options, const std::string& source) {
  std::string dir = cache_wanted(device) ? cache_dir() : std::string();
  if (dir.empty()) return;
  uint64_t h = fnv1a64(device.platform_name);
  h = fnv1a64(device.name, h);
  h = fnv1a64(device.driver_version, h);
  h = fnv1a64(options, h);
  h = fnv1a64(source, h);
  char name[32];
  std::snprintf(name, sizeof(name), "%016llx.bin", static_cast<unsigned long long>(h));
  path_ = (std::filesystem::path(dir) / name).string();
}

// An entry: kMagic, the binary's size (uint64), its FNV-1a hash (uint64), then the binary. A
// truncated, corrupt or foreign entry is never handed to the driver (a bad binary can crash it).
namespace {
constexpr char kMagic[8] = {'G', 'D', 'R', 'K', 'C', 'v', '1', '\n'};
constexpr size_t kHeader = 24;

void put_u64(std::string& out, uint64_t v) {
  for (int i = 0; i < 8; ++i) out += static_cast<char>((v >> (8 * i)) & 0xFF);
}
uint64_t get_u64(const std::string& in, size_t at) {
  uint64_t v = 0;
  for (int i = 0; i < 8; ++i) v |= static_cast<uint64_t>(static_cast<unsigned char>(in[at + i])) << (8 * i);
  return v;
}
}  // namespace

std::vector<unsigned char> KernelCache::load() const {
  if (path_.empty()) return {};
  namespace fs = std::filesystem;
  std::error_code ec;
  if (!fs::is_regular_file(path_, ec)) return {};
  uint64_t file_size = fs::file_size(path_, ec);
  bool valid = !ec && file_size >= kHeader && file_size <= (1ull << 31);
  std::string bytes;
  if (valid) {
    std::ifstream in(path_, std::ios::binary);
    bytes.assign(std::istreambuf_iterator<char>(in), {});
    valid = bytes.size() == file_size && std::equal(kMagic, kMagic + 8, bytes.begin()) &&
            get_u64(bytes, 8) == bytes.size() - kHeader &&
            get_u64(bytes, 16) == fnv1a64(std::string_view(bytes).substr(kHeader));
  }
  if (!valid) {
    // Removed so that the rebuilt program replaces it; a failure to remove is harmless (store()
    // renames over it).
    fs::remove(path_, ec);
    return {};
  }
  return std::vector<unsigned char>(bytes.begin() + kHeader, bytes.end());
}

void KernelCache::store(cl_program program) const {
  if (path_.empty()) return;
  size_t size = 0;
  if (clGetProgramInfo(program, CL_PROGRAM_BINARY_SIZES, sizeof(size), &size, nullptr) != CL_SUCCESS || size == 0)
    return;
  std::vector<unsigned char> binary(size);
  unsigned char* ptr = binary.data();
  if (clGetProgramInfo(program, CL_PROGRAM_BINARIES, sizeof(ptr), &ptr, nullptr) != CL_SUCCESS) return;
  store_binary(binary);
}

void KernelCache::store_binary(const std::vector<unsigned char>& binary) const {
  if (path_.empty() || binary.empty()) return;
  std::string entry(kMagic, kMagic + 8);
  std::string_view data(reinterpret_cast<const char*>(binary.data()), binary.size());
  put_u64(entry, data.size());
  put_u64(entry, fnv1a64(data));
  entry.append(data);
  try {
    std::error_code ec;
    std::filesystem::create_directories(std::filesystem::path(path_).parent_path(), ec);
    write_output_file(path_, std::vector<unsigned char>(entry.begin(), entry.end()));
  } catch (...) {
    // An unwritable cache only costs a rebuild next time.
  }
}

}  // namespace gdr
