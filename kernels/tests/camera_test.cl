// Camera importance for the host tests (kernels/camera/importance.h): the host draws the inputs
// and does the statistics; every value comes from the kernels.
#include "camera/importance.h"

// For film position raster[i].xy and distance raster[i].z along its camera ray: the ray's point
// projected back. out[i] = (raster x, raster y, projected (1) or not (0), cos theta).
__kernel void camera_round_trip(__global const GdrCamera* camera, uint n, __global const float4* raster,
                                __global float4* out) {
  uint i = get_global_id(0);
  if (i >= n) return;
  GdrCamera cam = *camera;
  float3 o, d;
  float tnear, tfar;
  camera_ray(&cam, raster[i].x, raster[i].y, &o, &d, &tnear, &tfar);
  CameraProjection pr;
  int ok = camera_project(&cam, o + raster[i].z * d, &pr);
  out[i] = ok ? (float4)(pr.raster, 1.0f, pr.cos_theta) : (float4)(0.0f);
}

// For world direction dir[i] from the camera (the point at distance `dist` along it): (raster x, raster y, inside the film (1) or not,
// cos theta) and (We, pdf_dir, 0, 0).
__kernel void camera_importance(__global const GdrCamera* camera, float dist, uint n, __global const float4* dir,
                                __global float4* raster, __global float4* importance) {
  uint i = get_global_id(0);
  if (i >= n) return;
  GdrCamera cam = *camera;
  CameraProjection pr;
  int ok = camera_project(&cam, camera_position(&cam) + dist * dir[i].xyz, &pr);
  raster[i] = ok ? (float4)(pr.raster, 1.0f, pr.cos_theta) : (float4)(0.0f);
  importance[i] = ok ? (float4)(camera_we(&cam, pr.cos_theta), camera_pdf_dir(&cam, pr.cos_theta), 0.0f, 0.0f)
                     : (float4)(0.0f);
}

// out[y * width + x] = sum over the film positions raster[0 .. n) of pixel (x, y)'s normalized
// filter, gathered over camera_pixel_footprint as a splat would.
__kernel void camera_pixel_weights(__global const GdrCamera* camera, uint n, __global const float2* raster,
                                   __global float* out) {
  if (get_global_id(0) != 0) return;
  GdrCamera cam = *camera;
  for (uint i = 0; i < n; ++i) {
    int2 lo, hi;
    camera_pixel_footprint(&cam, raster[i], &lo, &hi);
    for (int y = lo.y; y <= hi.y; ++y)
      for (int x = lo.x; x <= hi.x; ++x) out[y * cam.width + x] += camera_pixel_weight(&cam, x, y, raster[i]);
  }
}

// The filter's one-axis sampling (kernels/camera/camera.h): t[i] drawn from u[i] over [lo, hi].
__kernel void camera_filter_samples(int filter, float r, float lo, float hi, uint n, __global const float* u,
                                    __global float* t) {
  uint i = get_global_id(0);
  if (i < n) t[i] = sample_filter_axis(filter, r, (float2)(lo, hi), u[i]);
}

// The filter's value at t[i].
__kernel void camera_filter_values(int filter, float r, uint n, __global const float* t, __global float* out) {
  uint i = get_global_id(0);
  if (i < n) out[i] = filter_eval(filter, r, t[i]);
}

// The area density by finite differences: for in[2 i] = (film x, film y, distance along the ray)
// and in[2 i + 1] = a surface normal there, out[i] = (camera_pdf_area at the point; the film area,
// in pixels, that a small square of the surface about the point projects to, over the square's
// area). The two agree up to one factor, the film's pixels per unit of the image's area.
__kernel void camera_pdf_area_fd(__global const GdrCamera* camera, uint count, __global const float4* in,
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
  out[i] = (float2)(camera_pdf_area(&cam, &pr, n), 0.5f * fabs(a) / (4.0f * h * h));
}
