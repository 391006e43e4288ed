// Gradient-domain photon mapping (Hua et al. 2017) in a wavefront: G-PT's groups (a base camera
// subpath and four offsets through the neighbouring pixels, shifted by G-PT's shifts) are the
// camera subpaths, ending at the base's first rough vertex, the visible point (built with GDR_GPM:
// gpt/shade.h); the photons are the bidirectional kernels' light subpaths of the pass
// (bidir/bidir.cl, traced first, with their hash grid). After each shade step the host merges
// the visible points recorded there: gpm_count, gpm_shift_rays, Embree, gpm_merge
// (gbidir/merge.h, the photon shift in gbidir/photon_shift.h).
#include "gbidir/merge.h"
#include "gpt/generate.h"
#include "gpt/shade.h"
#include "gpt/shift_step.h"
#include "gradient/gather.h"
#include "path/aux.h"
#include "path/seen_emission.h"
