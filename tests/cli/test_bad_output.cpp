// Bad outputs and interruptions, as a user meets them: every output path is checked before the
// render starts, nothing that is not a regular file is ever replaced (devices and pipes are written
// in place, links are followed), a second interrupt ends the process at once, and no temporary
// file is ever left behind. Each case checks the exit code, the message and the folder's listing
// (hidden temporaries included).
#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <fstream>
#include <iterator>
#include <set>
#include <thread>
#include <vector>

#include "cli/cli_harness.h"
#include "device/devices.h"
#include "image/image.h"
#include "image/image_io.h"

namespace gdr::test {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

const std::string kScene = source_scene("cornell-box.xml");
const std::string kTiny = kCornell + " -D res=8 --quiet";

// Every name in `dir` (hidden ones too), sorted.
std::set<std::string> listing(const fs::path& dir) {
  std::set<std::string> names;
  for (const auto& e : fs::directory_iterator(dir)) names.insert(e.path().filename().string());
  return names;
}

std::string join(const std::set<std::string>& names) {
  std::string s;
  for (const std::string& n : names) s += (s.empty() ? "" : ", ") + n;
  return "{" + s + "}";
}

void expect_listing(const TempDir& dir, const std::set<std::string>& expected) {
  EXPECT_EQ(listing(dir.path()), expected) << "folder holds " << join(listing(dir.path())) << ", expected "
                                           << join(expected);
}

bool contains(const std::string& text, const std::string& needle) { return text.find(needle) != std::string::npos; }

// A failed run: exit 1 (an error, not a crash or a hang), the output names every needle.
void expect_error(const CliResult& r, const std::vector<std::string>& needles) {
  EXPECT_EQ(r.code, 1) << r.output;
  for (const std::string& n : needles) EXPECT_TRUE(contains(r.output, n)) << "expected '" << n << "' in: " << r.output;
}

// Runs a shell command line in `dir` (for environment variables and redirections).
CliResult run_sh(const std::string& script, const TempDir& dir) {
  return run_shell("cd '" + dir.path().string() + "' && " + script);
}

const std::string kExe = "'" + gdrender_exe() + "'";

bool is_exr(const std::string& path) {
  try {
    return read_image(path).width == 8;
  } catch (...) {
    return false;
  }
}

// ---- 1. Never replace what is not ours -------------------------------------------------------

// A FIFO given to --stats is written into (a reader gets the JSON) and stays a FIFO.
TEST(BadOutput, StatsIntoAPipeWritesThrough) {
  TempDir dir;
  ASSERT_EQ(mkfifo(dir.file("s.fifo").c_str(), 0644), 0);
  // A reader that never blocks: the JSON (a few KB) waits in the pipe's buffer.
  int reader = ::open(dir.file("s.fifo").c_str(), O_RDONLY | O_NONBLOCK);
  ASSERT_GE(reader, 0);
  CliResult r = run_gdrender(kTiny + " --spp 1 -o out.exr --stats s.fifo", dir);
  std::string got;
  char buf[4096];
  for (ssize_t n; (n = ::read(reader, buf, sizeof(buf))) > 0;) got.append(buf, size_t(n));
  ::close(reader);
  EXPECT_EQ(r.code, 0) << r.output;
  EXPECT_TRUE(contains(got, "\"settings\"")) << got;
  struct stat st {};
  ASSERT_EQ(::lstat(dir.file("s.fifo").c_str(), &st), 0);
  EXPECT_TRUE(S_ISFIFO(st.st_mode)) << "the FIFO was replaced";
  expect_listing(dir, {"out.exr", "out.png", "s.fifo"});
}

// Character devices are written in place: -o /dev/null writes no /dev/null.exr or .png, and
// nothing appears in the working folder.
TEST(BadOutput, DevNullIsWrittenInPlace) {
  TempDir dir;
  CliResult r = run_gdrender(kTiny + " --spp 1 -o /dev/null", dir);
  EXPECT_EQ(r.code, 0) << r.output;
  struct stat st {};
  ASSERT_EQ(::stat("/dev/null", &st), 0);
  EXPECT_TRUE(S_ISCHR(st.st_mode));
  for (const char* stray : {"/dev/null.exr", "/dev/null.png"}) {
    EXPECT_FALSE(fs::exists(stray));
    std::error_code ec;
    fs::remove(stray, ec);
  }
  expect_listing(dir, {});
}

// A full device fails with the path and the system's reason, and no file appears beside it.
TEST(BadOutput, FullDeviceNamesTheReason) {
  if (!fs::exists("/dev/full")) GTEST_SKIP() << "no /dev/full";
  TempDir dir;
  CliResult r = run_gdrender(kTiny + " --spp 1 -o /dev/full", dir);
  expect_error(r, {"/dev/full", "No space left on device"});
  EXPECT_FALSE(contains(r.output, "File output failed")) << r.output;
  for (const char* stray : {"/dev/full.exr", "/dev/full.png"}) {
    EXPECT_FALSE(fs::exists(stray));
    std::error_code ec;
    fs::remove(stray, ec);
  }
  TempDir stats;
  r = run_gdrender(kTiny + " --spp 1 -o out.exr --stats /dev/full", stats);
  expect_error(r, {"/dev/full", "No space left on device"});
  // The outputs are one set: the images are not renamed into place when the stats fail.
  expect_listing(stats, {});
}

// A symbolic link is followed: the file it points to is replaced, the link stays a link.
TEST(BadOutput, SymlinkIsFollowedNotReplaced) {
  TempDir dir;
  fs::create_directory(dir.path() / "real");
  fs::create_symlink("real/target.exr", dir.path() / "link.exr");
  fs::create_symlink("real/stats.json", dir.path() / "s.json");
  CliResult r = run_gdrender(kTiny + " --spp 1 -o link.exr --stats s.json", dir);
  EXPECT_EQ(r.code, 0) << r.output;
  EXPECT_TRUE(fs::is_symlink(dir.path() / "link.exr"));
  EXPECT_TRUE(fs::is_symlink(dir.path() / "s.json"));
  EXPECT_TRUE(is_exr(dir.file("real/target.exr")));
  EXPECT_TRUE(fs::file_size(dir.path() / "real/stats.json") > 0);
  expect_listing(dir, {"link.exr", "link.png", "real", "s.json"});
  EXPECT_EQ(listing(dir.path() / "real"), (std::set<std::string>{"stats.json", "target.exr"}));
}

// `-` is standard output for --stats and for -o (one image, the EXR).
TEST(BadOutput, DashIsStandardOutput) {
  TempDir dir;
  CliResult r = run_sh(kExe + " " + kTiny + " --spp 1 -o out.exr --stats - 2>err.txt", dir);
  EXPECT_EQ(r.code, 0) << r.output;
  EXPECT_TRUE(contains(r.output, "\"settings\"")) << r.output;
  expect_listing(dir, {"err.txt", "out.exr", "out.png"});
  TempDir devstdout;
  r = run_sh(kExe + " " + kTiny + " --spp 1 -o out.exr --stats /dev/stdout 2>err.txt", devstdout);
  EXPECT_EQ(r.code, 0) << r.output;
  EXPECT_TRUE(contains(r.output, "\"settings\"")) << r.output;
  expect_listing(devstdout, {"err.txt", "out.exr", "out.png"});
  TempDir piped;
  r = run_sh(kExe + " " + kTiny + " --spp 1 -o - 2>err.txt | cat > piped.exr", piped);
  EXPECT_EQ(r.code, 0) << r.output;
  EXPECT_TRUE(is_exr(piped.file("piped.exr")));
  expect_listing(piped, {"err.txt", "piped.exr"});
  TempDir both;
  expect_error(run_gdrender(kTiny + " --spp 1 -o - --stats -", both), {"standard output"});
  expect_listing(both, {});
}

// ---- 2. Every output path is checked before rendering ------------------------------------------

// A missing folder is reported before anything renders, even with a long time budget.
TEST(BadOutput, MissingFolderFailsBeforeRendering) {
  TempDir dir;
  auto start = Clock::now();
  CliResult r = run_gdrender(kTiny + " --time 600 -o nodir/out.exr", dir);
  double seconds = std::chrono::duration<double>(Clock::now() - start).count();
  expect_error(r, {"-o", "nodir", "does not exist"});
  EXPECT_LT(seconds, 30) << "the render ran before the output was checked";
  expect_listing(dir, {});
  r = run_gdrender(kTiny + " --time 600 -o out.exr --stats nodir/s.json", dir);
  expect_error(r, {"--stats", "nodir/s.json", "does not exist"});
  expect_listing(dir, {});
}

TEST(BadOutput, UnwritableFolderFailsBeforeRendering) {
  TempDir dir;
  // /proc takes no new files, even from root.
  CliResult r = run_gdrender(kTiny + " --time 600 -o /proc/gdr-out.exr", dir);
  expect_error(r, {"cannot write", "/proc/gdr-out"});
  EXPECT_FALSE(fs::exists("/proc/gdr-out.exr"));
  if (::geteuid() != 0) {
    fs::create_directory(dir.path() / "ro");
    fs::permissions(dir.path() / "ro", fs::perms::owner_read | fs::perms::owner_exec);
    r = run_gdrender(kTiny + " --time 600 -o ro/out.exr", dir);
    expect_error(r, {"ro/out.exr", "Permission denied"});
    EXPECT_TRUE(listing(dir.path() / "ro").empty());
    fs::permissions(dir.path() / "ro", fs::perms::owner_all);
  }
  expect_listing(dir, ::geteuid() != 0 ? std::set<std::string>{"ro"} : std::set<std::string>{});
}

TEST(BadOutput, FolderAsOutputIsRefused) {
  TempDir dir;
  fs::create_directory(dir.path() / "out.exr");
  expect_error(run_gdrender(kTiny + " --time 600 -o out.exr", dir), {"out.exr", "folder"});
  fs::create_directory(dir.path() / "s.json");
  expect_error(run_gdrender(kTiny + " --time 600 -o x.exr --stats s.json", dir), {"--stats", "s.json", "folder"});
  expect_listing(dir, {"out.exr", "s.json"});
  EXPECT_TRUE(fs::is_directory(dir.path() / "out.exr"));
}

// A name the file system takes is written even where its temporary name would be too long; a
// name it does not take is refused before rendering.
TEST(BadOutput, LongNames) {
  TempDir dir;
  std::string stem(250, 'n');
  CliResult r = run_gdrender(kTiny + " --spp 1 -o " + stem + ".exr --stats " + stem + ".js", dir);
  EXPECT_EQ(r.code, 0) << r.output;
  expect_listing(dir, {stem + ".exr", stem + ".png", stem + ".js"});
  TempDir too_long;
  std::string longer(300, 'n');
  r = run_gdrender(kTiny + " --time 600 -o " + longer + ".exr", too_long);
  expect_error(r, {"too long"});
  expect_listing(too_long, {});
}

// -o takes .exr (with a PNG beside it) and .png (with the EXR beside it); anything else is refused
// with the accepted extensions.
TEST(BadOutput, UnknownExtensionIsRefused) {
  TempDir dir;
  for (const char* name : {"out.xyz", "out", "out.jpg"}) {
    CliResult r = run_gdrender(kTiny + " --time 600 -o " + name, dir);
    expect_error(r, {"-o", "extension", ".exr", ".png"});
  }
  expect_listing(dir, {});
  CliResult r = run_gdrender(kTiny + " --spp 1 -o pic.PNG", dir);
  EXPECT_EQ(r.code, 0) << r.output;
  expect_listing(dir, {"pic.PNG", "pic.exr"});
  EXPECT_TRUE(is_exr(dir.file("pic.exr")));
}

TEST(BadOutput, OutputsNamingTheSameFileAreRefused) {
  TempDir dir;
  expect_error(run_gdrender(kTiny + " --time 600 -o out.exr --stats out.png", dir), {"--stats", "same file"});
  expect_listing(dir, {});
}

// --compare's --error-image and --reconstruct's -o are checked before the work too.
TEST(BadOutput, CompareAndReconstructOutputsAreChecked) {
  TempDir dir;
  ASSERT_EQ(run_gdrender(kTiny + " --integrator gpt --recon none --spp 1 -o in.exr", dir).code, 0);
  expect_error(run_gdrender("--compare in.exr in.exr --error-image nodir/err.png", dir),
               {"--error-image", "nodir", "does not exist"});
  expect_error(run_gdrender("--compare in.exr in.exr --error-image err.exr", dir), {"--error-image", ".png"});
  expect_error(run_gdrender("--compare in.exr in.exr --error-image -", dir), {"--error-image", "standard output"});
  expect_error(run_gdrender("--reconstruct in.exr -o nodir/r.exr", dir), {"-o", "nodir", "does not exist"});
  expect_error(run_gdrender("--reconstruct in.exr -o r.tiff", dir), {"extension"});
  expect_error(run_gdrender("--reconstruct in.exr -o r.exr --stats nodir/s.json", dir), {"--stats", "does not exist"});
  expect_listing(dir, {"in.exr", "in.png"});
  CliResult ok = run_gdrender("--compare in.exr in.exr --error-image err.png", dir);
  EXPECT_EQ(ok.code, 0) << ok.output;
  expect_listing(dir, {"err.png", "in.exr", "in.png"});
}

// ---- 5. Signals ---------------------------------------------------------------------------------

// gdrender started in the background in `dir`, output to `log`.
class Background {
 public:
  Background(const std::vector<std::string>& args, const TempDir& dir, const std::string& log) {
    pid_ = fork();
    if (pid_ == 0) {
      // The test runner may ignore or block these; gdrender gets them as a shell would give them.
      sigset_t none;
      sigemptyset(&none);
      sigprocmask(SIG_SETMASK, &none, nullptr);
      signal(SIGINT, SIG_DFL);
      signal(SIGTERM, SIG_DFL);
      if (chdir(dir.path().c_str()) != 0) _exit(126);
      int fd = ::open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
      if (fd >= 0) dup2(fd, 1), dup2(fd, 2);
      std::vector<char*> argv;
      std::string exe = gdrender_exe();
      argv.push_back(exe.data());
      std::vector<std::string> copy = args;
      for (std::string& a : copy) argv.push_back(a.data());
      argv.push_back(nullptr);
      execv(exe.c_str(), argv.data());
      _exit(127);
    }
  }
  ~Background() {
    if (pid_ > 0 && !done_) {
      kill(pid_, SIGKILL);
      waitpid(pid_, &status_, 0);
    }
  }
  void signal_it(int sig) { kill(pid_, sig); }
  // Waits up to `seconds` for the end; false if it is still running.
  bool wait(double seconds) {
    auto until = Clock::now() + std::chrono::duration<double>(seconds);
    while (!done_) {
      if (waitpid(pid_, &status_, WNOHANG) == pid_) {
        done_ = true;
        break;
      }
      if (Clock::now() > until) return false;
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    return true;
  }
  bool exited(int code) const { return done_ && WIFEXITED(status_) && WEXITSTATUS(status_) == code; }
  bool killed_by(int sig) const { return done_ && WIFSIGNALED(status_) && WTERMSIG(status_) == sig; }
  int status() const { return status_; }

 private:
  pid_t pid_ = -1;
  int status_ = 0;
  bool done_ = false;
};

std::string read_text(const std::string& path) {
  std::ifstream in(path);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

// Waits until `ready()` or `seconds` pass.
template <class F>
bool wait_for(F ready, double seconds) {
  auto until = Clock::now() + std::chrono::duration<double>(seconds);
  while (!ready()) {
    if (Clock::now() > until) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  return true;
}

// The first SIGINT or SIGTERM during a long render finishes the pass in flight and writes the
// image rendered so far, the stats and nothing else.
void interrupt_once(int sig) {
  TempDir dir, logs;
  std::string log = logs.file("log.txt");
  Background run({kScene, "-D", "res=8", "--time", "600", "-o", "out.exr", "--stats", "s.json", "--verbose"}, dir,
                 log);
  // The render loop says when it starts (after the kernels are built, which may take long on a
  // loaded machine the first time).
  ASSERT_TRUE(wait_for([&] { return contains(read_text(log), "rendering:"); }, 120)) << read_text(log);
  std::this_thread::sleep_for(std::chrono::milliseconds(500));
  run.signal_it(sig);
  ASSERT_TRUE(run.wait(60)) << "did not stop after the signal: " << read_text(log);
  std::string out = read_text(log);
  EXPECT_TRUE(run.exited(0)) << "status " << run.status() << ": " << out;
  EXPECT_TRUE(contains(out, "interrupted") || contains(out, "terminated")) << out;
  EXPECT_TRUE(is_exr(dir.file("out.exr")));
  EXPECT_TRUE(contains(read_text(dir.file("s.json")), "\"samples_per_second\"")) << read_text(dir.file("s.json"));
  expect_listing(dir, {"out.exr", "out.png", "s.json"});
}

TEST(BadOutput, SigintWritesWhatWasRendered) { interrupt_once(SIGINT); }
TEST(BadOutput, SigtermWritesWhatWasRendered) { interrupt_once(SIGTERM); }

bool has_temporary(const TempDir& dir) {
  for (const std::string& n : listing(dir.path())) {
    if (n.size() > 1 && n[0] == '.' && contains(n, ".tmp")) return true;
  }
  return false;
}

// While the outputs are being written (here: held up by a FIFO no one reads, with the images'
// temporaries already there), the first interrupt lets the write go on and a second one ends the
// process at once, removing the temporaries and leaving the old names alone. The temporaries are
// awaited once the render has begun: at start the process creates and removes one for each output
// (its check that the folders take new files), which a poll may see before any interrupt defers.
TEST(BadOutput, SecondInterruptDuringTheWriteEndsAtOnceAndLeavesNoTemporary) {
  TempDir dir, logs;
  std::string log = logs.file("log.txt");
  ASSERT_EQ(mkfifo(dir.file("s.fifo").c_str(), 0644), 0);
  Background run({kScene, "-D", "res=8", "--spp", "1", "-o", "out.exr", "--stats", "s.fifo", "--verbose"}, dir, log);
  ASSERT_TRUE(wait_for([&] { return contains(read_text(log), "rendering:"); }, 120)) << read_text(log);
  ASSERT_TRUE(wait_for([&] { return has_temporary(dir); }, 120)) << "no temporary appeared: " << join(listing(dir.path()))
                                                                << " " << read_text(log);
  run.signal_it(SIGINT);
  EXPECT_FALSE(run.wait(1.0)) << "the first interrupt during the write ended the process: " << read_text(log);
  run.signal_it(SIGINT);
  ASSERT_TRUE(run.wait(10)) << "a second interrupt did not end the process: " << read_text(log);
  EXPECT_TRUE(run.killed_by(SIGINT)) << "status " << run.status() << ": " << read_text(log);
  expect_listing(dir, {"s.fifo"});
  struct stat st {};
  ASSERT_EQ(::lstat(dir.file("s.fifo").c_str(), &st), 0);
  EXPECT_TRUE(S_ISFIFO(st.st_mode));
}

// Where nothing has been rendered (here --reconstruct, whose input is safe on disk), one interrupt
// ends the process at once.
TEST(BadOutput, InterruptOutsideARenderEndsAtOnce) {
  TempDir dir, logs;
  ASSERT_EQ(run_gdrender(kTiny + " --integrator gpt --recon none --spp 1 -o in.exr", dir).code, 0);
  ASSERT_EQ(mkfifo(dir.file("s.fifo").c_str(), 0644), 0);
  std::string log = logs.file("log.txt");
  Background run({"--reconstruct", "in.exr", "-o", "r.exr", "--stats", "s.fifo"}, dir, log);
  ASSERT_TRUE(wait_for([&] { return fs::exists(dir.path() / "r.png"); }, 120)) << read_text(log);
  std::this_thread::sleep_for(std::chrono::milliseconds(200));
  run.signal_it(SIGINT);
  ASSERT_TRUE(run.wait(10)) << "an interrupt did not end --reconstruct: " << read_text(log);
  EXPECT_TRUE(run.killed_by(SIGINT)) << "status " << run.status() << ": " << read_text(log);
  expect_listing(dir, {"in.exr", "in.png", "r.exr", "r.png", "s.fifo"});
}

// ---- 8. Messages that name the real cause --------------------------------------------------------

TEST(BadOutput, UncreatablePoclCacheDirIsNamed) {
  // With another OpenCL platform present, PoCL's absence is no error: gdrender renders there.
  for (const DeviceInfo& d : list_devices()) {
    if (!is_pocl(d)) {
      GTEST_SKIP() << "OpenCL platform " << d.platform_name << " is present besides PoCL";
    }
  }
  TempDir dir;
  dir.write("afile", "x");
  CliResult r = run_sh("POCL_CACHE_DIR=afile/cache " + kExe + " --list-devices 2>&1", dir);
  expect_error(r, {"POCL_CACHE_DIR", "afile/cache"});
  EXPECT_FALSE(contains(r.output, "ICD")) << r.output;
  r = run_sh("POCL_CACHE_DIR=afile/cache " + kExe + " " + kTiny + " --spp 1 -o out.exr 2>&1", dir);
  expect_error(r, {"POCL_CACHE_DIR", "afile/cache"});
  expect_listing(dir, {"afile"});
}

TEST(BadOutput, IncludedFolderIsNamed) {
  TempDir dir;
  fs::create_directory(dir.path() / "sub");
  dir.write("inc.xml", "<scene version=\"3.0.0\">\n  <include filename=\"sub\"/>\n</scene>\n");
  CliResult r = run_gdrender("inc.xml --spp 1 -o out.exr", dir);
  expect_error(r, {"inc.xml:2", "sub", "folder"});
  EXPECT_FALSE(contains(r.output, "malformed")) << r.output;
  expect_listing(dir, {"inc.xml", "sub"});
}

// A film larger than the device's largest allocation names the size asked for and the limit.
TEST(BadOutput, FilmTooLargeForTheDeviceNamesTheSizes) {
  TempDir dir;
  CliResult r = run_gdrender(kCornell + " -D res=65536 --spp 1 -o out.exr", dir);
  expect_error(r, {"CL_DEVICE_MAX_MEM_ALLOC_SIZE", "GiB"});
  EXPECT_FALSE(contains(r.output, "failed: CL_INVALID_BUFFER_SIZE")) << r.output;
  expect_listing(dir, {});
}

}  // namespace
}  // namespace gdr::test
