#include "accel/embree_scene.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <string>

#include "accel/ray_layout.h"
#include "device/runtime_env.h"
#include "scene/scene.h"
#include "stats/stats.h"
#include "util/error.h"

namespace gdr {
namespace {

// rtcIntersect1M runs on the calling thread only, so queues are split into chunks of this many
// rays for TBB (small enough to balance, large enough for Embree's stream traversal).
constexpr size_t kChunk = 512;

RTCBuildQuality to_rtc(BuildQuality q) {
  switch (q) {
    case BuildQuality::Low: return RTC_BUILD_QUALITY_LOW;
    case BuildQuality::Medium: return RTC_BUILD_QUALITY_MEDIUM;
    case BuildQuality::High: return RTC_BUILD_QUALITY_HIGH;
  }
  return RTC_BUILD_QUALITY_MEDIUM;
}

void check_device(RTCDevice device, const char* what) {
  RTCError err = rtcGetDeviceError(device);
  if (err != RTC_ERROR_NONE) throw Error(std::string("Embree: ") + what + " failed (error " + std::to_string(err) + ")");
}

}  // namespace

EmbreeScene::EmbreeScene(const Scene& scene, BuildQuality quality, Stats* stats) : stats_(stats) {
  ScopedTimer timer(stats, "embree/build");
  std::string config = "threads=" + std::to_string(runtime_threads());
  device_ = rtcNewDevice(config.c_str());
  if (!device_) throw Error("Embree: cannot create a device");
  scene_ = rtcNewScene(device_);
  if (scene.robust_intersections) rtcSetSceneFlags(scene_, RTC_SCENE_FLAG_ROBUST);
  rtcSetSceneBuildQuality(scene_, to_rtc(quality));
  if (!scene.triangles.empty()) {
    RTCGeometry geom = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_TRIANGLE);
    rtcSetGeometryBuildQuality(geom, to_rtc(quality));
    // The scene's arrays are shared, not copied: Vec4 positions (16-byte stride) and
    // GdrTriangle (three indices + shape id, 16-byte stride) are formats Embree reads directly.
    rtcSetSharedGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, scene.positions.data(), 0,
                               sizeof(Vec4), scene.positions.size());
    rtcSetSharedGeometryBuffer(geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, scene.triangles.data(), 0,
                               sizeof(GdrTriangle), scene.triangles.size());
    rtcCommitGeometry(geom);
    rtcAttachGeometryByID(scene_, geom, 0);
    rtcReleaseGeometry(geom);
  }
  rtcCommitScene(scene_);
  check_device(device_, "building the BVH");
}

EmbreeScene::~EmbreeScene() {
  if (scene_) rtcReleaseScene(scene_);
  if (device_) rtcReleaseDevice(device_);
}

void EmbreeScene::intersect(GdrRayHit* rays, size_t count, bool coherent, const char* kind) {
  if (count == 0) return;
  ScopedTimer timer(stats_, "embree/intersect");
  tbb::parallel_for(tbb::blocked_range<size_t>(0, count, kChunk), [&](const tbb::blocked_range<size_t>& r) {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    context.flags = coherent ? RTC_INTERSECT_CONTEXT_FLAG_COHERENT : RTC_INTERSECT_CONTEXT_FLAG_INCOHERENT;
    rtcIntersect1M(scene_, &context, reinterpret_cast<RTCRayHit*>(rays + r.begin()),
                   static_cast<unsigned>(r.size()), sizeof(GdrRayHit));
  });
  if (stats_) stats_->add_count(std::string("rays/") + kind, count);
}

void EmbreeScene::occluded(GdrRay* rays, size_t count, bool coherent, const char* kind) {
  if (count == 0) return;
  ScopedTimer timer(stats_, "embree/occluded");
  tbb::parallel_for(tbb::blocked_range<size_t>(0, count, kChunk), [&](const tbb::blocked_range<size_t>& r) {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    context.flags = coherent ? RTC_INTERSECT_CONTEXT_FLAG_COHERENT : RTC_INTERSECT_CONTEXT_FLAG_INCOHERENT;
    rtcOccluded1M(scene_, &context, reinterpret_cast<RTCRay*>(rays + r.begin()),
                  static_cast<unsigned>(r.size()), sizeof(GdrRay));
  });
  if (stats_) stats_->add_count(std::string("rays/") + kind, count);
}

}  // namespace gdr
