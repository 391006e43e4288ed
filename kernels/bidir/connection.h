// The connection of a camera subpath's vertex z with a light subpath's vertex y (s >= 2 light and
// t >= 2 camera vertices): its value without MIS, the other strategies' share from the two
// vertices' running sums, and the segment whose visibility decides it. bdpt's connections and
// G-BDPT's (base and offsets alike) evaluate it here; G-BDPT's offsets reuse the ends they share
// with the base (connection_end) and, at the base's vertex and direction, its whole evaluation
// (bidir_connection_rejoined).
#pragma once
#include "bidir/subpath_mis.h"
#include "bsdf/transport.h"
#include "path/scene.h"
#include "path/sides.h"
#include "path/spawn.h"
#include "shared/bidir_types.h"

// A subpath vertex's surface, BSDF and shading frame.
typedef struct ConnectionEnd {
  Surface s;
  Bsdf b;
  Frame f;
} ConnectionEnd;

inline ConnectionEnd connection_end(const SceneData* s, const GdrBidirVertex* v) {
  ConnectionEnd e;
  e.s = surface_at(s, v->prim, v->u, v->v);
  e.b = surface_bsdf(s, &e.s);
  e.f = frame_from_normal(e.s.ns);
  return e;
}

typedef struct BidirConnection {
  float3 value;   // throughputs, both BSDFs and the geometry term (0 where the sides disagree)
  float others;   // MIS: the other strategies' share, relative to this one's
  float3 from, from_ng, to;  // the segment: from z (normal from_ng) to just off y
  // What another camera vertex at z's point and direction shares: both BSDFs (f_z 0 where the
  // sides disagree), y's throughput, the squared distance, the light side's share and the camera
  // side's pdfs.
  float3 f_z, f_y, light_throughput;
  float dist2, w_light, camera_pdf_area, camera_pdf_rev;
  float light_pdf_area, light_pdf_rev;  // the light side's pdfs (as the camera side's: mis_side)
} BidirConnection;

// What each side's sums (dvcm, dvc, under o's heuristic) say of connection c's other strategies.
inline float bidir_connection_light_side(const BidirConnection* c, float dvcm, float dvc, const GdrBidirOptions* o) {
  return mis_side(c->light_pdf_area, dvcm, dvc, c->light_pdf_rev, o);
}
inline float bidir_connection_camera_side(const BidirConnection* c, float dvcm, float dvc, const GdrBidirOptions* o) {
  return mis_side(c->camera_pdf_area, dvcm, dvc, c->camera_pdf_rev, o);
}

// Returns 0 where the two points coincide (no connection at all).
inline int bidir_connection_ends(const ConnectionEnd* ez, const GdrBidirVertex* z, const ConnectionEnd* ey,
                                 const GdrBidirVertex* y, const GdrBidirOptions* o, BidirConnection* out) {
  float3 d = ey->s.p - ez->s.p;
  float dist2 = dot(d, d);
  if (!(dist2 > 0.0f)) return 0;
  float dist = sqrt(dist2);
  float3 dir = d / dist;  // from the camera vertex toward the light vertex

  // The camera vertex in radiance transport, with the side check of its light-side direction;
  // the light vertex in importance transport, with the shading-normal correction (as lt's
  // camera connection: bidir_light_shade).
  float3 wo_z = vload3(0, z->wo), wo_y = vload3(0, y->wo);
  float3 wo_z_local = frame_to_local(&ez->f, wo_z), dir_z_local = frame_to_local(&ez->f, dir);
  float3 wo_y_local = frame_to_local(&ey->f, wo_y), dir_y_local = frame_to_local(&ey->f, -dir);
  out->value = (float3)(0.0f);
  out->f_z = (float3)(0.0f);
  out->f_y = (float3)(0.0f);
  out->light_throughput = vload3(0, y->throughput);
  out->dist2 = dist2;
  if (sides_agree(dir, ez->s.ng, dir_z_local.z)) {
    out->f_z = bsdf_eval(&ez->b, wo_z_local, dir_z_local);
    out->f_y = bsdf_eval_transport(&ey->b, wo_y_local, dir_y_local, TRANSPORT_IMPORTANCE) *
               shading_normal_correction(wo_y, -dir, ey->s.ng, wo_y_local.z, dir_y_local.z);
    out->value = vload3(0, z->throughput) * out->f_z * out->f_y * out->light_throughput / dist2;
  }

  // Each side's vertex as the other side's BSDF would have drawn it (area pdfs).
  float pdf_z_fwd = bsdf_pdf(&ez->b, wo_z_local, dir_z_local), pdf_z_rev = bsdf_pdf(&ez->b, dir_z_local, wo_z_local);
  float pdf_y_fwd = bsdf_pdf(&ey->b, wo_y_local, dir_y_local), pdf_y_rev = bsdf_pdf(&ey->b, dir_y_local, wo_y_local);
  out->light_pdf_area = pdf_z_fwd * fabs(dot(ey->s.ng, dir)) / dist2;
  out->light_pdf_rev = pdf_y_rev;
  out->camera_pdf_area = pdf_y_fwd * fabs(dot(ez->s.ng, dir)) / dist2;
  out->camera_pdf_rev = pdf_z_rev;
  out->w_light = bidir_connection_light_side(out, y->dvcm, y->dvc, o);
  out->others = out->w_light + bidir_connection_camera_side(out, z->dvcm, z->dvc, o);
  out->from = ez->s.p;
  out->from_ng = ez->s.ng;
  out->to = leaving_origin(ey->s.p, ey->s.ng, -dir);
  return 1;
}

inline int bidir_connection(const SceneData* s, const GdrBidirVertex* z, const GdrBidirVertex* y,
                            const GdrBidirOptions* o, BidirConnection* out) {
  ConnectionEnd ez = connection_end(s, z), ey = connection_end(s, y);
  return bidir_connection_ends(&ez, z, &ey, y, o, out);
}

// The connection c again, for camera vertex z at c's camera point and direction with its own
// throughput and sums: the value and share bidir_connection_ends gives z, without its evaluation.
inline BidirConnection bidir_connection_rejoined(const BidirConnection* c, const GdrBidirVertex* z,
                                                 const GdrBidirOptions* o) {
  BidirConnection r = *c;
  r.value = vload3(0, z->throughput) * c->f_z * c->f_y * c->light_throughput / c->dist2;
  r.others = c->w_light + bidir_connection_camera_side(c, z->dvcm, z->dvc, o);
  return r;
}
