// Ray queues shared by the kernels and Embree: the layouts of Embree 3's RTCRay, RTCHit and
// RTCRayHit, so the host intersects a kernel-written queue in place (no repacking; zero-copy on
// CPU devices). Checked against Embree's headers in engine/accel/ray_layout.h.
#pragma once

typedef struct GdrRay {
  float org_x, org_y, org_z;
  float tnear;
  float dir_x, dir_y, dir_z;
  float time;
  float tfar;  // Embree sets it to -inf when an occlusion ray is blocked
  unsigned int mask;
  unsigned int id;  // the path slot the ray belongs to
  unsigned int flags;
} GdrRay;

typedef struct GdrHit {
  float Ng_x, Ng_y, Ng_z;  // unnormalized geometric normal from Embree
  float u, v;              // barycentrics of vertices 1 and 2
  unsigned int primID;     // triangle index
  unsigned int geomID;     // GDR_INVALID_ID when the ray missed
  unsigned int instID;
} GdrHit;

typedef struct GdrRayHit {
  GdrRay ray;
  GdrHit hit;
} GdrRayHit;

#define GDR_INVALID_ID 0xFFFFFFFFu
