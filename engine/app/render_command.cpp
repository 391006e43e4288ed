#include "app/render_command.h"

#include <filesystem>

#include "accel/embree_scene.h"
#include "device/context.h"
#include "image/image_io.h"
#include "integrators/progressive_loop.h"
#include "integrators/gpt/gradient_image.h"
#include "integrators/gpt/gradient_path_tracer.h"
#include "integrators/pt/path_tracer.h"
#include "scene/load_scene.h"
#include "stats/stats.h"
#include "util/error.h"
#include "util/log.h"

namespace gdr {
namespace {

// The integrator a scene asks for, in gdrender's names.
std::string integrator_name(const Options& o, const Scene& scene) {
  if (!o.integrator.empty()) return o.integrator;
  if (scene.integrator == "gpt" || scene.integrator == "gbdpt") return "gpt";
  return "pt";
}

std::string default_output(const std::string& scene_path) {
  return std::filesystem::path(scene_path).stem().string() + ".exr";
}

nlohmann::json settings_json(const Options& o, const RenderSettings& s, const std::string& integrator) {
  nlohmann::json j;
  j["integrator"] = integrator;
  j["seed"] = s.seed;
  j["spp_requested"] = s.spp;
  if (s.time_budget) j["time_budget"] = *s.time_budget;
  j["max_depth"] = s.max_depth;
  j["rr_depth"] = s.rr_depth;
  j["scene"] = o.scene;
  if (integrator == "gpt") {
    j["shift"] = o.shift;
    j["shift_threshold"] = o.shift_threshold;
    j["recon"] = o.recon;
    j["recon_solver"] = o.recon_solver;
    j["alpha"] = o.alpha;
  }
  for (const auto& [k, v] : o.defines) j["defines"][k] = v;
  return j;
}

}  // namespace

int render_command(const Options& o) {
  Stats stats;
  ScopedTimer total(&stats, "total");
  LoadOptions load;
  load.defines = o.defines;
  load.strict = o.strict;
  load.glossy_threshold = o.shift_threshold;
  Scene scene = [&] {
    ScopedTimer t(&stats, "scene/load");
    return load_scene(o.scene, load);
  }();
  if (!o.filter.empty()) {
    scene.camera.filter = o.filter == "box" ? FILTER_BOX : o.filter == "tent" ? FILTER_TENT : FILTER_GAUSSIAN;
    scene.camera.filter_radius = o.filter == "box" ? 0.5f : o.filter == "tent" ? 1.0f : 2.0f;
  }
  std::string integrator = integrator_name(o, scene);
  if (integrator != "pt" && integrator != "gpt") {
    throw Error("unknown integrator '" + integrator + "' (available: pt, gpt)");
  }

  RenderSettings settings;
  settings.seed = o.seed;
  settings.time_budget = o.time_budget;
  settings.spp = o.spp ? *o.spp : (o.time_budget ? 0 : scene.spp);
  settings.max_depth = o.max_depth > 0 ? o.max_depth : scene.max_depth;
  settings.strategy = o.strategy == "bsdf" ? PT_STRATEGY_BSDF : o.strategy == "light" ? PT_STRATEGY_LIGHT : PT_STRATEGY_MIS;
  settings.progress = !o.quiet;
  settings.aux = o.aux;
  stats.set("settings", settings_json(o, settings, integrator));

  Context ctx(select_device(o.device), &stats);
  log::info("device: ", ctx.device().name, " (", ctx.device().platform_name, ")");
  log::info("scene: ", o.scene, ": ", scene.triangles.size(), " triangles, ", scene.lights.size(), " lights, ",
            scene.camera.width, "x", scene.camera.height);
  for (const std::string& w : scene.warnings) log::warn(w);
  std::string effects = scene.features.describe();
  while (!effects.empty() && effects.back() == '\n') effects.pop_back();
  log::info(effects);
  EmbreeScene embree(scene, BuildQuality::High, &stats);
  RenderResult result;
  if (integrator == "gpt") {
    if (o.strategy != "mis") log::warn("--strategy applies to pt only; gpt always combines both techniques");
    if (o.aux) log::warn("--aux applies to pt only: no albedo, normal or depth layers");
    GptSettings gpt;
    gpt.shift = o.shift == "replay" ? GPT_SHIFT_REPLAY : GPT_SHIFT_HYBRID;
    gpt.shift_threshold = o.shift_threshold;
    GradientPathTracer tracer(ctx, scene, embree, gpt);
    GradientImages layers = tracer.render(settings);
    ScopedTimer t(&stats, "recon/total");
    std::optional<ReconSettings> recon;
    if (o.recon != "none") recon = recon_settings(o.recon, o.alpha, o.recon_solver);
    result.image = gradient_image(ctx, layers, recon, &stats);
    result.samples = layers.samples;
    result.seconds = layers.seconds + t.elapsed();
  } else {
    PathTracer tracer(ctx, scene, embree);
    result = tracer.render(settings);
  }
  if (render_interrupted()) log::warn("interrupted: writing the ", result.samples, " spp rendered so far");

  std::string out = o.output.empty() ? default_output(o.scene) : o.output;
  std::filesystem::path exr = std::filesystem::path(out).replace_extension(".exr");
  std::filesystem::path png = std::filesystem::path(out).replace_extension(".png");
  {
    ScopedTimer t(&stats, "image/write");
    write_exr(exr.string(), result.image);
    write_png(png.string(), result.image);
  }
  double seconds = result.seconds;
  stats.set("render/seconds", seconds);
  stats.set("render/samples_per_second", seconds > 0 ? result.samples / seconds : 0.0);
  log::info("rendered ", result.samples, " spp in ", seconds, " s; wrote ", exr.string(), " and ", png.string());
  if (!o.stats_path.empty()) {
    stats.set("total_seconds", total.elapsed());
    stats.write_json(o.stats_path);
  }
  return 0;
}

}  // namespace gdr
