// Runs an integrator's passes until the sample count or the time budget is reached, shows a
// progress line on a terminal, and stops early on the first Ctrl-C or SIGTERM (the pass in
// flight finishes, so the image rendered so far is written; util/interrupt.h: a second one ends
// the process at once).
//
// Under MPI each rank traces its share of the passes (render/pass_schedule.h), one round of N
// passes at a time; between rounds the ranks agree whether to go on: rank 0 decides from its
// elapsed time against the budget, and an interrupt on any rank stops all of them after the
// pass in flight. The count returned is the whole job's.
#pragma once
#include <functional>

#include "render/render_settings.h"

namespace gdr {

// Calls pass(sample_index) for the sample indices this process traces (0, 1, ... alone); returns
// the number of passes all ranks did together.
int run_progressive(const RenderSettings& settings, const std::function<void(int sample)>& pass);

// True once an interrupt asked the render to stop (the caller may say the render was cut short).
bool render_interrupted();

// What this process's last run_progressive did: its own passes, the seconds it spent in them,
// the seconds it waited for the other ranks at the end, and the loop's whole time (agreements
// between rounds included).
struct LoopTimes {
  int passes = 0;
  double pass_seconds = 0, wait_seconds = 0, seconds = 0;
};
LoopTimes last_loop_times();

}  // namespace gdr
