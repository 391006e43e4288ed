// Persistent cache of built program binaries, keyed by device, driver, build options and the
// resolved source text. Folder: $GDR_KERNEL_CACHE_DIR, else $XDG_CACHE_HOME/gdrender/kernels,
// else ~/.cache/gdrender/kernels. GDR_KERNEL_CACHE=off disables it.
#pragma once
#include <CL/cl.h>

#include <string>
#include <vector>

#include "device/devices.h"

namespace gdr {

class KernelCache {
 public:
  KernelCache(const DeviceInfo& device, const std::string& options, const std::string& source);
  // The cached binary, or empty when there is none (or the cache is off).
  std::vector<unsigned char> load() const;
  // Stores the binary of a built program; failures to write are ignored (the cache is optional).
  void store(cl_program program) const;

 private:
  std::string path_;  // empty when the cache is off
};

}  // namespace gdr
