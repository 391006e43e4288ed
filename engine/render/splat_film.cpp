#include "render/splat_film.h"

static_assert(sizeof(GdrSplat) == 32, "GdrSplat layout changed");

namespace gdr {

SplatFilm::SplatFilm(Context& ctx, const KernelFactory& kernels, const std::string& program, size_t slots)
    : ctx_(ctx),
      keys_(kernels.make(program, "path_splat_keys")),
      gather_(kernels.make(program, "path_splat_gather")),
      primitives_(ctx),
      slots_(ctx, slots),
      keys_buffer_(ctx, slots),
      sorted_(ctx, slots) {
  slots_.fill(GdrSplat{});
}

void SplatFilm::sort(const Buffer<GdrCamera>& camera, int height, cl_uint count) {
  if (starts_.size() < size_t(height) + 1) starts_ = Buffer<cl_uint>(ctx_, size_t(height) + 1);
  keys_.args(camera, count, slots_, keys_buffer_).run(count);
  primitives_.sort_by_key(keys_buffer_, count, cl_uint(height), starts_, sorted_);
}

void SplatFilm::gather(const Buffer<GdrCamera>& camera, int height, cl_uint count, Buffer<Vec4>& film) {
  if (count == 0 || height <= 0) return;
  sort(camera, height, count);
  gather_.args(camera, starts_, sorted_, slots_, film).run(size_t(height));
  clear();
}

}  // namespace gdr
