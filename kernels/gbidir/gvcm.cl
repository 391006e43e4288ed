// Gradient-domain vertex connection and merging (Sun et al. 2017) in a wavefront: G-BDPT's groups
// and connections (gbidir/gbdpt.cl), built with GDR_GVCM too: the bidirectional sums carry
// merging's factors, every rough camera vertex is recorded, and after its connections the host
// merges it with the pass's photons (the light subpaths of all groups, in their hash grid) by the
// merge stage G-PM uses (gbidir/merge.h), under G-VCM's weights over every strategy.
#include "gbidir/connect.h"
#include "gbidir/light_tracing.h"
#include "gbidir/merge.h"
#include "gpt/generate.h"
#include "gpt/shade.h"
#include "gpt/shift_step.h"
#include "gradient/gather.h"
#include "path/aux.h"
#include "path/seen_emission.h"
