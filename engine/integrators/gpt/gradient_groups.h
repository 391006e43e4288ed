// G-PT's groups (kernels/gpt/gpt.cl): a base path and four offset paths through the neighbouring
// pixels, traced in one wavefront for a batch of groups, with the shift mappings, the manifold
// walks where the scene has specular chains, and each group's sums left in `acc` (GPT_ACC_COUNT
// float4 at its path index). The gradient-domain path tracer traces a batch per chunk of pixels
// (the index is the pixel, and its gather reads the neighbours' sums); the gradient-domain
// Metropolis integrator one per step of its chains (the index is the chain, whose state feeds the
// group's random numbers through the sampler seam). The gradient-domain bidirectional path tracer
// builds them from its own program (G-PT's steps with G-BDPT's MIS) and connects each group's
// rough vertices to the vertices of one light subpath a group (GroupLightSubpaths); the
// gradient-domain photon mapper's end at the base's first rough vertex, which its merge stage
// (gbidir/photon_shifts.h) takes over from the records after each shade step.
#pragma once
#include <deque>
#include <functional>
#include <optional>

#include "render/aux_layers.h"
#include "render/integrator.h"
#include "render/integrator_params.h"
#include "render/manifold_walks.h"
#include "render/primary_samples.h"
#include "render/wavefront/device_counters.h"
#include "render/wavefront/kernel_factory.h"
#include "render/wavefront/material_queues.h"
#include "render/wavefront/ray_queues.h"
#include "shared/gbidir_types.h"
#include "shared/gpt_types.h"

namespace gdr {

struct GptSettings {
  int shift = GPT_SHIFT_HYBRID;  // GPT_SHIFT_*
  float shift_threshold = GDR_GLOSSY_THRESHOLD;
  bool aux = false;
  // Camera samples a pixel and pass of the emission seen directly, besides the base path's own
  // (render/seen_emission.h): the direct layer's mean over 1 + direct_samples. Eight took the
  // Cornell box's relMSE at 32 s to 0.26 of gpt's and 0.12 of gbdpt's without them (README).
  int direct_samples = 8;
  bool power_primal = false;  // G-BDPT: the primal under the power heuristic (kernels/gbidir/weights.h)
  ManifoldSettings manifold;
  size_t in_flight = 0;  // groups a chunk at most (0: GradientGroups::chunk_capacity_for's)
  // The bases' hits routed to per-material queues (render/wavefront/material_queues.h); unset: on
  // a GPU, not on a CPU device, where routing took the glass box's G-PT 1.05-1.07 times as long.
  std::optional<bool> route_materials;
  // G-PT's groups split into this many batches a chunk (1 or 2), stepped in turn so that the
  // device shades one while Embree traces the other (GradientGroups::trace); 1 with the manifold
  // shift and for the other kinds of groups, or where a batch would hold too few groups. 0: the
  // device's default, 2 on a GPU and 1 on a CPU device, whose cores the kernels share with
  // Embree (two batches took gpt 1.03 times as long on the Cornell box, 512 px, two cores).
  int batches = 0;
};
// The shift's parameters (shift, shift_threshold, manifold_*), with `shift` defaulting to
// `default_shift`.
GptSettings gpt_shift_settings(const IntegratorParams& params, const std::string& default_shift = "hybrid");

// Whether --shift manifold walks in this scene (it has specular chains).
bool gpt_manifold_enabled(const Scene& scene, const GptSettings& gpt);

// The light subpaths of a batch of groups (BidirSubpaths: group i's is subpath i), whose stored
// vertices (vertex j of subpath i at store[j * stride + i]) the groups connect to.
struct GroupLightSubpaths {
  const Buffer<GdrBidirPathState>& paths;
  const Buffer<GdrBidirVertex>& store;
  cl_uint stride;
  int stored_bound;  // no subpath stored more vertices
};

// What a batch of groups is: G-PT's paths, G-BDPT's camera subpaths (which connect to light
// subpaths), G-PM's (which end at their visible points, where the caller merges) or G-VCM's
// (which connect, and the caller merges at each of their rough vertices).
enum class GroupKind { kPaths, kConnecting, kMerging, kConnectingMerging };

class GradientGroups {
 public:
  static constexpr const char* kProgram = "gpt/gpt.cl";
  static constexpr const char* kConnectingProgram = "gbidir/gbdpt.cl";
  static constexpr const char* kMergingProgram = "gbidir/gpm.cl";
  static constexpr const char* kConnectingMergingProgram = "gbidir/gvcm.cl";

  // Up to `capacity` groups a batch; `indices` path indices (acc holds GPT_ACC_COUNT a path).
  GradientGroups(const RenderInputs& inputs, const GptSettings& gpt, size_t capacity, size_t indices,
                 GroupKind kind = GroupKind::kPaths);
  const char* program() const;

  // Groups in flight for a chunk of the scene's film: fewer with the manifold shift (its walks'
  // state), and on a CPU device (device_chunk_capacity) where there are no walks and the groups
  // do not merge (the chunk's photons are its own light subpaths, one a group).
  static size_t chunk_capacity_for(const RenderInputs& inputs, const GptSettings& gpt, GroupKind kind);

  const KernelFactory& kernels() const { return kernels_; }
  size_t capacity() const { return capacity_; }
  Buffer<Vec4>& acc() { return acc_; }
  // The base paths' states after a trace (a group's path.depth: the depth it ended at); one batch.
  const Buffer<GptBaseState>& bases() const { return batches_[0].bases; }
  // Connecting and merging groups: the vertices the last shade step recorded (records()[g]), for
  // the groups listed in connectable(); the counters the steps after it count into.
  const Buffer<GbdptCameraVertex>& records() const { return batches_[0].records; }
  const Buffer<cl_uint>& connectable() const { return batches_[0].connectable; }
  DeviceCounters& counters() { return batches_[0].counters; }

  // Called after each shade step of merging groups (and after the connections of connecting and
  // merging ones) with the number of groups it recorded.
  using RecordsStep = std::function<void(cl_uint recorded)>;

  // The groups of paths [p.path.first_pixel, + p.path.pixel_count), their sums into acc.
  // `aux`: the base camera rays' first hits. `light`: connecting groups' light subpaths.
  // `merge`: merging groups' merge step. With two batches, each takes a consecutive half of the
  // paths; the sums do not depend on the split.
  void trace(const GdrGptParams& p, const PrimarySamples& primary, AuxLayers* aux,
             const GroupLightSubpaths* light = nullptr, const RecordsStep& merge = {});
  GdrGptParams params(const RenderSettings& settings, uint32_t sample, uint32_t first, uint32_t count) const;
  void report(Stats* stats);

 private:
  // A part of a chunk's groups in flight: its queues, states and counters, its command queue, and
  // where it stands in its bounce loop (stepped batches: GradientGroups::step).
  struct Batch {
    Batch(const RenderInputs& in, const KernelFactory& kernels, const char* program, size_t capacity, GroupKind kind,
          bool route, int command_queue);
    int command_queue;
    MaterialQueues materials;  // the bases' hits by BSDF type, each type shaded by gpt_shade_<type>
    RayQueues base_queues;
    Buffer<cl_uint> shift_groups;  // the next base queue's entries whose groups have offsets to shift
    Buffer<GdrRayHit> offset_rays;
    Buffer<GdrRay> reconnect_rays;
    Buffer<GdrRay> shadow_rays;
    Buffer<GptBaseState> bases;
    Buffer<GptOffsetState> offsets;
    Buffer<Vec4> pend;  // GPT_PEND_COUNT per group
    Buffer<GbdptCameraVertex> records;  // connecting groups: the rough vertex of the last shade step
    Buffer<cl_uint> connectable;        // and the groups that recorded one
    DeviceCounters counters;
    // Stepping: the batch's paths, what its device runs (`phase`), its `active` groups in base
    // queue `cur` at `depth`, and the base rays the last shade step queued (`next`).
    enum class Phase { kGenerating, kShading, kShifting, kDone };
    GdrGptParams params{};
    Phase phase = Phase::kDone;
    cl_uint active = 0, next = 0;
    int cur = 0, depth = 0;
  };

  // Queues the camera rays of batch b's paths p (its part of the chunk).
  void start(Batch& b, const GdrGptParams& p, const PrimarySamples& primary);
  // One step of batch b: it waits for what its device was running, traces the rays that gave
  // (Embree), runs the connections and merges of the groups that recorded a vertex, and queues
  // its next kernels without waiting.
  void step(Batch& b, const PrimarySamples& primary, AuxLayers* aux, const GroupLightSubpaths* light,
            const RecordsStep& merge);
  // Queues the shade step of b's `active` groups in base queue `cur`, by the material queues of
  // the bases' hits (counters reset first; the queues' routing reads their counts where it routes).
  void shade(Batch& b, const PrimarySamples& primary);
  // Offset rays' hits and reconnection segments' visibility, filed into the offsets' states.
  void intersect_offsets(Batch& b, cl_uint rays, cl_uint reconnects, bool coherent);
  // Solves the walks the shift step queued and joins their offsets to the base.
  void walk_offsets(Batch& b, cl_uint walks);
  // The pending values behind the shadow rays written since the last reset, where unoccluded.
  void add_shadows(Batch& b, cl_uint count, const char* kind, bool coherent);
  // The recorded vertices (`connectable` of them, `camera_depth` segments from the camera) to
  // the light subpaths' stored vertices, one launch a vertex index.
  void connect(Batch& b, int camera_depth, cl_uint connectable, const GroupLightSubpaths& light);

  RenderInputs in_;
  GptSettings gpt_;
  GroupKind kind_;
  KernelFactory kernels_;
  Kernel generate_, scatter_, route_, shadow_, shift_;
  size_t capacity_;
  std::deque<Batch> batches_;
  Buffer<Vec4> acc_;
  std::optional<Kernel> connect_;
  // The manifold shift, where the scene has specular chains (else --shift manifold is hybrid).
  Buffer<GptChain> chains_;
  Buffer<GdrManifoldWalk> walks_;
  Buffer<GdrManifoldResult> walk_results_;
  std::optional<ManifoldWalks> manifold_;
  std::optional<Kernel> join_;
};

}  // namespace gdr
