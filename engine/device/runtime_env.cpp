#include "device/runtime_env.h"

#include <sys/stat.h>
#include <tbb/global_control.h>
#include <unistd.h>

#include <OpenImageIO/imageio.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <memory>
#include <mutex>
#include <string>

#include "util/cpus.h"
#include "util/log.h"

namespace gdr {
namespace {

int g_threads = 0;
std::unique_ptr<tbb::global_control> g_tbb_limit;

void set_env_default(const char* name, const std::string& value) {
  if (!std::getenv(name)) setenv(name, value.c_str(), 0);
}

// PoCL needs a writable cache folder; HOME may be read-only or missing under CI.
std::string default_pocl_cache_dir() {
  namespace fs = std::filesystem;
  const char* xdg = std::getenv("XDG_CACHE_HOME");
  const char* home = std::getenv("HOME");
  fs::path base = xdg ? fs::path(xdg) : home ? fs::path(home) / ".cache" : fs::temp_directory_path();
  fs::path dir = base / "gdrender" / "pocl";
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec) {
    dir = fs::temp_directory_path() / "gdrender-pocl-cache";
    fs::create_directories(dir, ec);
  }
  return dir.string();
}

}  // namespace

void configure_runtime(int threads) {
  static std::once_flag once;
  std::call_once(once, [threads] {
    int cpus = usable_cpu_count();
    g_threads = threads > 0 ? threads : cpus;
    // More threads than CPUs only oversubscribe them, and a count the system cannot create makes
    // the OpenCL driver abort: at most the CPUs this process may use.
    if (g_threads > cpus) {
      log::warn("--threads ", threads, " is more than the ", cpus, " CPUs this process may use: using ", cpus);
      g_threads = cpus;
    }
    set_env_default("POCL_CACHE_DIR", default_pocl_cache_dir());
    // PoCL's pthread device reads one or the other depending on its version.
    set_env_default("POCL_MAX_PTHREAD_COUNT", std::to_string(g_threads));
    set_env_default("POCL_CPU_MAX_CU_NUM", std::to_string(g_threads));
    g_tbb_limit = std::make_unique<tbb::global_control>(
        tbb::global_control::max_allowed_parallelism, static_cast<size_t>(g_threads));
    OIIO::attribute("threads", g_threads);
  });
}

int runtime_threads() { return g_threads > 0 ? g_threads : usable_cpu_count(); }

std::string opencl_environment_problem() {
  const char* dir = std::getenv("POCL_CACHE_DIR");
  if (!dir) return {};
  std::string d = dir;
  std::error_code ec;
  std::filesystem::create_directories(d, ec);  // PoCL needs it to exist
  struct stat st {};
  if (::stat(d.c_str(), &st) != 0) {
    return "POCL_CACHE_DIR=" + d + " cannot be created (" + (ec ? ec.message() : std::string(std::strerror(errno))) +
           "); PoCL needs a writable cache folder (unset POCL_CACHE_DIR to use the default)";
  }
  if (!S_ISDIR(st.st_mode)) {
    return "POCL_CACHE_DIR=" + d + " is not a folder; PoCL needs a writable cache folder (unset POCL_CACHE_DIR to use the default)";
  }
  if (::access(d.c_str(), W_OK | X_OK) != 0) {
    return "POCL_CACHE_DIR=" + d + " is not writable (" + std::strerror(errno) +
           "); PoCL needs a writable cache folder (unset POCL_CACHE_DIR to use the default)";
  }
  return {};
}

}  // namespace gdr
