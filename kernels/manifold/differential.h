// Differential geometry at a chain vertex: what the constraint derivative needs. A vertex moves
// in its triangle's plane, parametrized by an orthonormal basis (dpdu along the first edge, dpdv
// = ng x dpdu), so that 2x2 determinants measure area; the shading normal, interpolated from the
// mesh's vertex normals, turns by dndu and dndv along them (zero on a flat-shaded triangle).
// Spheres and other analytic shapes are tessellated at load (scene/shapes_analytic), so their
// vertex normals carry their curvature here too.
#pragma once
#include "manifold/precision.h"
#include "scene/surface.h"
#include "shared/manifold_types.h"

typedef struct ManifoldSurface {
  mreal3 p;           // position
  mreal3 n;           // shading normal
  mreal3 ng;          // geometric normal, on the side of n
  mreal3 dpdu, dpdv;  // orthonormal basis of the triangle's plane
  mreal3 dndu, dndv;  // change of n along dpdu and dpdv
  mreal3 s, t;        // the manifold frame: s = dpdu projected perpendicular to n, t = n x s
  mreal s_len;        // length of dpdu's projection before normalizing (0: n lies in the plane)
  int shape, material;
} ManifoldSurface;

inline mreal3 manifold_position(const SceneData* sd, GdrManifoldPoint q) {
  GdrTriangle tri = sd->triangles[q.prim];
  mreal3 p0 = to_mreal3(sd->positions[tri.v[0]].xyz), p1 = to_mreal3(sd->positions[tri.v[1]].xyz),
         p2 = to_mreal3(sd->positions[tri.v[2]].xyz);
  return p0 + (mreal)q.b1 * (p1 - p0) + (mreal)q.b2 * (p2 - p0);
}

inline float3 manifold_point_on(const SceneData* sd, GdrManifoldPoint q) {
  GdrTriangle tri = sd->triangles[q.prim];
  float3 p0 = sd->positions[tri.v[0]].xyz, p1 = sd->positions[tri.v[1]].xyz, p2 = sd->positions[tri.v[2]].xyz;
  return p0 + q.b1 * (p1 - p0) + q.b2 * (p2 - p0);
}

// The point where the ray o + t d meets triangle `prim`'s plane, with its barycentrics computed
// in mreal: Embree's own barycentrics are accurate to about 1e-4 only (a fast reciprocal), too
// coarse for a walk that converges to 1e-6 of the scene's size.
inline GdrManifoldPoint manifold_refine_hit(const SceneData* sd, uint prim, float3 of, float3 df) {
  GdrTriangle tri = sd->triangles[prim];
  mreal3 p0 = to_mreal3(sd->positions[tri.v[0]].xyz), p1 = to_mreal3(sd->positions[tri.v[1]].xyz),
         p2 = to_mreal3(sd->positions[tri.v[2]].xyz);
  mreal3 o = to_mreal3(of), d = to_mreal3(df);
  mreal3 e1 = p1 - p0, e2 = p2 - p0, n = cross(e1, e2);
  mreal t = dot(p0 - o, n) / dot(d, n);
  mreal3 q = o + t * d - p0;
  mreal d11 = dot(e1, e1), d12 = dot(e1, e2), d22 = dot(e2, e2), q1 = dot(q, e1), q2 = dot(q, e2);
  mreal det = d11 * d22 - d12 * d12;
  GdrManifoldPoint r = {prim, (float)((d22 * q1 - d12 * q2) / det), (float)((d11 * q2 - d12 * q1) / det)};
  return r;
}

inline int manifold_shape(const SceneData* sd, GdrManifoldPoint q) { return sd->triangles[q.prim].shape; }

inline ManifoldSurface manifold_surface(const SceneData* sd, GdrManifoldPoint q) {
  GdrTriangle tri = sd->triangles[q.prim];
  GdrShape shape = sd->shapes[tri.shape];
  ManifoldSurface m;
  mreal3 p0 = to_mreal3(sd->positions[tri.v[0]].xyz), p1 = to_mreal3(sd->positions[tri.v[1]].xyz),
         p2 = to_mreal3(sd->positions[tri.v[2]].xyz);
  mreal b1 = q.b1, b2 = q.b2, b0 = (mreal)1 - b1 - b2;
  mreal3 e1 = p1 - p0, e2 = p2 - p0;
  m.p = p0 + b1 * e1 + b2 * e2;
  mreal3 c = cross(e1, e2);
  mreal cl = length(c), el = length(e1);
  m.ng = cl > (mreal)0 ? c / cl : (mreal3)(0, 0, 1);
  m.dpdu = el > (mreal)0 ? e1 / el : (mreal3)(1, 0, 0);
  m.dpdv = cross(m.ng, m.dpdu);
  m.n = m.ng;
  m.dndu = m.dndv = (mreal3)(0);
  if (shape.flags & SHAPE_HAS_NORMALS) {
    mreal3 n0 = to_mreal3(sd->normals[tri.v[0]].xyz), n1 = to_mreal3(sd->normals[tri.v[1]].xyz),
           n2 = to_mreal3(sd->normals[tri.v[2]].xyz);
    mreal3 nn = b0 * n0 + b1 * n1 + b2 * n2;
    mreal len = length(nn);
    if (len > (mreal)0 && isfinite(len)) {
      m.n = nn / len;
      // Barycentrics from plane coordinates: [u v] = A [b1 b2] with A's columns e1, e2 in the basis.
      mreal a11 = dot(e1, m.dpdu), a12 = dot(e2, m.dpdu), a21 = dot(e1, m.dpdv), a22 = dot(e2, m.dpdv);
      mreal det = a11 * a22 - a12 * a21;
      if (fabs(det) > (mreal)0) {
        mreal3 dn1 = n1 - n0, dn2 = n2 - n0;  // d nn / d b1, d b2
        mreal3 dnn_du = (dn1 * a22 - dn2 * a21) / det, dnn_dv = (dn2 * a11 - dn1 * a12) / det;
        m.dndu = (dnn_du - m.n * dot(m.n, dnn_du)) / len;
        m.dndv = (dnn_dv - m.n * dot(m.n, dnn_dv)) / len;
      }
    }
  }
  if (shape.flags & SHAPE_FLIP_NORMALS) {
    m.n = -m.n;
    m.dndu = -m.dndu;
    m.dndv = -m.dndv;
  }
  if (dot(m.ng, m.n) < (mreal)0) m.ng = -m.ng;
  mreal3 st = m.dpdu - m.n * dot(m.dpdu, m.n);
  m.s_len = length(st);
  m.s = m.s_len > (mreal)0 ? st / m.s_len : m.dpdu;
  m.t = cross(m.n, m.s);
  m.shape = tri.shape;
  m.material = shape.material;
  return m;
}

// Change of the manifold frame (s, t) when the normal turns by dn along the plane direction of
// dpdu (s = normalize(dpdu - (dpdu.n) n), t = n x s).
inline void manifold_frame_derivative(const ManifoldSurface* m, mreal3 dn, mreal3* ds, mreal3* dt) {
  mreal3 dst = -dot(m->dpdu, dn) * m->n - dot(m->dpdu, m->n) * dn;
  *ds = (dst - m->s * dot(m->s, dst)) / m->s_len;
  *dt = cross(dn, m->s) + cross(m->n, *ds);
}

inline mreal3 manifold_to_world(const ManifoldSurface* m, mreal3 v) { return m->s * v.x + m->t * v.y + m->n * v.z; }
