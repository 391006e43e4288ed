#include "stats/stats.h"

#include "image/atomic_file.h"

namespace gdr {
namespace {

// Inserts `value` at the slash-separated `key` of `root`.
void put(nlohmann::json& root, const std::string& key, nlohmann::json value) {
  nlohmann::json* node = &root;
  size_t start = 0;
  for (size_t slash; (slash = key.find('/', start)) != std::string::npos; start = slash + 1) {
    node = &(*node)[key.substr(start, slash - start)];
  }
  (*node)[key.substr(start)] = std::move(value);
}

}  // namespace

void Stats::add_time(const std::string& key, double seconds) {
  std::lock_guard<std::mutex> lock(mutex_);
  Timer& t = timers_[key];
  t.seconds += seconds;
  t.calls += 1;
}

void Stats::add_count(const std::string& key, uint64_t n) {
  std::lock_guard<std::mutex> lock(mutex_);
  counters_[key] += n;
}

void Stats::set(const std::string& key, nlohmann::json value) {
  std::lock_guard<std::mutex> lock(mutex_);
  values_[key] = std::move(value);
}

double Stats::seconds(const std::string& key) const {
  std::lock_guard<std::mutex> lock(mutex_);
  auto it = timers_.find(key);
  return it == timers_.end() ? 0.0 : it->second.seconds;
}

uint64_t Stats::count(const std::string& key) const {
  std::lock_guard<std::mutex> lock(mutex_);
  auto it = counters_.find(key);
  return it == counters_.end() ? 0 : it->second;
}

nlohmann::json Stats::to_json() const {
  std::lock_guard<std::mutex> lock(mutex_);
  nlohmann::json root = nlohmann::json::object();
  for (const auto& [key, value] : values_) put(root, key, value);
  for (const auto& [key, n] : counters_) put(root["counters"], key, n);
  for (const auto& [key, t] : timers_) {
    put(root["time"], key, {{"seconds", t.seconds}, {"calls", t.calls}});
  }
  return root;
}

std::vector<unsigned char> Stats::json_bytes() const {
  std::string text = to_json().dump(2) + "\n";
  return std::vector<unsigned char>(text.begin(), text.end());
}

void Stats::write_json(const std::string& path) const { write_output_file(path, json_bytes(), /*allow_stdout=*/true); }

}  // namespace gdr
