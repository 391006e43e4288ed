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

// One value's moment set on the wire: passes, sum, m2.
constexpr int kMomentFloats = 3;

#ifdef GDR_HAVE_MPI
// MPI_User_function over MPI_FLOAT triples (the datatype is a contiguous triple).
void combine_op(void* in, void* inout, int* count, MPI_Datatype*) {
  const float* a = static_cast<const float*>(in);
  float* b = static_cast<float*>(inout);
  for (int i = 0; i < *count; ++i, a += kMomentFloats, b += kMomentFloats) {
    double n = b[0], s = b[1], m2 = b[2];
    combine_into(n, s, m2, a[0], a[1], a[2]);
    b[0] = float(n);
    b[1] = float(s);
    b[2] = float(m2);
  }
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
  if (m.sum.size() != m.m2.size()) throw Error("combine_to_root: sum and m2 differ in size");
#ifdef GDR_HAVE_MPI
  ScopedTimer t(nullptr, "");
  // Each value travels with its pass count, so that the operation needs nothing but its operands.
  std::vector<float> packed(m.sum.size() * kMomentFloats);
  for (size_t i = 0; i < m.sum.size(); ++i) {
    packed[kMomentFloats * i + 0] = float(m.passes);
    packed[kMomentFloats * i + 1] = m.sum[i];
    packed[kMomentFloats * i + 2] = m.m2[i];
  }
  MPI_Datatype triple;
  MPI_Type_contiguous(kMomentFloats, MPI_FLOAT, &triple);
  MPI_Type_commit(&triple);
  MPI_Op op;
  MPI_Op_create(&combine_op, 1, &op);  // commutative: the update is symmetric in its operands
  for (size_t first = 0; first < m.sum.size(); first += kMaxPiece) {
    const int n = int(std::min(kMaxPiece, m.sum.size() - first));
    float* data = packed.data() + first * kMomentFloats;
    if (root()) {
      MPI_Reduce(MPI_IN_PLACE, data, n, triple, op, 0, MPI_COMM_WORLD);
    } else {
      MPI_Reduce(data, nullptr, n, triple, op, 0, MPI_COMM_WORLD);
    }
  }
  MPI_Op_free(&op);
  MPI_Type_free(&triple);
  if (root()) {
    int passes = 0;
    for (size_t i = 0; i < m.sum.size(); ++i) {
      passes = int(packed[kMomentFloats * i]);  // 0 for a value no rank had a pass of
      m.sum[i] = packed[kMomentFloats * i + 1];
      m.m2[i] = packed[kMomentFloats * i + 2];
    }
    if (!m.sum.empty()) m.passes = passes;
  }
  record(stats, t.elapsed(), packed.size() * sizeof(float));
#else
  (void)stats;
#endif
}

}  // namespace gdr::cluster
