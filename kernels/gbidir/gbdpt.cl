// Gradient-domain bidirectional path tracing (Manzi et al. 2015) in a wavefront: G-PT's groups
// (a base camera subpath and four offsets through the neighbouring pixels, shifted by G-PT's
// shifts) are the camera subpaths, and each group connects to one light subpath of the
// bidirectional kernels (bidir/bidir.cl, traced first). Built with GDR_GBDPT, G-PT's steps weigh
// every strategy by G-BDPT's MIS (gbidir/weights.h), carry the bidirectional sums and record each
// rough camera vertex; per bounce the host then runs gbdpt_connect once per stored light vertex.
// Light tracing (t = 1) is shifted from its splat pixel after each light bounce
// (gbidir/light_tracing.h).
#include "gbidir/connect.h"
#include "gbidir/light_tracing.h"
#include "gpt/generate.h"
#include "gpt/shade.h"
#include "gpt/shift_step.h"
#include "gradient/gather.h"
#include "path/aux.h"
#include "path/seen_emission.h"
