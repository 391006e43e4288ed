#include "render/progressive_loop.h"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>

#include "util/interrupt.h"
#include "util/log.h"

namespace gdr {
namespace {

void print_progress(int done, int total, double elapsed, const std::optional<double>& budget) {
  double fraction = total > 0 ? double(done) / total : 0.0;
  if (budget) fraction = std::max(fraction, std::min(1.0, elapsed / *budget));
  double eta = fraction > 0 ? elapsed / fraction - elapsed : 0;
  std::fprintf(stderr, "\r%5.1f%%  %d spp  %.1f spp/s  elapsed %.1f s  ETA %.1f s   ", 100 * fraction, done,
               elapsed > 0 ? done / elapsed : 0.0, elapsed, eta);
  std::fflush(stderr);
}

}  // namespace

bool render_interrupted() { return interrupt_requested(); }

int run_progressive(const RenderSettings& settings, const std::function<void(int)>& pass) {
  // From here on there is a render to save: the first interrupt asks the loop to stop.
  defer_interrupts();
  log::verbose("rendering: Ctrl-C or SIGTERM stops after the pass in flight and writes the image; a second one stops at once");
  bool show = settings.progress && isatty(STDERR_FILENO);
  auto start = std::chrono::steady_clock::now();
  int total = settings.spp;
  int done = 0;
  for (;;) {
    if (total > 0 && done >= total) break;
    if (interrupt_requested()) break;
    pass(done);
    ++done;
    double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (show) print_progress(done, total, elapsed, settings.time_budget);
    if (settings.time_budget && elapsed >= *settings.time_budget) break;
  }
  if (show) std::fputc('\n', stderr);
  return done;
}

}  // namespace gdr
