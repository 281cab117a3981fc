#pragma once
/// Closed-form inertia tensors of uniform solids of mass M about their centre of mass,
/// in their body axes (notes eqs 141, 161-163), and exact point-mass equivalents used to
/// cross-check them: Gauss rules that integrate quadratics exactly give point clouds
/// with the same mass, centre and second moments as the solid.

#include <array>

#include "mechcheck/rigid_body/inertia.hpp"

namespace mechcheck::reference {

/// Box with edges a, b, c along x, y, z: (M/12) diag(b^2 + c^2, a^2 + c^2, a^2 + b^2).
template <class T>
matrix3<T> box_inertia(const T& mass, const T& a, const T& b, const T& c) {
  require_positive(mass, "box_inertia", "mass");
  require_positive(a, "box_inertia", "edge a");
  require_positive(b, "box_inertia", "edge b");
  require_positive(c, "box_inertia", "edge c");
  const vector3<T> d(b * b + c * c, a * a + c * c, a * a + b * b);
  return (mass / 12 * d).asDiagonal();
}

/// Cube of edge l: M l^2 / 6 times the identity (eqs 161-163).
template <class T>
matrix3<T> cube_inertia(const T& mass, const T& l) {
  require_positive(mass, "cube_inertia", "mass");
  require_positive(l, "cube_inertia", "edge l");
  return box_inertia(mass, l, l, l);
}

/// Solid sphere of radius R: (2/5) M R^2 times the identity.
template <class T>
matrix3<T> solid_sphere_inertia(const T& mass, const T& r) {
  require_positive(mass, "solid_sphere_inertia", "mass");
  require_positive(r, "solid_sphere_inertia", "radius");
  return (T(2) / 5 * mass * r * r) * matrix3<T>::Identity();
}

/// Thin spherical shell of radius R: (2/3) M R^2 times the identity.
template <class T>
matrix3<T> spherical_shell_inertia(const T& mass, const T& r) {
  require_positive(mass, "spherical_shell_inertia", "mass");
  require_positive(r, "spherical_shell_inertia", "radius");
  return (T(2) / 3 * mass * r * r) * matrix3<T>::Identity();
}

/// Solid cylinder of radius R and height h, axis z:
/// diag(M (3R^2 + h^2)/12, M (3R^2 + h^2)/12, M R^2 / 2).
template <class T>
matrix3<T> solid_cylinder_inertia(const T& mass, const T& r, const T& h) {
  require_positive(mass, "solid_cylinder_inertia", "mass");
  require_positive(r, "solid_cylinder_inertia", "radius");
  require_positive(h, "solid_cylinder_inertia", "height");
  const T side = mass * (3 * r * r + h * h) / 12;
  return vector3<T>(side, side, mass * r * r / 2).asDiagonal();
}

/// Solid capsule: a cylinder of radius R and length h along z capped by two solid
/// hemispheres, uniform density. With the cylinder's mass m_c = M h / (h + 4R/3) and each
/// cap's m_h = (M - m_c) / 2 (volumes pi R^2 h and (2/3) pi R^3):
///   I_zz = m_c R^2 / 2 + 2 (2/5) m_h R^2,
///   I_xx = I_yy = m_c (3R^2 + h^2) / 12 + 2 m_h (2R^2/5 + h^2/4 + 3hR/8),
/// each cap's transverse moment being (2/5) m_h R^2 about its flat face's centre (half a
/// sphere's) moved by the parallel-axis theorem (eq 160) from its centre of mass 3R/8 off
/// the face to the capsule's centre h/2 + 3R/8 away: + m_h ((h/2 + 3R/8)^2 - (3R/8)^2).
template <class T>
matrix3<T> solid_capsule_inertia(const T& mass, const T& r, const T& h) {
  require_positive(mass, "solid_capsule_inertia", "mass");
  require_positive(r, "solid_capsule_inertia", "radius");
  require_positive(h, "solid_capsule_inertia", "cylinder length");
  const T m_c = mass * h / (h + 4 * r / 3), m_h = (mass - m_c) / 2;
  const T axial = m_c * r * r / 2 + 4 * m_h * r * r / 5;
  const T side = m_c * (3 * r * r + h * h) / 12 + 2 * m_h * (2 * r * r / 5 + h * h / 4 + 3 * h * r / 8);
  return vector3<T>(side, side, axial).asDiagonal();
}

/// Solid right circular cone of base radius R and height h, axis z, about its centre of
/// mass (h/4 above the base): diag(3M R^2/20 + 3M h^2/80, the same, 3M R^2/10).
template <class T>
matrix3<T> solid_cone_inertia(const T& mass, const T& r, const T& h) {
  require_positive(mass, "solid_cone_inertia", "mass");
  require_positive(r, "solid_cone_inertia", "radius");
  require_positive(h, "solid_cone_inertia", "height");
  const T side = 3 * mass * r * r / 20 + 3 * mass * h * h / 80;
  return vector3<T>(side, side, 3 * mass * r * r / 10).asDiagonal();
}

/// Solid ellipsoid of semi-axes a, b, c along x, y, z: (M/5) diag(b^2 + c^2, a^2 + c^2,
/// a^2 + b^2).
template <class T>
matrix3<T> solid_ellipsoid_inertia(const T& mass, const T& a, const T& b, const T& c) {
  require_positive(mass, "solid_ellipsoid_inertia", "mass");
  require_positive(a, "solid_ellipsoid_inertia", "semi-axis a");
  require_positive(b, "solid_ellipsoid_inertia", "semi-axis b");
  require_positive(c, "solid_ellipsoid_inertia", "semi-axis c");
  const vector3<T> d(b * b + c * c, a * a + c * c, a * a + b * b);
  return (mass / 5 * d).asDiagonal();
}

/// Thin rod of length L along z: diag(M L^2 / 12, M L^2 / 12, 0).
template <class T>
matrix3<T> thin_rod_inertia(const T& mass, const T& length) {
  require_positive(mass, "thin_rod_inertia", "mass");
  require_positive(length, "thin_rod_inertia", "length");
  const T side = mass * length * length / 12;
  return vector3<T>(side, side, T(0)).asDiagonal();
}

/// Uniform tetrahedron with vertices v_0..v_3, about the origin: with the second moment
/// C = (M / 20) (sum_i v_i v_i^T + s s^T), s = sum_i v_i, I = tr(C) 1 - C.
template <class T>
matrix3<T> tetrahedron_inertia(const T& mass, const std::array<vector3<T>, 4>& v) {
  require_positive(mass, "tetrahedron_inertia", "mass");
  for (int i = 0; i < 4; ++i)
    require_finite_vector(v[i], "tetrahedron_inertia", ("vertex " + std::to_string(i)).c_str());
  matrix3<T> c = matrix3<T>::Zero();
  vector3<T> s = vector3<T>::Zero();
  for (const auto& x : v) {
    c += x * x.transpose();
    s += x;
  }
  c = mass / 20 * (c + s * s.transpose());
  return c.trace() * matrix3<T>::Identity() - c;
}

/// Point-mass equivalent of a box: 8 masses M/8 at (+-a, +-b, +-c) / (2 sqrt 3), the
/// two-point Gauss-Legendre rule in each direction (exact for quadratics).
template <class T>
point_cloud<T> box_points(const T& mass, const T& a, const T& b, const T& c) {
  using std::sqrt;
  require_positive(mass, "box_points", "mass");
  require_positive(a, "box_points", "edge a");
  require_positive(b, "box_points", "edge b");
  require_positive(c, "box_points", "edge c");
  const T g = 1 / (2 * sqrt(T(3)));
  point_cloud<T> cloud;
  for (int k = 0; k < 8; ++k) {
    cloud.masses.push_back(mass / 8);
    cloud.positions.emplace_back((k & 1 ? 1 : -1) * g * a, (k & 2 ? 1 : -1) * g * b,
                                 (k & 4 ? 1 : -1) * g * c);
  }
  return cloud;
}

/// Point-mass equivalent of a tetrahedron: 4 masses M/4 at barycentric coordinates
/// (alpha, beta, beta, beta) and permutations, alpha = (5 + 3 sqrt 5)/20,
/// beta = (5 - sqrt 5)/20 (the degree-2 exact rule on a simplex).
template <class T>
point_cloud<T> tetrahedron_points(const T& mass, const std::array<vector3<T>, 4>& v) {
  using std::sqrt;
  require_positive(mass, "tetrahedron_points", "mass");
  for (int i = 0; i < 4; ++i)
    require_finite_vector(v[i], "tetrahedron_points", ("vertex " + std::to_string(i)).c_str());
  const T root5 = sqrt(T(5));
  const T alpha = (5 + 3 * root5) / 20, beta = (5 - root5) / 20;
  point_cloud<T> cloud;
  for (int i = 0; i < 4; ++i) {
    vector3<T> x = vector3<T>::Zero();
    for (int j = 0; j < 4; ++j) x += (i == j ? alpha : beta) * v[j];
    cloud.masses.push_back(mass / 4);
    cloud.positions.push_back(x);
  }
  return cloud;
}

}  // namespace mechcheck::reference
