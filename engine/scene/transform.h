// A small 3-vector and 4x4 affine matrix (row-major, double precision) for scene set-up:
// Mitsuba transforms are composed on the host once, so precision beats speed here.
#pragma once
#include <cmath>

namespace gdr {

struct Vec3d {
  double x = 0, y = 0, z = 0;
  Vec3d() = default;
  Vec3d(double x_, double y_, double z_) : x(x_), y(y_), z(z_) {}
  double operator[](int i) const { return i == 0 ? x : (i == 1 ? y : z); }
  double& operator[](int i) { return i == 0 ? x : (i == 1 ? y : z); }
};

inline Vec3d operator+(Vec3d a, Vec3d b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
inline Vec3d operator-(Vec3d a, Vec3d b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline Vec3d operator*(Vec3d a, double s) { return {a.x * s, a.y * s, a.z * s}; }
inline Vec3d operator-(Vec3d a) { return {-a.x, -a.y, -a.z}; }
inline double dot(Vec3d a, Vec3d b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline Vec3d cross(Vec3d a, Vec3d b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
inline double length(Vec3d a) { return std::sqrt(dot(a, a)); }
// Unit vector along a; the zero vector stays zero (no NaN).
inline Vec3d normalize(Vec3d a) {
  double l = length(a);
  return l > 0 ? a * (1.0 / l) : Vec3d{};
}

struct Mat4d {
  double m[4][4] = {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}};

  static Mat4d identity() { return {}; }
  static Mat4d translate(Vec3d t);
  static Mat4d scale(Vec3d s);
  // Right-handed rotation by `degrees` about `axis` (Mitsuba's rotate).
  static Mat4d rotate(Vec3d axis, double degrees);
  // Mitsuba's look_at: columns (left, up, dir, origin); the camera looks along local +z.
  static Mat4d look_at(Vec3d origin, Vec3d target, Vec3d up);

  Vec3d point(Vec3d p) const;   // applies the full affine map
  Vec3d vector(Vec3d v) const;  // linear part only
  Vec3d normal(Vec3d n) const;  // inverse transpose of the linear part, normalized
  Vec3d translation() const { return {m[0][3], m[1][3], m[2][3]}; }
  double det3() const;        // determinant of the linear part
  Mat4d inverse() const;       // affine inverse (a singular linear part gives the identity)
  bool finite() const;
};

// a * b: applies b first, then a.
Mat4d operator*(const Mat4d& a, const Mat4d& b);

}  // namespace gdr
