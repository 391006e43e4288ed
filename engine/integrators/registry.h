// Every integrator by name: what it is, whether it writes gradients, which parameters it reads,
// which Mitsuba <integrator type="..."> values stand for it, and how to build it. The command
// line, --list-integrators, --help and scene files all go through this list; adding an
// integrator is its own folders plus one entry in registry.cpp.
#pragma once
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "render/integrator.h"
#include "render/integrator_params.h"

namespace gdr {

struct IntegratorEntry {
  std::string name;
  std::string description;  // one line
  bool gradient = false;    // writes primal, dx, dy (and reconstructs)
  std::vector<std::string> params;       // the IntegratorParams it reads
  std::vector<std::string> scene_types;  // <integrator type> values of scene files
  std::function<std::unique_ptr<Integrator>(const RenderInputs&, const IntegratorParams&)> make;
};

const std::vector<IntegratorEntry>& integrator_registry();

// The entry called `name`, or nullptr.
const IntegratorEntry* integrator_for_name(const std::string& name);
// The entry called `name`; throws Error listing the names when there is none.
const IntegratorEntry& find_integrator(const std::string& name);
// The entry a scene's <integrator type> stands for, or nullptr.
const IntegratorEntry* integrator_for_scene_type(const std::string& type);
// "pt, gpt"
std::string integrator_names();
// The names of the integrators that read parameter `param` ("pt, gpt").
std::string integrators_reading(const std::string& param);
// One line per integrator: name, description, parameters (for --list-integrators and --help).
std::string describe_integrators();

}  // namespace gdr
