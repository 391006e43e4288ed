// The device layer: enumeration, selection, program builds, and a real kernel on every device.
#include <gtest/gtest.h>

#include <cmath>

#include "device/context.h"
#include "device/devices.h"
#include "device/kernel_sources.h"
#include "support/devices.h"

namespace gdr {
namespace {

TEST(Devices, AtLeastOneOpenClDeviceExists) {
  std::vector<DeviceInfo> devices = list_devices();
  ASSERT_FALSE(devices.empty()) << "no OpenCL device: install pocl-opencl-icd";
  for (size_t i = 0; i < devices.size(); ++i) {
    EXPECT_EQ(devices[i].index, static_cast<int>(i));
    EXPECT_FALSE(devices[i].name.empty());
    EXPECT_GT(devices[i].compute_units, 0u);
  }
}

TEST(Devices, SelectorsFindDevices) {
  std::vector<DeviceInfo> devices = list_devices();
  ASSERT_FALSE(devices.empty());
  EXPECT_EQ(select_device("0").device, devices[0].device);
  EXPECT_EQ(select_device(devices[0].type).type, devices[0].type);
  // Case-insensitive substring of the platform name.
  std::string part = devices[0].platform_name.substr(0, 4);
  for (char& c : part) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  EXPECT_EQ(select_device(part).platform, devices[0].platform);
}

TEST(Devices, UnknownSelectorListsDevices) {
  try {
    select_device("no-such-device-anywhere");
    FAIL() << "selection should have failed";
  } catch (const DeviceError& e) {
    std::string msg = e.what();
    EXPECT_NE(msg.find("no-such-device-anywhere"), std::string::npos);
    EXPECT_NE(msg.find(list_devices()[0].name), std::string::npos) << msg;
  }
  EXPECT_THROW(select_device("999"), DeviceError);
}

TEST(KernelSources, IncludesAreInlinedWithLineMarkers) {
  std::string text = resolve_kernel_source("util/rng_fill.cl");
  EXPECT_NE(text.find("philox4x32_10"), std::string::npos);
  EXPECT_NE(text.find("#line 1 \"kernels/core/rng.h\""), std::string::npos);
  EXPECT_THROW(resolve_kernel_source("no/such/file.cl"), Error);
}

TEST(KernelBuild, CompileErrorNamesFileAndLine) {
  Context& ctx = test::default_context();
  // A define the kernel does not expect turns into a syntax error inside kernels/core/rng.h.
  try {
    ctx.program("util/rng_fill.cl", {{"inline", "@"}});
    FAIL() << "build should have failed";
  } catch (const DeviceError& e) {
    std::string msg = e.what();
    EXPECT_NE(msg.find("kernels/util/rng_fill.cl"), std::string::npos) << msg;
    EXPECT_NE(msg.find("kernels/core/rng.h:"), std::string::npos) << msg;
  }
}

// Runs the RNG kernel on every device: proves kernels execute (the buffer starts at -1, which
// the RNG never produces) and that all devices give the same numbers for the same key.
TEST(KernelRun, RngKernelRunsOnEveryDeviceAndAgrees) {
  std::vector<DeviceInfo> devices = list_devices();
  ASSERT_FALSE(devices.empty());
  const unsigned count = 1000, dims = 7;
  std::vector<float> first;
  for (const DeviceInfo& info : devices) {
    SCOPED_TRACE(info.name);
    Stats stats;
    Context ctx(info, &stats);
    Kernel k = ctx.program("util/rng_fill.cl")->kernel("rng_fill");
    Buffer<float> out(ctx, count);
    out.fill(-1.0f);
    k.args(out, count, 1234u, 42u, dims).run(count);
    std::vector<float> values = out.read();
    for (float v : values) {
      ASSERT_GE(v, 0.0f);
      ASSERT_LT(v, 1.0f);
    }
    EXPECT_EQ(stats.count("kernel_items/rng_fill"), count);
    if (first.empty()) {
      first = values;
    } else {
      EXPECT_EQ(values, first);
    }
  }
}

}  // namespace
}  // namespace gdr
