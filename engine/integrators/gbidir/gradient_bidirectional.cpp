#include "integrators/gbidir/gradient_bidirectional.h"

namespace gdr {

GdrBidirOptions gbdpt_light_options(bool power_sums) {
  GdrBidirOptions o{BIDIR_BDPT, BIDIR_MIS_BALANCE, -1, -1, 0.0f, 0.0f, 0.0f, 0.0f, 0, power_sums ? 1 : 0};
  return o;
}

const std::vector<std::string> kGbdptParams = {"shift", "shift_threshold", "aux", "direct_samples",
                                               "manifold_iterations", "manifold_tolerance", "manifold_precision",
                                               "primal"};
const std::vector<std::string> kGvcmParams = {"shift", "shift_threshold", "aux", "direct_samples",
                                              "manifold_iterations", "manifold_tolerance", "manifold_precision",
                                              "radius", "radius_alpha"};

GptSettings gbdpt_settings(const IntegratorParams& params) {
  GptSettings s = gpt_settings(params);
  s.power_primal = params.choice("primal", "pairs", {"pairs", "power"}) == "power";
  return s;
}
GptSettings gvcm_settings(const IntegratorParams& params) { return gpt_settings(params); }

BidirSettings gvcm_photon_settings(const IntegratorParams& params) {
  BidirSettings s = vcm_settings(params);
  s.options.mis = BIDIR_MIS_BALANCE;
  return s;
}

GradientBidirectional::GradientBidirectional(const RenderInputs& in, const GptSettings& gpt,
                                             const IntegratorParams& params, std::optional<BidirSettings> merging)
    : GradientPathTracer(in, gpt, params, merging ? GroupKind::kConnectingMerging : GroupKind::kConnecting),
      merging_(merging),
      light_options_(gbdpt_light_options(gpt.power_primal)),
      subpaths_(in, merging ? BIDIR_VCM : BIDIR_BDPT, groups_.capacity()),
      splats_(in.context, subpaths_.kernels(), BidirSubpaths::kProgram, subpaths_.capacity()),
      light_tracing_(in, groups_, subpaths_.capacity(), gpt_manifold_enabled(in.scene, gpt), gpt.manifold) {
  // Light-traced vertices and photons behind delta vertices are shifted by manifold walks where
  // the camera subpaths' offsets walk.
  const bool walks = gpt_manifold_enabled(in.scene, gpt);
  if (walks) subpaths_.record_delta_points();
  if (merging_) shifts_.emplace(in, groups_, walks, manifold_settings(params, PhotonShifts::kWalkIterations));
}

void GradientBidirectional::trace_chunk(const RenderSettings& settings, uint32_t sample, uint32_t first,
                                        uint32_t count) {
  GdrGptParams p = groups_.params(settings, sample, first, count);
  p.path.max_depth = bdpt_segments(settings.max_depth);
  const GdrBidirOptions o =
      merging_ ? merging_pass_options(*merging_, in_.scene, sample, count) : light_options_;
  // The camera subpaths' sums take the light subpaths' merging factors (kernels/gbidir/weights.h).
  p.vm_factor = o.vm_factor;
  p.vc_factor = o.vc_factor;
  const bool light = light_subpaths_allowed(settings.max_depth) && p.path.light_count > 0;
  if (light) {
    BidirSink sink{groups_.acc(), splats_};
    sink.take_splats = [&](cl_uint slots) { light_tracing_.shift(p, o, slots, subpaths_, splats_, groups_); };
    subpaths_.trace_light(p.path, o, sink);
  }
  const GroupLightSubpaths subpaths{subpaths_.light_paths(), subpaths_.store(), cl_uint(subpaths_.capacity()),
                                    subpaths_.stored_bound()};
  const PhotonGrid grid = subpaths_.grid();
  GradientGroups::RecordsStep merge;
  if (light && shifts_) merge = [&](cl_uint recorded) { shifts_->merge(p, o, recorded, groups_, grid); };
  groups_.trace(p, PrimarySamples(), aux(), light ? &subpaths : nullptr, merge);
  groups_.report(in_.context.stats());
  subpaths_.report(in_.context.stats());
  light_tracing_.report(in_.context.stats());
  if (shifts_) shifts_->report(in_.context.stats());
}

void GradientBidirectional::end_pass() { light_tracing_.end_pass(groups_); }

RenderResult GradientBidirectional::render(const RenderSettings& settings) {
  warn_beyond_store(merging_ ? "gvcm" : "gbdpt", settings.max_depth);
  return GradientPathTracer::render(settings);
}

}  // namespace gdr
