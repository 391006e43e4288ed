// Helpers for tests that run kernels: the devices to run on, and a shared context.
#pragma once

#include <memory>
#include <vector>

#include "device/context.h"
#include "device/devices.h"

namespace gdr::test {

// Every OpenCL device present. Tests that run kernels fail (not skip) when there is none:
// a suite in which no kernel executed proves nothing.
inline std::vector<DeviceInfo> all_devices() { return list_devices(); }

// A context on the device tests use by default ($GDR_DEVICE, else the first GPU, else CPU),
// shared by all tests of the process so kernels are built once.
inline Context& default_context() {
  static std::unique_ptr<Context> context = std::make_unique<Context>(select_device(""));
  return *context;
}

}  // namespace gdr::test
