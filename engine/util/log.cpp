#include "util/log.h"

#include <atomic>
#include <cstdio>
#include <mutex>

namespace gdr::log {
namespace {
std::atomic<Level> g_level{Level::Info};
std::atomic<bool> g_muted{false};
std::mutex g_mutex;
}  // namespace

void set_muted(bool muted) { g_muted = muted; }

void set_level(Level l) { g_level = l; }
Level level() { return g_level; }

void write(const char* prefix, const std::string& message) {
  if (g_muted) return;
  std::lock_guard<std::mutex> lock(g_mutex);
  std::fprintf(stderr, "%s%s\n", prefix, message.c_str());
}

}  // namespace gdr::log
