// Process-wide set-up of the runtimes that start thread pools or need folders, done once before
// any of them starts: PoCL (cache folder, worker threads), TBB (Embree's pool), OpenImageIO.
#pragma once
#include <string>

namespace gdr {

// `threads` <= 0 means: as many as the CPUs this process may use. Safe to call more than once;
// only the first call sets the environment.
void configure_runtime(int threads);

// The thread count configure_runtime settled on.
int runtime_threads();

// Why the OpenCL runtime may have failed to start, when the environment shows it: a
// POCL_CACHE_DIR that is not a folder this process can write (PoCL then offers no platform).
// Empty when nothing is wrong that way.
std::string opencl_environment_problem();

}  // namespace gdr
