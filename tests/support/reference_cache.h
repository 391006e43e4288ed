// Long reference renders shared by the suite's processes. ctest runs every test in a process of
// its own, so a reference that several tests compare with (the consistency tests' 4096-spp path
// tracing, 15 to 23 s on two cores) would be rendered again by each. An entry is kept beside the
// test binary under a key that names the binary's bytes (the engine and its embedded kernels), the
// project's scenes folder, the OpenCL device and what the caller says it renders; a lock keeps two
// processes from rendering the same entry at once.
#pragma once
#include <functional>
#include <string>
#include <vector>

namespace gdr {
class Context;
}

namespace gdr::test {

// The values `render` returns for `key` on `context`'s device: read from the cache, or rendered and
// stored there.
std::vector<float> cached_render(const Context& context, const std::string& key,
                                 const std::function<std::vector<float>()>& render);

}  // namespace gdr::test
