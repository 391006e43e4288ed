// Runs the built gdrender as a user would (through the shell) in a fresh temporary folder and
// captures its exit code and output (stdout and stderr together).
#pragma once
#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "support/source_scene.h"

namespace gdr::test {

struct CliResult {
  int code = -1;       // exit status; -1 when gdrender did not exit normally (a crash)
  std::string output;  // stdout and stderr
};

// A temporary folder removed with the object.
class TempDir {
 public:
  TempDir() {
    std::string tmpl = (std::filesystem::temp_directory_path() / "gdr-cli-XXXXXX").string();
    if (!mkdtemp(tmpl.data())) throw std::runtime_error("mkdtemp failed");
    path_ = tmpl;
  }
  ~TempDir() {
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
  }
  const std::filesystem::path& path() const { return path_; }
  std::string file(const std::string& name) const { return (path_ / name).string(); }
  std::string write(const std::string& name, const std::string& text) const {
    std::ofstream(path_ / name, std::ios::binary) << text;
    return file(name);
  }

 private:
  std::filesystem::path path_;
};

// Runs the shell command line `cmd` and returns its exit code and output (stdout; redirect
// stderr into it where needed).
inline CliResult run_shell(const std::string& cmd) {
  CliResult r;
  FILE* pipe = popen(cmd.c_str(), "r");
  if (!pipe) return r;
  std::array<char, 4096> buf;
  size_t n;
  while ((n = fread(buf.data(), 1, buf.size(), pipe)) > 0) r.output.append(buf.data(), n);
  int status = pclose(pipe);
  r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return r;
}

// The gdrender the tests start: this build's, or $GDR_TEST_GDRENDER (a packed copy started
// through its own loader, as scripts/gpu-check runs it on a machine without the build).
inline std::string gdrender_exe() {
  const char* exe = std::getenv("GDR_TEST_GDRENDER");
  return exe && *exe ? exe : GDR_GDRENDER_EXE;
}

// Runs `gdrender ARGS` with `dir` as the working folder. ARGS is shell syntax. A run that hangs
// is stopped after 60 s (exit code 124).
inline CliResult run_gdrender(const std::string& args, const TempDir& dir) {
  return run_shell("cd '" + dir.path().string() + "' && timeout 60 '" + gdrender_exe() + "' " + args + " 2>&1");
}

// Files in `dir` whose name ends with `suffix`.
inline int count_files(const TempDir& dir, const std::string& suffix) {
  int n = 0;
  for (const auto& e : std::filesystem::directory_iterator(dir.path())) {
    std::string name = e.path().filename().string();
    if (name.size() >= suffix.size() && name.compare(name.size() - suffix.size(), suffix.size(), suffix) == 0) ++n;
  }
  return n;
}

// The project's Cornell box, quoted for a command line.
inline const std::string kCornell = "'" + source_scene("cornell-box.xml") + "'";

}  // namespace gdr::test
