#include "image/atomic_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <climits>
#include <cstring>
#include <filesystem>
#include <iterator>

#include "util/error.h"
#include "util/interrupt.h"

namespace gdr {
namespace fs = std::filesystem;
namespace {

[[noreturn]] void fail(const OutputTarget& t, const std::string& reason) {
  throw Error("cannot write " + t.shown() + ": " + reason);
}
[[noreturn]] void fail_errno(const OutputTarget& t, int err) { fail(t, std::strerror(err)); }

std::string folder_of(const std::string& file) {
  std::string dir = fs::path(file).parent_path().string();
  return dir.empty() ? "." : dir;
}

long name_max(const std::string& dir) {
  long n = ::pathconf(dir.c_str(), _PC_NAME_MAX);
  return n > 0 ? n : 255;
}

bool under(const std::string& path, const char* prefix) { return path.rfind(prefix, 0) == 0; }

// Follows symbolic links from `path` to the file they end at (which need not exist). A link
// through /proc or /dev/fd (/dev/stdout is one) stands for an open descriptor, not a name: such
// a target is written in place through the path as given (`magic`).
std::string follow_links(const OutputTarget& t, bool& magic) {
  std::string p = t.path;
  magic = false;
  for (int hops = 0; hops < 40; ++hops) {
    struct stat st {};
    if (::lstat(p.c_str(), &st) != 0 || !S_ISLNK(st.st_mode)) return p;
    std::string abs = fs::absolute(p).lexically_normal().string();
    if (under(abs, "/proc/") || under(abs, "/dev/fd/") || abs == "/dev/stdout" || abs == "/dev/stderr") {
      magic = true;
      return t.path;
    }
    std::vector<char> buf(PATH_MAX + 1);
    ssize_t n = ::readlink(p.c_str(), buf.data(), buf.size() - 1);
    if (n < 0) fail_errno(t, errno);
    fs::path to(std::string(buf.data(), size_t(n)));
    p = to.is_absolute() ? to.string() : (fs::path(p).parent_path() / to).string();
  }
  fail_errno(t, ELOOP);
}

void write_all(const OutputTarget& t, int fd, const std::vector<unsigned char>& bytes) {
  size_t done = 0;
  while (done < bytes.size()) {
    ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) fail_errno(t, errno);
    if (n == 0) fail_errno(t, EIO);
    done += size_t(n);
  }
}

void write_in_place(const OutputTarget& t, const std::vector<unsigned char>& bytes) {
  if (t.to_stdout) {
    std::fflush(stdout);
    write_all(t, STDOUT_FILENO, bytes);
    return;
  }
  int fd;
  do fd = ::open(t.file.c_str(), O_WRONLY | O_CLOEXEC | O_NOCTTY);
  while (fd < 0 && errno == EINTR);
  if (fd < 0) fail_errno(t, errno);
  try {
    write_all(t, fd, bytes);
  } catch (...) {
    ::close(fd);
    throw;
  }
  if (::close(fd) != 0 && errno != EINTR) fail_errno(t, errno);
}

// Creates the registered temporary for `t`; returns its descriptor.
int create_temporary(const OutputTarget& t, const std::string& tmp) {
  for (int attempt = 0;; ++attempt) {
    int fd = open_temporary(tmp, O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0666);
    if (fd >= 0) return fd;
    int err = errno;
    struct stat st {};
    // A regular file under this process's temporary name is left from an earlier run that had the
    // same process id and was killed: it is ours to replace. Anything else is not.
    if (err == EEXIST && attempt == 0 && ::lstat(tmp.c_str(), &st) == 0 && S_ISREG(st.st_mode)) {
      ::unlink(tmp.c_str());
      continue;
    }
    if (err == EINTR) continue;
    if (err == EEXIST) fail(t, "something named " + tmp + " is in the way of the temporary file");
    fail_errno(t, err);
  }
}

// Writes `bytes` to the temporary `tmp` of `t` (mode copied from the file it replaces).
void write_temporary(const OutputTarget& t, const std::string& tmp, const std::vector<unsigned char>& bytes) {
  int fd = create_temporary(t, tmp);
  try {
    write_all(t, fd, bytes);
    struct stat st {};
    if (t.exists && ::stat(t.file.c_str(), &st) == 0) ::fchmod(fd, st.st_mode & 07777);
    if (::fsync(fd) != 0 && errno != EINVAL && errno != EROFS) fail_errno(t, errno);
  } catch (...) {
    ::close(fd);
    discard_temporary(tmp);
    throw;
  }
  if (::close(fd) != 0 && errno != EINTR) {
    int err = errno;
    discard_temporary(tmp);
    fail_errno(t, err);
  }
}

}  // namespace

std::string OutputTarget::shown() const {
  if (to_stdout) return "standard output";
  return file == path ? path : path + " (-> " + file + ")";
}

std::string temporary_name(const std::string& file) {
  fs::path target(file);
  std::string stem = target.stem().string(), ext = target.extension().string();
  std::string tag = ".tmp" + std::to_string(::getpid());
  long max = name_max(folder_of(file));
  long room = max - long(1 + tag.size() + ext.size());
  if (room < 1) ext.clear(), room = max - long(1 + tag.size());
  if (long(stem.size()) > room) stem.resize(size_t(std::max(1L, room)));
  return (target.parent_path() / ("." + stem + tag + ext)).string();
}

OutputTarget check_output(const std::string& path, bool allow_stdout) {
  OutputTarget t;
  t.path = path;
  t.file = path;
  if (path.empty()) throw Error("cannot write an output with an empty name");
  if (path == "-") {
    if (!allow_stdout) throw Error("cannot write '-': standard output is not available for this output");
    t.in_place = t.to_stdout = t.exists = true;
    return t;
  }
  bool magic = false;
  t.file = follow_links(t, magic);
  if (magic) {
    struct stat st {};
    if (::stat(t.file.c_str(), &st) != 0) fail_errno(t, errno);
    if (S_ISDIR(st.st_mode)) fail(t, "it is a folder, not a file");
    t.in_place = t.exists = true;
    return t;
  }
  std::string name = fs::path(t.file).filename().string();
  if (name.empty() || name == "." || name == "..") fail(t, "it names a folder, not a file");
  std::string dir = folder_of(t.file);
  struct stat st {};
  if (::stat(t.file.c_str(), &st) == 0) {
    t.exists = true;
    if (S_ISDIR(st.st_mode)) fail(t, "it is a folder, not a file");
    if (S_ISCHR(st.st_mode) || S_ISFIFO(st.st_mode)) {
      t.in_place = true;
      if (::access(t.file.c_str(), W_OK) != 0) fail_errno(t, errno);
      return t;
    }
    if (S_ISBLK(st.st_mode)) fail(t, "it is a block device; gdrender does not write over devices of that kind");
    if (!S_ISREG(st.st_mode)) fail(t, "it exists and is not a regular file (a socket?); it is not replaced");
    if (::access(t.file.c_str(), W_OK) != 0) fail_errno(t, errno);
  } else if (errno == ENOTDIR) {
    fail(t, "a part of the path is not a folder");
  } else if (errno != ENOENT) {
    fail_errno(t, errno);
  }
  struct stat dst {};
  if (::stat(dir.c_str(), &dst) != 0) {
    if (errno == ENOENT) fail(t, "the folder " + dir + " does not exist");
    fail(t, "the folder " + dir + ": " + std::strerror(errno));
  }
  if (!S_ISDIR(dst.st_mode)) fail(t, dir + " is not a folder");
  if (long(name.size()) > name_max(dir)) {
    fail(t, "file name too long (" + std::to_string(name.size()) + " bytes; the file system takes at most " +
                std::to_string(name_max(dir)) + ")");
  }
  // Creating and removing the temporary shows the folder takes new files (permissions, a
  // read-only file system, the path's length) before any time is spent rendering.
  std::string tmp = temporary_name(t.file);
  int fd = create_temporary(t, tmp);
  ::close(fd);
  discard_temporary(tmp);
  return t;
}

OutputSet::~OutputSet() {
  for (Entry& e : entries_) {
    if (!e.tmp.empty()) discard_temporary(e.tmp);
  }
}

void OutputSet::add(const std::string& path, std::vector<unsigned char> bytes, bool allow_stdout) {
  entries_.push_back({check_output(path, allow_stdout), std::move(bytes), {}});
}

void OutputSet::commit() {
  for (Entry& e : entries_) {
    if (e.target.in_place) continue;
    std::string tmp = temporary_name(e.target.file);
    write_temporary(e.target, tmp, e.bytes);
    e.tmp = tmp;
  }
  for (Entry& e : entries_) {
    if (e.target.in_place) write_in_place(e.target, e.bytes);
  }
  for (Entry& e : entries_) {
    if (e.tmp.empty()) continue;
    if (std::error_code ec = commit_temporary(e.tmp, e.target.file)) fail(e.target, ec.message());
    e.tmp.clear();
  }
  entries_.clear();
}

void write_output_file(const std::string& path, const std::vector<unsigned char>& bytes, bool allow_stdout) {
  OutputSet set;
  set.add(path, bytes, allow_stdout);
  set.commit();
}

}  // namespace gdr
