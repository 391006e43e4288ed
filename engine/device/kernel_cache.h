// Persistent cache of built program binaries, keyed by device, driver, build options and the
// resolved source text. Folder: $GDR_KERNEL_CACHE_DIR, else $XDG_CACHE_HOME/gdrender/kernels,
// else ~/.cache/gdrender/kernels. GDR_KERNEL_CACHE=off disables it; on PoCL, which caches its own
// builds, it is used only with GDR_KERNEL_CACHE=on. Each entry carries its size and a checksum: a
// truncated or corrupt entry is removed and the program rebuilt.
#pragma once
#include <CL/cl.h>

#include <string>
#include <vector>

#include "device/devices.h"

namespace gdr {

class KernelCache {
 public:
  KernelCache(const DeviceInfo& device, const std::string& options, const std::string& source);
  // The cached binary, or empty when there is none, the cache is off, or the entry fails its size
  // or checksum check (the entry is then removed).
  std::vector<unsigned char> load() const;
  // Stores the binary of a built program; failures to write are ignored (the cache is optional).
  void store(cl_program program) const;
  // Stores `binary` as the entry (what store() does once it has the program's binary).
  void store_binary(const std::vector<unsigned char>& binary) const;
  // The entry's file; empty when the cache is off.
  const std::string& path() const { return path_; }

 private:
  std::string path_;  // empty when the cache is off
};

}  // namespace gdr
