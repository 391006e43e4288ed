#include "render/progressive_loop.h"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>

#include "cluster/ranks.h"
#include "render/pass_schedule.h"
#include "util/interrupt.h"
#include "util/log.h"

namespace gdr {
namespace {

LoopTimes g_last;

double since(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

void print_progress(int done, int total, double elapsed, const std::optional<double>& budget) {
  double fraction = total > 0 ? double(done) / total : 0.0;
  if (budget) fraction = std::max(fraction, std::min(1.0, elapsed / *budget));
  double eta = fraction > 0 ? elapsed / fraction - elapsed : 0;
  std::fprintf(stderr, "\r%5.1f%%  %d spp  %.1f spp/s  elapsed %.1f s  ETA %.1f s   ", 100 * fraction, done,
               elapsed > 0 ? done / elapsed : 0.0, elapsed, eta);
  std::fflush(stderr);
}

}  // namespace

PassSchedule PassSchedule::of_this_process() { return PassSchedule{cluster::rank(), cluster::size()}; }

bool render_interrupted() { return interrupt_requested(); }

LoopTimes last_loop_times() { return g_last; }

int run_progressive(const RenderSettings& settings, const std::function<void(int)>& pass) {
  // From here on there is a render to save: the first interrupt asks the loop to stop.
  defer_interrupts();
  log::verbose("rendering: Ctrl-C or SIGTERM stops after the pass in flight and writes the image; a second one stops at once");
  const PassSchedule schedule = PassSchedule::of_this_process();
  const bool show = settings.progress && cluster::root() && isatty(STDERR_FILENO);
  const auto start = std::chrono::steady_clock::now();
  const int total = settings.spp;
  g_last = LoopTimes{};
  int done = 0;  // passes of all ranks
  for (;;) {
    if (total > 0 && done >= total) break;
    // The time budget is rank 0's to judge, so that all ranks stop after the same round.
    bool over = settings.time_budget && cluster::root() && since(start) >= *settings.time_budget;
    if (cluster::any(over || interrupt_requested())) break;
    const int sample = done + schedule.rank;
    if (total <= 0 || sample < total) {
      const auto t = std::chrono::steady_clock::now();
      pass(sample);
      g_last.pass_seconds += since(t);
      ++g_last.passes;
    }
    done = total > 0 ? std::min(total, done + schedule.ranks) : done + schedule.ranks;
    if (show) print_progress(done, total, since(start), settings.time_budget);
  }
  if (show) std::fputc('\n', stderr);
  // The reductions that follow then time the transfer alone, not a slower rank's last pass.
  const auto t = std::chrono::steady_clock::now();
  cluster::barrier();
  g_last.wait_seconds = since(t);
  g_last.seconds = since(start);
  return done;
}

}  // namespace gdr
