// Timers and counters for every stage of a render; `--stats FILE.json` writes them.
// Keys are slash-separated paths ("embree/trace", "kernel/pt_shade") and become nested JSON.
#pragma once
#include <chrono>
#include <cstdint>
#include <map>
#include <mutex>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace gdr {

class Stats {
 public:
  // Adds `seconds` to the timer `key` and counts one call.
  void add_time(const std::string& key, double seconds);
  void add_count(const std::string& key, uint64_t n = 1);
  // Settings and results that are not sums (seed, device name, final residual...).
  void set(const std::string& key, nlohmann::json value);

  double seconds(const std::string& key) const;
  uint64_t count(const std::string& key) const;
  nlohmann::json to_json() const;
  // Writes the JSON as image/atomic_file.h writes outputs (temporary file, then rename; a device
  // or pipe in place; `-` is standard output).
  void write_json(const std::string& path) const;
  std::vector<unsigned char> json_bytes() const;  // what write_json writes

 private:
  struct Timer {
    double seconds = 0;
    uint64_t calls = 0;
  };
  mutable std::mutex mutex_;
  std::map<std::string, Timer> timers_;
  std::map<std::string, uint64_t> counters_;
  std::map<std::string, nlohmann::json> values_;
};

// Times its own lifetime into `stats` (when not null).
class ScopedTimer {
 public:
  ScopedTimer(Stats* stats, std::string key)
      : stats_(stats), key_(std::move(key)), start_(std::chrono::steady_clock::now()) {}
  ~ScopedTimer() {
    if (stats_) stats_->add_time(key_, elapsed());
  }
  double elapsed() const {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  }
  ScopedTimer(const ScopedTimer&) = delete;
  ScopedTimer& operator=(const ScopedTimer&) = delete;

 private:
  Stats* stats_;
  std::string key_;
  std::chrono::steady_clock::time_point start_;
};

}  // namespace gdr
