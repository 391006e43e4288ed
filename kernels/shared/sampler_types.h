// Where a path's primary-sample-space numbers lie when Metropolis chains (kernels/mlt) drive the
// bidirectional kernels or G-PT's groups, for the sampler seam (sampling/path_sampler.h). A
// chain's state holds `blocks` blocks of four dimensions. For bidirectional paths they are ordered
// by the path length that first reads them (sampling/dimensions.h: primary_block_index), so that
// a path of n segments reads the first GDR_PRIMARY_BLOCKS(n) blocks alone and a mutation need
// only touch those; camera paths alone (camera_only) hold the camera's blocks in their order.
#pragma once

typedef struct GdrPrimaryLayout {
  unsigned int chains;       // 0: no chains, paths draw from the counter-based generator
  unsigned int blocks;       // per chain; dimension d of chain c at d * chains + c
  unsigned int camera_only;  // 1: camera paths alone (G-PT's groups): block b of the camera at b
  unsigned int pad0;
} GdrPrimaryLayout;

// The blocks a path of at most n segments reads: the strategy block; the camera subpath's block
// 0 (film position) and, while another segment may follow its vertex at depth d (d <= n - 2),
// blocks 1 + 2d (light sample) and 2 + 2d (BSDF sample); the light subpath's two emission blocks
// and one a bounce while two more segments may follow (depth <= n - 3). That is 4 at n = 1 and
// 3n from n = 2 on: each length adds two camera blocks and (from n = 3) one light block.
#define GDR_PRIMARY_BLOCKS(n) ((n) < 2 ? 4 : 3 * (n))
// The blocks a camera path of at most n segments reads alone (camera_only).
#define GDR_PRIMARY_CAMERA_BLOCKS(n) (2 * (n) - 1)
