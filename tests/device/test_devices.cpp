// The device layer: enumeration, selection, program builds, and a real kernel on every device.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <regex>
#include <string>

#include "device/context.h"
#include "device/devices.h"
#include "device/kernel_sources.h"
#include "support/devices.h"

namespace gdr {
namespace {

std::string find_embedded(const std::string& path) {
  for (const EmbeddedKernelFile& f : embedded_kernel_files()) {
    if (f.path == path) return f.text;
  }
  return {};
}

// The 1-based line of a text at which offset `at` lies.
size_t line_of(const std::string& text, size_t at) {
  return size_t(std::count(text.begin(), text.begin() + std::min(at, text.size()), '\n')) + 1;
}

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

// Compilers that ignore #line (NVIDIA's) name places by the line of the whole resolved text.
TEST(KernelSources, ResolvedLinesAreNamedByTheirFile) {
  const std::string text = resolve_kernel_source("util/rng_fill.cl");
  const std::string rng = find_embedded("core/rng.h");
  const std::string definition = "inline uint4 philox4x32_10(";
  ASSERT_NE(rng.find(definition), std::string::npos);
  const size_t resolved_line = line_of(text, text.find(definition));
  const size_t original_line = line_of(rng, rng.find(definition));
  const std::string log = "<kernel>:" + std::to_string(resolved_line) + ":1: error: x\n<kernel>:999999:2: note";
  EXPECT_EQ(name_resolved_lines(log, text),
            "kernels/core/rng.h:" + std::to_string(original_line) + ":1: error: x\n<kernel>:999999:2: note");
  EXPECT_EQ(name_resolved_lines("kernels/core/rng.h:3:1: error", text), "kernels/core/rng.h:3:1: error");
}

// NVIDIA's OpenCL compiler refuses variadic macros, which PoCL's accepts: none may creep in.
TEST(KernelSources, NoVariadicMacros) {
  const std::regex variadic(R"(#\s*define\s+\w+\([^)]*\.\.\.\s*\))");
  for (const EmbeddedKernelFile& f : embedded_kernel_files()) {
    EXPECT_FALSE(std::regex_search(f.text, variadic)) << "kernels/" << f.path << " defines a variadic macro";
  }
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
