#include "app/render_command.h"

#include <filesystem>

#include "accel/embree_scene.h"
#include "app/output_paths.h"
#include "device/context.h"
#include "image/atomic_file.h"
#include "image/image_io.h"
#include "integrators/registry.h"
#include "render/device_scene.h"
#include "render/progressive_loop.h"
#include "scene/load_scene.h"
#include "stats/stats.h"
#include "util/error.h"
#include "util/log.h"

namespace gdr {
namespace {

// The integrator to run: --integrator, else the one the scene's <integrator type> stands for,
// else pt. A type gdrender does not have is a warning naming the element (an error with
// --strict), and pt renders.
const IntegratorEntry& choose_integrator(const Options& o, const Scene& scene) {
  if (!o.integrator.empty()) return find_integrator(o.integrator);
  if (scene.integrator.empty()) return find_integrator("pt");
  if (const IntegratorEntry* e = integrator_for_scene_type(scene.integrator)) return *e;
  std::string problem = "<integrator type=\"" + scene.integrator + "\">: no such integrator in gdrender (it has: " +
                        integrator_names() + ")";
  if (o.strict) throw InputError(scene.integrator_file, scene.integrator_line, problem);
  log::warn(scene.integrator_file, ":", scene.integrator_line, ": ", problem, "; rendering with pt");
  return find_integrator("pt");
}

// Command-line parameters the chosen integrator does not read are named, not silently dropped.
void warn_unread_params(const IntegratorEntry& entry, const IntegratorParams& params) {
  for (const auto& [name, value] : params.values()) {
    bool read = false;
    for (const std::string& p : entry.params) read |= p == name;
    if (read) continue;
    std::string flag = "--" + name;
    for (char& c : flag) c = c == '_' ? '-' : c;
    std::string readers = integrators_reading(name);
    log::warn(flag, " does not apply to ", entry.name, (readers.empty() ? "" : " (it applies to " + readers + ")"));
  }
}

std::string default_output(const std::string& scene_path) {
  return std::filesystem::path(scene_path).stem().string() + ".exr";
}

nlohmann::json settings_json(const Options& o, const RenderSettings& s, const IntegratorEntry& integrator,
                             const GdrCamera& camera) {
  nlohmann::json j;
  j["integrator"] = integrator.name;
  j["width"] = camera.width;
  j["height"] = camera.height;
  j["seed"] = s.seed;
  j["spp_requested"] = s.spp;
  if (s.time_budget) j["time_budget"] = *s.time_budget;
  j["max_depth"] = s.max_depth;
  j["rr_depth"] = s.rr_depth;
  j["scene"] = o.scene;
  for (const auto& [k, v] : o.integrator_params) j["params"][k] = v;
  for (const auto& [k, v] : o.defines) j["defines"][k] = v;
  return j;
}

}  // namespace

LoadOptions load_options(const Options& o) {
  LoadOptions load;
  load.defines = o.defines;
  load.strict = o.strict;
  load.width = o.width;
  load.height = o.height;
  load.glossy_threshold = IntegratorParams(o.integrator_params).non_negative("shift_threshold", GDR_GLOSSY_THRESHOLD);
  return load;
}

int render_command(const Options& o) {
  Stats stats;
  ScopedTimer total(&stats, "total");
  // Every output is checked before the scene is loaded: a long render must not find at its end
  // that it cannot write.
  std::string out = o.output.empty() ? default_output(o.scene) : o.output;
  ImageOutputs images = checked_render_outputs(out, o.stats_path);
  IntegratorParams params(o.integrator_params);
  Scene scene = [&] {
    ScopedTimer t(&stats, "scene/load");
    return load_scene(o.scene, load_options(o));
  }();
  if (!o.filter.empty()) {
    scene.camera.filter = o.filter == "box" ? FILTER_BOX : o.filter == "tent" ? FILTER_TENT : FILTER_GAUSSIAN;
    scene.camera.filter_radius = o.filter == "box" ? 0.5f : o.filter == "tent" ? 1.0f : 2.0f;
  }
  const IntegratorEntry& entry = choose_integrator(o, scene);
  warn_unread_params(entry, params);

  RenderSettings settings;
  settings.seed = o.seed;
  settings.time_budget = o.time_budget;
  settings.spp = o.spp ? *o.spp : (o.time_budget ? 0 : scene.spp);
  settings.max_depth = o.max_depth > 0 ? o.max_depth : scene.max_depth;
  settings.progress = !o.quiet;
  stats.set("settings", settings_json(o, settings, entry, scene.camera));

  Context ctx(select_device(o.device), &stats);
  log::info("device: ", ctx.device().name, " (", ctx.device().platform_name, ")");
  log::info("scene: ", o.scene, ": ", scene.triangles.size(), " triangles, ", scene.lights.size(), " lights, ",
            scene.camera.width, "x", scene.camera.height);
  log::info("integrator: ", entry.name);
  for (const std::string& w : scene.warnings) log::warn(w);
  std::string effects = scene.features.describe();
  while (!effects.empty() && effects.back() == '\n') effects.pop_back();
  log::info(effects);
  EmbreeScene embree(scene, BuildQuality::High, &stats);
  DeviceScene device_scene(ctx, scene);
  std::unique_ptr<Integrator> integrator = entry.make(RenderInputs{ctx, scene, embree, device_scene}, params);
  RenderResult result = integrator->render(settings);
  if (render_interrupted()) log::warn("interrupted: writing the ", result.samples, " spp rendered so far");

  double seconds = result.seconds;
  stats.set("render/seconds", seconds);
  stats.set("render/samples_per_second", seconds > 0 ? result.samples / seconds : 0.0);
  // The images and the stats are written as one set: temporaries first, then renamed together.
  OutputSet outputs;
  {
    ScopedTimer t(&stats, "image/write");
    add_image_outputs(outputs, images, result.image);
  }
  if (!o.stats_path.empty()) {
    stats.set("total_seconds", total.elapsed());
    outputs.add(o.stats_path, stats.json_bytes(), true);
  }
  outputs.commit();
  std::string wrote = images.exr.empty() ? images.png : images.png.empty() ? images.exr : images.exr + " and " + images.png;
  log::info("rendered ", result.samples, " spp in ", seconds, " s; wrote ", wrote);
  return 0;
}

}  // namespace gdr
