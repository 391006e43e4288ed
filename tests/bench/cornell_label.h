// The label of a benchmark over the Cornell box at 256x256: what it counts, and the device.
#pragma once
#include <benchmark/benchmark.h>

#include <string>

#include "support/devices.h"

namespace gdr::bench {

inline void cornell_label(benchmark::State& state, const std::string& what) {
  state.SetLabel(what + ", cornell-box 256x256 on " + test::default_context().device().name);
}

}  // namespace gdr::bench
