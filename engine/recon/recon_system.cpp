#include "recon/recon_system.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace gdr {

ReconSystem::ReconSystem(Context& ctx, int width, int height, const std::vector<float>& primal_rgb,
                         const std::vector<float>& dx_rgb, const std::vector<float>& dy_rgb)
    : ReconSystem(ctx, width, height) {
  load(primal_rgb, dx_rgb, dy_rgb);
}

ReconSystem::ReconSystem(Context& ctx, int width, int height)
    : grid_(width, height, recon_vector_width(ctx)),
      dots_(ctx),
      P_(grid_.buffer(ctx)),
      Gx_(grid_.buffer(ctx)),
      Gy_(grid_.buffer(ctx)),
      wp_(grid_.buffer(ctx)),
      wx_(grid_.buffer(ctx)),
      wy_(grid_.buffer(ctx)),
      step_(grid_.buffer(ctx)),
      b_(grid_.buffer(ctx)),
      x_(grid_.buffer(ctx)),
      r_(grid_.buffer(ctx)),
      primal_in_(ctx, size_t(width) * height * 3, CL_MEM_READ_ONLY),
      dx_in_(ctx, size_t(width) * height * 3, CL_MEM_READ_ONLY),
      dy_in_(ctx, size_t(width) * height * 3, CL_MEM_READ_ONLY),
      rgb_out_(ctx, size_t(width) * height * 3),
      count_(ctx, 1),
      pack_(recon_program(ctx, "recon/setup.cl")->kernel("recon_pack")),
      weights_l2_(recon_program(ctx, "recon/setup.cl")->kernel("recon_weights_l2")),
      weights_l1_(recon_program(ctx, "recon/setup.cl")->kernel("recon_weights_l1")),
      weights_variance_(recon_program(ctx, "recon/setup.cl")->kernel("recon_weights_variance")),
      step_kernel_(recon_program(ctx, "recon/setup.cl")->kernel("recon_step")),
      rhs_(recon_program(ctx, "recon/setup.cl")->kernel("recon_rhs")),
      energy_(recon_program(ctx, "recon/setup.cl")->kernel("recon_energy")),
      energy_weighted_(recon_program(ctx, "recon/setup.cl")->kernel("recon_energy_weighted")),
      unpack_(recon_program(ctx, "recon/setup.cl")->kernel("recon_unpack")) {}

void ReconSystem::load(const std::vector<float>& primal_rgb, const std::vector<float>& dx_rgb,
                       const std::vector<float>& dy_rgb) {
  primal_in_.write(primal_rgb);
  dx_in_.write(dx_rgb);
  dy_in_.write(dy_rgb);
  // Everything not packed below is absent (NaN); x is 0 where the primal is absent.
  const float absent = std::numeric_limits<float>::quiet_NaN();
  P_.fill(absent);
  Gx_.fill(absent);
  Gy_.fill(absent);
  x_.fill(0.0f);
  count_.fill(0);
  pack_.args(primal_in_, dx_in_, dy_in_, grid_.w, grid_.h, grid_.ws, P_, Gx_, Gy_, x_, count_)
      .run_2d(size_t(grid_.w), size_t(grid_.h), 64, 1);
  nonfinite_inputs_ = count_.read()[0];
  // x is the primal with its absent values at 0.
  dots_.dot(x_, x_, grid_, DeviceDots::kEnergy);
  cl_float4 s = dots_.read(DeviceDots::kEnergy);
  double m = std::max({double(s.s[0]), double(s.s[1]), double(s.s[2])});
  primal_rms_ = std::sqrt(std::max(0.0, m) / (double(grid_.w) * grid_.h));
}

LinearSystem ReconSystem::system() {
  return LinearSystem{grid_, &wp_, &wx_, &wy_, &step_, &b_, &x_, &r_};
}

void ReconSystem::set_l2_weights(float alpha) {
  weights_l2_.args(P_, Gx_, Gy_, alpha * alpha, grid_.ws, grid_.h, wp_, wx_, wy_, step_);
  grid_.run(weights_l2_);
}

void ReconSystem::set_l1_weights(float alpha, float reg) {
  weights_l1_.args(x_, P_, Gx_, Gy_, alpha, reg, grid_.ws, grid_.h, wp_, wx_, wy_, step_, b_, r_);
  grid_.run(weights_l1_);
}

void ReconSystem::set_variance_weights(const ReconVariance& v, float alpha, float floor_rel) {
  // The image's variance scale, per channel: the median of the positive finite estimates of all
  // three inputs (a few fireflies would set a mean, a dark background of zero estimates a plain
  // median, and an exact primal would leave the gradients' estimates out of a primal-only one).
  // Weights relative to it do not depend on the exposure, and neither does the floor.
  cl_float4 inv_scale{};
  std::vector<float> positive;
  positive.reserve(v.primal.size());
  for (int c = 0; c < 3; ++c) {
    positive.clear();
    for (const std::vector<float>* layer : {&v.primal, &v.dx, &v.dy}) {
      for (size_t i = size_t(c); i < layer->size(); i += 3) {
        float x = (*layer)[i];
        if (std::isfinite(x) && x > 0) positive.push_back(x);
      }
    }
    if (positive.empty()) continue;  // no variance in this channel: uniform weights
    auto mid = positive.begin() + positive.size() / 2;
    std::nth_element(positive.begin(), mid, positive.end());
    double inv = 1.0 / double(*mid);
    inv_scale.s[c] = inv < double(std::numeric_limits<float>::max()) ? float(inv) : 0.0f;
  }
  // The interleaved inputs were packed already (load): their buffers carry the estimates now.
  primal_in_.write(v.primal);
  dx_in_.write(v.dx);
  dy_in_.write(v.dy);
  count_.fill(0);
  weights_variance_
      .args(primal_in_, dx_in_, dy_in_, grid_.w, grid_.h, grid_.ws, inv_scale, floor_rel, alpha * alpha, P_, Gx_,
            Gy_, wp_, wx_, wy_, count_)
      .run_2d(size_t(grid_.w), size_t(grid_.h), 64, 1);
  nonfinite_inputs_ += count_.read()[0];
  step_kernel_.args(wp_, wx_, wy_, grid_.ws, grid_.h, step_);
  grid_.run(step_kernel_);
}

void ReconSystem::build_rhs() {
  rhs_.args(P_, Gx_, Gy_, wp_, wx_, wy_, grid_.ws, grid_.h, b_);
  grid_.run(rhs_);
}

double ReconSystem::energy(float alpha, bool l2) {
  energy_.args(x_, P_, Gx_, Gy_, alpha, l2 ? 1 : 0, grid_.ws, grid_.h, dots_.partial());
  dots_.reduce(energy_, grid_, DeviceDots::kEnergy);
  cl_float4 e = dots_.read(DeviceDots::kEnergy);
  return double(e.s[0]) + e.s[1] + e.s[2];
}

double ReconSystem::weighted_energy() {
  energy_weighted_.args(x_, P_, Gx_, Gy_, wp_, wx_, wy_, grid_.ws, grid_.h, dots_.partial());
  dots_.reduce(energy_weighted_, grid_, DeviceDots::kEnergy);
  cl_float4 e = dots_.read(DeviceDots::kEnergy);
  return double(e.s[0]) + e.s[1] + e.s[2];
}

std::vector<float> ReconSystem::result(unsigned* nonfinite_outputs) {
  count_.fill(0);
  unpack_.args(x_, P_, grid_.w, grid_.h, grid_.ws, rgb_out_, count_)
      .run_2d(size_t(grid_.w), size_t(grid_.h), 64, 1);
  if (nonfinite_outputs) *nonfinite_outputs = count_.read()[0];
  return rgb_out_.read();
}

}  // namespace gdr
