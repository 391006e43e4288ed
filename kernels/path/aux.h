// Auxiliary layers from the camera rays' first hits (for denoisers and inspection): albedo (the
// diffuse reflectance, or the specular scale of a material without one), shading normal and
// distance. Misses add zero. Ray i of the queue traces pixel params.first_pixel + its id.
#pragma once
#include "path/scene.h"
#include "shared/ray_types.h"

__kernel void path_aux(GdrPtParams params, uint count, __global const GdrRayHit* rays, __global float4* albedo,
                       __global float4* normal, __global float* depth, SCENE_DATA_ARGS) {
  uint i = get_global_id(0);
  if (i >= count) return;
  GdrRayHit rh = rays[i];
  if (rh.hit.geomID == GDR_INVALID_ID) return;
  SceneData s = path_scene(&params, SCENE_DATA_NAMES);
  Surface su = surface_at(&s, rh.hit.primID, rh.hit.u, rh.hit.v);
  Bsdf b = surface_bsdf(&s, &su);
  float3 a = bsdf_has_diffuse_lobe(&b) ? b.diffuse : b.specular_r;
  uint pixel = params.first_pixel + rh.ray.id;
  albedo[pixel] += (float4)(a, 0.0f);
  normal[pixel] += (float4)(su.ns, 0.0f);
  depth[pixel] += rh.ray.tfar;
}
