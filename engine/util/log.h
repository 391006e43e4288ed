// Minimal levelled logging to stderr; the CLI sets the level from --verbose / --quiet.
#pragma once
#include <sstream>
#include <string>

namespace gdr::log {

enum class Level { Quiet = 0, Info = 1, Verbose = 2 };
void set_level(Level level);
Level level();
// Nothing is written while muted (the ranks of an MPI job other than rank 0, whose lines would
// repeat rank 0's; their errors are printed apart, naming the rank).
void set_muted(bool muted);

void write(const char* prefix, const std::string& message);

template <class... Args>
std::string concat(const Args&... args) {
  std::ostringstream out;
  (out << ... << args);
  return out.str();
}
template <class... Args> void info(const Args&... a) { if (level() >= Level::Info) write("", concat(a...)); }
template <class... Args> void verbose(const Args&... a) { if (level() >= Level::Verbose) write("", concat(a...)); }
// Warnings are printed even with --quiet: they report something the user must know about.
template <class... Args> void warn(const Args&... a) { write("warning: ", concat(a...)); }

}  // namespace gdr::log
