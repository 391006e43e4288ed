// Direct solve of the L2 system when every term has its full weight (no missing inputs): the
// DCT along y diagonalises the screened Poisson operator into independent tridiagonal systems
// along x (kernels/recon/dct.cl). O(n log h) work, no iterations.
#pragma once
#include <vector>

#include "recon/recon_system.h"

namespace gdr {

class DctSolver {
 public:
  // Whether the FFT along a column of this height is supported (prime factors small enough for
  // the radix butterflies; any width works).
  static bool supports(int height);

  DctSolver(Context& ctx, int width, int height);
  // sys.x = A^-1 sys.b for the uniform weights wp = alpha^2, wx = wy = 1 inside the image
  // (alpha > 0); sys's weight buffers are not read.
  void solve(const LinearSystem& sys, float alpha);

 private:
  // Runs the FFT stages along y from plane pair `from` (0: a, 1: b); returns the pair holding
  // the result.
  int fft(int from, float sign);
  int w_, h_;
  std::vector<int> radices_;
  Buffer<cl_float2> twiddles_;
  Buffer<cl_float4> re_[2], im_[2];
  Kernel load_, stage2_, stage3_, stage4_, stage5_, stage_, rows_, inverse_load_, store_;
};

}  // namespace gdr
