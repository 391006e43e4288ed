// Test entry point: configures the runtimes (PoCL cache folder, thread caps) like gdrender does.
#include <gtest/gtest.h>

#include <cstdlib>

#include "device/runtime_env.h"

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  // The suite renders dozens of scenes with each integrator: kernels built with every BSDF, light
  // and texture type serve them all from one build of each program (and the gdrender processes
  // the tests start inherit it). With an empty PoCL cache, as in CI, ctest took 632 s
  // instead of 909 to 995 s. Scene builds are what tests SceneKernels and MaterialQueues check;
  // GDR_KERNELS=scene runs every test on them.
  setenv("GDR_KERNELS", "all", 0);
  gdr::configure_runtime(0);
  return RUN_ALL_TESTS();
}
