#include "recon/dct_solver.h"

#include "util/error.h"

namespace gdr {
namespace {

// Must match DCT_MAX_RADIX in kernels/recon/dct.cl.
constexpr int kMaxRadix = 64;

// Radices of the Stockham stages: 4s first (the cheap butterfly), then the prime factors.
std::vector<int> radices(int n) {
  std::vector<int> r;
  while (n % 4 == 0) {
    r.push_back(4);
    n /= 4;
  }
  for (int p = 2; p * p <= n; ++p) {
    while (n % p == 0) {
      r.push_back(p);
      n /= p;
    }
  }
  if (n > 1) r.push_back(n);
  return r;
}

}  // namespace

bool DctSolver::supports(int height) {
  if (height <= 0) return false;
  for (int p : radices(height)) {
    if (p > kMaxRadix) return false;
  }
  return true;
}

DctSolver::DctSolver(Context& ctx, int width, int height)
    : w_(width),
      h_(height),
      radices_(radices(height)),
      twiddles_(ctx, size_t(height)),
      load_(recon_program(ctx, "recon/dct.cl")->kernel("dct_load")),
      stage2_(recon_program(ctx, "recon/dct.cl")->kernel("dct_fft_stage2")),
      stage3_(recon_program(ctx, "recon/dct.cl")->kernel("dct_fft_stage3")),
      stage4_(recon_program(ctx, "recon/dct.cl")->kernel("dct_fft_stage4")),
      stage5_(recon_program(ctx, "recon/dct.cl")->kernel("dct_fft_stage5")),
      stage_(recon_program(ctx, "recon/dct.cl")->kernel("dct_fft_stage")),
      rows_(recon_program(ctx, "recon/dct.cl")->kernel("dct_solve_rows")),
      inverse_load_(recon_program(ctx, "recon/dct.cl")->kernel("dct_inverse_load")),
      store_(recon_program(ctx, "recon/dct.cl")->kernel("dct_store")) {
  if (!supports(height)) throw Error("DctSolver: unsupported height " + std::to_string(height));
  for (int i = 0; i < 2; ++i) {
    re_[i] = Buffer<cl_float4>(ctx, size_t(width) * height);
    im_[i] = Buffer<cl_float4>(ctx, size_t(width) * height);
  }
  Kernel tw = recon_program(ctx, "recon/dct.cl")->kernel("dct_twiddles");
  tw.args(height, twiddles_).run(size_t(height));
}

int DctSolver::fft(int from, float sign) {
  int L = 1;
  for (int p : radices_) {
    int to = 1 - from;
    Kernel& k = p == 2 ? stage2_ : p == 3 ? stage3_ : p == 4 ? stage4_ : p == 5 ? stage5_ : stage_;
    k.args(re_[from], im_[from], re_[to], im_[to], twiddles_, w_, h_, L, sign);
    if (&k == &stage_) k.set_arg(9, p);
    k.run_2d(size_t(w_), size_t(h_ / p), 64, 1);
    L *= p;
    from = to;
  }
  return from;
}

void DctSolver::solve(const LinearSystem& sys, float alpha) {
  load_.args(*sys.b, w_, h_, sys.grid.ws, re_[0], im_[0]).run_2d(size_t(w_), size_t(h_), 64, 1);
  int f = fft(0, -1.0f);
  int other = 1 - f;
  // The tridiagonal solutions go to the free real plane, the inverse FFT's input back to f.
  rows_.args(re_[f], im_[f], w_, h_, alpha * alpha, re_[other]).run(size_t(h_));
  inverse_load_.args(re_[other], w_, h_, re_[f], im_[f]).run_2d(size_t(w_), size_t(h_), 64, 1);
  int g = fft(f, 1.0f);
  store_.args(re_[g], w_, h_, sys.grid.ws, *sys.x).run_2d(size_t(w_), size_t(h_), 64, 1);
}

}  // namespace gdr
