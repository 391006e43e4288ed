// The subpaths of the bidirectional kernels (kernels/bidir/bidir.cl), traced for a batch of
// paths: light subpaths with their camera connections, the light-vertex store and its hash grid,
// camera subpaths with their emission, light connections, connections to the store and merges.
// The bidirectional integrator traces a batch per chunk of pixels into its film; the Metropolis
// integrator traces one per step of its chains, whose states feed the paths' random numbers.
//
// Where contributions go (BidirSink): the camera subpaths add into `values` at their path's index
// (the pixel, or the chain); light vertices seen by the camera (t = 1) write the splat slot of
// their path, which after every light bounce gather_into (a film layer) receives, or path_sums
// adds into its path's entry wherever it lands, or, without either, the caller reads (one
// strategy per path under multiplexing: at most one splat a path), unless take_splats takes them
// (the gradient integrators shift them: the light vertex each slot's splat came from is in seen()).
#pragma once
#include <functional>
#include <optional>

#include "render/aux_layers.h"
#include "render/integrator.h"
#include "render/primary_samples.h"
#include "render/seen_emission.h"
#include "render/splat_film.h"
#include "render/wavefront/device_counters.h"
#include "render/wavefront/kernel_factory.h"
#include "render/wavefront/primitives.h"
#include "render/wavefront/ray_queues.h"
#include "shared/bidir_types.h"
#include "shared/manifold_types.h"

namespace gdr {

// The longest path bdpt, pm, vcm and mlt render (segments): the light-vertex store holds
// kBdptMaxSegments - 1 vertices a subpath.
constexpr int kBdptMaxSegments = 16;

struct BidirSink {
  Buffer<Vec4>& values;
  SplatFilm& splats;
  Buffer<Vec4>* gather_into = nullptr;
  Buffer<Vec4>* path_sums = nullptr;
  std::function<void(cl_uint slots)> take_splats = nullptr;  // after each light bounce: slots [0, slots)
};

// A batch's stored light vertices as photons (pm, vcm: vertex j of subpath i at
// store[j * stride + i]), the hash grid over them (bidir/hash_grid.h: each bucket's entries
// sorted[starts[b], starts[b + 1])) and where each subpath left its light. buckets 0: no photons.
struct PhotonGrid {
  const Buffer<GdrBidirVertex>& store;
  const Buffer<Vec4>& points;
  const Buffer<cl_uint>& starts;
  const Buffer<cl_uint>& sorted;
  const Buffer<GdrLightOrigin>& origins;
  cl_uint buckets;
  cl_uint stride;
  // Where record_delta_points() was asked: the delta vertices' points (the vertex k bounces from
  // its light at delta_points[(k - 1) * stride + i], k up to delta_depths; 0: none kept).
  const Buffer<GdrManifoldPoint>& delta_points;
  cl_uint delta_depths;
};

class BidirSubpaths {
 public:
  static constexpr const char* kProgram = "bidir/bidir.cl";

  // Up to `capacity` paths a batch, for `technique` (BIDIR_*: which buffers it needs).
  BidirSubpaths(const RenderInputs& inputs, int technique, size_t capacity);

  const KernelFactory& kernels() const { return kernels_; }
  size_t capacity() const { return capacity_; }

  // The batch of paths [p.first_pixel, p.first_pixel + p.pixel_count) with options `o`: lt's
  // camera rays for the emission seen directly (into sink.values) and its light subpaths, or
  // the light subpaths, the grid when merging, and the camera subpaths. `light` false: no light
  // subpaths (no light, or paths too short for them). `aux`: the camera rays' first hits.
  void trace(const GdrPtParams& p, const GdrBidirOptions& o, bool light, const PrimarySamples& primary,
             const BidirSink& sink, AuxLayers* aux);
  // The light subpaths alone, their vertices left in the store (and, merging, the grid built) for
  // the caller's own camera subpaths (G-BDPT's groups: GroupLightSubpaths; G-PM's: grid()).
  void trace_light(const GdrPtParams& p, const GdrBidirOptions& o, const BidirSink& sink);
  PhotonGrid grid() const;
  // From now on the light subpaths keep their delta vertices' points too (PhotonGrid).
  void record_delta_points();
  const Buffer<GdrBidirPathState>& light_paths() const { return light_paths_; }
  const Buffer<GdrBidirVertex>& store() const { return store_; }
  const Buffer<GdrLightOrigin>& origins() const { return light_origins_; }
  const Buffer<GdrBidirVertex>& seen() const { return seen_; }  // each valid splat slot's light vertex
  int stored_bound() const { return stored_bound_; }

  // Adds the counters' totals to the stats.
  void report(Stats* stats) {
    counters_.report(stats);
    direct_.report(stats);
  }

 private:
  bool lt() const { return technique_ == BIDIR_LT; }
  bool connects() const { return technique_ == BIDIR_BDPT || technique_ == BIDIR_VCM; }
  bool merges() const { return technique_ == BIDIR_PM || technique_ == BIDIR_VCM; }
  // A batch's options and primary samples; its store starts empty.
  void begin(const GdrBidirOptions& o, const PrimarySamples& primary);
  void trace_light_subpaths(const GdrPtParams& p, const BidirSink& sink);
  void trace_camera_subpaths(const GdrPtParams& p, const BidirSink& sink, AuxLayers* aux);
  // The camera vertices of `camera_depth` segments queued in connectable_ to the store.
  void connect(const GdrPtParams& p, int camera_depth, cl_uint connectable, Buffer<Vec4>& values);
  // The hash grid over the batch's stored light vertices, and the merges of the queued camera
  // vertices with them.
  void build_grid(const GdrPtParams& p);
  void merge(const GdrPtParams& p, cl_uint connectable, Buffer<Vec4>& values);
  void add_shadows(cl_uint count, const char* kind, Buffer<Vec4>& values);

  const RenderInputs in_;
  int technique_;
  KernelFactory kernels_;
  SeenEmission direct_;  // lt: the emission seen by camera rays
  Kernel emit_, light_shade_, camera_blocked_;
  Kernel generate_, camera_shade_, connect_, shadow_add_, grid_keys_, merge_, splats_to_paths_;
  GdrBidirOptions options_{};  // this batch's
  PrimarySamples primary_;     // this batch's
  size_t capacity_;      // subpaths of each kind in flight at once
  int store_vertices_;   // light-vertex store: vertices a light subpath (bdpt; 0 for lt)
  int stored_bound_ = 0; // the batch's light subpaths stored at most this many vertices
  cl_uint stored_ = 0;   // and this many in all
  RayQueues queues_;
  Buffer<GdrBidirPathState> light_paths_, camera_paths_;
  Buffer<GdrLightOrigin> light_origins_;
  Buffer<GdrManifoldPoint> delta_points_;  // record_delta_points(): a point a bounce a subpath
  cl_uint delta_depths_ = 0;
  Buffer<GdrBidirVertex> seen_, store_, camera_vertices_;
  Buffer<cl_uint> connectable_;
  std::optional<DevicePrimitives> primitives_;      // merging: the grid's sort
  Buffer<cl_uint> grid_keys_buffer_, grid_starts_, grid_sorted_;
  Buffer<Vec4> store_points_;
  cl_uint grid_buckets_ = 1;
  Buffer<GdrRay> shadow_rays_;
  Buffer<Vec4> shadow_values_;
  DeviceCounters counters_;
};

}  // namespace gdr
