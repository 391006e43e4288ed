// Runs an integrator's passes until the sample count or the time budget is reached, shows a
// progress line on a terminal, and stops early on the first Ctrl-C or SIGTERM (the pass in
// flight finishes, so the image rendered so far is written; util/interrupt.h: a second one ends
// the process at once).
#pragma once
#include <functional>

#include "render/render_settings.h"

namespace gdr {

// Calls pass(sample_index) for sample_index = 0, 1, ...; returns the number of passes done.
int run_progressive(const RenderSettings& settings, const std::function<void(int sample)>& pass);

// True once an interrupt asked the render to stop (the caller may say the render was cut short).
bool render_interrupted();

}  // namespace gdr
