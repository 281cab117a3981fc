#pragma once
/// Systems the integrators advance. A state is (q, p) in any Eigen vector type Vec (fixed
/// size for speed, dynamic_vector for generality, AD scalars for Jacobians of a step).
///
/// A *separable* system H = T(p) + V(q) provides
///     void velocity(const Vec& p, Vec& dq) const;   // dq = dT/dp
///     void force(const Vec& q, Vec& dp) const;      // dp = -dV/dq
/// and every system provides the Hamiltonian vector field (notes eq 250)
///     void vector_field(const Vec& q, const Vec& p, Vec& dq, Vec& dp) const;
/// plus `energy(q, p)`.

#include <string>
#include <vector>

#include "mechcheck/core.hpp"
#include "mechcheck/core/inplace.hpp"
#include "mechcheck/models/particles.hpp"
#include "mechcheck/poisson/bracket.hpp"

namespace mechcheck {

template <class Vec>
struct phase_state {
  Vec q, p;
};

namespace detail {
/// Multiprecision numbers of a system's own tier T are computed into kept numbers
/// (mechcheck/core/inplace.hpp), so that an evaluation allocates nothing.
template <class S, class T>
constexpr bool in_place = inplace::is_number_v<S> && std::is_same_v<S, T>;

/// dq = p (1/m), the velocity of a kinetic energy |p|^2 / (2m).
template <class T, class Vec>
void velocity_of_mass(const T& mass, const Vec& p, Vec& dq) {
  using S = typename Vec::Scalar;
  using R = real_type_t<S>;  // derived constants in the evaluation tier
  if constexpr (in_place<S, T>) {
    thread_local S inv_m;
    inv_m = 1;
    inv_m /= mass;
    for (Eigen::Index i = 0; i < p.size(); ++i) inplace::multiply(dq(i), p(i), inv_m);
  } else {
    const S inv_m = lift<S>(R(1) / R(mass));
    for (Eigen::Index i = 0; i < p.size(); ++i) dq(i) = p(i) * inv_m;
  }
}
}  // namespace detail

/// Kepler problem H = |p|^2 / (2m) - k / |q| in any dimension (k > 0: attraction).
template <class T>
struct kepler_system {
  T mass, k;
  kepler_system(T m, T k_) : mass(std::move(m)), k(std::move(k_)) {
    require_positive(mass, "kepler_system", "mass");
    require_positive(k, "kepler_system", "k");
  }
  template <class Vec>
  void velocity(const Vec& p, Vec& dq) const {
    detail::velocity_of_mass(mass, p, dq);
  }
  template <class Vec>
  void force(const Vec& q, Vec& dp) const {
    using S = typename Vec::Scalar;
    using std::sqrt;
    if constexpr (detail::in_place<S, T>) {  // the operations below, into kept numbers
      thread_local S r2, c;
      r2 = 0;
      for (Eigen::Index i = 0; i < q.size(); ++i) inplace::add_product(r2, q(i), q(i), c);
      inplace::sqrt(c, r2);
      c *= r2;                     // r^3
      inplace::divide(c, k, c);    // k / r^3
      inplace::negate(c);
      for (Eigen::Index i = 0; i < q.size(); ++i) inplace::multiply(dp(i), c, q(i));
    } else if constexpr (!is_ad_v<S>) {
      const S r2 = q.squaredNorm();
      dp.noalias() = (-S(k) / (r2 * sqrt(r2))) * q;
    } else {
      S r2 = lift<S>(0);
      for (Eigen::Index i = 0; i < q.size(); ++i) {
        const S qi2 = q(i) * q(i);
        r2 += qi2;
      }
      const S r = sqrt(r2);
      const S r3 = r2 * r;
      const S minus_k_over_r3 = -lift<S>(k) * inverse(r3);
      for (Eigen::Index i = 0; i < q.size(); ++i) dp(i) = q(i) * minus_k_over_r3;
    }
  }
  template <class Vec>
  void vector_field(const Vec& q, const Vec& p, Vec& dq, Vec& dp) const {
    velocity(p, dq);
    force(q, dp);
  }
  template <class Vec>
  typename Vec::Scalar energy(const Vec& q, const Vec& p) const {
    using S = typename Vec::Scalar;
    using std::sqrt;
    using R = real_type_t<S>;
    S p2 = lift<S>(0);
    for (Eigen::Index i = 0; i < p.size(); ++i) {
      const S pi2 = p(i) * p(i);
      p2 += pi2;
    }
    S q2 = lift<S>(0);
    for (Eigen::Index i = 0; i < q.size(); ++i) {
      const S qi2 = q(i) * q(i);
      q2 += qi2;
    }
    const S kinetic = p2 * lift<S>(R(1) / (R(2) * R(mass)));
    const S potential = -lift<S>(k) * inverse(S(sqrt(q2)));
    return kinetic + potential;
  }
};

/// Isotropic harmonic oscillator H = |p|^2 / (2m) + k |q|^2 / 2 in any dimension.
template <class T>
struct harmonic_oscillator_system {
  T mass, stiffness;
  harmonic_oscillator_system(T m, T k) : mass(std::move(m)), stiffness(std::move(k)) {
    require_positive(mass, "harmonic_oscillator_system", "mass");
    require_positive(stiffness, "harmonic_oscillator_system", "stiffness");
  }
  template <class Vec>
  void velocity(const Vec& p, Vec& dq) const {
    detail::velocity_of_mass(mass, p, dq);
  }
  template <class Vec>
  void force(const Vec& q, Vec& dp) const {
    using S = typename Vec::Scalar;
    if constexpr (detail::in_place<S, T>) {
      thread_local S minus_k;
      minus_k = stiffness;
      inplace::negate(minus_k);
      for (Eigen::Index i = 0; i < q.size(); ++i) inplace::multiply(dp(i), q(i), minus_k);
    } else {
      const S minus_k = lift<S>(real_type_t<S>(-stiffness));
      for (Eigen::Index i = 0; i < q.size(); ++i) dp(i) = q(i) * minus_k;
    }
  }
  template <class Vec>
  void vector_field(const Vec& q, const Vec& p, Vec& dq, Vec& dp) const {
    velocity(p, dq);
    force(q, dp);
  }
  template <class Vec>
  typename Vec::Scalar energy(const Vec& q, const Vec& p) const {
    using S = typename Vec::Scalar;
    using R = real_type_t<S>;
    S p2 = lift<S>(0), q2 = lift<S>(0);
    for (Eigen::Index i = 0; i < p.size(); ++i) {
      const S a = p(i) * p(i), b = q(i) * q(i);
      p2 += a;
      q2 += b;
    }
    const S kinetic = p2 * lift<S>(R(1) / (R(2) * R(mass)));
    const S potential = q2 * lift<S>(R(stiffness) / R(2));
    return kinetic + potential;
  }
};

/// Simple pendulum H = p^2 / (2 m l^2) - m g l cos(q) (notes eq 260), n = 1.
template <class T>
struct pendulum_system {
  T mass, length, gravity;
  pendulum_system(T m, T l, T g) : mass(std::move(m)), length(std::move(l)), gravity(std::move(g)) {
    require_positive(mass, "pendulum_system", "mass");
    require_positive(length, "pendulum_system", "length");
    require_positive(gravity, "pendulum_system", "gravity");
  }
  template <class Vec>
  void velocity(const Vec& p, Vec& dq) const {
    using S = typename Vec::Scalar;
    using R = real_type_t<S>;
    dq(0) = p(0) * lift<S>(R(1) / (R(mass) * R(length) * R(length)));
  }
  template <class Vec>
  void force(const Vec& q, Vec& dp) const {
    using S = typename Vec::Scalar;
    using std::sin;
    const S s = sin(q(0));
    using R = real_type_t<S>;
    dp(0) = -lift<S>(R(mass) * R(gravity) * R(length)) * s;
  }
  template <class Vec>
  void vector_field(const Vec& q, const Vec& p, Vec& dq, Vec& dp) const {
    velocity(p, dq);
    force(q, dp);
  }
  template <class Vec>
  typename Vec::Scalar energy(const Vec& q, const Vec& p) const {
    using S = typename Vec::Scalar;
    using std::cos;
    using R = real_type_t<S>;
    const R ml2 = R(mass) * R(length) * R(length);
    const S kinetic = p(0) * p(0) * lift<S>(R(1) / (2 * ml2));
    const S c = cos(q(0));
    const S potential = lift<S>(R(mass) * R(gravity) * R(length)) * c;
    return kinetic - potential;
  }
};

/// N particles in 3D with one pair potential U(r) (generic callable of r): forces are
/// computed once per pair and applied with opposite signs, so the total force is zero
/// and the total torque vanishes up to rounding (the structure Stormer-Verlet keeps).
template <class T, class Pair>
struct pair_force_system {
  std::vector<T> masses;
  Pair pair;

  pair_force_system(std::vector<T> m, Pair u) : masses(std::move(m)), pair(std::move(u)) {
    for (std::size_t i = 0; i < masses.size(); ++i)
      require_positive(masses[i], "pair_force_system", ("mass " + std::to_string(i)).c_str());
  }

  Eigen::Index particles() const { return static_cast<Eigen::Index>(masses.size()); }

  template <class Vec>
  void velocity(const Vec& p, Vec& dq) const {
    using S = typename Vec::Scalar;
    using R = real_type_t<S>;
    for (Eigen::Index i = 0; i < p.size(); ++i) dq(i) = p(i) * lift<S>(R(1) / R(masses[i / 3]));
  }
  template <class Vec>
  void force(const Vec& q, Vec& dp) const {
    using S = typename Vec::Scalar;
    using std::sqrt;
    for (Eigen::Index i = 0; i < dp.size(); ++i) dp(i) = lift<S>(0);
    for (Eigen::Index i = 0; i < particles(); ++i)
      for (Eigen::Index j = i + 1; j < particles(); ++j) {
        S d[3];
        S r2 = lift<S>(0);
        for (int c = 0; c < 3; ++c) {
          d[c] = q(3 * i + c) - q(3 * j + c);
          const S dc2 = d[c] * d[c];
          r2 += dc2;
        }
        const S r = sqrt(r2);
        // U'(r) by one forward-AD direction in r.
        using A = ad<S>;
        const ad_width_scope<A> width(1);
        const A ra(r, dynamic_vector<S>::Constant(1, lift<S>(1)));
        const A u = pair(ra);
        const S du = derivatives_of(u, 1)(0);
        const S coefficient = -du * inverse(r);  // F_i = -U'(r) (r_i - r_j) / r
        for (int c = 0; c < 3; ++c) {
          const S f = coefficient * d[c];
          dp(3 * i + c) += f;
          dp(3 * j + c) -= f;
        }
      }
  }
  template <class Vec>
  void vector_field(const Vec& q, const Vec& p, Vec& dq, Vec& dp) const {
    velocity(p, dq);
    force(q, dp);
  }
  /// H = sum |p_i|^2 / 2m_i + sum_{i<j} U(|r_i - r_j|): the potential of the same
  /// N-particle model the Lagrangian laws use.
  template <class Vec>
  typename Vec::Scalar energy(const Vec& q, const Vec& p) const {
    using S = typename Vec::Scalar;
    using R = real_type_t<S>;
    const dynamic_vector<S> qs = q;
    dynamic_vector<S> velocities(p.size());
    for (Eigen::Index i = 0; i < p.size(); ++i)
      velocities(i) = p(i) * lift<S>(R(1) / R(masses[i / 3]));
    const models::particle_system<T, Pair> model(masses, pair);
    const S kinetic = model.kinetic(velocities);
    const S potential = model.potential(qs);
    return kinetic + potential;
  }
};

/// Any Hamiltonian H(q, p) (a phase-space function) as a system, its vector field by AD.
/// Not separable: only the implicit (Gauss-Legendre) and the non-symplectic methods
/// take it.
template <class H>
struct hamiltonian_system {
  H hamiltonian;
  template <class Vec>
  void vector_field(const Vec& q, const Vec& p, Vec& dq, Vec& dp) const {
    using S = typename Vec::Scalar;
    const dynamic_vector<S> qs = q, ps = p;
    const dynamic_vector<S> v = hamiltonian_vector_field(hamiltonian, phase_point<S>(qs, ps));
    const Eigen::Index n = q.size();
    for (Eigen::Index i = 0; i < n; ++i) {
      dq(i) = v(i);
      dp(i) = v(n + i);
    }
  }
  template <class Vec>
  typename Vec::Scalar energy(const Vec& q, const Vec& p) const {
    using S = typename Vec::Scalar;
    const dynamic_vector<S> qs = q, ps = p;
    return hamiltonian(qs, ps);
  }
};

}  // namespace mechcheck
