// Where the project's own scenes are: scenes/ of the source tree.
#pragma once
#include <string>

namespace gdr::test {

inline std::string source_scene(const std::string& name) { return std::string(GDR_SOURCE_DIR) + "/scenes/" + name; }

}  // namespace gdr::test
