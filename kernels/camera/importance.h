// Camera importance of the pinhole perspective camera (camera.h), for paths that reach the
// camera from the scene (light tracing, and the t = 1 connections of bidirectional methods):
// the projection of a world point to the film, the importance We and its pdfs, after pbrt-v4's
// PerspectiveCamera::We / PdfWe. The lens is a point (the engine models no aperture), so the
// position pdf is a delta and a connection's area-to-solid-angle factor is cos / d^2 alone.
//
// Units. A is the area of the image on the plane at distance 1 along the view axis,
// A = 4 tan(fov_x / 2) tan(fov_y / 2). A direction at angle theta to the axis has
//   We = 1 / (A cos^4 theta),   pdf_dir = 1 / (A cos^3 theta)   (solid angle),
// so that the integral of We cos theta (and of pdf_dir) over the directions through the image is
// 1. Pixel p of a film of W x H pixels measures I_p = integral of h_p(x) L(x) dx over film
// positions x in pixels, h_p the pixel's normalized filter; a light subpath vertex seen from
// the camera estimates it, with W H light subpaths per pass, by
//   beta f (cos_y / d^2) cos theta We h_p(x)
// (dx in pixels is W H / (A cos^3 theta) d(omega), and the W H cancels the number of paths).
#pragma once
#include "camera/camera.h"

// A point's image on the film, as seen from the camera.
typedef struct CameraProjection {
  float2 raster;   // film position in pixels from the top-left corner (camera_ray's fx, fy)
  float3 dir;      // unit direction from the camera to the point (world)
  float dist;      // distance from the camera to the point
  float cos_theta; // cosine between dir and the view axis
} CameraProjection;

inline float3 camera_position(const GdrCamera* cam) {
  return (float3)(cam->to_world[3], cam->to_world[7], cam->to_world[11]);
}

// Area of the image on the plane at distance 1 (A above).
inline float camera_image_area(const GdrCamera* cam) {
  return 4.0f * cam->tan_half_fov_x * cam->tan_half_fov_y;
}

// The inverse of the camera's 3x3 linear part applied to v (cofactors: the sensor's to_world is a
// rotation for a lookat, but the inverse does not rely on it).
inline float3 camera_to_local_vector(const GdrCamera* cam, float3 v) {
  const float* m = cam->to_world;
  float a = m[0], b = m[1], c = m[2], d = m[4], e = m[5], f = m[6], g = m[8], h = m[9], i = m[10];
  float c00 = e * i - f * h, c01 = c * h - b * i, c02 = b * f - c * e;
  float c10 = f * g - d * i, c11 = a * i - c * g, c12 = c * d - a * f;
  float c20 = d * h - e * g, c21 = b * g - a * h, c22 = a * e - b * d;
  float det = a * c00 + b * c10 + c * c20;
  if (!(fabs(det) > 0.0f)) return (float3)(0.0f);
  float inv = 1.0f / det;
  return (float3)(c00 * v.x + c01 * v.y + c02 * v.z, c10 * v.x + c11 * v.y + c12 * v.z,
                  c20 * v.x + c21 * v.y + c22 * v.z) * inv;
}

// The film positions a camera sample may take: the image, or with sample_border the image
// grown by the filter radius (pt samples border pixels' whole footprints there).
inline int camera_raster_inside(const GdrCamera* cam, float2 raster) {
  float r = cam->sample_border ? cam->filter_radius : 0.0f;
  return raster.x >= -r && raster.x <= (float)cam->width + r && raster.y >= -r && raster.y <= (float)cam->height + r;
}

// Projects world point p onto the film (the inverse of camera_ray). Returns 0 where no camera
// ray reaches p: behind the camera, outside the clip range or outside the film.
inline int camera_project(const GdrCamera* cam, float3 p, CameraProjection* out) {
  float3 o = camera_position(cam);
  float3 d = p - o;
  float dist = length(d);
  if (!(dist > 0.0f) || !isfinite(dist)) return 0;
  float3 l = camera_to_local_vector(cam, d);
  if (!(l.z > 0.0f)) return 0;
  float3 ln = normalize(l);
  float cos_theta = ln.z;
  // camera_ray's clip: tnear = near_clip / cos, tfar = far_clip / cos along the unit direction.
  float depth = dist * cos_theta;
  if (depth < cam->near_clip || depth > cam->far_clip) return 0;
  float x = l.x / l.z, y = l.y / l.z;
  out->raster = (float2)(0.5f * (float)cam->width * (1.0f - x / cam->tan_half_fov_x),
                         0.5f * (float)cam->height * (1.0f - y / cam->tan_half_fov_y));
  if (!camera_raster_inside(cam, out->raster)) return 0;
  out->dir = d / dist;
  out->dist = dist;
  out->cos_theta = cos_theta;
  return 1;
}

// We of a direction at cos_theta to the view axis (0 for directions behind the camera).
inline float camera_we(const GdrCamera* cam, float cos_theta) {
  if (!(cos_theta > 0.0f)) return 0.0f;
  float c2 = cos_theta * cos_theta;
  return 1.0f / (camera_image_area(cam) * c2 * c2);
}

// Cosine between a unit direction leaving the camera and its view axis.
inline float camera_cos_theta(const GdrCamera* cam, float3 dir) {
  float3 l = camera_to_local_vector(cam, dir);
  float len = length(l);
  return len > 0.0f ? l.z / len : 0.0f;
}

// Solid-angle pdf of the camera's direction for a ray drawn uniformly over the image (the
// position pdf is a delta: the pinhole).
inline float camera_pdf_dir(const GdrCamera* cam, float cos_theta) {
  if (!(cos_theta > 0.0f)) return 0.0f;
  return 1.0f / (camera_image_area(cam) * cos_theta * cos_theta * cos_theta);
}

// The camera's area density at a surface point (geometric normal ng) it sees as pr: the
// direction's pdf times the solid angle a unit of that surface subtends.
inline float camera_pdf_area(const GdrCamera* cam, const CameraProjection* pr, float3 ng) {
  return camera_pdf_dir(cam, pr->cos_theta) * fabs(dot(ng, pr->dir)) / (pr->dist * pr->dist);
}

// One axis of a pixel's normalized filter: for pixel p of an axis of `size` pixels at film
// coordinate `raster`, the filter's value at the offset from the pixel's centre over its mass on
// the offsets the pixel samples (filter_range); 0 outside them. `full_mass`: the filter's mass
// over [-r, r] (camera_filter_full_mass), the mass of every pixel whose range the image does
// not cut, passed in so that a loop over pixels computes it once (the gaussian's cdf is costly).
inline float camera_axis_weight_full(const GdrCamera* cam, int p, int size, float raster, float full_mass) {
  float r = cam->filter_radius;
  float t = raster - ((float)p + 0.5f);
  float2 range = filter_range(cam, p, size);
  if (t < range.x || t > range.y) return 0.0f;
  float mass = range.x == -r && range.y == r ? full_mass : filter_mass(cam->filter, r, range);
  return mass > 0.0f ? filter_eval(cam->filter, r, t) / mass : 0.0f;
}

inline float camera_filter_full_mass(const GdrCamera* cam) {
  float r = cam->filter_radius;
  return filter_mass(cam->filter, r, (float2)(-r, r));
}

inline float camera_axis_weight(const GdrCamera* cam, int p, int size, float raster) {
  return camera_axis_weight_full(cam, p, size, raster, camera_filter_full_mass(cam));
}

// Pixel (x, y)'s normalized filter h_p at film position `raster` (the product of its axes), so
// that for each pixel h_p integrates to 1 over the film, as pt's samples of it do.
inline float camera_pixel_weight(const GdrCamera* cam, int x, int y, float2 raster) {
  return camera_axis_weight(cam, x, cam->width, raster.x) * camera_axis_weight(cam, y, cam->height, raster.y);
}

// The pixels whose filter may cover film position `raster`: [lo.x, hi.x] x [lo.y, hi.y],
// clamped to the image.
inline void camera_pixel_footprint(const GdrCamera* cam, float2 raster, int2* lo, int2* hi) {
  float r = cam->filter_radius;
  *lo = (int2)(max((int)floor(raster.x - 0.5f - r), 0), max((int)floor(raster.y - 0.5f - r), 0));
  *hi = (int2)(min((int)ceil(raster.x - 0.5f + r), cam->width - 1), min((int)ceil(raster.y - 0.5f + r), cam->height - 1));
}
