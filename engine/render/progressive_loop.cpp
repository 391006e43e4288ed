#include "render/progressive_loop.h"

#include <unistd.h>

#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <algorithm>

namespace gdr {
namespace {

std::atomic<bool> g_interrupted{false};

void on_sigint(int) { g_interrupted = true; }

// Installs the SIGINT handler for its lifetime; a second Ctrl-C then ends the process as usual.
class SigintGuard {
 public:
  SigintGuard() { previous_ = std::signal(SIGINT, on_sigint); }
  ~SigintGuard() { std::signal(SIGINT, previous_); }

 private:
  void (*previous_)(int);
};

void print_progress(int done, int total, double elapsed, const std::optional<double>& budget) {
  double fraction = total > 0 ? double(done) / total : 0.0;
  if (budget) fraction = std::max(fraction, std::min(1.0, elapsed / *budget));
  double eta = fraction > 0 ? elapsed / fraction - elapsed : 0;
  std::fprintf(stderr, "\r%5.1f%%  %d spp  %.1f spp/s  elapsed %.1f s  ETA %.1f s   ", 100 * fraction, done,
               elapsed > 0 ? done / elapsed : 0.0, elapsed, eta);
  std::fflush(stderr);
}

}  // namespace

bool render_interrupted() { return g_interrupted; }

int run_progressive(const RenderSettings& settings, const std::function<void(int)>& pass) {
  g_interrupted = false;
  SigintGuard guard;
  bool show = settings.progress && isatty(STDERR_FILENO);
  auto start = std::chrono::steady_clock::now();
  int total = settings.spp;
  int done = 0;
  for (;;) {
    if (total > 0 && done >= total) break;
    if (g_interrupted) break;
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
