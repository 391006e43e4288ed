// gdrender: the command-line front end. Parses options, configures the runtimes, runs a command.
#include <cstdio>
#include <exception>
#include <optional>

#include "app/commands.h"
#include "app/options.h"
#include "cluster/ranks.h"
#include "device/runtime_env.h"
#include "util/interrupt.h"
#include "util/log.h"

int main(int argc, char** argv) {
  // Before any thread starts: Ctrl-C and SIGTERM are taken by one thread (util/interrupt.h).
  gdr::install_interrupt_handling();
  // After the signal mask is set, so that MPI's own threads inherit it; finalized on return.
  std::optional<gdr::cluster::Session> mpi;
  try {
    mpi.emplace(argc, argv);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "gdrender: error: %s\n", e.what());
    return 1;
  }
  // Rank 0 speaks for the job; the others' lines would repeat its own.
  if (!gdr::cluster::root()) gdr::log::set_muted(true);
  gdr::Options options;
  std::optional<int> code = gdr::parse_options(argc, argv, options);
  // A rank whose command line ends it (refused, or --help) must not leave the others waiting.
  if (gdr::cluster::stopped_early(code.has_value(),
                                  code && *code != 0 ? "its command line was refused (its message is above)" : "")) {
    return code ? *code : 1;
  }
  if (code) return *code;
  gdr::log::set_level(options.quiet ? gdr::log::Level::Quiet
                      : options.verbose ? gdr::log::Level::Verbose
                                        : gdr::log::Level::Info);
  try {
    // Ranks sharing a node share its cores.
    gdr::configure_runtime(options.threads > 0 ? options.threads : gdr::cluster::cpu_share());
    return gdr::run_command(options);
  } catch (const gdr::cluster::JobFailed&) {
    return 1;  // rank 0 has named the failing ranks and their reasons
  } catch (const std::exception& e) {
    // The other ranks may be waiting for this one: the job ends here.
    if (gdr::cluster::distributed()) gdr::cluster::abort_job(e.what());
    std::fprintf(stderr, "gdrender: error: %s\n", e.what());
    return 1;
  }
}
