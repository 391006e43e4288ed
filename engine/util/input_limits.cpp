#include "util/input_limits.h"

#include <sys/stat.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <new>

#include "util/error.h"

namespace gdr {

uint64_t max_input_bytes() {
  const char* env = std::getenv("GDR_MAX_INPUT_BYTES");
  if (!env || !*env) return kDefaultMaxInputBytes;
  errno = 0;
  char* end = nullptr;
  unsigned long long v = std::strtoull(env, &end, 10);
  uint64_t scale = 1;
  if (end && (*end == 'k' || *end == 'K')) scale = 1ull << 10, ++end;
  else if (end && (*end == 'm' || *end == 'M')) scale = 1ull << 20, ++end;
  else if (end && (*end == 'g' || *end == 'G')) scale = 1ull << 30, ++end;
  if (end == env || *end || errno == ERANGE || env[0] == '-' || v == 0 || v > UINT64_MAX / scale) {
    throw Error("GDR_MAX_INPUT_BYTES='" + std::string(env) +
                "' is not a positive size in bytes (an optional K, M or G suffix is allowed)");
  }
  return v * scale;
}

std::string format_bytes(uint64_t bytes) {
  if (bytes < 1024) return std::to_string(bytes) + " bytes";
  const char* units[] = {"KiB", "MiB", "GiB", "TiB", "PiB", "EiB"};
  double v = static_cast<double>(bytes);
  int u = -1;
  while (v >= 1024.0 && u < 5) v /= 1024.0, ++u;
  char buf[64];
  std::snprintf(buf, sizeof(buf), "%.1f %s (%llu bytes)", v, units[u], static_cast<unsigned long long>(bytes));
  return buf;
}

uint64_t checked_input_size(const std::string& path, const std::string& what) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) {
    throw InputError(path, 0, "cannot read the " + what + ": " + std::strerror(errno));
  }
  if (S_ISDIR(st.st_mode)) throw InputError(path, 0, "the " + what + " is a folder, not a file");
  if (!S_ISREG(st.st_mode)) {
    throw InputError(path, 0, "the " + what + " is not a regular file (a device, pipe or socket)");
  }
  uint64_t size = static_cast<uint64_t>(st.st_size);
  uint64_t limit = max_input_bytes();
  if (size > limit) {
    throw InputError(path, 0, "the " + what + " is " + format_bytes(size) + ", over the input limit of " +
                                  format_bytes(limit) + " (GDR_MAX_INPUT_BYTES)");
  }
  return size;
}

std::string read_input_file(const std::string& path, const std::string& what) {
  uint64_t size = checked_input_size(path, what);
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, 0, "cannot read the " + what);
  std::string text;
  try {
    text.resize(static_cast<size_t>(size));
  } catch (const std::bad_alloc&) {
    throw InputError(path, 0, "out of memory reading the " + what + " (" + format_bytes(size) + ")");
  }
  in.read(text.data(), static_cast<std::streamsize>(size));
  // A file that shrank while being read: keep what was there (the parser reports what is missing).
  text.resize(static_cast<size_t>(in.gcount()));
  if (in.bad()) throw InputError(path, 0, "error reading the " + what);
  return text;
}

void check_input_allocation(const std::string& path, uint64_t bytes, const std::string& purpose) {
  uint64_t limit = max_input_bytes();
  if (bytes > limit) {
    throw InputError(path, 0, purpose + " needs " + format_bytes(bytes) + ", over the input limit of " +
                                  format_bytes(limit) + " (GDR_MAX_INPUT_BYTES)");
  }
}

void check_declared_size(const std::string& path, double declared, uint64_t file_size, double max_ratio,
                         const std::string& claim) {
  // A few kilobytes of slack for headers and tables around tiny payloads.
  if (declared > static_cast<double>(file_size) * max_ratio + 4096.0) {
    std::string size = declared >= 1.8e19 ? std::string("more than 16 EiB")
                                          : format_bytes(static_cast<uint64_t>(declared));
    throw InputError(path, 0, claim + " (" + size + "), but the file has only " + format_bytes(file_size));
  }
}

}  // namespace gdr
