#include "util/interrupt.h"

#include <fcntl.h>
#include <pthread.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <csignal>
#include <cstdio>
#include <mutex>
#include <thread>
#include <vector>

namespace gdr {
namespace {

std::atomic<bool> g_deferred{false};
std::atomic<bool> g_requested{false};
std::mutex g_mutex;  // guards g_temporaries; held by the waiting thread while the process ends
std::vector<std::string> g_temporaries;

// Removes the registered temporaries and ends the process by `sig` (its default action).
[[noreturn]] void end_process(int sig) {
  std::lock_guard<std::mutex> lock(g_mutex);  // no temporary is created or renamed from now on
  for (const std::string& path : g_temporaries) ::unlink(path.c_str());
  std::fflush(stderr);
  std::signal(sig, SIG_DFL);
  sigset_t only;
  sigemptyset(&only);
  sigaddset(&only, sig);
  pthread_sigmask(SIG_UNBLOCK, &only, nullptr);
  std::raise(sig);
  _exit(128 + sig);
}

void wait_for_interrupts(sigset_t set) {
  for (;;) {
    int sig = 0;
    if (sigwait(&set, &sig) != 0) continue;
    if (!g_deferred || g_requested.exchange(true)) {
      std::fprintf(stderr, "\ngdrender: %s: stopping now\n", sig == SIGINT ? "interrupted" : "terminated");
      end_process(sig);
    }
    std::fprintf(stderr,
                 "\ngdrender: %s: finishing the pass in flight, then writing what was rendered "
                 "(interrupt again to stop at once)\n",
                 sig == SIGINT ? "interrupted" : "terminated");
    std::fflush(stderr);
  }
}

}  // namespace

void install_interrupt_handling() {
  static std::once_flag once;
  std::call_once(once, [] {
    sigset_t set;
    sigemptyset(&set);
    for (int sig : {SIGINT, SIGTERM}) {
      // A signal the parent ignores (a background job of a non-interactive shell) stays ignored.
      struct sigaction current {};
      if (sigaction(sig, nullptr, &current) == 0 && current.sa_handler == SIG_IGN) continue;
      sigaddset(&set, sig);
    }
    // Threads started later (TBB, PoCL, OIIO) inherit the mask: only the waiting thread takes them.
    pthread_sigmask(SIG_BLOCK, &set, nullptr);
    std::thread(wait_for_interrupts, set).detach();
  });
}

void defer_interrupts() { g_deferred = true; }

bool interrupt_requested() { return g_requested; }

void register_temporary(const std::string& path) {
  std::lock_guard<std::mutex> lock(g_mutex);
  g_temporaries.push_back(path);
}

int open_temporary(const std::string& path, int flags, int mode) {
  std::lock_guard<std::mutex> lock(g_mutex);
  int fd = ::open(path.c_str(), flags, mode);
  if (fd >= 0) g_temporaries.push_back(path);
  return fd;
}

std::error_code commit_temporary(const std::string& tmp, const std::string& target) {
  std::lock_guard<std::mutex> lock(g_mutex);
  std::error_code ec;
  if (::rename(tmp.c_str(), target.c_str()) != 0) ec = std::error_code(errno, std::generic_category());
  if (!ec) g_temporaries.erase(std::remove(g_temporaries.begin(), g_temporaries.end(), tmp), g_temporaries.end());
  return ec;
}

void discard_temporary(const std::string& tmp) {
  std::lock_guard<std::mutex> lock(g_mutex);
  ::unlink(tmp.c_str());
  g_temporaries.erase(std::remove(g_temporaries.begin(), g_temporaries.end(), tmp), g_temporaries.end());
}

}  // namespace gdr
