// Everything the command line can set. Parsed by parse_options (CLI11); the commands read it.
#pragma once
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace gdr {

struct Options {
  // What to do (the first that is set wins, in this order).
  bool list_devices = false;
  bool list_integrators = false;
  std::string info_scene;   // --info SCENE
  std::string reconstruct;  // --reconstruct IN.exr
  std::vector<std::string> compare;  // --compare A.exr [B.exr ...] REFERENCE.exr
  std::string error_image;            // --error-image: false-colour relMSE PNG of --compare
  std::string scene;        // positional: render this scene

  std::string output;  // -o; default: <scene stem>.exr in the current folder
  std::string integrator;  // empty: the scene's, else "pt"
  std::optional<int> spp;
  std::optional<double> time_budget;  // --time SECONDS
  uint32_t seed = 0;
  std::map<std::string, std::string> defines;  // -D name=value: the scene's $name defaults
  std::string device;
  std::string kernels;  // --kernels scene|all; empty: $GDR_KERNELS, else scene
  std::string stats_path;
  int threads = 0;
  bool strict = false;
  std::string filter;  // overrides the scene's reconstruction filter
  int max_depth = -1;  // overrides the scene's integrator max_depth (-1: keep)
  int width = 0, height = 0;  // --resolution WxH or W (height from the film's aspect); 0: keep

  // Integrator parameters given on the command line (--strategy, --aux, --shift,
  // --shift-threshold, --recon, --recon-solver, --alpha), by their registry names (strategy,
  // aux, shift, shift_threshold, recon, recon_solver, alpha). Only those given are present.
  std::map<std::string, std::string> integrator_params;

  bool verbose = false;
  bool quiet = false;
};

// Parses argv. Returns an exit code to stop with (0 after --help/--version, 2 on bad usage;
// the message is already printed), or nothing to go on.
std::optional<int> parse_options(int argc, char** argv, Options& options);

}  // namespace gdr
