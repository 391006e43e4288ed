// Helpers for scene tests: a temporary folder that the test fills with small scene files.
#pragma once
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>
#include <vector>

#include "scene/load_scene.h"

namespace gdr::test {

class TempFolder {
 public:
  TempFolder() {
    const testing::TestInfo* info = testing::UnitTest::GetInstance()->current_test_info();
    path_ = std::filesystem::temp_directory_path() /
            ("gdr_scene_" + std::string(info->test_suite_name()) + "_" + info->name() + "_" +
             std::to_string(::getpid()));
    std::filesystem::remove_all(path_);
    std::filesystem::create_directories(path_);
  }
  ~TempFolder() { std::filesystem::remove_all(path_); }

  // Writes `text` (binary-safe) to a file under the folder and returns its full path.
  std::string write(const std::string& name, const std::string& text) const {
    std::filesystem::path p = path_ / name;
    std::filesystem::create_directories(p.parent_path());
    std::ofstream out(p, std::ios::binary);
    out << text;
    return p.string();
  }
  std::string path(const std::string& name) const { return (path_ / name).string(); }

 private:
  std::filesystem::path path_;
};

// Whether one of the scene's warnings contains every one of `words`.
inline bool has_warning(const Scene& s, const std::vector<std::string>& words) {
  for (const std::string& w : s.warnings) {
    bool all = true;
    for (const std::string& word : words) all = all && w.find(word) != std::string::npos;
    if (all) return true;
  }
  return false;
}

// Every warning, one per line (for failure messages).
inline std::string all_warnings(const Scene& s) {
  std::string out;
  for (const std::string& w : s.warnings) out += w + "\n";
  return out;
}

// A scene document around `body`.
inline std::string scene_xml(const std::string& body, const std::string& version = "3.0.0") {
  return "<scene version=\"" + version + "\">\n" + body + "\n</scene>\n";
}

}  // namespace gdr::test
