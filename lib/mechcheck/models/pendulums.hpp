#pragma once
/// Model Lagrangians L(q, qdot, t) of the notes' examples, in every tier. Parameters are
/// stored in a tier type P and lifted into the evaluation scalar S.

#include <string>

#include "mechcheck/core.hpp"

namespace mechcheck::models {

namespace detail {
template <class S>
void require_dof(const dynamic_vector<S>& q, Eigen::Index n, const char* where) {
  if (q.size() != n)
    throw dimension_error(std::string(where) + ": q needs " + std::to_string(n) +
                          " coordinates, got " + std::to_string(q.size()));
}
}  // namespace detail

/// Free particle in any dimension: L = m |qdot|^2 / 2 (notes eq 48).
template <class P>
struct free_particle {
  P mass;
  explicit free_particle(P m) : mass(std::move(m)) { require_positive(mass, "free_particle", "mass"); }
  template <class S>
  S operator()(const dynamic_vector<S>&, const dynamic_vector<S>& qdot, const S&) const {
    S v2 = lift<S>(0);
    for (Eigen::Index i = 0; i < qdot.size(); ++i) {
      const S vi2 = qdot(i) * qdot(i);
      v2 += vi2;
    }
    const S half_m = lift<S>(mass) * half<S>();
    return half_m * v2;
  }
};

/// Isotropic harmonic oscillator L = m |qdot|^2 / 2 - k |q|^2 / 2.
template <class P>
struct oscillator {
  P mass, stiffness;
  oscillator(P m, P k) : mass(std::move(m)), stiffness(std::move(k)) {
    require_positive(mass, "oscillator", "mass");
    require_positive(stiffness, "oscillator", "stiffness");
  }
  template <class S>
  S operator()(const dynamic_vector<S>& q, const dynamic_vector<S>& qdot, const S& t) const {
    const S kinetic = free_particle<P>(mass)(q, qdot, t);
    S q2 = lift<S>(0);
    for (Eigen::Index i = 0; i < q.size(); ++i) {
      const S qi2 = q(i) * q(i);
      q2 += qi2;
    }
    const S half_k = lift<S>(stiffness) * half<S>();
    const S potential = half_k * q2;
    return kinetic - potential;
  }
};

/// Simple pendulum, q = (theta): L = m l^2 thetadot^2 / 2 + m g l cos(theta)
/// (notes eqs 31-33, 258).
template <class P>
struct simple_pendulum {
  P mass, length, gravity;
  simple_pendulum(P m, P l, P g) : mass(std::move(m)), length(std::move(l)), gravity(std::move(g)) {
    require_positive(mass, "simple_pendulum", "mass");
    require_positive(length, "simple_pendulum", "length");
    require_positive(gravity, "simple_pendulum", "gravity");
  }
  template <class S>
  S operator()(const dynamic_vector<S>& q, const dynamic_vector<S>& qdot, const S&) const {
    using std::cos;
    detail::require_dof(q, 1, "simple_pendulum");
    const S m = lift<S>(mass), l = lift<S>(length), g = lift<S>(gravity);
    const S ml2 = m * l * l;
    const S w2 = qdot(0) * qdot(0);
    const S kinetic = ml2 * w2 * half<S>();
    const S c = cos(q(0));
    const S mgl = m * g * l;
    const S potential_term = mgl * c;
    return kinetic + potential_term;
  }
};

/// Spherical pendulum, q = (theta, phi), theta from the downward vertical:
/// L = m l^2 (thetadot^2 + phidot^2 sin^2 theta) / 2 + m g l cos(theta)  (notes eq 39).
template <class P>
struct spherical_pendulum {
  P mass, length, gravity;
  spherical_pendulum(P m, P l, P g)
      : mass(std::move(m)), length(std::move(l)), gravity(std::move(g)) {
    require_positive(mass, "spherical_pendulum", "mass");
    require_positive(length, "spherical_pendulum", "length");
    require_positive(gravity, "spherical_pendulum", "gravity");
  }
  template <class S>
  S operator()(const dynamic_vector<S>& q, const dynamic_vector<S>& qdot, const S&) const {
    using std::cos;
    using std::sin;
    detail::require_dof(q, 2, "spherical_pendulum");
    const S m = lift<S>(mass), l = lift<S>(length), g = lift<S>(gravity);
    const S s = sin(q(0));
    const S a = qdot(0) * qdot(0);
    const S b = qdot(1) * qdot(1) * s * s;
    const S ml2 = m * l * l;
    const S kinetic = ml2 * (a + b) * half<S>();
    const S c = cos(q(0));
    const S mgl = m * g * l;
    const S potential_term = mgl * c;
    return kinetic + potential_term;
  }
};

/// Spring pendulum in (x, theta): a mass on a spring of rest length l and stiffness k,
/// x the extension, theta from the downward vertical (notes eqs 7-8):
/// L = m (xdot^2 + (l + x)^2 thetadot^2) / 2 - k x^2 / 2 + m g (l + x) cos(theta).
template <class P>
struct spring_pendulum {
  P mass, stiffness, length, gravity;
  spring_pendulum(P m, P k, P l, P g)
      : mass(std::move(m)), stiffness(std::move(k)), length(std::move(l)), gravity(std::move(g)) {
    require_positive(mass, "spring_pendulum", "mass");
    require_positive(stiffness, "spring_pendulum", "stiffness");
    require_positive(length, "spring_pendulum", "length");
    require_positive(gravity, "spring_pendulum", "gravity");
  }
  template <class S>
  S operator()(const dynamic_vector<S>& q, const dynamic_vector<S>& qdot, const S&) const {
    using std::cos;
    detail::require_dof(q, 2, "spring_pendulum");
    const S m = lift<S>(mass), k = lift<S>(stiffness), g = lift<S>(gravity);
    const S r = arm(q);
    const S radial = qdot(0) * qdot(0);
    const S angular = r * r * qdot(1) * qdot(1);
    const S kinetic = m * (radial + angular) * half<S>();
    const S spring = k * q(0) * q(0) * half<S>();
    const S c = cos(q(1));
    const S gravity_term = m * g * r * c;
    const S l1 = kinetic - spring;
    return l1 + gravity_term;
  }
  /// Cartesian position (X, Y) = ((l + x) sin theta, -(l + x) cos theta) of a state.
  /// The arm l + x; throws domain_error when it is not positive (the bob through the pivot).
  template <class S>
  S arm(const dynamic_vector<S>& q) const {
    const S r = lift<S>(length) + q(0);
    if (!(innermost_value(r) > 0))
      throw domain_error("spring_pendulum: the arm l + x must be positive, got l + x = " +
                         to_text(r) + " at extension q[0] = " + to_text(q(0)));
    return r;
  }
  template <class S>
  dynamic_vector<S> position(const dynamic_vector<S>& q) const {
    using std::cos;
    using std::sin;
    detail::require_dof(q, 2, "spring_pendulum::position");
    const S r = arm(q);
    dynamic_vector<S> out(2);
    out(0) = r * sin(q(1));
    out(1) = -(r * cos(q(1)));
    return out;
  }
};

/// The same spring pendulum in Cartesian coordinates q = (X, Y), Y upwards:
/// L = m |qdot|^2 / 2 - k (|q| - l)^2 / 2 - m g Y.
template <class P>
struct spring_pendulum_cartesian {
  P mass, stiffness, length, gravity;
  spring_pendulum_cartesian(P m, P k, P l, P g)
      : mass(std::move(m)), stiffness(std::move(k)), length(std::move(l)), gravity(std::move(g)) {
    require_positive(mass, "spring_pendulum_cartesian", "mass");
    require_positive(stiffness, "spring_pendulum_cartesian", "stiffness");
    require_positive(length, "spring_pendulum_cartesian", "length");
    require_positive(gravity, "spring_pendulum_cartesian", "gravity");
  }
  template <class S>
  S operator()(const dynamic_vector<S>& q, const dynamic_vector<S>& qdot, const S&) const {
    using std::sqrt;
    detail::require_dof(q, 2, "spring_pendulum_cartesian");
    const S m = lift<S>(mass), k = lift<S>(stiffness), g = lift<S>(gravity);
    const S v2a = qdot(0) * qdot(0);
    const S v2b = qdot(1) * qdot(1);
    const S kinetic = m * (v2a + v2b) * half<S>();
    const S r2a = q(0) * q(0);
    const S r2b = q(1) * q(1);
    const S r = sqrt(r2a + r2b);
    const S x = r - lift<S>(length);
    const S spring = k * x * x * half<S>();
    const S height = m * g * q(1);
    const S l1 = kinetic - spring;
    return l1 - height;
  }
};

/// Pendulum of length l hung from a point moving on a circle of radius R at angular
/// velocity w, q = (theta) (notes eqs 42-47). The pivot follows the notes' eq 45,
/// (R cos wt, -R sin wt), and y points up; the bob is at
///   x = R cos(wt) + l sin(theta),  y = -R sin(wt) - l cos(theta),
/// L = m (R^2 w^2 - 2 R w l thetadot sin(theta + wt) + l^2 thetadot^2) / 2
///     + m g (R sin(wt) + l cos(theta)).
/// Its equation of motion is the notes' eq 47:
///   thetaddot + (g/l) sin(theta) = (R w^2 / l) cos(theta + wt).
template <class P>
struct rotating_pivot_pendulum {
  P mass, length, gravity, radius, omega;
  rotating_pivot_pendulum(P m, P l, P g, P big_r, P w)
      : mass(std::move(m)), length(std::move(l)), gravity(std::move(g)), radius(std::move(big_r)),
        omega(std::move(w)) {
    require_positive(mass, "rotating_pivot_pendulum", "mass");
    require_positive(length, "rotating_pivot_pendulum", "length");
    require_positive(gravity, "rotating_pivot_pendulum", "gravity");
    require_non_negative(radius, "rotating_pivot_pendulum", "radius");
    require_finite_value(omega, "rotating_pivot_pendulum", "omega");
  }
  template <class S>
  S operator()(const dynamic_vector<S>& q, const dynamic_vector<S>& qdot, const S& t) const {
    using std::cos;
    using std::sin;
    detail::require_dof(q, 1, "rotating_pivot_pendulum");
    const S m = lift<S>(mass), l = lift<S>(length), g = lift<S>(gravity);
    const S big_r = lift<S>(radius), w = lift<S>(omega);
    const S wt = w * t;
    // Velocity of the bob from the position above, then L = T - V with V = m g y.
    const S vx_pivot = -(big_r * w * sin(wt));
    const S vy_pivot = -(big_r * w * cos(wt));
    const S vx_arm = l * qdot(0) * cos(q(0));
    const S vy_arm = l * qdot(0) * sin(q(0));
    const S vx = vx_pivot + vx_arm;
    const S vy = vy_pivot + vy_arm;
    const S v2a = vx * vx;
    const S v2b = vy * vy;
    const S kinetic = m * (v2a + v2b) * half<S>();
    const S y_pivot = -(big_r * sin(wt));
    const S y_arm = l * cos(q(0));
    const S y = y_pivot - y_arm;
    const S potential = m * g * y;
    return kinetic - potential;
  }
};

}  // namespace mechcheck::models
