// The connection of a camera subpath's vertex z with a light subpath's vertex y (s >= 2 light and
// t >= 2 camera vertices): its value without MIS, the other strategies' share from the two
// vertices' running sums, and the segment whose visibility decides it. bdpt's connections and
// G-BDPT's (base and offsets alike) evaluate it here.
#pragma once
#include "bidir/subpath_mis.h"
#include "bsdf/transport.h"
#include "path/scene.h"
#include "path/sides.h"
#include "path/spawn.h"
#include "shared/bidir_types.h"

typedef struct BidirConnection {
  float3 value;   // throughputs, both BSDFs and the geometry term (0 where the sides disagree)
  float others;   // MIS: the other strategies' share, relative to this one's
  float3 from, from_ng, to;  // the segment: from z (normal from_ng) to just off y
} BidirConnection;

// Returns 0 where the two points coincide (no connection at all).
inline int bidir_connection(const SceneData* s, const GdrBidirVertex* z, const GdrBidirVertex* y,
                            const GdrBidirOptions* o, BidirConnection* out) {
  Surface sz = surface_at(s, z->prim, z->u, z->v), sy = surface_at(s, y->prim, y->u, y->v);
  float3 d = sy.p - sz.p;
  float dist2 = dot(d, d);
  if (!(dist2 > 0.0f)) return 0;
  float dist = sqrt(dist2);
  float3 dir = d / dist;  // from the camera vertex toward the light vertex

  // The camera vertex in radiance transport, with the side check of its light-side direction;
  // the light vertex in importance transport, with the shading-normal correction (as lt's
  // camera connection: bidir_light_shade).
  Bsdf bz = surface_bsdf(s, &sz), by = surface_bsdf(s, &sy);
  Frame fz = frame_from_normal(sz.ns), fy = frame_from_normal(sy.ns);
  float3 wo_z = vload3(0, z->wo), wo_y = vload3(0, y->wo);
  float3 wo_z_local = frame_to_local(&fz, wo_z), dir_z_local = frame_to_local(&fz, dir);
  float3 wo_y_local = frame_to_local(&fy, wo_y), dir_y_local = frame_to_local(&fy, -dir);
  out->value = (float3)(0.0f);
  if (sides_agree(dir, sz.ng, dir_z_local.z)) {
    float3 f_z = bsdf_eval(&bz, wo_z_local, dir_z_local);
    float3 f_y = bsdf_eval_transport(&by, wo_y_local, dir_y_local, TRANSPORT_IMPORTANCE) *
                 shading_normal_correction(wo_y, -dir, sy.ng, wo_y_local.z, dir_y_local.z);
    out->value = vload3(0, z->throughput) * f_z * f_y * vload3(0, y->throughput) / dist2;
  }

  // Each side's vertex as the other side's BSDF would have drawn it (area pdfs).
  float pdf_z_fwd = bsdf_pdf(&bz, wo_z_local, dir_z_local), pdf_z_rev = bsdf_pdf(&bz, dir_z_local, wo_z_local);
  float pdf_y_fwd = bsdf_pdf(&by, wo_y_local, dir_y_local), pdf_y_rev = bsdf_pdf(&by, dir_y_local, wo_y_local);
  float w_light = mis_side(pdf_z_fwd * fabs(dot(sy.ng, dir)) / dist2, y->dvcm, y->dvc, pdf_y_rev, o);
  float w_camera = mis_side(pdf_y_fwd * fabs(dot(sz.ng, dir)) / dist2, z->dvcm, z->dvc, pdf_z_rev, o);
  out->others = w_light + w_camera;
  out->from = sz.p;
  out->from_ng = sz.ng;
  out->to = leaving_origin(sy.p, sy.ng, -dir);
  return 1;
}
