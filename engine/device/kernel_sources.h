// The OpenCL C sources embedded at build time (cmake/EmbedKernels.cmake), and the include
// resolution that turns one root file into a single compilable text.
#pragma once
#include <string>
#include <vector>

namespace gdr {

struct EmbeddedKernelFile {
  const char* path;  // relative to kernels/, e.g. "shared/camera.h"
  std::string text;
};

// Generated at build time.
const std::vector<EmbeddedKernelFile>& embedded_kernel_files();

// The text of `root` (a path relative to kernels/) with every `#include "..."` inlined once
// (resolved against the including file's folder, then against kernels/), and `#line` markers so
// compiler messages name the original file and line. Throws gdr::Error for a missing file.
std::string resolve_kernel_source(const std::string& root);

// A build log with every place given as a line of the resolved text ("<kernel>:4369:35:", as
// compilers that ignore #line write it, NVIDIA's among them) named by its original file and line
// ("kernels/gpt/shade.h:33:35:"). Places already named by file stay as they are.
std::string name_resolved_lines(const std::string& log, const std::string& resolved);

}  // namespace gdr
