// Errors the engine reports to the user: one line, naming the file and line where there is one.
#pragma once
#include <stdexcept>
#include <string>

namespace gdr {

class Error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Bad input in a file: the message reads "FILE:LINE: problem".
class InputError : public Error {
 public:
  InputError(const std::string& file, int line, const std::string& problem)
      : Error(file + (line > 0 ? ":" + std::to_string(line) : std::string()) + ": " + problem),
        file_(file), line_(line) {}
  const std::string& file() const { return file_; }
  int line() const { return line_; }

 private:
  std::string file_;
  int line_;
};

}  // namespace gdr
