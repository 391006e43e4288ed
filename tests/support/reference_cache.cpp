#include "support/reference_cache.h"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>

#include "device/context.h"

namespace gdr::test {
namespace {

namespace fs = std::filesystem;

std::string file_bytes(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

// What every entry depends on besides its own key: the test binary (the engine and the kernel
// sources built into it) and the scene files the tests load at run time.
const std::string& build_key() {
  static const std::string key = [] {
    std::vector<fs::path> scenes;
    for (const auto& entry : fs::recursive_directory_iterator(fs::path(GDR_SOURCE_DIR) / "scenes")) {
      if (entry.is_regular_file()) scenes.push_back(entry.path());
    }
    std::sort(scenes.begin(), scenes.end());
    std::string all = file_bytes("/proc/self/exe");
    for (const fs::path& p : scenes) all += p.string() + '\n' + file_bytes(p);
    return std::to_string(std::hash<std::string>{}(all));
  }();
  return key;
}

// Reads an entry written for exactly `key` (the file starts with it), or returns nothing.
std::vector<float> read_entry(const fs::path& file, const std::string& key) {
  std::ifstream in(file, std::ios::binary);
  std::string stored;
  if (!in || !std::getline(in, stored, '\0') || stored != key) return {};
  uint64_t n = 0;
  in.read(reinterpret_cast<char*>(&n), sizeof n);
  std::vector<float> values(n);
  in.read(reinterpret_cast<char*>(values.data()), std::streamsize(n * sizeof(float)));
  return in ? values : std::vector<float>{};
}

void write_entry(const fs::path& file, const std::string& key, const std::vector<float>& values) {
  // Written aside and renamed into place: a reader never sees half an entry.
  const fs::path part = file.string() + ".part" + std::to_string(getpid());
  {
    std::ofstream out(part, std::ios::binary);
    const uint64_t n = values.size();
    out.write(key.c_str(), std::streamsize(key.size() + 1));
    out.write(reinterpret_cast<const char*>(&n), sizeof n);
    out.write(reinterpret_cast<const char*>(values.data()), std::streamsize(n * sizeof(float)));
  }
  fs::rename(part, file);
}

}  // namespace

std::vector<float> cached_render(const Context& context, const std::string& key,
                                 const std::function<std::vector<float>()>& render) {
  const std::string full_key = build_key() + '\n' + context.device().platform_name + ' ' + context.device().name + ' ' +
                               context.device().driver_version + '\n' + key;
  const fs::path dir = GDR_TEST_CACHE_DIR;
  fs::create_directories(dir);
  std::ostringstream name;
  name << std::hex << std::hash<std::string>{}(full_key);
  const fs::path file = dir / (name.str() + ".f32");
  const int lock = open((file.string() + ".lock").c_str(), O_CREAT | O_RDWR, 0644);
  if (lock >= 0) flock(lock, LOCK_EX);
  std::vector<float> values = read_entry(file, full_key);
  if (values.empty()) {
    values = render();
    write_entry(file, full_key, values);
  }
  if (lock >= 0) close(lock);
  return values;
}

}  // namespace gdr::test
