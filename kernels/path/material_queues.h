// Per-material queues (pbrt-v4's wavefront design, wavefront/intersect.h and surfscatter.cpp):
// after an intersection each hit is routed by its material's BSDF type, and one kernel per type
// the scene has shades that type's queue. The kernels are one body specialized per type: the
// BSDF's type is a constant there (surface_bsdf_of_type), so each kernel holds only its own
// material's code and no switch over the others, where the constant reaches the switch: PoCL
// keeps larger functions as calls, so the BSDF's entry points, next-event sampling and the light
// connection are always_inline (the continuation's sampling stays a call: inlined, G-PT's kernels
// ran slower).
// GDR_MATERIAL_QUEUES(X) expands X(name, TYPE) for every type the build selects (a scene build:
// the scene's types; kernels named <stage>_<name>, the host's MaterialQueues launches them by
// that name).
#pragma once
#include "path/scene.h"

// The queue a hit on triangle `prim` goes to: its material's BSDF type.
inline uint material_queue_key(const SceneData* s, uint prim) {
  return (uint)s->materials[s->shapes[s->triangles[prim].shape].material].type;
}
// The key of an entry in no material queue (a miss).
#define MATERIAL_QUEUE_NONE ((uint)BSDF_TYPE_COUNT)

// The BSDF at su as a kernel specialized for `type` sees it (the hit's material is of that type).
inline Bsdf surface_bsdf_of_type(const SceneData* s, const Surface* su, int type) {
  Bsdf b = surface_bsdf(s, su);
  b.type = type;
  return b;
}
// The same in a kernel built for a routed queue (`type` >= 0) or for every type (`type` < 0: the
// queue was not routed). `type` is a constant in each kernel: the branch folds.
inline Bsdf surface_bsdf_queued(const SceneData* s, const Surface* su, int type) {
  return type < 0 ? surface_bsdf(s, su) : surface_bsdf_of_type(s, su, type);
}

#if !defined(GDR_BSDF_SELECTED) || defined(GDR_BSDF_DIFFUSE)
#define GDR_QUEUE_DIFFUSE(X) X(diffuse, BSDF_DIFFUSE)
#else
#define GDR_QUEUE_DIFFUSE(X)
#endif
#if !defined(GDR_BSDF_SELECTED) || defined(GDR_BSDF_CONDUCTOR)
#define GDR_QUEUE_CONDUCTOR(X) X(conductor, BSDF_CONDUCTOR)
#else
#define GDR_QUEUE_CONDUCTOR(X)
#endif
#if !defined(GDR_BSDF_SELECTED) || defined(GDR_BSDF_ROUGH_CONDUCTOR)
#define GDR_QUEUE_ROUGH_CONDUCTOR(X) X(roughconductor, BSDF_ROUGH_CONDUCTOR)
#else
#define GDR_QUEUE_ROUGH_CONDUCTOR(X)
#endif
#if !defined(GDR_BSDF_SELECTED) || defined(GDR_BSDF_DIELECTRIC)
#define GDR_QUEUE_DIELECTRIC(X) X(dielectric, BSDF_DIELECTRIC)
#else
#define GDR_QUEUE_DIELECTRIC(X)
#endif
#if !defined(GDR_BSDF_SELECTED) || defined(GDR_BSDF_THIN_DIELECTRIC)
#define GDR_QUEUE_THIN_DIELECTRIC(X) X(thindielectric, BSDF_THIN_DIELECTRIC)
#else
#define GDR_QUEUE_THIN_DIELECTRIC(X)
#endif
#if !defined(GDR_BSDF_SELECTED) || defined(GDR_BSDF_ROUGH_DIELECTRIC)
#define GDR_QUEUE_ROUGH_DIELECTRIC(X) X(roughdielectric, BSDF_ROUGH_DIELECTRIC)
#else
#define GDR_QUEUE_ROUGH_DIELECTRIC(X)
#endif
#if !defined(GDR_BSDF_SELECTED) || defined(GDR_BSDF_PLASTIC)
#define GDR_QUEUE_PLASTIC(X) X(plastic, BSDF_PLASTIC)
#else
#define GDR_QUEUE_PLASTIC(X)
#endif
#if !defined(GDR_BSDF_SELECTED) || defined(GDR_BSDF_ROUGH_PLASTIC)
#define GDR_QUEUE_ROUGH_PLASTIC(X) X(roughplastic, BSDF_ROUGH_PLASTIC)
#else
#define GDR_QUEUE_ROUGH_PLASTIC(X)
#endif

#define GDR_MATERIAL_QUEUES(X)                                                                      \
  GDR_QUEUE_DIFFUSE(X) GDR_QUEUE_CONDUCTOR(X) GDR_QUEUE_ROUGH_CONDUCTOR(X) GDR_QUEUE_DIELECTRIC(X) \
  GDR_QUEUE_THIN_DIELECTRIC(X) GDR_QUEUE_ROUGH_DIELECTRIC(X) GDR_QUEUE_PLASTIC(X) GDR_QUEUE_ROUGH_PLASTIC(X)
