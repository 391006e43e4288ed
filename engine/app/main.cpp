// gdrender: the command-line front end. Parses options, configures the runtimes, runs a command.
#include <cstdio>
#include <exception>

#include "app/commands.h"
#include "app/options.h"
#include "device/runtime_env.h"
#include "util/interrupt.h"
#include "util/log.h"

int main(int argc, char** argv) {
  // Before any thread starts: Ctrl-C and SIGTERM are taken by one thread (util/interrupt.h).
  gdr::install_interrupt_handling();
  gdr::Options options;
  if (auto code = gdr::parse_options(argc, argv, options)) return *code;
  gdr::log::set_level(options.quiet ? gdr::log::Level::Quiet
                      : options.verbose ? gdr::log::Level::Verbose
                                        : gdr::log::Level::Info);
  try {
    gdr::configure_runtime(options.threads);
    return gdr::run_command(options);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "gdrender: error: %s\n", e.what());
    return 1;
  }
}
