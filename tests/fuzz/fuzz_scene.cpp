// libFuzzer target: the Mitsuba XML loader and the OBJ, PLY and .serialized mesh readers. Bad
// input must end in gdr::InputError; any other exception, a crash, a leak or an out-of-memory is a
// finding. Build and run with scripts/fuzz.
#include <cstddef>
#include <cstdint>

#include "fuzz/fuzz_input.h"
#include "util/error.h"
#include "util/log.h"

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  gdr::log::set_level(gdr::log::Level::Quiet);  // loader warnings would flood the fuzzer's output
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  try {
    gdr::fuzz::load_fuzz_input(data, size);
  } catch (const gdr::InputError&) {
  }
  return 0;
}
