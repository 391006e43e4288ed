#include "app/output_paths.h"

#include <unistd.h>

#include <algorithm>
#include <filesystem>

#include "image/image_io.h"
#include "util/error.h"

namespace gdr {
namespace fs = std::filesystem;

namespace {

std::string lower_extension(const std::string& path) {
  std::string ext = fs::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), ::tolower);
  return ext;
}

}  // namespace

ImageOutputs image_outputs(const std::string& out, const std::string& option) {
  std::string ext = lower_extension(out);
  ImageOutputs images;
  OutputTarget target;
  try {
    target = check_output(out, /*allow_stdout=*/true);
  } catch (const Error& e) {
    throw Error(option + ": " + e.what());
  }
  if (target.in_place) {
    if (target.to_stdout && isatty(STDOUT_FILENO)) {
      throw Error(option + " -: standard output is a terminal; redirect it to a file or a pipe");
    }
    (ext == ".png" ? images.png : images.exr) = out;
    return images;
  }
  if (ext != ".exr" && ext != ".png") {
    throw Error(option + " " + out + ": unknown image extension '" + ext +
                "' (accepted: .exr, written with a tone-mapped .png beside it; .png, written with the .exr beside it)");
  }
  // The name given is kept as spelled; the other image takes its stem.
  images.exr = ext == ".exr" ? out : fs::path(out).replace_extension(".exr").string();
  images.png = ext == ".png" ? out : fs::path(out).replace_extension(".png").string();
  return images;
}

void check_outputs(const std::vector<PlannedOutput>& outputs) {
  std::vector<std::pair<std::string, const PlannedOutput*>> regular;
  const PlannedOutput* on_stdout = nullptr;
  for (const PlannedOutput& o : outputs) {
    OutputTarget t;
    try {
      t = check_output(o.path, o.allow_stdout);
    } catch (const Error& e) {
      throw Error(o.option + ": " + e.what());
    }
    if (t.to_stdout) {
      if (on_stdout) throw Error(o.option + " - and " + on_stdout->option + " - would both write to standard output");
      on_stdout = &o;
    }
    if (t.in_place) continue;
    std::error_code ec;
    std::string key = fs::weakly_canonical(fs::absolute(t.file), ec).string();
    if (ec) key = t.file;
    for (const auto& [other, by] : regular) {
      if (other == key) {
        throw Error(o.option + " " + o.path + " and " + by->option + " " + by->path + " name the same file");
      }
    }
    regular.emplace_back(key, &o);
  }
}

ImageOutputs checked_render_outputs(const std::string& out, const std::string& stats_path) {
  ImageOutputs images = image_outputs(out);
  std::vector<PlannedOutput> planned;
  if (!images.exr.empty()) planned.push_back({"-o", images.exr, true});
  if (!images.png.empty()) planned.push_back({"-o", images.png, true});
  if (!stats_path.empty()) planned.push_back({"--stats", stats_path, true});
  check_outputs(planned);
  return images;
}

void add_image_outputs(OutputSet& set, const ImageOutputs& images, const Image& image) {
  if (!images.exr.empty()) set.add(images.exr, encode_exr(image, images.exr), true);
  if (!images.png.empty()) set.add(images.png, encode_png(image, 0.0f, images.png), true);
}

}  // namespace gdr
