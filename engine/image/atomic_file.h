// Writing outputs. A regular file (or a new name) is written to a temporary file beside it,
// `.<stem>.tmp<pid><ext>`, which is renamed over it, so that an interrupted or failed run never
// leaves a truncated file under the final name. A symbolic link is followed: the file it points
// to is replaced, the link stays. A character device or a pipe (/dev/null, /dev/stdout, a FIFO)
// and `-` (standard output, where a command allows it) are written in place; anything else that
// exists and is not a regular file (a folder, a block device, a socket) is refused, never
// replaced. Every failure names the path and the reason ("No space left on device").
#pragma once
#include <memory>
#include <string>
#include <vector>

namespace gdr {

// Where an output's bytes go.
struct OutputTarget {
  std::string path;       // as given (messages name it)
  std::string file;       // the file written: symbolic links followed
  bool in_place = false;  // a device, a pipe or standard output: written straight into
  bool to_stdout = false; // `-`
  bool exists = false;    // a file is there now (replaced, or written into)
  bool is_regular() const { return !in_place; }
  // What messages call it: "PATH", or "PATH (-> FILE)" for a link.
  std::string shown() const;
};

// Checks, without leaving anything behind, that `path` can be written now: its folder exists and
// takes a new file (a temporary is created and removed there), its name is not too long, it is
// not a folder, a block device or a socket. `-` is standard output when allow_stdout is true.
// Throws gdr::Error "cannot write PATH: reason".
OutputTarget check_output(const std::string& path, bool allow_stdout = false);

// The temporary name beside `file`: ".<stem>.tmp<pid><ext>", the stem shortened where the name
// would otherwise be too long for the folder's file system.
std::string temporary_name(const std::string& file);

// Writes several outputs as one: every regular file goes to its temporary first, targets written
// in place are written next, and only then are the temporaries renamed into place (an error, or
// an interrupt that ends the process, removes the temporaries and keeps the old files).
class OutputSet {
 public:
  OutputSet() = default;
  ~OutputSet();
  OutputSet(const OutputSet&) = delete;
  OutputSet& operator=(const OutputSet&) = delete;
  void add(const std::string& path, std::vector<unsigned char> bytes, bool allow_stdout = false);
  void commit();

 private:
  struct Entry {
    OutputTarget target;
    std::vector<unsigned char> bytes;
    std::string tmp;
  };
  std::vector<Entry> entries_;
};

// One output (see OutputSet).
void write_output_file(const std::string& path, const std::vector<unsigned char>& bytes,
                       bool allow_stdout = false);

}  // namespace gdr
