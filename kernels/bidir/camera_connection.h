// A light subpath's vertex seen by the camera (t = 1): what it sends toward the camera, beta f
// (cos / d^2) cos_theta We, under light tracing's weight over every strategy. The bidirectional
// kernels splat it (bidir/bidir.cl); G-BDPT's light-tracing shift evaluates its offsets with it
// (gbidir/light_tracing.h).
#pragma once
#include "bidir/subpath_mis.h"
#include "bsdf/transport.h"
#include "camera/importance.h"

// Light tracing's MIS weight over every strategy for a vertex (geometric normal ng, BSDF b, frame
// f, direction wo toward its subpath, MIS sums dvcm and dvc) seen as pr.
inline float camera_connection_weight(const GdrCamera* cam, const CameraProjection* pr, const Bsdf* b,
                                      const Frame* f, float3 ng, float3 wo, float dvcm, float dvc,
                                      const GdrBidirOptions* o) {
  float3 wo_l = frame_to_local(f, wo), wc_l = frame_to_local(f, -pr->dir);
  return mis_weight(mis_side(camera_pdf_area(cam, pr, ng), dvcm, dvc, bsdf_pdf(b, wc_l, wo_l), o));
}

// That vertex's connection: returns the BSDF toward the camera with its cosine and shading-normal
// correction; *scale: the factor that makes it the connection's value per unit of the subpath's
// throughput, the camera's importance with light tracing's weight (1 where `weighted` is 0: light
// tracing is the only strategy).
inline float3 camera_connection(const GdrCamera* cam, const CameraProjection* pr, const Bsdf* b, const Frame* f,
                                float3 ng, float3 wo, float dvcm, float dvc, const GdrBidirOptions* o, int weighted,
                                float* scale) {
  float3 wc = -pr->dir, wo_l = frame_to_local(f, wo), wc_l = frame_to_local(f, wc);
  float3 fc = bsdf_eval_transport(b, wo_l, wc_l, TRANSPORT_IMPORTANCE) *
              shading_normal_correction(wo, wc, ng, wo_l.z, wc_l.z);
  float w = weighted ? bidir_weight(o, camera_connection_weight(cam, pr, b, f, ng, wo, dvcm, dvc, o)) : 1.0f;
  *scale = w * pr->cos_theta * camera_we(cam, pr->cos_theta) / (pr->dist * pr->dist);
  return fc;
}
