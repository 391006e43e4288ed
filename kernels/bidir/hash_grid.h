// The hash grid over light vertices for merging (SmallVCM's src/hashgrid.hxx): cells of twice
// the merging radius, hashed into `buckets` buckets; a query at p visits the 2 x 2 x 2 cells
// that the ball of radius r about p can reach (p's cell and, per axis, the neighbour on the side
// of p's half of it). Each bucket is visited once even where two cells hash to it (no merge
// counted twice); distinct cells sharing a bucket only add candidates, which the distance test
// rejects. The buckets' lists are built by the sort by key (kernels/wavefront/scan.cl).
#pragma once

inline int4 hash_grid_cell(float3 p, float radius) {
  float3 c = floor(p / (2.0f * radius));
  return (int4)(convert_int_sat(c.x), convert_int_sat(c.y), convert_int_sat(c.z), 0);
}

inline uint hash_grid_bucket(int4 c, uint buckets) {
  uint h = ((uint)c.x * 73856093u) ^ ((uint)c.y * 19349663u) ^ ((uint)c.z * 83492791u);
  return h % buckets;
}

// The buckets to visit for a query at p; returns their count (at most 8, distinct).
inline int hash_grid_query_cells(float3 p, float radius, uint buckets, uint* out) {
  float3 g = p / (2.0f * radius), f = floor(g);
  int4 c = (int4)(convert_int_sat(f.x), convert_int_sat(f.y), convert_int_sat(f.z), 0);
  float3 frac = g - f;
  int4 o = (int4)(frac.x < 0.5f ? -1 : 1, frac.y < 0.5f ? -1 : 1, frac.z < 0.5f ? -1 : 1, 0);
  int n = 0;
  for (int k = 0; k < 8; ++k) {
    int4 cell = c + (int4)((k & 1) ? o.x : 0, (k & 2) ? o.y : 0, (k & 4) ? o.z : 0, 0);
    uint b = hash_grid_bucket(cell, buckets);
    int seen = 0;
    for (int i = 0; i < n; ++i) seen |= out[i] == b;
    if (!seen) out[n++] = b;
  }
  return n;
}
