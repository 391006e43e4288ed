#include "render/aux_layers.h"

#include "cluster/reduce.h"
#include "render/film.h"

namespace gdr {

AuxLayers::AuxLayers(Context& ctx, const KernelFactory& kernels, const std::string& program, size_t pixels)
    : kernel_(kernels.make(program, "path_aux")), stats_(ctx.stats()), albedo_(ctx, pixels), normal_(ctx, pixels), depth_(ctx, pixels) {}

void AuxLayers::clear() {
  albedo_.fill(Vec4{});
  normal_.fill(Vec4{});
  depth_.fill(0.0f);
}

void AuxLayers::add(const GdrPtParams& params, const Buffer<GdrRayHit>& first_hits, cl_uint count,
                    const DeviceScene& scene) {
  kernel_.args(params, count, first_hits, albedo_, normal_, depth_, scene).run(count);
}

void AuxLayers::add_to(Image& image, int samples) const {
  float scale = mean_scale(samples);
  std::vector<float> depth = depth_.read(), d(depth.size() * 3);
  cluster::sum_to_root(depth, stats_);
  for (size_t p = 0; p < depth.size(); ++p) d[3 * p] = d[3 * p + 1] = d[3 * p + 2] = depth[p] * scale;
  image.add_rgb_layer("albedo", reduced_rgb(albedo_, scale, stats_));
  image.add_rgb_layer("normal", reduced_rgb(normal_, scale, stats_));
  image.add_rgb_layer("depth", d);
}

}  // namespace gdr
