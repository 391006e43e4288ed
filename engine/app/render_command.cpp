#include "app/render_command.h"

#include <filesystem>
#include <memory>
#include <optional>

#include "accel/embree_scene.h"
#include "app/output_paths.h"
#include "cluster/ranks.h"
#include "device/context.h"
#include "device/devices.h"
#include "device/runtime_env.h"
#include "image/atomic_file.h"
#include "image/image_io.h"
#include "integrators/registry.h"
#include "render/device_scene.h"
#include "render/progressive_loop.h"
#include "scene/load_scene.h"
#include "stats/memory.h"
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

namespace {

// What each rank did, on rank 0 (per_rank[r]), and the job's totals: under MPI the stats of rank 0
// are the job's, and these say how its passes were shared and what the reductions cost.
void add_rank_stats(Stats& stats, const DeviceInfo& device, const RenderResult& result) {
  const LoopTimes loop = last_loop_times();
  nlohmann::json mine;
  mine["rank"] = cluster::rank();
  mine["host"] = cluster::host();
  mine["device"] = device.name;
  mine["threads"] = runtime_threads();
  mine["passes"] = loop.passes;
  mine["pass_seconds"] = loop.pass_seconds;
  mine["wait_seconds"] = loop.wait_seconds;
  mine["loop_seconds"] = loop.seconds;
  mine["render_seconds"] = result.seconds;
  mine["reduce_seconds"] = stats.seconds("mpi/reduce");
  std::vector<std::string> all = cluster::gather_to_root(mine.dump());
  if (!cluster::root()) return;
  nlohmann::json per_rank = nlohmann::json::array();
  int passes = 0;
  for (const std::string& text : all) {
    per_rank.push_back(nlohmann::json::parse(text));
    passes += per_rank.back()["passes"].get<int>();
  }
  stats.set("mpi/ranks", cluster::size());
  stats.set("mpi/passes", passes);
  stats.set("mpi/per_rank", per_rank);
}

}  // namespace

int render_command(const Options& o) {
  Stats stats;
  ScopedTimer total(&stats, "total");
  // Everything a render needs before its first pass, set up on every rank; under MPI the ranks
  // then agree that all of them succeeded (cluster::all_or_none), so that a rank that cannot
  // load the scene or start its device ends the job with its reason instead of leaving the
  // others waiting.
  std::string out = o.output.empty() ? default_output(o.scene) : o.output;
  ImageOutputs images;
  std::optional<Scene> scene_holder;
  const IntegratorEntry* entry_ptr = nullptr;
  IntegratorParams params(o.integrator_params);
  RenderSettings settings;
  DeviceInfo device;
  std::unique_ptr<Context> ctx;
  std::unique_ptr<EmbreeScene> embree;
  std::unique_ptr<DeviceScene> device_scene;
  std::unique_ptr<Integrator> integrator;
  cluster::all_or_none([&] {
    // Every output is checked before the scene is loaded: a long render must not find at its
    // end that it cannot write. Only rank 0 writes.
    if (cluster::root()) images = checked_render_outputs(out, o.stats_path);
    scene_holder = [&] {
      ScopedTimer t(&stats, "scene/load");
      return load_scene(o.scene, load_options(o));
    }();
    Scene& scene = *scene_holder;
    if (!o.filter.empty()) {
      scene.camera.filter = o.filter == "box" ? FILTER_BOX : o.filter == "tent" ? FILTER_TENT : FILTER_GAUSSIAN;
      scene.camera.filter_radius = o.filter == "box" ? 0.5f : o.filter == "tent" ? 1.0f : 2.0f;
    }
    entry_ptr = &choose_integrator(o, scene);
    warn_unread_params(*entry_ptr, params);

    settings.seed = o.seed;
    settings.time_budget = o.time_budget;
    settings.spp = o.spp ? *o.spp : (o.time_budget ? 0 : scene.spp);
    settings.max_depth = o.max_depth > 0 ? o.max_depth : scene.max_depth;
    settings.progress = !o.quiet;
    stats.set("settings", settings_json(o, settings, *entry_ptr, scene.camera));

    // Processes sharing a node take its devices in turn (--device or GDR_DEVICE choose for all).
    device = select_device(o.device, cluster::local_rank());
    ctx = std::make_unique<Context>(device, &stats);
    if (!o.kernels.empty()) ctx->set_scene_kernels(o.kernels == "scene");
    log::info("device: ", ctx->device().name, " (", ctx->device().platform_name, ")");
    if (cluster::distributed()) log::info("ranks: ", cluster::size(), " (rank r traces passes r, r + ", cluster::size(), ", ...)");
    log::info("scene: ", o.scene, ": ", scene.triangles.size(), " triangles, ", scene.lights.size(), " lights, ",
              scene.camera.width, "x", scene.camera.height);
    log::info("integrator: ", entry_ptr->name);
    for (const std::string& w : scene.warnings) log::warn(w);
    std::string effects = scene.features.describe();
    while (!effects.empty() && effects.back() == '\n') effects.pop_back();
    log::info(effects);
    embree = std::make_unique<EmbreeScene>(scene, BuildQuality::High, &stats);
    device_scene = std::make_unique<DeviceScene>(*ctx, scene);
    integrator = entry_ptr->make(RenderInputs{*ctx, scene, *embree, *device_scene}, params);
  });
  // The ranks' films are summed: they must all render the same job (a scene that differs
  // between machines, say).
  cluster::check_same("render", settings_json(o, settings, *entry_ptr, scene_holder->camera).dump());
  RenderResult result = integrator->render(settings);
  if (render_interrupted()) log::warn("interrupted: writing the ", result.samples, " spp rendered so far");

  double seconds = result.seconds;
  stats.set("render/seconds", seconds);
  stats.set("render/samples_per_second", seconds > 0 ? result.samples / seconds : 0.0);
  // The passes alone (render/seconds of a gradient render includes its reconstruction): the
  // throughput that more ranks raise.
  stats.set("render/loop_seconds", last_loop_times().seconds);
  stats.set("memory/peak_resident_bytes", peak_resident_bytes());
  if (cluster::distributed()) add_rank_stats(stats, device, result);
  if (!cluster::root()) return 0;
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
