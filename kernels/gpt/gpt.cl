// Gradient-domain path tracing (Kettunen et al. 2015) in a wavefront. A group per pixel sample:
// the base path and four offset paths through the neighbouring pixels. Per bounce:
//   gpt_shade  (base at x_k, offsets at their vertices): emission and next-event estimation for
//              all five paths with the pairwise MIS weights, then the base's BSDF sample;
//   host       Embree: the base's next ray, all shadow rays; gpt_shadow adds the unoccluded ones;
//   gpt_shift  (the base's next vertex x_{k+1} is known): each traced offset follows the base's
//              scattering at its own vertex by reconnection, half-vector copy, delta-lobe copy or
//              random-number replay;
//   host       Embree: offset rays, reconnection segments; gpt_scatter files the results;
//              with --shift manifold, the manifold stage solves the walks of offsets that waited
//              for the base's specular chain, and gpt_manifold_join joins them to the base.
// gpt_gather turns a pass's per-group sums into primal, gradient and direct-light images;
// path_aux writes the first hits' auxiliary layers. Each step lives in its own file (the stages
// they share with the path tracer in kernels/path, the shifts in kernels/shift, the offsets and
// the gather in kernels/gradient); this program compiles them together.
#include "gpt/generate.h"
#include "gpt/shade.h"
#include "gpt/shift_step.h"
#include "gradient/gather.h"
#include "path/aux.h"
#include "path/seen_emission.h"
