// Which files a command writes, checked before any work is done (a long render must not find
// at its end that it cannot write).
//
// -o NAME.exr writes NAME.exr and a tone-mapped NAME.png beside it; -o NAME.png writes NAME.png
// and keeps the render's data in NAME.exr beside it. Any other extension is refused. A target
// that is written in place (a device such as /dev/null, a pipe, `-` for standard output) gets
// the one image its extension names (EXR without one) and nothing beside it.
#pragma once
#include <string>
#include <vector>

#include "image/atomic_file.h"
#include "image/image.h"

namespace gdr {

struct ImageOutputs {
  std::string exr;  // empty: not written
  std::string png;
};

// The images `-o out` stands for. Throws gdr::Error for an unknown extension (listing the
// accepted ones), or when a target cannot be written (check_output).
ImageOutputs image_outputs(const std::string& out, const std::string& option = "-o");

// Checks every output before work starts: each is writable (check_output), and no two regular
// files are the same file. `stdout_taken` says standard output already carries something (then
// `-` is refused). Throws gdr::Error naming the option and the path.
struct PlannedOutput {
  std::string option;  // "-o", "--stats", "--error-image"
  std::string path;
  bool allow_stdout = false;
};
void check_outputs(const std::vector<PlannedOutput>& outputs);

// Adds the images `image` is written as (encoded EXR and PNG) to `set`.
void add_image_outputs(OutputSet& set, const ImageOutputs& images, const Image& image);

// The images of `-o out` and the stats file (if any), checked together with check_outputs.
ImageOutputs checked_render_outputs(const std::string& out, const std::string& stats_path);

}  // namespace gdr
