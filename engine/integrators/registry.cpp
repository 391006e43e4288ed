#include "integrators/registry.h"

#include <sstream>

#include "integrators/bidir/bidirectional.h"
#include "integrators/gbidir/gradient_bidirectional.h"
#include "integrators/gbidir/gradient_photon_mapping.h"
#include "integrators/gpt/gradient_path_tracer.h"
#include "integrators/mlt/gradient_metropolis.h"
#include "integrators/mlt/metropolis.h"
#include "integrators/pt/path_tracer.h"
#include "util/error.h"

namespace gdr {
namespace {

template <class T>
std::vector<T> join(std::vector<T> a, const std::vector<T>& b) {
  a.insert(a.end(), b.begin(), b.end());
  return a;
}

std::vector<IntegratorEntry> make_registry() {
  return {
      {"pt", "wavefront path tracer: next-event estimation and BSDF sampling by MIS, Russian roulette", false,
       kPtParams, {"path", "pt"},
       [](const RenderInputs& in, const IntegratorParams& p) -> std::unique_ptr<Integrator> {
         return std::make_unique<PathTracer>(in, pt_settings(p));
       }},
      {"gpt", "gradient-domain path tracing (Kettunen et al. 2015): hybrid or replay shifts, Poisson reconstruction",
       true, join(kGptParams, kReconParams), {"gpt"},
       [](const RenderInputs& in, const IntegratorParams& p) -> std::unique_ptr<Integrator> {
         return std::make_unique<GradientPathTracer>(in, gpt_settings(p), p);
       }},
      {"gbdpt", "gradient-domain bidirectional path tracing (Manzi et al. 2015): G-PT's shifted camera subpaths "
                "connected to one light subpath each, light tracing shifted from its splat pixel, Poisson "
                "reconstruction",
       true, join(kGbdptParams, kReconParams), {"gbdpt"},
       [](const RenderInputs& in, const IntegratorParams& p) -> std::unique_ptr<Integrator> {
         return std::make_unique<GradientBidirectional>(in, gbdpt_settings(p), p);
       }},
      {"gpm", "gradient-domain photon mapping (Hua et al. 2017): G-PT's shifted camera subpaths to their visible "
              "points, photons shifted there from their parents, the radius shrinking by pass, Poisson reconstruction",
       true, join(kGpmParams, kReconParams), {"gpm"},
       [](const RenderInputs& in, const IntegratorParams& p) -> std::unique_ptr<Integrator> {
         return std::make_unique<GradientPhotonMapping>(in, gpm_settings(p), p);
       }},
      {"gvcm", "gradient-domain vertex connection and merging (Sun et al. 2017): gbdpt's connections and merges with "
               "the pass's photons shifted to the offsets, weighted over every strategy of both paths, the radius "
               "shrinking by pass, Poisson reconstruction",
       true, join(kGvcmParams, kReconParams), {"gvcm"},
       [](const RenderInputs& in, const IntegratorParams& p) -> std::unique_ptr<Integrator> {
         return std::make_unique<GradientBidirectional>(in, gvcm_settings(p), p, gvcm_photon_settings(p));
       }},
      {"lt", "light tracer: light subpaths connected to the camera and splatted, emission seen directly by camera rays",
       false, kLtParams, {"ptracer", "lt"},
       [](const RenderInputs& in, const IntegratorParams& p) -> std::unique_ptr<Integrator> {
         return std::make_unique<Bidirectional>(in, lt_settings(p));
       }},
      {"bdpt", "bidirectional path tracer: every connection of a camera and a light subpath, weighted by MIS",
       false, kBdptParams, {"bdpt"},
       [](const RenderInputs& in, const IntegratorParams& p) -> std::unique_ptr<Integrator> {
         return std::make_unique<Bidirectional>(in, bdpt_settings(p));
       }},
      {"pm", "progressive photon mapping: photons from the lights merged at each pixel's first rough vertex, "
             "the radius shrinking by pass",
       false, kPmParams, {"ppm", "sppm", "photonmapper"},
       [](const RenderInputs& in, const IntegratorParams& p) -> std::unique_ptr<Integrator> {
         return std::make_unique<Bidirectional>(in, pm_settings(p));
       }},
      {"vcm", "vertex connection and merging: bdpt's connections and photon merging weighted together by MIS",
       false, kVcmParams, {"vcm"},
       [](const RenderInputs& in, const IntegratorParams& p) -> std::unique_ptr<Integrator> {
         return std::make_unique<Bidirectional>(in, vcm_settings(p));
       }},
      {"mlt", "Metropolis light transport: primary-sample-space chains over bdpt's paths, one multiplexed strategy "
              "a path",
       false, kMltParams, {"pssmlt", "mlt"},
       [](const RenderInputs& in, const IntegratorParams& p) -> std::unique_ptr<Integrator> {
         return std::make_unique<Metropolis>(in, mlt_settings(p));
       }},
      {"gmlt", "gradient-domain Metropolis light transport: chains over G-PT's base and offset paths, sampling where "
               "the gradients are, L1 or L2 reconstruction",
       true, join(kGmltParams, kReconParams), {"gmlt", "gdmlt"},
       [](const RenderInputs& in, const IntegratorParams& p) -> std::unique_ptr<Integrator> {
         return std::make_unique<GradientMetropolis>(in, gmlt_settings(p), p);
       }},
  };
}

}  // namespace

const std::vector<IntegratorEntry>& integrator_registry() {
  static const std::vector<IntegratorEntry> registry = make_registry();
  return registry;
}

const IntegratorEntry* integrator_for_name(const std::string& name) {
  for (const IntegratorEntry& e : integrator_registry()) {
    if (e.name == name) return &e;
  }
  return nullptr;
}

const IntegratorEntry& find_integrator(const std::string& name) {
  if (const IntegratorEntry* e = integrator_for_name(name)) return *e;
  throw Error("unknown integrator '" + name + "' (available: " + integrator_names() + ")");
}

const IntegratorEntry* integrator_for_scene_type(const std::string& type) {
  for (const IntegratorEntry& e : integrator_registry()) {
    for (const std::string& t : e.scene_types) {
      if (t == type) return &e;
    }
  }
  return nullptr;
}

std::string integrator_names() {
  std::string names;
  for (const IntegratorEntry& e : integrator_registry()) names += (names.empty() ? "" : ", ") + e.name;
  return names;
}

std::string integrators_reading(const std::string& param) {
  std::string names;
  for (const IntegratorEntry& e : integrator_registry()) {
    for (const std::string& p : e.params) {
      if (p == param) names += (names.empty() ? "" : ", ") + e.name;
    }
  }
  return names;
}

std::string describe_integrators() {
  std::ostringstream out;
  for (const IntegratorEntry& e : integrator_registry()) {
    out << "  " << e.name << (e.gradient ? " (gradient)" : "") << ": " << e.description << "\n";
    if (!e.params.empty()) {
      out << "      parameters:";
      for (const std::string& p : e.params) out << " " << p;
      out << "\n";
    }
  }
  return out.str();
}

}  // namespace gdr
