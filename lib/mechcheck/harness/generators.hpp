#pragma once
/// Every RapidCheck generator of the property suite lives here (declared here, defined
/// once in generators.cpp, so that a law's translation unit does not instantiate
/// RapidCheck's generator machinery): coordinates, phase-space
/// points, positive masses, random smooth phase-space functions, radial potentials.
///
/// Generated numbers are dyadic rationals (k / 256) held in doubles: they convert exactly
/// into every tier, so one seed gives the same case in double, float128 and mpfr50, and a
/// printed counterexample reproduces the case exactly.

#include <cmath>
#include <initializer_list>
#include <ostream>
#include <sstream>
#include <string>
#include <vector>

#include <rapidcheck.h>

#include "mechcheck/mechcheck.hpp"

namespace mechcheck::generators {

/// An integer in [lo, hi], each equally likely in every case, shrinking towards lo.
/// (RapidCheck's gen::inRange draws from a range scaled by the case's size, and a run of
/// n cases has sizes below 100: in 1000 cases inRange(0, 257) never drew above 250, and
/// inRange(1, 4) drew 3 in 11 of 100 cases.)
rc::Gen<int> uniform_int(int lo, int hi);

/// An integer in [lo, hi]: each end in 1/16 of the cases, else uniform_int.
rc::Gen<int> int_with_ends(int lo, int hi);

/// Dyadic numbers k / 256 in [lo, hi], each end in 1/16 of the cases, shrinking towards lo.
rc::Gen<double> dyadic(double lo, double hi);

/// Dyadic numbers k / 256 in [-bound, bound] that shrink towards 0; 0 and |x| = bound
/// each in 1/16 of the cases.
rc::Gen<double> dyadic_towards_zero(double bound);

/// A coordinate or momentum component in [-2, 2], shrinking towards 0.
rc::Gen<double> coordinate();

/// A positive mass or stiffness in [1/4, 4].
rc::Gen<double> positive();

/// A coefficient with 1 <= |c| <= 2 of either sign, shrinking towards 1; |c| = 1 and
/// |c| = 2 each in 1/16 of the cases.
rc::Gen<double> coefficient();

/// Degrees of freedom n in [1, 3].
rc::Gen<int> degrees_of_freedom();

/// A phase-space point with exactly representable coordinates.
struct phase_sample {
  std::vector<double> q, p;

  template <class Scalar>
  phase_point<Scalar> at() const {
    dynamic_vector<Scalar> qs(q.size()), ps(p.size());
    for (std::size_t i = 0; i < q.size(); ++i) qs(i) = Scalar(q[i]);
    for (std::size_t i = 0; i < p.size(); ++i) ps(i) = Scalar(p[i]);
    return phase_point<Scalar>(qs, ps);
  }
};

void showValue(const phase_sample& x, std::ostream& os);

/// A phase-space point with n degrees of freedom, components in [-2, 2].
rc::Gen<phase_sample> phase_points(int n);

/// A random smooth phase-space function on 2n variables z = (q, p):
///   f(z) = sum_terms c * z^e * w(a.z + b),   w in {1, sin, cos},
/// with monomial exponents e_i in 0..2 (total degree <= 3) and integer frequencies a_i in
/// -2..2. Values and derivatives stay O(10) on [-2, 2]^2n, so residuals measure rounding.
struct smooth_function {
  enum class wave { none, sine, cosine };
  struct term {
    double coefficient = 1;
    std::vector<int> exponents;    // length 2n
    wave kind = wave::none;
    std::vector<int> frequencies;  // length 2n
    double phase = 0;
  };
  int dof = 1;
  std::vector<term> terms;

  template <class T>
  static T monomial_bound(const term& t, const phase_point<T>& x,
                          std::initializer_list<int> lowered);

  bool has_wave() const {
    for (const auto& t : terms)
      if (t.kind != wave::none) return true;
    return false;
  }

  /// True when no term depends on variable k of z = (q, p).
  bool independent_of(int k) const {
    for (const auto& t : terms)
      if (t.exponents[k] != 0 || (t.kind != wave::none && t.frequencies[k] != 0)) return false;
    return true;
  }

  /// Magnitudes of what an evaluation sums, the scales its rounding is relative to (a
  /// sum that cancels has a small value but errors as large as its terms'). With
  /// |sin|, |cos| <= 1, term t = c z^e w(a.z + b) and its derivatives are bounded by
  ///   |t| <= |c| |z|^e,
  ///   |d_i t| <= |c| (e_i |z|^(e - 1_i) + |a_i| |z|^e),
  ///   |d_ij t| <= |c| (e_i (e_j - d_ij) |z|^(e - 1_i - 1_j) + e_i |a_j| |z|^(e - 1_i)
  ///                    + |a_i| e_j |z|^(e - 1_j) + |a_i a_j| |z|^e),
  /// summed over the terms. magnitude() gives the value bound, gradient_magnitude() and
  /// hessian_magnitude() the Euclidean and Frobenius norms of the derivative bounds.
  template <class T>
  T magnitude(const phase_point<T>& x) const {
    T sum = lift<T>(0);
    for (const auto& t : terms) sum += monomial_bound(t, x, {});
    return sum;
  }
  template <class T>
  T gradient_magnitude(const phase_point<T>& x) const {
    T norm2 = lift<T>(0);
    for (int i = 0; i < 2 * dof; ++i) {
      T g = lift<T>(0);
      for (const auto& t : terms) {
        g += lift<T>(t.exponents[i]) * monomial_bound(t, x, {i});
        g += lift<T>(std::abs(t.frequencies[i])) * monomial_bound(t, x, {});
      }
      norm2 += g * g;
    }
    using std::sqrt;
    return sqrt(norm2);
  }
  template <class T>
  T hessian_magnitude(const phase_point<T>& x) const {
    T norm2 = lift<T>(0);
    for (int i = 0; i < 2 * dof; ++i)
      for (int j = 0; j < 2 * dof; ++j) {
        T h = lift<T>(0);
        for (const auto& t : terms) {
          const int ej = t.exponents[j] - (i == j ? 1 : 0);
          if (ej > 0) h += lift<T>(t.exponents[i] * ej) * monomial_bound(t, x, {i, j});
          h += lift<T>(t.exponents[i] * std::abs(t.frequencies[j])) * monomial_bound(t, x, {i});
          h += lift<T>(std::abs(t.frequencies[i]) * t.exponents[j]) * monomial_bound(t, x, {j});
          h += lift<T>(std::abs(t.frequencies[i] * t.frequencies[j])) * monomial_bound(t, x, {});
        }
        norm2 += h * h;
      }
    using std::sqrt;
    return sqrt(norm2);
  }

  template <class S>
  S operator()(const dynamic_vector<S>& q, const dynamic_vector<S>& p) const {
    using std::cos;
    using std::sin;
    if (q.size() != dof || p.size() != dof)
      throw dimension_error("smooth_function: defined on " + std::to_string(dof) +
                            " degrees of freedom, called with q of " + std::to_string(q.size()) +
                            " and p of " + std::to_string(p.size()));
    const auto z = [&](int i) -> const S& { return i < dof ? q(i) : p(i - dof); };
    S sum = lift<S>(0);
    for (const auto& t : terms) {
      S value = lift<S>(t.coefficient);
      for (int i = 0; i < 2 * dof; ++i)
        for (int e = 0; e < t.exponents[i]; ++e) value *= z(i);
      if (t.kind != wave::none) {
        S arg = lift<S>(t.phase);
        for (int i = 0; i < 2 * dof; ++i)
          if (t.frequencies[i] != 0) {
            const S a = lift<S>(t.frequencies[i]);
            arg += a * z(i);
          }
        const S w = t.kind == wave::sine ? S(sin(arg)) : S(cos(arg));
        value *= w;
      }
      sum += value;
    }
    return sum;
  }
};

/// |c| prod_i |z_i|^(e_i - d_i) with the exponents lowered by one for each index in
/// `lowered` (0 when an exponent would go negative: that derivative term is absent).
template <class T>
T smooth_function::monomial_bound(const term& t, const phase_point<T>& x,
                                  std::initializer_list<int> lowered) {
  using std::abs;
  T value = lift<T>(std::abs(t.coefficient));
  const int n = static_cast<int>(x.q().size());
  for (int i = 0; i < 2 * n; ++i) {
    int e = t.exponents[i];
    for (const int l : lowered) e -= l == i ? 1 : 0;
    if (e < 0) return lift<T>(0);
    const T z = abs(i < n ? x.q()(i) : x.p()(i - n));
    for (int k = 0; k < e; ++k) value *= z;
  }
  return value;
}

void showValue(const smooth_function& f, std::ostream& os);


/// A random smooth function of n degrees of freedom with 1 to 4 terms.
rc::Gen<smooth_function> smooth_functions(int dof);

/// A random smooth function of n degrees of freedom that does not depend on q_k.
rc::Gen<smooth_function> smooth_functions_without_q(int dof, int k);

/// A random radial potential U(r) = sum_j c_j r^j, j in {-2, -1, 1, 2, 3}, for r > 0.
struct radial_potential {
  std::vector<std::pair<int, double>> terms;  // (power, coefficient)
  template <class S>
  S operator()(const S& r) const {
    S u = lift<S>(0);
    for (const auto& [power, c] : terms) {
      S rn = lift<S>(1);
      for (int j = 0; j < (power < 0 ? -power : power); ++j) rn *= r;
      if (power < 0) rn = inverse(rn);
      const S cs = lift<S>(c);
      u += cs * rn;
    }
    return u;
  }
};

void showValue(const radial_potential& u, std::ostream& os);

rc::Gen<radial_potential> radial_potentials();

/// A point in R^3 x R^3 with |r| >= 1/4 (away from the centre of force).
rc::Gen<phase_sample> points_away_from_origin();

/// A pair potential of random shape: power law c r^k, Lennard-Jones-like or Morse-like.
struct pair_potential {
  enum class shape { power_law, lennard_jones, morse };
  shape kind = shape::power_law;
  double a = 1, b = 1, c = 1;  // power: (c, k = a); LJ: (depth a, size b); Morse: (a, b, r0 c)
  int k = -1;

  template <class S>
  S operator()(const S& r) const {
    switch (kind) {
      case shape::power_law:
        return models::power_law_pair<double>{a, k}(r);
      case shape::lennard_jones:
        return models::lennard_jones_pair<double>{a, b}(r);
      default:
        return models::morse_pair<double>{a, b, c}(r);
    }
  }
};

void showValue(const pair_potential& u, std::ostream& os);

rc::Gen<pair_potential> pair_potentials();

/// A homogeneous pair potential c r^k (degree k in {-2, -1, 1, 2, 3}).
rc::Gen<pair_potential> homogeneous_pair_potentials();

/// N particles (at most 8): masses, positions at pairwise distances >= 1, velocities.
struct particle_sample {
  std::vector<double> masses, q, qdot;
  Eigen::Index particles() const { return static_cast<Eigen::Index>(masses.size()); }

  template <class T>
  dynamic_vector<T> positions() const {
    dynamic_vector<T> v(q.size());
    for (std::size_t i = 0; i < q.size(); ++i) v(i) = T(q[i]);
    return v;
  }
  template <class T>
  dynamic_vector<T> velocities() const {
    dynamic_vector<T> v(qdot.size());
    for (std::size_t i = 0; i < qdot.size(); ++i) v(i) = T(qdot[i]);
    return v;
  }
  template <class T>
  std::vector<T> tier_masses() const {
    return std::vector<T>(masses.begin(), masses.end());
  }
};

void showValue(const particle_sample& s, std::ostream& os);

rc::Gen<particle_sample> particle_samples(int min_particles = 2, int max_particles = 4);

/// A model system chosen at random, with a state where its kinetic matrix is regular.
struct model_case {
  int which = 0;  // 0 spring pendulum, 1 spherical, 2 rotating pivot, 3 N-body, 4 and 5 N-body
                  // relativistic / quartic with velocity coupling (params beta, kappa)
  std::vector<double> params, q, qdot;
  double t = 0;
  pair_potential pair;
  particle_sample particles;
};

void showValue(const model_case& c, std::ostream& os);

/// A model system with its parameters and a state: spring, spherical and rotating-pivot
/// pendulums, N particles with a random pair potential, and N particles whose L is not
/// quadratic in the velocities (relativistic or quartic, with Darwin-like coupling).
rc::Gen<model_case> model_cases();

/// The closed N-particle cases of model_cases (which = 3, 4, 5): invariant under
/// translations, rotations and time translation; Galilean boosts only for which = 3.
rc::Gen<model_case> closed_particle_cases();

/// A random robot (robots/robot.hpp): 1 to max_links moving links under a massless base, as a
/// chain or a branching tree; revolute, continuous, prismatic and fixed joints with axes
/// along x, y, z or any direction; joint origins turned by any roll-pitch-yaw; centres of
/// mass off the axes; inertia tensors with off-diagonal terms (principal moments over three
/// decades, up to the triangle bound I1 + I2 = I3), turned again by the inertial origin;
/// masses over four decades. Every number is dyadic (exact in every tier). Shrinks towards
/// one link, a chain, revolute joints about z, zero offsets and angles, diagonal unit
/// inertias and unit masses.
rc::Gen<robots::robot> random_robots(int max_links = 8);

/// A robot with a state: q (angles in [-pi, pi], slides in [-1, 1]), qdot, qddot and tau,
/// the rates up to 16 in size.
struct robot_case {
  robots::robot robot;
  std::vector<double> q, qdot, qddot, tau;
};

void showValue(const robot_case& c, std::ostream& os);

rc::Gen<robot_case> robot_cases(int max_links = 8);

/// Inside an rc::gen::exec: every moving joint of `r` draws, where asked, an armature in
/// [0, 1/4] kg m^2 (or kg) and a damping in [0, 2] N m s/rad (or N s/m) (robots::joint),
/// dyadic (exact in every tier), zero about a third of the time each; shrinks towards none.
/// Drawn after the robot, so that the robot is the one drawn without them.
void draw_joint_terms(robots::robot& r, bool armature, bool damping);

/// A robot of `joints` on a floating base (robots/floating.hpp): the root link (a torso) given a
/// body of its own; the base's pose (xyz in [-1, 1], rpy in [-3.14, 3.14]), its twist
/// (v_b; w_b), the twist's rate and a wrench (f_b; n_b) on it, each component in [-4, 4].
struct floating_robot_case {
  robot_case joints;
  robots::pose base;
  std::vector<double> twist, twist_rate, wrench;
};

void showValue(const floating_robot_case& c, std::ostream& os);

rc::Gen<floating_robot_case> floating_robot_cases(rc::Gen<robot_case> joints);

/// A case of bodies in contact (reference/contact.hpp; the engines' contact scenarios): every
/// number dyadic, so that a case is exact in every tier and in an engine's input file.
///   theta, psi: the velocity's direction and the body's yaw about z, in [-3.15, 3.15] rad;
///   mu: the friction coefficient in [0.05, 1.5];
///   mass: 2^-6 to 2^7 times a dyadic in [1, 2) (four decades);
///   size: a half-edge or radius in 2^-3 to 2^3 times a dyadic in [1, 2) (two decades);
///   aspect: the box's other half-edges over `size`, in [1/2, 2];
///   e: the restitution in [0, 1];
///   speed: in [1/4, 4];
///   slope: the ground's angle relative to the friction angle atan(mu): below it, near it
///     (within 1/64 rad) or above it, never steeper than 1.3 rad;
///   height: a drop in [1/8, 2].
struct contact_case {
  double theta = 0, psi = 0, mu = 0.5, mass = 1, size = 0.1, aspect_b = 1, aspect_c = 1, e = 0.5, speed = 1,
         slope = 0, height = 1;
};

void showValue(const contact_case& c, std::ostream& os);

rc::Gen<contact_case> contact_cases();

/// A direction: three dyadic components in [-2, 2], not all zero.
rc::Gen<std::vector<double>> directions();

/// Generic (q, qdot) of n coordinates in [-2, 2].
rc::Gen<std::vector<double>> coordinates(int n);

template <class T>
dynamic_vector<T> to_tier(const std::vector<double>& v) {
  dynamic_vector<T> out(v.size());
  for (std::size_t i = 0; i < v.size(); ++i) out(i) = T(v[i]);
  return out;
}

/// A 3-vector of coordinates in [-2, 2], drawn inside a property.
template <class T>
vector3<T> draw_vector3() {
  const auto v = *coordinates(3);
  return vector3<T>(T(v[0]), T(v[1]), T(v[2]));
}

}  // namespace mechcheck::generators
