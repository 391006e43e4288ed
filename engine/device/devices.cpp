#include "device/devices.h"

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <sstream>

#include "device/cl.h"
#include "device/runtime_env.h"

namespace gdr {
namespace {

std::string device_string(cl_device_id d, cl_device_info what) {
  size_t size = 0;
  if (clGetDeviceInfo(d, what, 0, nullptr, &size) != CL_SUCCESS || size == 0) return {};
  std::string s(size, '\0');
  clGetDeviceInfo(d, what, size, s.data(), nullptr);
  s.resize(s.find('\0') == std::string::npos ? s.size() : s.find('\0'));
  return s;
}

std::string platform_string(cl_platform_id p, cl_platform_info what) {
  size_t size = 0;
  if (clGetPlatformInfo(p, what, 0, nullptr, &size) != CL_SUCCESS || size == 0) return {};
  std::string s(size, '\0');
  clGetPlatformInfo(p, what, size, s.data(), nullptr);
  s.resize(s.find('\0') == std::string::npos ? s.size() : s.find('\0'));
  return s;
}

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
  return s;
}

bool is_index(const std::string& s) {
  return !s.empty() && std::all_of(s.begin(), s.end(), [](unsigned char c) { return std::isdigit(c); });
}

DeviceError no_match(const std::string& why, const std::vector<DeviceInfo>& devices) {
  std::string msg = why;
  if (devices.empty()) {
    msg += "; no OpenCL device exists (is an ICD such as pocl-opencl-icd installed?)";
  } else {
    msg += "; devices:\n" + format_device_list(devices);
    if (msg.back() == '\n') msg.pop_back();
  }
  return DeviceError(msg);
}

}  // namespace

bool is_pocl(const DeviceInfo& device) {
  return device.platform_name.find("Portable Computing Language") != std::string::npos;
}

std::vector<DeviceInfo> list_devices() {
  std::vector<DeviceInfo> out;
  cl_uint nplatforms = 0;
  // With no ICD installed the loader reports CL_PLATFORM_NOT_FOUND_KHR: that is "no devices".
  if (clGetPlatformIDs(0, nullptr, &nplatforms) != CL_SUCCESS || nplatforms == 0) return out;
  std::vector<cl_platform_id> platforms(nplatforms);
  cl_check(clGetPlatformIDs(nplatforms, platforms.data(), nullptr), "clGetPlatformIDs");
  for (cl_platform_id p : platforms) {
    cl_uint ndevices = 0;
    if (clGetDeviceIDs(p, CL_DEVICE_TYPE_ALL, 0, nullptr, &ndevices) != CL_SUCCESS) continue;
    std::vector<cl_device_id> devices(ndevices);
    clGetDeviceIDs(p, CL_DEVICE_TYPE_ALL, ndevices, devices.data(), nullptr);
    for (cl_device_id d : devices) {
      DeviceInfo info;
      info.index = static_cast<int>(out.size());
      info.platform = p;
      info.device = d;
      info.platform_name = platform_string(p, CL_PLATFORM_NAME);
      info.name = device_string(d, CL_DEVICE_NAME);
      info.driver_version = device_string(d, CL_DRIVER_VERSION);
      info.opencl_c_version = device_string(d, CL_DEVICE_OPENCL_C_VERSION);
      cl_device_type type = 0;
      clGetDeviceInfo(d, CL_DEVICE_TYPE, sizeof(type), &type, nullptr);
      info.type = (type & CL_DEVICE_TYPE_GPU)           ? "gpu"
                  : (type & CL_DEVICE_TYPE_CPU)         ? "cpu"
                  : (type & CL_DEVICE_TYPE_ACCELERATOR) ? "accelerator"
                                                        : "other";
      clGetDeviceInfo(d, CL_DEVICE_MAX_COMPUTE_UNITS, sizeof(info.compute_units), &info.compute_units, nullptr);
      clGetDeviceInfo(d, CL_DEVICE_GLOBAL_MEM_SIZE, sizeof(info.global_memory), &info.global_memory, nullptr);
      clGetDeviceInfo(d, CL_DEVICE_MAX_MEM_ALLOC_SIZE, sizeof(info.max_alloc), &info.max_alloc, nullptr);
      info.fp64 = (" " + device_string(d, CL_DEVICE_EXTENSIONS) + " ").find(" cl_khr_fp64 ") != std::string::npos;
      cl_bool unified = CL_FALSE;
      clGetDeviceInfo(d, CL_DEVICE_HOST_UNIFIED_MEMORY, sizeof(unified), &unified, nullptr);
      info.host_unified = unified == CL_TRUE;
      out.push_back(info);
    }
  }
  return out;
}

std::string format_device_list(const std::vector<DeviceInfo>& devices) {
  std::ostringstream s;
  for (const DeviceInfo& d : devices) {
    s << "  [" << d.index << "] " << d.platform_name << " | " << d.name << " | " << d.type << " | "
      << d.compute_units << " compute units | " << d.opencl_c_version << (d.fp64 ? " | fp64" : "") << " | "
      << (d.global_memory >> 20) << " MiB\n";
  }
  return s.str();
}

DeviceInfo select_device(const std::string& selector_in, int nth) {
  std::string selector = selector_in;
  if (selector.empty()) {
    if (const char* env = std::getenv("GDR_DEVICE")) selector = env;
  }
  std::vector<DeviceInfo> devices = list_devices();
  if (devices.empty()) {
    std::string problem = opencl_environment_problem();
    if (!problem.empty()) throw DeviceError("no OpenCL platform started: " + problem);
    throw no_match("no OpenCL platform found", devices);
  }

  if (selector.empty()) {
    for (const char* kind : {"gpu", "cpu"}) {
      std::vector<const DeviceInfo*> of_kind;
      for (const DeviceInfo& d : devices) {
        if (d.type == kind) of_kind.push_back(&d);
      }
      if (!of_kind.empty()) return *of_kind[size_t(std::max(nth, 0)) % of_kind.size()];
    }
    return devices.front();
  }
  if (is_index(selector)) {
    size_t i = std::stoul(selector);
    if (i < devices.size()) return devices[i];
    throw no_match("device index " + selector + " is out of range", devices);
  }
  std::string want = lower(selector);
  if (want == "cpu" || want == "gpu" || want == "accelerator") {
    for (const DeviceInfo& d : devices) {
      if (d.type == want) return d;
    }
    throw no_match("no " + want + " device", devices);
  }
  for (const DeviceInfo& d : devices) {
    if (lower(d.name).find(want) != std::string::npos ||
        lower(d.platform_name).find(want) != std::string::npos) {
      return d;
    }
  }
  throw no_match("no OpenCL device matches '" + selector + "'", devices);
}

}  // namespace gdr
