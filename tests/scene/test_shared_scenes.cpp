// Every Mitsuba scene under ../shared/scenes (real scenes written elsewhere) either loads or is
// rejected with an InputError naming the file; none crashes. Skipped where the folder is absent.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "scene/describe_scene.h"
#include "scene/load_scene.h"
#include "util/error.h"

namespace fs = std::filesystem;

namespace gdr {
namespace {

std::string shared_scenes() { return std::string(GDR_SOURCE_DIR) + "/../shared/scenes"; }

#define REQUIRE_SHARED()                                                                   \
  if (!fs::is_directory(shared_scenes())) GTEST_SKIP() << "no shared scenes at " << shared_scenes()

TEST(SharedScenes, EveryXmlLoadsOrFailsCleanly) {
  REQUIRE_SHARED();
  int loaded = 0, rejected = 0;
  for (const auto& entry : fs::recursive_directory_iterator(shared_scenes())) {
    if (entry.path().extension() != ".xml") continue;
    std::string path = entry.path().string();
    try {
      Scene s = load_scene(path);
      ++loaded;
      std::printf("LOADED %s: %zu triangles, %zu lights, %zu warnings\n", path.c_str(), s.triangles.size(),
                  s.lights.size(), s.warnings.size());
      for (const auto& w : s.warnings) std::printf("   warning: %s\n", w.c_str());
    } catch (const InputError& e) {
      ++rejected;
      std::printf("REJECTED %s: %s\n", path.c_str(), e.what());
      EXPECT_NE(std::string(e.what()).find(".xml"), std::string::npos) << e.what();
    }
  }
  EXPECT_GT(loaded, 0);
  std::printf("%d loaded, %d rejected\n", loaded, rejected);
}

}  // namespace
}  // namespace gdr
