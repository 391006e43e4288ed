#include "render/splat_film.h"

#include <algorithm>

static_assert(sizeof(GdrSplat) == 32, "GdrSplat layout changed");

namespace gdr {
namespace {

// Bands of rows gathered in parallel: each work item reads every slot, so more bands cost reads
// and fewer leave cores idle; 32 keeps a 16-core device busy at a few reads per slot and pixel.
constexpr cl_uint kDefaultBands = 32;

}  // namespace

SplatFilm::SplatFilm(Context& ctx, const KernelFactory& kernels, const std::string& program, size_t slots)
    : gather_(kernels.make(program, "path_splat_gather")), slots_(ctx, slots) {
  slots_.fill(GdrSplat{});
}

void SplatFilm::gather(const Buffer<GdrCamera>& camera, int height, cl_uint count, Buffer<Vec4>& film, cl_uint bands) {
  if (count == 0) return;
  if (bands == 0) bands = std::min<cl_uint>(kDefaultBands, cl_uint(std::max(height, 1)));
  gather_.args(camera, count, bands, slots_, film).run(bands);
  slots_.fill(GdrSplat{});
}

}  // namespace gdr
