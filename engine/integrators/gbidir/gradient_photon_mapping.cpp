#include "integrators/gbidir/gradient_photon_mapping.h"

namespace gdr {

const std::vector<std::string> kGpmParams = {"shift", "shift_threshold", "aux", "direct_samples",
                                             "manifold_iterations", "manifold_tolerance", "manifold_precision",
                                             "radius", "radius_alpha"};

GptSettings gpm_settings(const IntegratorParams& params) { return gpt_settings(params); }

GradientPhotonMapping::GradientPhotonMapping(const RenderInputs& in, const GptSettings& gpt,
                                             const IntegratorParams& params)
    : GradientPathTracer(in, gpt, params, GroupKind::kMerging),
      photons_(pm_settings(params)),
      subpaths_(in, BIDIR_PM, groups_.capacity()),
      splats_(in.context, subpaths_.kernels(), BidirSubpaths::kProgram, 1),
      shifts_(in, groups_, gpt_manifold_enabled(in.scene, gpt),
              manifold_settings(params, PhotonShifts::kWalkIterations)) {
  if (gpt_manifold_enabled(in.scene, gpt)) subpaths_.record_delta_points();
}

void GradientPhotonMapping::trace_chunk(const RenderSettings& settings, uint32_t sample, uint32_t first,
                                        uint32_t count) {
  GdrGptParams p = groups_.params(settings, sample, first, count);
  p.path.max_depth = bdpt_segments(settings.max_depth);
  const GdrBidirOptions o = merging_pass_options(photons_, in_.scene, sample, count);
  const bool light = light_subpaths_allowed(settings.max_depth) && p.path.light_count > 0;
  if (light) subpaths_.trace_light(p.path, o, BidirSink{groups_.acc(), splats_});
  const PhotonGrid grid = subpaths_.grid();
  GradientGroups::RecordsStep merge;
  if (light) merge = [&](cl_uint recorded) { shifts_.merge(p, o, recorded, groups_, grid); };
  groups_.trace(p, PrimarySamples(), aux(), nullptr, merge);
  groups_.report(in_.context.stats());
  subpaths_.report(in_.context.stats());
  shifts_.report(in_.context.stats());
}

RenderResult GradientPhotonMapping::render(const RenderSettings& settings) {
  warn_beyond_store("gpm", settings.max_depth);
  return GradientPathTracer::render(settings);
}

}  // namespace gdr
