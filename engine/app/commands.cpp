#include "app/commands.h"

#include <cstdio>

#include "device/devices.h"
#include "util/error.h"

namespace gdr {

int list_devices_command() {
  std::vector<DeviceInfo> devices = list_devices();
  if (devices.empty()) throw Error("no OpenCL device found (is an ICD such as pocl-opencl-icd installed?)");
  std::fputs(format_device_list(devices).c_str(), stdout);
  return 0;
}

int run_command(const Options& options) {
  if (options.list_devices) return list_devices_command();
  throw Error("this command is not available in this build");
}

}  // namespace gdr
