#pragma once
/// Rigid bodies: inertia tensors, the parallel-axis theorem, principal axes (notes
/// lectures 13-16, eqs 123-164).
///
/// Tolerance model: a tensor entry of an N-point cloud is a sum of N terms of size
/// m |r|^2; each term has a few roundings, so entries carry error <= (N + 4) eps times
/// sum m |r|^2 (the cloud's scale). Eigen decompositions add O(10) eps of |I|.

#include <array>
#include <boost/math/quadrature/gauss.hpp>
#include "mechcheck/harness/generators.hpp"
#include "mechcheck/harness/law.hpp"
#include "mechcheck/reference.hpp"

namespace mechcheck::laws::bodies {

namespace mc = mechcheck;
namespace gen = mechcheck::generators;
using mc::lift;
using mc::matrix3;
using mc::vector3;
using mc::harness::at_least_one;
using mc::harness::check_close;
using mc::harness::check_zero;
using mc::harness::law_info;

template <class T>
void check_matrices(const std::string& what, const matrix3<T>& computed,
                    const matrix3<T>& expected, const T& scale, double budget) {
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      check_close(what + "(" + std::to_string(i) + "," + std::to_string(j) + ")", computed(i, j),
                  expected(i, j), scale, budget);
}

/// A cloud of 1 to 6 point masses in [-2, 2]^3.
template <class T>
mc::point_cloud<T> random_cloud() {
  const int n = *gen::uniform_int(1, 6);
  mc::point_cloud<T> cloud;
  for (int a = 0; a < n; ++a) {
    cloud.masses.push_back(T(*gen::positive()));
    const auto r = *gen::coordinates(3);
    cloud.positions.emplace_back(T(r[0]), T(r[1]), T(r[2]));
  }
  return cloud;
}

/// sum m |r - o|^2 + M |o|^2: the scale of the entries of I about o.
template <class T>
T cloud_scale(const mc::point_cloud<T>& cloud, const vector3<T>& o) {
  T s = lift<T>(1);
  for (std::size_t a = 0; a < cloud.masses.size(); ++a)
    s += cloud.masses[a] * (cloud.positions[a].squaredNorm() + o.squaredNorm());
  return s;
}

// --- Euler angles ------------------------------------------------------------------------

/// Euler angles (phi, theta, psi) and rates.
template <class T>
std::array<T, 6> random_angles_and_rates() {
  std::array<T, 6> a;
  for (auto& x : a) x = T(*gen::coordinate());
  return a;
}

/// Body angular velocity from dR/dt: the rows of R are the body axes, d x_i/dt =
/// Omega x x_i, so A = Rdot R^T has A_23 = Omega_1, A_31 = Omega_2, A_12 = Omega_3.
template <class T>
vector3<T> angular_velocity_from_rotation(const std::array<T, 6>& a) {
  using A = mc::ad<T>;
  const mc::ad_width_scope<A> width(1);
  const auto seeded = [](const T& x, const T& rate) {
    return A(x, mc::dynamic_vector<T>::Constant(1, rate));
  };
  const matrix3<A> r = mc::euler_rotation(seeded(a[0], a[3]), seeded(a[1], a[4]), seeded(a[2], a[5]));
  matrix3<T> value, rate;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      value(i, j) = r(i, j).value();
      rate(i, j) = mc::derivatives_of(r(i, j), 1)(0);
    }
  const matrix3<T> m = rate * value.transpose();
  return vector3<T>(m(1, 2), m(2, 0), m(0, 1));
}

}  // namespace mechcheck::laws::bodies
