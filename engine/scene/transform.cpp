#include "scene/transform.h"

namespace gdr {

Mat4d Mat4d::translate(Vec3d t) {
  Mat4d r;
  r.m[0][3] = t.x;
  r.m[1][3] = t.y;
  r.m[2][3] = t.z;
  return r;
}

Mat4d Mat4d::scale(Vec3d s) {
  Mat4d r;
  r.m[0][0] = s.x;
  r.m[1][1] = s.y;
  r.m[2][2] = s.z;
  return r;
}

Mat4d Mat4d::rotate(Vec3d axis, double degrees) {
  Vec3d a = normalize(axis);
  double t = degrees * M_PI / 180.0;
  double s = std::sin(t), c = std::cos(t), ic = 1.0 - c;
  Mat4d r;
  r.m[0][0] = a.x * a.x * ic + c;
  r.m[0][1] = a.x * a.y * ic - a.z * s;
  r.m[0][2] = a.x * a.z * ic + a.y * s;
  r.m[1][0] = a.y * a.x * ic + a.z * s;
  r.m[1][1] = a.y * a.y * ic + c;
  r.m[1][2] = a.y * a.z * ic - a.x * s;
  r.m[2][0] = a.z * a.x * ic - a.y * s;
  r.m[2][1] = a.z * a.y * ic + a.x * s;
  r.m[2][2] = a.z * a.z * ic + c;
  return r;
}

Mat4d Mat4d::look_at(Vec3d origin, Vec3d target, Vec3d up) {
  Vec3d dir = normalize(target - origin);
  Vec3d left = normalize(cross(up, dir));
  if (length(left) == 0) {
    // `up` parallel to the view direction: any perpendicular keeps the frame valid.
    Vec3d other = std::fabs(dir.x) < 0.9 ? Vec3d{1, 0, 0} : Vec3d{0, 1, 0};
    left = normalize(cross(other, dir));
  }
  Vec3d new_up = cross(dir, left);
  Mat4d r;
  for (int i = 0; i < 3; ++i) {
    r.m[i][0] = left[i];
    r.m[i][1] = new_up[i];
    r.m[i][2] = dir[i];
    r.m[i][3] = origin[i];
  }
  return r;
}

Vec3d Mat4d::point(Vec3d p) const { return vector(p) + translation(); }

Vec3d Mat4d::vector(Vec3d v) const {
  return {m[0][0] * v.x + m[0][1] * v.y + m[0][2] * v.z, m[1][0] * v.x + m[1][1] * v.y + m[1][2] * v.z,
          m[2][0] * v.x + m[2][1] * v.y + m[2][2] * v.z};
}

Vec3d Mat4d::normal(Vec3d n) const {
  Mat4d inv = inverse();
  // Transpose of the inverse's linear part.
  Vec3d r{inv.m[0][0] * n.x + inv.m[1][0] * n.y + inv.m[2][0] * n.z,
         inv.m[0][1] * n.x + inv.m[1][1] * n.y + inv.m[2][1] * n.z,
         inv.m[0][2] * n.x + inv.m[1][2] * n.y + inv.m[2][2] * n.z};
  return normalize(r);
}

double Mat4d::det3() const {
  return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
         m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
         m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
}

Mat4d Mat4d::inverse() const {
  double d = det3();
  if (!(std::fabs(d) > 1e-300) || !std::isfinite(d)) return Mat4d{};
  double id = 1.0 / d;
  Mat4d r;
  r.m[0][0] = (m[1][1] * m[2][2] - m[1][2] * m[2][1]) * id;
  r.m[0][1] = (m[0][2] * m[2][1] - m[0][1] * m[2][2]) * id;
  r.m[0][2] = (m[0][1] * m[1][2] - m[0][2] * m[1][1]) * id;
  r.m[1][0] = (m[1][2] * m[2][0] - m[1][0] * m[2][2]) * id;
  r.m[1][1] = (m[0][0] * m[2][2] - m[0][2] * m[2][0]) * id;
  r.m[1][2] = (m[0][2] * m[1][0] - m[0][0] * m[1][2]) * id;
  r.m[2][0] = (m[1][0] * m[2][1] - m[1][1] * m[2][0]) * id;
  r.m[2][1] = (m[0][1] * m[2][0] - m[0][0] * m[2][1]) * id;
  r.m[2][2] = (m[0][0] * m[1][1] - m[0][1] * m[1][0]) * id;
  Vec3d t = r.vector(translation());
  r.m[0][3] = -t.x;
  r.m[1][3] = -t.y;
  r.m[2][3] = -t.z;
  return r;
}

bool Mat4d::finite() const {
  for (auto& row : m)
    for (double v : row)
      if (!std::isfinite(v)) return false;
  return true;
}

Mat4d operator*(const Mat4d& a, const Mat4d& b) {
  Mat4d r;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) {
      double s = 0;
      for (int k = 0; k < 4; ++k) s += a.m[i][k] * b.m[k][j];
      r.m[i][j] = s;
    }
  return r;
}

}  // namespace gdr
