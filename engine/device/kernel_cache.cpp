#include "device/kernel_cache.h"

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>

#include "image/atomic_file.h"
#include "util/hash.h"

namespace gdr {
namespace {

std::string cache_dir() {
  namespace fs = std::filesystem;
  if (const char* off = std::getenv("GDR_KERNEL_CACHE"); off && std::string(off) == "off") return {};
  if (const char* dir = std::getenv("GDR_KERNEL_CACHE_DIR")) return dir;
  if (const char* xdg = std::getenv("XDG_CACHE_HOME")) return (fs::path(xdg) / "gdrender" / "kernels").string();
  if (const char* home = std::getenv("HOME")) return (fs::path(home) / ".cache" / "gdrender" / "kernels").string();
  return {};
}

}  // namespace

KernelCache::KernelCache(const DeviceInfo& device, const std::string& options, const std::string& source) {
  std::string dir = cache_dir();
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

std::vector<unsigned char> KernelCache::load() const {
  if (path_.empty()) return {};
  std::ifstream in(path_, std::ios::binary);
  if (!in) return {};
  return std::vector<unsigned char>(std::istreambuf_iterator<char>(in), {});
}

void KernelCache::store(cl_program program) const {
  if (path_.empty()) return;
  size_t size = 0;
  if (clGetProgramInfo(program, CL_PROGRAM_BINARY_SIZES, sizeof(size), &size, nullptr) != CL_SUCCESS || size == 0)
    return;
  std::vector<unsigned char> binary(size);
  unsigned char* ptr = binary.data();
  if (clGetProgramInfo(program, CL_PROGRAM_BINARIES, sizeof(ptr), &ptr, nullptr) != CL_SUCCESS) return;
  try {
    std::error_code ec;
    std::filesystem::create_directories(std::filesystem::path(path_).parent_path(), ec);
    write_file_atomically(path_, [&](const std::string& tmp) {
      write_text_file(tmp, std::string(binary.begin(), binary.end()));
    });
  } catch (...) {
    // An unwritable cache only costs a rebuild next time.
  }
}

}  // namespace gdr
