#include "cluster/reduce.h"

#include <algorithm>
#include <cstdint>

#include "cluster/ranks.h"
#include "util/error.h"

#ifdef GDR_HAVE_MPI
#include <mpi.h>
#endif

namespace gdr::cluster {
namespace {

// One pixel's moment sets on the wire: its passes (shared by the three channels), sum.rgb, m2.rgb.
constexpr int kMomentFloats = 7;

#ifdef GDR_HAVE_MPI
// MPI_User_function over pixels (the datatype is kMomentFloats contiguous floats).
void combine_op(void* in, void* inout, int* count, MPI_Datatype*) {
  const float* a = static_cast<const float*>(in);
  float* b = static_cast<float*>(inout);
  for (int i = 0; i < *count; ++i, a += kMomentFloats, b += kMomentFloats) {
    double n = 0;
    for (int c = 0; c < 3; ++c) {
      double nc = b[0], s = b[1 + c], m2 = b[4 + c];
      combine_into(nc, s, m2, a[0], a[1 + c], a[4 + c]);
      b[1 + c] = float(s);
      b[4 + c] = float(m2);
      n = nc;
    }
    b[0] = float(n);
  }
}

// Waits for every rank to reach the reduction (timed apart as mpi/reduce_wait), so that
// mpi/reduce times the transfer and the combination alone, not a slower rank's reading of its
// film.
void wait_for_all(Stats* stats) {
  ScopedTimer t(stats, "mpi/reduce_wait");
  barrier();
}

void record(Stats* stats, double seconds, size_t bytes) {
  if (!stats) return;
  stats->add_time("mpi/reduce", seconds);
  stats->add_count("mpi/reduce_bytes", bytes);
}

// MPI counts are ints: reductions go in pieces of at most this many elements.
constexpr size_t kMaxPiece = size_t(1) << 28;
#endif

}  // namespace

void combine_into(double& n, double& s, double& m2, double nb, double sb, double m2b) {
  if (nb <= 0) return;
  if (n <= 0) {
    n = nb, s = sb, m2 = m2b;
    return;
  }
  const double delta = sb / nb - s / n;
  m2 += m2b + delta * delta * n * nb / (n + nb);
  s += sb;
  n += nb;
}

void sum_to_root(std::vector<float>& values, Stats* stats) {
  if (!distributed()) return;
#ifdef GDR_HAVE_MPI
  wait_for_all(stats);
  ScopedTimer t(nullptr, "");
  for (size_t first = 0; first < values.size(); first += kMaxPiece) {
    const int n = int(std::min(kMaxPiece, values.size() - first));
    float* data = values.data() + first;
    if (root()) {
      MPI_Reduce(MPI_IN_PLACE, data, n, MPI_FLOAT, MPI_SUM, 0, MPI_COMM_WORLD);
    } else {
      MPI_Reduce(data, nullptr, n, MPI_FLOAT, MPI_SUM, 0, MPI_COMM_WORLD);
    }
  }
  record(stats, t.elapsed(), values.size() * sizeof(float));
#else
  (void)stats;
#endif
}

void combine_to_root(Moments& m, Stats* stats) {
  if (!distributed()) return;
  if (m.sum.size() != m.m2.size() || m.sum.size() % 3 != 0) {
    throw Error("combine_to_root: sum and m2 must be RGB layers of the same size");
  }
#ifdef GDR_HAVE_MPI
  // Each pixel travels with its pass count, so that the operation needs nothing but its operands
  // (MPI may hand it any piece of the buffer).
  const size_t pixels = m.sum.size() / 3;
  std::vector<float> packed(pixels * kMomentFloats);
  for (size_t p = 0; p < pixels; ++p) {
    float* e = &packed[kMomentFloats * p];
    e[0] = float(m.passes);
    for (int c = 0; c < 3; ++c) e[1 + c] = m.sum[3 * p + c], e[4 + c] = m.m2[3 * p + c];
  }
  MPI_Datatype pixel;
  MPI_Type_contiguous(kMomentFloats, MPI_FLOAT, &pixel);
  MPI_Type_commit(&pixel);
  MPI_Op op;
  MPI_Op_create(&combine_op, 1, &op);  // commutative: the update is symmetric in its operands
  wait_for_all(stats);
  ScopedTimer t(nullptr, "");
  for (size_t first = 0; first < pixels; first += kMaxPiece) {
    const int n = int(std::min(kMaxPiece, pixels - first));
    float* data = packed.data() + first * kMomentFloats;
    if (root()) {
      MPI_Reduce(MPI_IN_PLACE, data, n, pixel, op, 0, MPI_COMM_WORLD);
    } else {
      MPI_Reduce(data, nullptr, n, pixel, op, 0, MPI_COMM_WORLD);
    }
  }
  MPI_Op_free(&op);
  MPI_Type_free(&pixel);
  if (root()) {
    for (size_t p = 0; p < pixels; ++p) {
      const float* e = &packed[kMomentFloats * p];
      for (int c = 0; c < 3; ++c) m.sum[3 * p + c] = e[1 + c], m.m2[3 * p + c] = e[4 + c];
    }
    if (pixels > 0) m.passes = int(packed[0]);  // every pixel has the same passes
  }
  record(stats, t.elapsed(), packed.size() * sizeof(float));
#else
  (void)stats;
#endif
}

}  // namespace gdr::cluster
