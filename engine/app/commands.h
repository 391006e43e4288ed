// The commands gdrender runs: list devices, describe a scene, render, reconstruct.
#pragma once
#include "app/options.h"

namespace gdr {

// Runs the command the options ask for; returns the process exit code. Throws gdr::Error
// (reported by main as one line) on failure.
int run_command(const Options& options);

int list_devices_command();

}  // namespace gdr
