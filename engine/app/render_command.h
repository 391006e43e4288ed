// `gdrender SCENE.xml ...`: load, render with the chosen integrator, write EXR + PNG and stats.
#pragma once
#include "app/options.h"

namespace gdr {
int render_command(const Options& options);
}
