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
