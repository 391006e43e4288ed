// What every technique of the bidirectional integrator (lt, bdpt, pm, vcm) shares: at max_depth 1
// the image is the emission the camera sees directly, exactly pt's camera rays' (same pixel
// sampler and seed: bit for bit), and max_depth 0 renders nothing; the same seed gives the same
// image (splats and merges add in a fixed order), another seed another image.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>

#include "integrators/bidir/bidirectional.h"
#include "support/agreement.h"
#include "support/render.h"

namespace gdr {
namespace {

class BidirTechnique : public ::testing::TestWithParam<int> {
 protected:
  BidirSettings settings() const { return bidir_settings(GetParam(), IntegratorParams{}); }
  Scene scene = test::project_scene("cornell-box.xml", 32);
};

std::vector<float> render(Integrator& integrator, int spp, uint32_t seed, int max_depth) {
  RenderSettings s;
  s.spp = spp;
  s.seed = seed;
  s.max_depth = max_depth;
  return integrator.render(s).image.rgb_layer("");
}

TEST_P(BidirTechnique, DirectlyVisibleEmissionIsPtsFirstSegment) {
  test::SceneOnDevice on_device(scene);
  Bidirectional bidir(on_device.inputs(), settings());
  PathTracer pt(on_device.inputs(), PtSettings{});
  std::vector<float> a = render(bidir, 4, 3, 1), b = render(pt, 4, 3, 1);
  ASSERT_EQ(a.size(), b.size());
  EXPECT_EQ(0, std::memcmp(a.data(), b.data(), a.size() * sizeof(float)));
  EXPECT_GT(*std::max_element(a.begin(), a.end()), 0.0f) << "the light is not in view";
  std::vector<float> none = render(bidir, 4, 3, 0);
  EXPECT_EQ(*std::max_element(none.begin(), none.end()), 0.0f);
}

TEST_P(BidirTechnique, SameSeedSameImage) {
  test::SceneOnDevice on_device(scene);
  Bidirectional bidir(on_device.inputs(), settings());
  std::vector<float> a = render(bidir, 2, 9, 8), b = render(bidir, 2, 9, 8), c = render(bidir, 2, 10, 8);
  EXPECT_EQ(0, std::memcmp(a.data(), b.data(), a.size() * sizeof(float)));
  EXPECT_NE(0, std::memcmp(a.data(), c.data(), a.size() * sizeof(float)));
}

std::string technique_name(const ::testing::TestParamInfo<int>& i) { return bidir_technique_name(i.param); }

INSTANTIATE_TEST_SUITE_P(Techniques, BidirTechnique, ::testing::Values(BIDIR_LT, BIDIR_BDPT, BIDIR_PM, BIDIR_VCM),
                         technique_name);

}  // namespace
}  // namespace gdr
