#include "recon/recon_system.h"

#include <algorithm>
#include <cmath>

namespace gdr {

ReconSystem::ReconSystem(Context& ctx, int width, int height, const std::vector<float>& primal_rgb,
                         const std::vector<float>& dx_rgb, const std::vector<float>& dy_rgb)
    : ReconSystem(ctx, width, height) {
  load(primal_rgb, dx_rgb, dy_rgb);
}

ReconSystem::ReconSystem(Context& ctx, int width, int height)
    : ctx_(ctx),
      width_(width),
      height_(height),
      P_(ctx, size_t(width) * height),
      Gx_(ctx, size_t(width) * height),
      Gy_(ctx, size_t(width) * height),
      mp_(ctx, size_t(width) * height),
      mx_(ctx, size_t(width) * height),
      my_(ctx, size_t(width) * height),
      wp_(ctx, size_t(width) * height),
      wx_(ctx, size_t(width) * height),
      wy_(ctx, size_t(width) * height),
      b_(ctx, size_t(width) * height),
      x_(ctx, size_t(width) * height),
      primal_in_(ctx, size_t(width) * height * 3, CL_MEM_READ_ONLY),
      dx_in_(ctx, size_t(width) * height * 3, CL_MEM_READ_ONLY),
      dy_in_(ctx, size_t(width) * height * 3, CL_MEM_READ_ONLY),
      rgb_out_(ctx, size_t(width) * height * 3),
      count_(ctx, 1),
      pack_(recon_program(ctx, "recon/setup.cl")->kernel("recon_pack")),
      weights_l2_(recon_program(ctx, "recon/setup.cl")->kernel("recon_weights_l2")),
      weights_l1_(recon_program(ctx, "recon/setup.cl")->kernel("recon_weights_l1")),
      rhs_(recon_program(ctx, "recon/setup.cl")->kernel("recon_rhs")),
      energy_(recon_program(ctx, "recon/setup.cl")->kernel("recon_energy")),
      unpack_(recon_program(ctx, "recon/setup.cl")->kernel("recon_unpack")) {}

void ReconSystem::load(const std::vector<float>& primal_rgb, const std::vector<float>& dx_rgb,
                       const std::vector<float>& dy_rgb) {
  primal_in_.write(primal_rgb);
  dx_in_.write(dx_rgb);
  dy_in_.write(dy_rgb);
  count_.fill(0);
  pack_.args(primal_in_, dx_in_, dy_in_, width_, height_, P_, Gx_, Gy_, mp_, mx_, my_, count_)
      .run(size_t(width_) * height_);
  nonfinite_inputs_ = count_.read()[0];
  // The primal (0 where missing) is the starting estimate.
  cl_check(clEnqueueCopyBuffer(ctx_.queue(), P_.handle(), x_.handle(), 0, 0,
                               sizeof(cl_float4) * size_t(width_) * height_, 0, nullptr, nullptr),
           "clEnqueueCopyBuffer");
}

LinearSystem ReconSystem::system() {
  return LinearSystem{width_, height_, &wp_, &wx_, &wy_, &b_, &x_};
}

void ReconSystem::set_l2_weights(float alpha) {
  int n = width_ * height_;
  weights_l2_.args(mp_, mx_, my_, alpha * alpha, n, wp_, wx_, wy_).run(n);
}

void ReconSystem::set_l1_weights(float alpha, float reg) {
  weights_l1_.args(x_, P_, Gx_, Gy_, mp_, mx_, my_, alpha, reg, width_, height_, wp_, wx_, wy_)
      .run(size_t(width_) * height_);
}

void ReconSystem::build_rhs() {
  rhs_.args(P_, Gx_, Gy_, wp_, wx_, wy_, width_, height_, b_).run(size_t(width_) * height_);
}

double ReconSystem::energy(float alpha, bool l2, DeviceDots& dots) {
  int n = width_ * height_;
  energy_.args(x_, P_, Gx_, Gy_, mp_, mx_, my_, alpha, l2 ? 1 : 0, width_, height_, dots.partial())
      .run(DeviceDots::reduce_global(n));
  dots.sum_partials(n, DeviceDots::kEnergy);
  cl_float4 e = dots.read(DeviceDots::kEnergy);
  return double(e.s[0]) + e.s[1] + e.s[2];
}

double ReconSystem::primal_rms(DeviceDots& dots) {
  int n = width_ * height_;
  dots.dot(P_, P_, n, DeviceDots::kEnergy);
  cl_float4 s = dots.read(DeviceDots::kEnergy);
  double m = std::max({double(s.s[0]), double(s.s[1]), double(s.s[2])});
  return std::sqrt(std::max(0.0, m) / n);
}

std::vector<float> ReconSystem::result(unsigned* nonfinite_outputs) {
  size_t n = size_t(width_) * height_;
  count_.fill(0);
  unpack_.args(x_, P_, int(n), rgb_out_, count_).run(n);
  if (nonfinite_outputs) *nonfinite_outputs = count_.read()[0];
  return rgb_out_.read();
}

}  // namespace gdr
