// Loads a Mitsuba XML scene (the 0.5/0.6 camelCase dialect and the 2/3 snake_case one) into a
// gdr::Scene. What the renderer cannot reproduce is listed in Scene::warnings (each naming the
// element, file and line and what was done instead); with `strict` it is an error instead.
#pragma once
#include <map>
#include <string>

#include "scene/scene.h"

namespace gdr {

struct LoadOptions {
  std::map<std::string, std::string> defines;  // override the scene's <default> values
  bool strict = false;                         // unsupported features are errors, not warnings
  float glossy_threshold = GDR_GLOSSY_THRESHOLD;  // alpha below which a rough surface is near-delta
  // Film size replacing the scene's (0: keep); a height of 0 with a width keeps the film's
  // aspect ratio. Applied where the film is read, so the field of view follows as if the file
  // said it.
  int width = 0, height = 0;
};

// Throws gdr::InputError (file, line, problem) for malformed XML, missing files, bad values,
// unknown references or names, and invalid meshes; nothing partial is returned.
Scene load_scene(const std::string& path, const LoadOptions& options = {});

}  // namespace gdr
