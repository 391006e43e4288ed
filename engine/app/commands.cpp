#include "app/commands.h"

#include <cctype>
#include <cstdio>
#include <filesystem>

#include "app/output_paths.h"
#include "app/reconstruct_command.h"
#include "app/render_command.h"
#include "cluster/ranks.h"
#include "device/context.h"
#include "device/devices.h"
#include "device/runtime_env.h"
#include "image/atomic_file.h"
#include "image/image_io.h"
#include "image/image_metrics.h"
#include "integrators/registry.h"
#include "render/gradient_images.h"
#include "render/manifold_walks.h"
#include "scene/describe_scene.h"
#include "scene/load_scene.h"
#include "util/error.h"

namespace gdr {

int list_devices_command() {
  std::vector<DeviceInfo> devices = list_devices();
  if (devices.empty()) {
    std::string problem = opencl_environment_problem();
    if (!problem.empty()) throw Error("no OpenCL platform started: " + problem);
    throw Error("no OpenCL device found (is an ICD such as pocl-opencl-icd installed?)");
  }
  std::fputs(format_device_list(devices).c_str(), stdout);
  return 0;
}

namespace {

int list_integrators_command() {
  std::fputs(describe_integrators().c_str(), stdout);
  return 0;
}

int info_command(const Options& o) {
  DeviceInfo device = select_device(o.device);
  Scene scene = load_scene(o.info_scene, load_options(o));
  std::printf("%s", describe_scene(scene).c_str());
  std::printf("%s\n", manifold_description(scene, device, manifold_settings(IntegratorParams(o.integrator_params))).c_str());
  std::printf("device: [%d] %s (%s)\n", device.index, device.name.c_str(), device.platform_name.c_str());
  return 0;
}

int compare_command(const Options& o) {
  if (!o.error_image.empty()) {
    // Standard output carries the JSON: `-` is refused. The image is a PNG.
    check_outputs({{"--error-image", o.error_image, false}});
    OutputTarget t = check_output(o.error_image);
    std::string ext = std::filesystem::path(o.error_image).extension().string();
    for (char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
    if (!t.in_place && ext != ".png") {
      throw Error("--error-image " + o.error_image + ": the error image is a PNG: name it with .png");
    }
  }
  // The last image is the reference; with several before it, their errors are averaged and
  // split into bias^2 and variance.
  std::vector<Image> runs;
  for (size_t i = 0; i + 1 < o.compare.size(); ++i) runs.push_back(read_image(o.compare[i]));
  Image reference = read_image(o.compare.back());
  ImageSetError set = compare_image_set(runs, reference);
  const ImageError& e = set.mean;
  nlohmann::json j = {{"relmse", e.rel_mse}, {"mse", e.mse},       {"mape", e.mape}, {"brightness", e.brightness},
                      {"values", e.values},  {"skipped_nonfinite", e.skipped}};
  if (runs.size() > 1) {
    j["runs"] = runs.size();
    j["bias2"] = set.bias2;
    j["variance"] = set.variance;
  }
  std::printf("%s\n", j.dump().c_str());
  if (!o.error_image.empty()) write_png(o.error_image, error_image(runs.front(), reference));
  return 0;
}

}  // namespace

int run_command(const Options& options) {
  if (cluster::distributed() && options.scene.empty()) {
    // N ranks would each do the same and write the same files.
    throw Error("only a render runs across MPI ranks: run --list-devices, --list-integrators, --info, --compare and "
                "--reconstruct without mpirun");
  }
  if (options.list_devices) return list_devices_command();
  if (options.list_integrators) return list_integrators_command();
  if (!options.info_scene.empty()) return info_command(options);
  if (!options.compare.empty()) return compare_command(options);
  if (!options.reconstruct.empty()) {
    Stats stats;
    Context ctx(select_device(options.device), &stats);
    std::string out = options.output.empty()
                          ? std::filesystem::path(options.reconstruct).stem().string() + "-recon.exr"
                          : options.output;
    // Outputs are checked before the reconstruction runs.
    checked_render_outputs(out, options.stats_path);
    int code = reconstruct_command(options.reconstruct, out, IntegratorParams(options.integrator_params), ctx, &stats);
    if (!options.stats_path.empty()) stats.write_json(options.stats_path);
    return code;
  }
  return render_command(options);
}

}  // namespace gdr
