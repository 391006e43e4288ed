// The photons within the merging radius of a point, one at a time, from the hash grid over the
// light-vertex store (bidir/hash_grid.h; each bucket's entries sorted[starts[b], starts[b + 1])).
// Every merging kernel walks them through this, in the same order: the grid's buckets as
// hash_grid_query_cells lists them, each bucket's entries in store order.
#pragma once
#include "bidir/hash_grid.h"
#include "bsdf/bsdf.h"
#include "path/sides.h"

typedef struct PhotonQuery {
  uint cells[8];
  int ncells, c;
  uint i, end;
  float3 p;
  float r2;
} PhotonQuery;

inline PhotonQuery photon_query(float3 p, float radius, uint buckets) {
  PhotonQuery q;
  q.ncells = buckets > 0 ? hash_grid_query_cells(p, radius, buckets, q.cells) : 0;
  q.c = -1;
  q.i = q.end = 0;
  q.p = p;
  q.r2 = radius * radius;
  return q;
}

// The next store entry whose photon lies within the radius; 0 when there is none left.
inline int photon_query_next(PhotonQuery* q, __global const uint* starts, __global const uint* sorted,
                             __global const float4* points, uint* entry) {
  for (;;) {
    while (q->i >= q->end) {
      if (++q->c >= q->ncells) return 0;
      q->i = starts[q->cells[q->c]];
      q->end = starts[q->cells[q->c] + 1];
    }
    uint e = sorted[q->i++];
    float3 d = points[e].xyz - q->p;
    if (dot(d, d) <= q->r2) {
      *entry = e;
      return 1;
    }
  }
}

// A photon arriving along wi (world, toward where it came from) at a camera vertex (BSDF b in
// shading frame f, geometric normal ng, wo_local toward the camera): the density estimate's BSDF
// factor. The estimate counts flux per area, so the BSDF's cosine gives way to the geometric one.
// 0 where wi lies on the side the shading frame disagrees with.
inline float3 photon_merge_value(const Bsdf* b, const Frame* f, float3 ng, float3 wo_local, float3 wi) {
  float3 wi_local = frame_to_local(f, wi);
  float cos_g = fabs(dot(ng, wi));
  if (!sides_agree(wi, ng, wi_local.z) || !(cos_g > 0.0f)) return (float3)(0.0f);
  return bsdf_eval(b, wo_local, wi_local) / cos_g;
}
