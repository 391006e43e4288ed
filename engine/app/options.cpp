#include "app/options.h"

#include "integrators/registry.h"

#include <CLI/CLI.hpp>

#include <cmath>
#include <iostream>
#include <limits>
#include <list>

namespace gdr {
namespace {

// CLI11's PositiveNumber and NonNegativeNumber let "nan" and "inf" through (nan <= 0 is false):
// a --time of nan or inf would render for ever. Their messages also print DBL_MAX in full.
CLI::Validator finite_number(bool allow_zero) {
  return CLI::Validator(
      [allow_zero](std::string& s) -> std::string {
        double v = 0;
        if (!CLI::detail::lexical_cast(s, v)) return "Value " + s + " is not a number";
        if (!std::isfinite(v) || v < 0 || (v == 0 && !allow_zero)) {
          return "Value " + s + (allow_zero ? " is not a finite number >= 0" : " is not a finite positive number");
        }
        return {};
      },
      allow_zero ? "NONNEGATIVE" : "POSITIVE");
}
const CLI::Validator kFinitePositive = finite_number(false);
const CLI::Validator kFiniteNonNegative = finite_number(true);

// --integrator takes a registry name.
CLI::Validator registered_integrator() {
  return CLI::Validator(
      [](std::string& s) -> std::string {
        if (integrator_for_name(s)) return {};
        return "unknown integrator '" + s + "' (available: " + integrator_names() + ")";
      },
      "INTEGRATOR");
}

// --resolution: "W" or "WxH", each 1..65536 (the film sizes a scene file may give).
bool parse_resolution(const std::string& s, int* width, int* height) {
  auto number = [](const std::string& t, int* v) {
    if (t.empty() || t.size() > 5 || t.find_first_not_of("0123456789") != std::string::npos) return false;
    *v = std::stoi(t);
    return *v >= 1 && *v <= 65536;
  };
  size_t x = s.find('x');
  *height = 0;
  if (x == std::string::npos) return number(s, width);
  return number(s.substr(0, x), width) && number(s.substr(x + 1), height);
}

CLI::Validator resolution_check() {
  return CLI::Validator(
      [](std::string& s) -> std::string {
        int w, h;
        if (parse_resolution(s, &w, &h)) return {};
        return "Value " + s + " is not a film size WxH or W (1 to 65536 pixels)";
      },
      "WxH");
}

// pt's strategy names, or bdpt's "s,t" (the integrator checks which strategies exist).
CLI::Validator strategy_check() {
  return CLI::Validator(
      [](std::string& s) -> std::string {
        if (s == "mis" || s == "bsdf" || s == "light") return {};
        size_t comma = s.find(',');
        auto digits = [](const std::string& d) {
          return !d.empty() && d.size() < 4 && d.find_first_not_of("0123456789") == std::string::npos;
        };
        if (comma != std::string::npos && digits(s.substr(0, comma)) && digits(s.substr(comma + 1))) return {};
        return "Value " + s + " is not mis, bsdf, light or s,t";
      },
      "STRATEGY");
}

// An integrator parameter on the command line: kept under its registry name when given.
struct ParamOption {
  CLI::Option* option;
  std::string name;
  std::string value;
};

}  // namespace

std::optional<int> parse_options(int argc, char** argv, Options& o) {
  CLI::App app{"gdrender: gradient-domain Monte Carlo renderer (Embree + OpenCL)", "gdrender"};
  app.set_version_flag("--version", std::string("gdrender ") + GDR_VERSION);
  app.add_option("scene", o.scene, "Scene to render (Mitsuba XML)")->check(CLI::ExistingFile);
  app.add_flag("--list-devices", o.list_devices, "List the OpenCL devices and exit");
  app.add_option("--info", o.info_scene, "Print a scene's size and the effects it calls for, then exit")
      ->check(CLI::ExistingFile);
  app.add_option("--reconstruct", o.reconstruct,
                 "Reconstruct a saved gradient-domain render (EXR with primal/dx/dy layers)")
      ->check(CLI::ExistingFile);
  app.add_option("--compare", o.compare,
                 "A.exr [B.exr ...] REFERENCE.exr: print relMSE, MSE, MAPE and the brightness ratio of the images "
                 "against the last one as JSON; several images (renders with different seeds) are averaged and their "
                 "relMSE split into bias2 and variance")
      ->expected(2, std::numeric_limits<int>::max())
      ->check(CLI::ExistingFile);
  app.add_option("--error-image", o.error_image, "With --compare: write a false-colour relMSE image (PNG) of the first image");
  app.add_option("-o,--output", o.output, "Output image (.exr; a tone-mapped .png is written beside it)");
  app.add_option("--integrator", o.integrator, "Integrator: " + integrator_names() +
                                                   " (default: the scene's integrator, else pt; see --list-integrators)")
      ->check(registered_integrator());
  app.add_flag("--list-integrators", o.list_integrators, "List the integrators and their parameters, and exit");
  app.add_option("--spp", o.spp, "Samples per pixel")->check(kFinitePositive);
  app.add_option("--time", o.time_budget, "Render for this many seconds")->check(kFinitePositive);
  app.add_option("--seed", o.seed, "Random seed");
  std::vector<std::string> defines;
  app.add_option("-D", defines, "Scene parameter: -D name=value (overrides <default name=...>)");
  app.add_option("--device", o.device,
                 "OpenCL device: index, cpu, gpu, or part of its name (default: $GDR_DEVICE, else first GPU, else CPU)");
  app.add_option("--kernels", o.kernels,
                 "Kernel builds: scene (only the BSDF, light and texture code the scene uses) or all (every type: "
                 "one build serves every scene; default: $GDR_KERNELS, else scene)")
      ->check(CLI::IsMember({"scene", "all"}));
  app.add_option("--stats", o.stats_path, "Write timers and counters to this JSON file");
  app.add_option("--threads", o.threads, "Host and CPU-device threads (default and maximum: the usable CPUs)")
      ->check(kFinitePositive);
  app.add_flag("--strict", o.strict, "Unsupported scene features are errors instead of warnings");
  app.add_option("--filter", o.filter, "Pixel filter: box | tent | gaussian (default: the scene's)")
      ->check(CLI::IsMember({"box", "tent", "gaussian"}));
  app.add_option("--max-depth", o.max_depth, "Maximum path length (default: the scene's, else 16)")
      ->check(CLI::Range(1, 1024));
  std::string resolution;
  app.add_option("--resolution", resolution,
                 "Film size WxH, or W with the height from the scene's aspect ratio (default: the scene's)")
      ->check(resolution_check());

  // Integrator parameters (the registry says which integrator reads which).
  std::list<ParamOption> params;  // CLI11 keeps references to the values: no reallocation
  auto param = [&](const std::string& flag, const std::string& name, const std::string& help) {
    params.push_back({nullptr, name, ""});
    params.back().option = app.add_option(flag, params.back().value, integrators_reading(name) + ": " + help)
                               ->group("Integrator parameters");
    return params.back().option;
  };
  param("--strategy", "strategy",
        "pt: mis (BSDF and light sampling) | bsdf (BSDF only) | light (light sampling only); bdpt: s,t (the "
        "strategy with s light and t camera vertices alone, unweighted)")
      ->check(strategy_check());
  param("--mis", "mis", "heuristic weighting the strategies: power (default) | balance")
      ->check(CLI::IsMember({"power", "balance"}));
  param("--radius", "radius",
        "initial merging radius over the radius of the scene's bounding sphere (default 1.5 / max(width, height))")
      ->check(kFinitePositive);
  param("--radius-alpha", "radius_alpha", "alpha of the radius schedule r_i = r_0 i^((alpha - 1) / 2), in (0, 1] (default 0.75)")
      ->check(kFinitePositive);
  params.push_back({nullptr, "aux", "true"});
  params.back().option = app.add_flag("--aux")
                             ->description(integrators_reading("aux") + ": also write albedo, normal and depth layers (first hit)")
                             ->group("Integrator parameters");
  param("--direct-samples", "direct_samples",
        "camera rays a pixel and pass, besides the base paths', that estimate the emission seen directly (the "
        "direct layer, which the gradients leave out): a primary ray each (default 8)")
      ->check(CLI::Range(0, 64));
  param("--batches", "batches",
        "batches of paths (gpt: groups) a chunk, stepped in turn so that the device shades one while Embree "
        "traces the other: 1 | 2 (default: 2; gpt: 2 on a GPU, 1 on a CPU device)")
      ->check(CLI::IsMember({"1", "2"}));
  param("--lanes", "lanes",
        "paths a work item of the camera-ray, routing, diffuse and plastic shading kernels: 8 (default on CPU "
        "devices, whose OpenCL compiler widens none of them across work items) | 1 (default on GPUs)")
      ->check(CLI::IsMember({"1", "8"}));
  param("--chains", "chains", "Markov chains run side by side (default: one a pixel, at most 32768)")->check(CLI::Range(1, 1 << 30));
  param("--bootstrap", "bootstrap", "bootstrap samples of the normalization and the chains' starts (default: four a chain, at least 65536)")
      ->check(CLI::Range(1, 1 << 30));
  param("--sigma", "sigma", "small step: standard deviation of each primary sample's perturbation, in (0, 1] (default 0.01)")
      ->check(kFinitePositive);
  param("--large-step", "large_step", "probability of a large step (a fresh uniform state), in [0, 1] (default 0.3)")
      ->check(kFiniteNonNegative);
  param("--mutations-per-pixel", "mutations_per_pixel", "the render's length in mutations a pixel (default: --spp)")
      ->check(CLI::Range(1, 1 << 30));
  param("--start-cap", "start_cap",
        "k > 0: the chains' start weights capped at the bootstrap's k-th largest target (fewer chains stuck on "
        "a lone bright sample, a start further from the stationary one; default 0: off)")
      ->check(CLI::Range(0, 1 << 30));
  param("--target-alpha", "target_alpha",
        "gmlt: weight of the primal against the gradients in the chains' target (default 0.2)")
      ->check(kFinitePositive);
  param("--shift", "shift",
        "shift mapping: hybrid (default; gmlt: manifold) | replay | manifold (hybrid, with manifold walks across specular chains "
        "between rough vertices; not gpm)")
      ->check(CLI::IsMember({"hybrid", "replay", "manifold"}));
  param("--manifold-iterations", "manifold_iterations", "Newton iterations per manifold walk (default 20; gpm's and gvcm's photon walks 5)")
      ->check(CLI::Range(1, 1000));
  param("--manifold-tolerance", "manifold_tolerance",
        "distance at which a manifold walk has converged, over the scene's bounding radius (default 1e-4)")
      ->check(kFinitePositive);
  param("--manifold-precision", "manifold_precision",
        "precision of the manifold solve: auto (default: double where the device has cl_khr_fp64) | float | double")
      ->check(CLI::IsMember({"auto", "float", "double"}));
  param("--shift-threshold", "shift_threshold",
        "roughness at or below which a vertex counts as glossy/specular (not reconnected; default 0.001)")
      ->check(kFiniteNonNegative);
  param("--primal", "primal",
        "the primal image: pairs (default: each pixel the mean of its four pairs' estimates, as G-PT's) | "
        "power (bdpt's estimate of the base paths alone under the power heuristic, as Manzi et al.'s)")
      ->check(CLI::IsMember({"pairs", "power"}));
  param("--recon", "recon",
        "Poisson reconstruction: weighted (default: L2 with each term weighted by the inverse of its "
        "per-pixel variance estimate) | l1 | l2 | none")
      ->check(CLI::IsMember({"l1", "l2", "weighted", "none"}));
  param("--recon-solver", "recon_solver",
        "Poisson solver, also for --reconstruct: fast (multigrid-preconditioned CG, direct DCT solve for L2; "
        "default) | cg (the published baseline: plain CG, 50 iterations per solve)")
      ->check(CLI::IsMember({"fast", "cg"}));
  param("--alpha", "alpha", "weight of the primal in the screened Poisson solve, also for --reconstruct (default 1 for weighted, 0.2 for "
        "l1 and l2)")
      ->check(kFinitePositive);
  app.footer("Integrators:\n" + describe_integrators());
  auto* verbose = app.add_flag("-v,--verbose", o.verbose, "More log output");
  app.add_flag("-q,--quiet", o.quiet, "Only warnings and errors")->excludes(verbose);

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  }
  for (const ParamOption& p : params) {
    if (p.option->count() > 0) o.integrator_params[p.name] = p.value;
  }
  for (const std::string& d : defines) {
    size_t eq = d.find('=');
    if (eq == std::string::npos || eq == 0) {
      std::cerr << "gdrender: -D expects name=value, got '" << d << "'\n";
      return 2;
    }
    o.defines[d.substr(0, eq)] = d.substr(eq + 1);
  }
  if (!resolution.empty()) parse_resolution(resolution, &o.width, &o.height);
  if (!o.list_devices && !o.list_integrators && o.info_scene.empty() && o.reconstruct.empty() && o.scene.empty() &&
      o.compare.empty()) {
    std::cerr << "gdrender: nothing to do: give a scene to render, --info SCENE, --reconstruct IN.exr, "
                 "--list-devices or --list-integrators (see --help)\n";
    return 2;
  }
  return std::nullopt;
}

}  // namespace gdr
