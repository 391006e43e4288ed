// Proof that kernels/shared/ray_types.h matches Embree's ray structs, member by member.
#pragma once
#include <embree3/rtcore.h>

#include <cstddef>

#include "shared/ray_types.h"

#define GDR_SAME_MEMBER(A, B, a, b) \
  static_assert(offsetof(A, a) == offsetof(B, b), #A "." #a " must sit where " #B "." #b " does")

GDR_SAME_MEMBER(GdrRay, RTCRay, org_x, org_x);
GDR_SAME_MEMBER(GdrRay, RTCRay, tnear, tnear);
GDR_SAME_MEMBER(GdrRay, RTCRay, dir_x, dir_x);
GDR_SAME_MEMBER(GdrRay, RTCRay, tfar, tfar);
GDR_SAME_MEMBER(GdrRay, RTCRay, mask, mask);
GDR_SAME_MEMBER(GdrRay, RTCRay, id, id);
GDR_SAME_MEMBER(GdrRay, RTCRay, flags, flags);
GDR_SAME_MEMBER(GdrHit, RTCHit, Ng_x, Ng_x);
GDR_SAME_MEMBER(GdrHit, RTCHit, u, u);
GDR_SAME_MEMBER(GdrHit, RTCHit, primID, primID);
GDR_SAME_MEMBER(GdrHit, RTCHit, geomID, geomID);
GDR_SAME_MEMBER(GdrHit, RTCHit, instID, instID);
GDR_SAME_MEMBER(GdrRayHit, RTCRayHit, hit, hit);
static_assert(sizeof(GdrRay) == sizeof(RTCRay), "GdrRay must match RTCRay");
static_assert(sizeof(GdrRayHit) == sizeof(RTCRayHit), "GdrRayHit must match RTCRayHit");
static_assert(GDR_INVALID_ID == RTC_INVALID_GEOMETRY_ID, "invalid id must match Embree's");

#undef GDR_SAME_MEMBER
