// Enumerating OpenCL platforms and devices, and choosing one from a user's selector.
#pragma once
#include <CL/cl.h>

#include <string>
#include <vector>

namespace gdr {

struct DeviceInfo {
  int index = 0;  // position in list_devices(), as --list-devices prints it
  cl_platform_id platform = nullptr;
  cl_device_id device = nullptr;
  std::string platform_name;
  std::string name;
  std::string type;  // "cpu", "gpu", "accelerator" or "other"
  std::string driver_version;
  std::string opencl_c_version;
  cl_uint compute_units = 0;
  cl_ulong global_memory = 0;
  cl_ulong max_alloc = 0;  // CL_DEVICE_MAX_MEM_ALLOC_SIZE: the largest single buffer
  bool fp64 = false;       // cl_khr_fp64: double-precision kernels
  bool host_unified = false;  // CL_DEVICE_HOST_UNIFIED_MEMORY: the device works in the host's memory
};

// Whether the device is PoCL's (which caches its own builds and runs on the host's cores).
bool is_pocl(const DeviceInfo& device);

// All devices of all platforms; an empty list when there is no OpenCL platform at all.
std::vector<DeviceInfo> list_devices();

// One line per device: index, platform, name, type, compute units, OpenCL C, memory.
std::string format_device_list(const std::vector<DeviceInfo>& devices);

// Selector: empty (then env GDR_DEVICE, then the first GPU, then the first CPU), an index,
// "cpu"/"gpu", or a case-insensitive substring of the device or platform name.
// Throws DeviceError listing the devices that exist when nothing matches. `nth`: without a
// selector, the nth process on a node takes the nth GPU (cycling), else the nth CPU device, so
// that processes sharing a node spread over its devices.
DeviceInfo select_device(const std::string& selector, int nth = 0);

}  // namespace gdr
