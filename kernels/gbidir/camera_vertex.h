// G-BDPT's record of a rough camera vertex of a group (shared/gbidir_types.h): written by the shade
// step (gpt/shade.h built with GDR_GBDPT), read by the connections (gbidir/connect.h). G-PM records
// its visible points the same way (GDR_GPM; read by gbidir/merge.h).
#pragma once
#include "gradient/offsets.h"
#include "path/scene.h"
#include "shared/gbidir_types.h"
#include "shared/gpt_types.h"
#include "shift/policy.h"

// Whether a camera vertex of `depth` scatterings before it can still connect to a light
// subpath's vertex (one more segment each side at least; max_depth in segments, < 0: unbounded).
inline int gbdpt_connects_at(int depth, int max_depth) { return max_depth < 0 || depth + 3 <= max_depth; }
// Whether a visible point of `depth` scatterings before it can merge with a photon (one more
// segment from the light at least).
inline int gpm_merges_at(int depth, int max_depth) { return max_depth < 0 || depth + 2 <= max_depth; }
// Whether G-BDPT's shade step records a rough camera vertex: to connect it, and for G-VCM also to
// merge there.
inline int gbdpt_records_at(int depth, int max_depth) {
#if defined(GDR_GVCM)
  return gpm_merges_at(depth, max_depth);
#else
  return gbdpt_connects_at(depth, max_depth);
#endif
}

inline GdrBidirVertex gbdpt_vertex(uint prim, float u, float v, float3 wo, float3 throughput, const GbdptSums* m,
                                   int depth) {
  GdrBidirVertex x;
  x.prim = prim;
  x.u = u;
  x.v = v;
  vstore3(wo, 0, x.wo);
  vstore3(throughput, 0, x.throughput);
  x.dvcm = m->dvcm;
  x.dvc = m->dvc;
  x.dvm = m->dvm;
  x.power_dvcm = m->power_dvcm;
  x.power_dvc = m->power_dvc;
  x.depth = depth;
  return x;
}

// The base at hit h (toward its previous vertex wo, throughput beta, diffuse or not) with its
// offsets o at their vertices so (toward their previous vertices wo_off). A traced offset connects
// by reconnection, as the shift would go on from a pair of diffuse vertices; from any other pair
// the shift copies the half vector, which no connection to a given light vertex follows.
inline GbdptCameraVertex gbdpt_camera_vertex(const SceneData* s, const GdrHit* h, float3 wo, float3 beta,
                                             const GptBaseState* base, int diffuse, const GptOffsetState* o,
                                             const Surface* so, const float3* wo_off, float threshold) {
  GbdptCameraVertex r;
  int depth = base->path.depth + 1;
  r.base = gbdpt_vertex(h->primID, h->u, h->v, wo, beta, &base->mis, depth);
  r.all_dvcm[0] = base->mis.all_dvcm;
  r.all_dvc[0] = base->mis.all_dvc;
  r.all_dvm[0] = base->mis.all_dvm;
  for (int k = 0; k < GPT_OFFSETS; ++k) {
    float3 thr = vload3(0, o[k].throughput);
    r.ratio[k] = o[k].ratio;
    r.state[k] = GBDPT_OFFSET_NONE;
    r.offset[k] = r.base;
    if (o[k].mode == GPT_MODE_JOINED || o[k].mode == GPT_MODE_JOINED_RECENT) {
      r.state[k] = GBDPT_OFFSET_SHARED;
      r.offset[k] = gbdpt_vertex(h->primID, h->u, h->v, wo_off[k], thr, &o[k].mis, depth);
    } else if (o[k].mode == GPT_MODE_TRACE) {
      Bsdf bo = surface_bsdf(s, &so[k]);
      r.state[k] = diffuse && is_diffuse(&bo, threshold) ? GBDPT_OFFSET_OWN : GBDPT_OFFSET_GLOSSY;
      r.offset[k] = gbdpt_vertex(o[k].prim, o[k].b1, o[k].b2, wo_off[k], thr, &o[k].mis, depth);
    }
    r.all_dvcm[1 + k] = o[k].mis.all_dvcm;
    r.all_dvc[1 + k] = o[k].mis.all_dvc;
    r.all_dvm[1 + k] = o[k].mis.all_dvm;
  }
  return r;
}
