// Replays every input in tests/fuzz/regressions/ (inputs that once crashed the scene loader under
// the fuzzer) with the normal build: each must load or fail with gdr::InputError.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <vector>

#include "fuzz/fuzz_input.h"
#include "util/error.h"

namespace gdr {
namespace {

TEST(FuzzRegressions, EveryInputLoadsOrIsAnInputError) {
  std::filesystem::path dir = std::filesystem::path(GDR_SOURCE_DIR) / "tests" / "fuzz" / "regressions";
  int inputs = 0;
  for (const auto& e : std::filesystem::directory_iterator(dir)) {
    if (!e.is_regular_file() || e.path().filename().string()[0] == '.') continue;
    std::ifstream in(e.path(), std::ios::binary);
    std::vector<uint8_t> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    ++inputs;
    try {
      fuzz::load_fuzz_input(bytes.data(), bytes.size());
    } catch (const InputError&) {
    } catch (const std::exception& ex) {
      ADD_FAILURE() << e.path() << ": not an InputError: " << ex.what();
    }
  }
  EXPECT_GT(inputs, 0) << "no regression inputs in " << dir;
}

// The seeds whose headers claim huge sizes reach the size checks: each is refused with a message
// naming what it claims, not allocated (and not accepted).
TEST(FuzzRegressions, SizeClaimingSeedsAreRefusedByTheSizeChecks) {
  std::filesystem::path dir = std::filesystem::path(GDR_SOURCE_DIR) / "tests" / "fuzz" / "corpus";
  int seeds = 0;
  for (const auto& e : std::filesystem::directory_iterator(dir)) {
    std::string name = e.path().filename().string();
    if (name.find("huge") == std::string::npos) continue;
    std::ifstream in(e.path(), std::ios::binary);
    std::vector<uint8_t> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    ++seeds;
    try {
      fuzz::load_fuzz_input(bytes.data(), bytes.size());
      ADD_FAILURE() << name << " loaded";
    } catch (const InputError& ex) {
      EXPECT_NE(std::string(ex.what()).find("claims"), std::string::npos) << name << ": " << ex.what();
    }
  }
  EXPECT_GE(seeds, 5) << "size-claiming seeds missing from " << dir;
}

}  // namespace
}  // namespace gdr
