// Ray queues on a device that does not share the host's memory (a discrete GPU) are copied to the
// host around each Embree traversal instead of mapped. On PoCL, with the context told it is not
// zero-copy, every integrator stage that traces renders bit for bit what the zero-copy context
// renders: pt in two batches (the environment scene at 256 x 144, 2 spp), G-PT with manifold walks
// and gvcm (connections, photons, photon-shift rays) on the caustics box at 32 px (2 spp); and no
// ray queue is mapped (the stats time reads and writes, no maps).
#include <gtest/gtest.h>

#include <functional>
#include <map>
#include <memory>
#include <string>

#include "integrators/registry.h"
#include "support/agreement.h"
#include "support/render.h"

namespace gdr {
namespace {

struct Rendered {
  Image image;
  nlohmann::json transfers;
};

Rendered render(const Scene& scene, const std::string& integrator, const IntegratorParams& params, bool zero_copy) {
  Stats stats;
  Context ctx(select_device(""), &stats);
  ctx.set_zero_copy(zero_copy);
  test::SceneOnDevice on_device(scene, &stats, ctx);
  RenderSettings s;
  s.spp = 2;
  s.seed = 5;
  s.max_depth = 6;
  Rendered r{find_integrator(integrator).make(on_device.inputs(), params)->render(s).image, {}};
  r.transfers = stats.to_json()["time"]["transfer"];
  return r;
}

void expect_same_with_copies(const Scene& scene, const std::string& integrator,
                             std::map<std::string, std::string> params = {}) {
  const IntegratorParams p(params);
  const Rendered mapped = render(scene, integrator, p, true), copied = render(scene, integrator, p, false);
  EXPECT_TRUE(mapped.transfers.contains("map")) << integrator;
  EXPECT_FALSE(copied.transfers.contains("map")) << integrator << ": a ray queue was mapped";
  ASSERT_TRUE(copied.transfers.contains("write")) << integrator;
  EXPECT_GT(copied.transfers["read"]["calls"].get<uint64_t>(), mapped.transfers["read"]["calls"].get<uint64_t>());
  for (const char* layer : {"", "primal", "dx", "dy"}) {
    if (!mapped.image.has_rgb_layer(layer)) continue;
    EXPECT_EQ(mapped.image.rgb_layer(layer), copied.image.rgb_layer(layer)) << integrator << ", layer '" << layer << "'";
  }
}

TEST(RayTransfers, PtInBatchesRendersTheSame) {
  expect_same_with_copies(test::project_scene("environment.xml", 256), "pt");
}

TEST(RayTransfers, GradientIntegratorsRenderTheSame) {
  const Scene caustics = test::project_scene("cornell-box-caustics.xml", 32);
  expect_same_with_copies(caustics, "gpt", {{"shift", "manifold"}});
  expect_same_with_copies(caustics, "gvcm");
}

}  // namespace
}  // namespace gdr
