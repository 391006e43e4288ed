// An independent model of Mitsuba 3's roughplastic, in double precision, for checking the
// kernels: the microfacet formulas (Beckmann and GGX D, exact Smith G1, dielectric Fresnel,
// refraction) written out here, and integrals of them by quadrature over microfacet normals.
// Nothing here calls a kernel or reads a kernel's table.
//
// Integrals over normals use the distribution's own cdf: with u = P(tan^2 theta_m <= t) and a
// uniform azimuth, D(m) cos(theta_m) dm = du dphi / (2 pi), so a tensor Gauss-Legendre rule in
// (u, phi) puts its nodes where D has its mass, whatever alpha.
#pragma once
#include <cmath>
#include <functional>
#include <vector>

#include "util/gauss_legendre.h"

namespace gdr::test::coating {

struct V3 {
  double x, y, z;
};
inline V3 operator*(double s, V3 a) { return {s * a.x, s * a.y, s * a.z}; }
inline V3 operator+(V3 a, V3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
inline V3 operator-(V3 a, V3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline double dot(V3 a, V3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline V3 dir(double mu) { return {std::sqrt(std::fmax(0.0, 1.0 - mu * mu)), 0.0, mu}; }

struct Model {
  bool beckmann;
  double alpha;
  double eta;  // int_ior / ext_ior
};

inline double D(const Model& md, V3 m) {
  if (m.z <= 0) return 0;
  double c2 = m.z * m.z, t2 = (m.x * m.x + m.y * m.y) / c2, a2 = md.alpha * md.alpha;
  if (md.beckmann) return std::exp(-t2 / a2) / (M_PI * a2 * c2 * c2);
  return 1.0 / (M_PI * a2 * c2 * c2 * (1 + t2 / a2) * (1 + t2 / a2));
}

// Smith masking of v by normal m (0 where v sees the back of m).
inline double G1(const Model& md, V3 v, V3 m) {
  if (dot(v, m) * v.z <= 0) return 0;
  double t2 = md.alpha * md.alpha * (v.x * v.x + v.y * v.y) / (v.z * v.z);
  if (t2 == 0) return 1;
  if (md.beckmann) {
    double a = 1 / std::sqrt(t2);
    return 2 / (1 + std::erf(a) + std::exp(-a * a) / (std::sqrt(M_PI) * a));
  }
  return 2 / (1 + std::sqrt(1 + t2));
}

// Unpolarized reflectance for cos_i > 0 toward a medium of relative IOR eta (1: total internal
// reflection); *cos_t: cosine of the refracted direction.
inline double fresnel(double cos_i, double eta, double* cos_t) {
  double s2 = 1 - cos_i * cos_i, c2 = 1 - s2 / (eta * eta);
  if (c2 <= 0) {
    *cos_t = 0;
    return 1;
  }
  double ct = std::sqrt(c2);
  *cos_t = ct;
  double rs = (cos_i - eta * ct) / (cos_i + eta * ct), rp = (eta * cos_i - ct) / (eta * cos_i + ct);
  return 0.5 * (rs * rs + rp * rp);
}

// Nodes m and weights w with sum w g(m) ~ integral of g(m) D(m) cos(theta_m) dm.
struct Normals {
  std::vector<V3> m;
  std::vector<double> w;
};

inline Normals normal_nodes(const Model& md, int n) {
  GaussLegendre gs = gauss_legendre(n, 0.0, 1.0), gp = gauss_legendre(n, 0.0, 2 * M_PI);
  Normals r;
  for (int i = 0; i < n; ++i) {
    // u = 1 - (1 - x)^2: the visible-normal factor (w.m) / m.z grows like (1 - u)^(-1/2) toward
    // the horizon (GGX), which this substitution makes smooth in x.
    double x = gs.nodes[i], u = 1 - (1 - x) * (1 - x), du = 2 * (1 - x), a2 = md.alpha * md.alpha;
    double t2 = md.beckmann ? -a2 * std::log1p(-u) : a2 * u / (1 - u);
    double c = 1 / std::sqrt(1 + t2), s = std::sqrt(t2) * c;
    for (int j = 0; j < n; ++j) {
      r.m.push_back({s * std::cos(gp.nodes[j]), s * std::sin(gp.nodes[j]), c});
      r.w.push_back(gs.weights[i] * du * gp.weights[j] / (2 * M_PI));
    }
  }
  return r;
}

// Mean over the normals visible from w (density D G1(w, m) max(0, w.m) / w.z) of g(m).
inline double visible_mean(const Model& md, const Normals& nn, V3 w,
                           const std::function<double(V3)>& g) {
  double sum = 0;
  for (size_t k = 0; k < nn.m.size(); ++k) {
    V3 m = nn.m[k];
    double wm = dot(w, m);
    if (wm <= 0) continue;
    sum += nn.w[k] * G1(md, w, m) * wm / (w.z * m.z) * g(m);
  }
  return sum;
}

// Fraction of light from w (outside) that the rough interface transmits and that is not masked
// on its way in: E[(1 - F(w.m)) G1(w_t, m)].
inline double transmittance(const Model& md, const Normals& nn, double mu) {
  V3 w = dir(mu);
  return visible_mean(md, nn, w, [&](V3 m) {
    double wm = dot(w, m), ct = 0;
    double f = fresnel(wm, md.eta, &ct);
    if (f >= 1) return 0.0;
    V3 wt = (wm / md.eta - ct) * m - (1 / md.eta) * w;
    return wt.z < 0 ? (1 - f) * G1(md, wt, m) : 0.0;
  });
}

// Single-scattering reflectance of the interface for light from w on the side where the other
// medium has relative IOR eta_rel: E[F(w.m) G1(w_r, m)], w_r on the same side.
inline double reflectance(const Model& md, const Normals& nn, double mu, double eta_rel) {
  V3 w = dir(mu);
  return visible_mean(md, nn, w, [&](V3 m) {
    double wm = dot(w, m), ct = 0;
    V3 wr = (2 * wm) * m - w;
    return wr.z > 0 ? fresnel(wm, eta_rel, &ct) * G1(md, wr, m) : 0.0;
  });
}

// Directional albedo of the specular lobe: integral of F D G / (4 cos_o) over wi.
inline double specular_albedo(const Model& md, const Normals& nn, double mu) {
  V3 w = dir(mu);
  return visible_mean(md, nn, w, [&](V3 m) {
    double wm = dot(w, m), ct = 0;
    V3 wi = (2 * wm) * m - w;
    return wi.z > 0 ? fresnel(wm, md.eta, &ct) * G1(md, wi, m) : 0.0;
  });
}

// Mitsuba 3's internal reflectance of the coating (roughplastic.cpp): twice the mean of
// r(mu) mu over the 64 equally spaced cosines mu_i = max(1e-6, i / 63), r seen from inside
// (relative IOR 1 / eta). That rule is part of the model the engine reproduces; r is this
// file's own integral.
inline double internal_reflectance(const Model& md, const Normals& nn) {
  double sum = 0;
  for (int i = 0; i < 64; ++i) {
    double mu = std::fmax(1e-6, i / 63.0);
    sum += reflectance(md, nn, mu, 1 / md.eta) * mu;
  }
  return 2 * sum / 64;
}

// 2 * integral_0^1 t(mu) mu dmu: the cosine-weighted mean transmittance.
inline double hemispherical_transmittance(const Model& md, const Normals& nn, int n_mu) {
  GaussLegendre g = gauss_legendre(n_mu, 0.0, 1.0);
  double sum = 0;
  for (int i = 0; i < n_mu; ++i)
    sum += g.weights[i] * g.nodes[i] * transmittance(md, nn, g.nodes[i]);
  return 2 * sum;
}

// The diffuse lobe's albedo toward wo (cos mu) for base reflectance d:
// d' t(wo) / eta^2 * 2 int t(mu) mu dmu, d' = d / (1 - d R_int) (nonlinear) or d / (1 - R_int).
inline double diffuse_albedo(double d, bool nonlinear, double eta, double r_int, double t_o,
                             double t_hemi) {
  double base = d / (1 - (nonlinear ? d * r_int : r_int));
  return base * t_o * t_hemi / (eta * eta);
}

}  // namespace gdr::test::coating
