// Test entry point: configures the runtimes (PoCL cache folder, thread caps) like gdrender does.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>

#include "device/runtime_env.h"

namespace {

// GDR_TEST_THREADS caps the host and CPU-device threads (default: every usable CPU). ctest sets it
// to 1 (suites.cmake), as it runs one suite a core side by side.
int test_threads() {
  const char* v = std::getenv("GDR_TEST_THREADS");
  if (!v) return 0;
  char* end = nullptr;
  long n = std::strtol(v, &end, 10);
  if (end == v || *end != '\0' || n < 1 || n > 4096) {
    std::fprintf(stderr, "GDR_TEST_THREADS=%s: expected a positive thread count\n", v);
    std::exit(2);
  }
  return static_cast<int>(n);
}

}  // namespace

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  // The suite renders dozens of scenes with each integrator: kernels built with every BSDF, light
  // and texture type serve them all from one build of each program (and the gdrender processes
  // the tests start inherit it). With an empty PoCL cache, as in CI, ctest took 632 s
  // instead of 909 to 995 s. Scene builds are what tests SceneKernels and MaterialQueues check;
  // GDR_KERNELS=scene runs every test on them.
  setenv("GDR_KERNELS", "all", 0);
  gdr::configure_runtime(test_threads());
  return RUN_ALL_TESTS();
}
