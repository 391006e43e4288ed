// libFuzzer target: the Mitsuba XML loader, the OBJ, PLY and .serialized mesh readers and the
// texture reader. Bad
// input must end in gdr::InputError; any other exception, a crash, a leak or an out-of-memory is a
// finding. Build and run with scripts/fuzz.
#include <cstddef>
#include <cstdint>
#include <cstdlib>

#include "fuzz/fuzz_input.h"
#include "util/error.h"
#include "util/log.h"

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  gdr::log::set_level(gdr::log::Level::Quiet);  // loader warnings would flood the fuzzer's output
  // Well under the fuzzer's -rss_limit_mb: a header that claims more than this must be refused,
  // not allocated.
  setenv("GDR_MAX_INPUT_BYTES", "256M", 0);
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  try {
    gdr::fuzz::load_fuzz_input(data, size);
  } catch (const gdr::InputError&) {
  }
  return 0;
}
