// Bounds on what an input file may make the engine allocate. Every reader of a user-supplied file
// (scene, include, mesh, texture, image) reads it through these checks: the file must be a regular
// file, and a size it declares (pixels, vertices, an inflated stream) is checked against the file's
// real size and against a memory limit before anything is allocated.
//
// The limit is GDR_MAX_INPUT_BYTES (bytes, with an optional K, M or G suffix, powers of 1024),
// default 4G: the most one input file may occupy in memory once decoded.
#pragma once
#include <cstdint>
#include <string>

namespace gdr {

constexpr uint64_t kDefaultMaxInputBytes = 4ull << 30;

// The limit in bytes (GDR_MAX_INPUT_BYTES, else the default). A malformed value is an Error.
uint64_t max_input_bytes();

// "4.0 GiB", "92 bytes": a size for messages (also the device's buffer limits).
std::string format_bytes(uint64_t bytes);

// The size of `path` in bytes. InputError(path, 0, ...) when it does not exist, or is not a
// regular file (a directory, a device such as /dev/zero, a pipe), or is larger than the limit.
// `what` names the file's role in messages ("scene file", "mesh", "texture").
uint64_t checked_input_size(const std::string& path, const std::string& what);

// The whole file, after checked_input_size. InputError naming the file on any failure.
std::string read_input_file(const std::string& path, const std::string& what);

// InputError(path, 0, ...) when `bytes` (what `purpose` needs, as declared by the file) exceeds the
// limit; the message names the size and the limit.
void check_input_allocation(const std::string& path, uint64_t bytes, const std::string& purpose);

// InputError(path, 0, ...) when a size the file's header declares (`declared` bytes once decoded)
// cannot come from a file of `file_size` bytes compressed at most `max_ratio` to 1: "`claim` (SIZE),
// but the file has only SIZE". `claim` says what the header claims ("the header claims 30000x30000
// pixels").
void check_declared_size(const std::string& path, double declared, uint64_t file_size, double max_ratio,
                         const std::string& claim);

// The most any image format the engine reads compresses (deflate reaches about 1032:1; a margin
// for formats with long runs).
constexpr double kMaxImageCompression = 65536.0;

}  // namespace gdr
