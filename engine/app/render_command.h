// `gdrender SCENE.xml ...`: load, render with the chosen integrator, write EXR + PNG and stats.
#pragma once
#include "app/options.h"
#include "scene/load_scene.h"

namespace gdr {

int render_command(const Options& options);

// How the command line asks scenes to be loaded (defines, --strict, the glossy threshold).
LoadOptions load_options(const Options& options);

}  // namespace gdr
