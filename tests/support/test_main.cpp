// Test entry point: configures the runtimes (PoCL cache folder, thread caps) like gdrender does.
#include <gtest/gtest.h>

#include "device/runtime_env.h"

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  gdr::configure_runtime(0);
  return RUN_ALL_TESTS();
}
