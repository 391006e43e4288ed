// Test kernel for G-BDPT's light-tracing shift (kernels/gbidir/light_tracing.h): a light vertex
// shifted to another point and back.
#include "gbidir/light_tracing.h"

// For each store entry e of a traced batch (vertex j of subpath slot at j * stride + slot, below
// `stored` of its subpath) that the camera sees (occlusion aside), x: the vertex is shifted to
// the point of entry j of one of the next subpaths that the camera sees (y1: any rough point,
// sharing x's parent), and y back to x1. out[e] = (R(x -> y) R(y -> x), the reverse's value over x's own
// light-tracing value times R(y -> x), 0, 0): both 1 for a shift whose densities and Jacobians
// invert and whose re-aimed sums give x's own weight back. kind[e]: x's parent (GPM_PARENT_*),
// -1 where the pair was not formed.
__kernel void lt_offset_round_trip(GdrPtParams params, GdrBidirOptions opts, uint entries, uint stride,
                                   __global const GdrCamera* camera, __global const GdrBidirPathState* light_paths,
                                   __global const GdrBidirVertex* store, __global const GdrLightOrigin* origins,
                                   __global float4* out, __global int* kind, SCENE_DATA_ARGS) {
  uint e = get_global_id(0);
  if (e >= entries) return;
  uint j = e / stride, slot = e % stride;
  kind[e] = -1;
  out[e] = (float4)(0.0f);
  if (slot >= params.pixel_count || (int)j >= light_paths[slot].stored) return;
  SceneData s = path_scene(&params, SCENE_DATA_NAMES);
  GdrCamera cam = *camera;
  GdrBidirVertex x = store[e], src;
  PhotonParent pa = photon_parent(&s, store, origins, stride, e, &x);
  CameraProjection pr;
  Surface sx = surface_at(&s, x.prim, x.u, x.v), sy;
  if (pa.kind == GPM_PARENT_NONE || !camera_project(&cam, sx.p, &pr)) return;
  int found = 0;
  for (uint t = 1; t <= 64 && !found; ++t) {
    uint other = (slot + t) % params.pixel_count;
    if ((int)j >= light_paths[other].stored) continue;
    src = store[j * stride + other];
    sy = surface_at(&s, src.prim, src.u, src.v);
    CameraProjection po;
    found = camera_project(&cam, sy.p, &po);
  }
  if (!found) return;
  GdrBidirVertex y, back;
  float3 v, v2;
  float r, r2;
  if (!lt_offset(&s, &cam, &opts, &pa, &x, &sx, &sy, &y, &v, &r)) return;
  y.prim = src.prim;
  y.u = src.u;
  y.v = src.v;
  if (!lt_offset(&s, &cam, &opts, &pa, &y, &sy, &sx, &back, &v2, &r2)) return;
  // x's own light-tracing value, as bidir_light_shade splats it.
  Bsdf b = surface_bsdf(&s, &sx);
  Frame f = frame_from_normal(sx.ns);
  float3 wo = vload3(0, x.wo), wc = -pr.dir, wo_l = frame_to_local(&f, wo), wc_l = frame_to_local(&f, wc);
  float3 fx = bsdf_eval_transport(&b, wo_l, wc_l, TRANSPORT_IMPORTANCE) *
              shading_normal_correction(wo, wc, sx.ng, wo_l.z, wc_l.z);
  float w = bidir_weight(&opts, mis_weight(mis_side(lt_camera_density(&cam, &pr, sx.ng), x.dvcm, x.dvc,
                                                    bsdf_pdf(&b, wc_l, wo_l), &opts)));
  float3 c = vload3(0, x.throughput) * fx * (w * pr.cos_theta * camera_we(&cam, pr.cos_theta) / (pr.dist * pr.dist));
  float expect = (c.x + c.y + c.z) * r2;
  if (!(expect > 0.0f)) return;
  kind[e] = pa.kind;
  out[e] = (float4)(r * r2, (v2.x + v2.y + v2.z) / expect, 0.0f, 0.0f);
}

// The film shift's Jacobian by finite differences: for in[2 i] = (film x, film y, distance along the
// ray) and in[2 i + 1] = a surface normal there, out[i] = (the camera's area density at the point,
// lt_camera_density; the film area, in pixels, that a small square of the surface about the point
// projects to, over the square's area). The Jacobian pc(x) / pc(y) of light tracing's shift holds
// where the two agree up to one factor for every point (pixels per unit of the image's area).
__kernel void lt_camera_density_fd(__global const GdrCamera* camera, uint count, __global const float4* in,
                                   __global float2* out) {
  uint i = get_global_id(0);
  if (i >= count) return;
  GdrCamera cam = *camera;
  float3 o, d;
  float tnear, tfar;
  camera_ray(&cam, in[2 * i].x, in[2 * i].y, &o, &d, &tnear, &tfar);
  float3 p = o + in[2 * i].z * d, n = normalize(in[2 * i + 1].xyz);
  CameraProjection pr;
  out[i] = (float2)(0.0f);
  // Grazing squares (their film area a small difference of large terms) are left out.
  if (!camera_project(&cam, p, &pr) || fabs(dot(n, pr.dir)) < 0.3f) return;
  Frame f = frame_from_normal(n);
  float h = 1e-3f * pr.dist;
  float2 c[4];
  for (int k = 0; k < 4; ++k) {
    float3 q = p + f.s * (k == 1 || k == 2 ? h : -h) + f.t * (k >= 2 ? h : -h);
    CameraProjection pq;
    if (!camera_project(&cam, q, &pq)) return;
    c[k] = pq.raster;
  }
  // The film quad's area (shoelace, about its first corner: the corners lie a fraction of a pixel
  // apart), over the square's 4 h^2.
  float a = 0.0f;
  for (int k = 1; k < 3; ++k) {
    float2 e = c[k] - c[0], e2 = c[k + 1] - c[0];
    a += e.x * e2.y - e2.x * e.y;
  }
  out[i] = (float2)(lt_camera_density(&cam, &pr, n), 0.5f * fabs(a) / (4.0f * h * h));
}
