#pragma once
/// Standard phase-space functions: angular momentum and model Hamiltonians.
/// Parameters are stored in a tier type P and lifted into the evaluation scalar S.

#include <string>

#include "mechcheck/phase_space.hpp"

namespace mechcheck {

namespace detail {
template <class S>
void require_three_dof(const dynamic_vector<S>& q, const char* where) {
  if (q.size() != 3)
    throw dimension_error(std::string(where) + ": q needs 3 degrees of freedom (Cartesian r), got " +
                          std::to_string(q.size()));
}
template <class S>
S squared_norm(const dynamic_vector<S>& v) {
  S s = lift<S>(0);
  for (Eigen::Index i = 0; i < v.size(); ++i) s += v(i) * v(i);
  return s;
}
}  // namespace detail

/// The coordinate function (q, p) -> q_i.
struct q_component {
  int i;
  template <class S>
  S operator()(const dynamic_vector<S>& q, const dynamic_vector<S>&) const {
    return q(i);
  }
};

/// The momentum function (q, p) -> p_i.
struct p_component {
  int i;
  template <class S>
  S operator()(const dynamic_vector<S>&, const dynamic_vector<S>& p) const {
    return p(i);
  }
};

/// The Levi-Civita symbol eps_ijk on 0-based indices: +1 for even permutations of
/// (0, 1, 2), -1 for odd ones, 0 when two indices agree (notes lecture 22, eq. 281).
constexpr int levi_civita(int i, int j, int k) { return (i - j) * (j - k) * (k - i) / 2; }
static_assert(levi_civita(0, 1, 2) == 1 && levi_civita(1, 2, 0) == 1 &&
              levi_civita(1, 0, 2) == -1 && levi_civita(2, 1, 0) == -1 &&
              levi_civita(0, 0, 1) == 0 && levi_civita(2, 1, 2) == 0);

/// Component M_i of the angular momentum M = r x p, M_i = eps_ijk r_j p_k
/// (notes lecture 22, eq. 281); index i in {0, 1, 2} for M_1, M_2, M_3. Needs n = 3.
struct angular_momentum {
  int i;
  template <class S>
  S operator()(const dynamic_vector<S>& q, const dynamic_vector<S>& p) const {
    detail::require_three_dof(q, "angular_momentum");
    return cross_component(q, p, i);
  }
};

/// M^2 = |r x p|^2. Needs n = 3.
struct angular_momentum_squared {
  template <class S>
  S operator()(const dynamic_vector<S>& q, const dynamic_vector<S>& p) const {
    S m2 = lift<S>(0);
    for (int i = 0; i < 3; ++i) {
      const S mi = angular_momentum{i}(q, p);
      m2 += mi * mi;
    }
    return m2;
  }
};

/// Isotropic harmonic oscillator H = |p|^2 / (2m) + k |q|^2 / 2, any n (mass m, stiffness k).
template <class P>
struct harmonic_oscillator {
  P mass, stiffness;
  harmonic_oscillator(P m, P k) : mass(std::move(m)), stiffness(std::move(k)) {
    require_positive(mass, "harmonic_oscillator", "mass");
    require_positive(stiffness, "harmonic_oscillator", "stiffness");
  }
  template <class S>
  S operator()(const dynamic_vector<S>& q, const dynamic_vector<S>& p) const {
    using R = real_type_t<S>;  // derived constants in the evaluation tier, never in P
    const S inv_two_m = lift<S>(R(1) / (R(2) * R(mass)));
    const S half_k = lift<S>(stiffness) * half<S>();
    const S kinetic = detail::squared_norm(p) * inv_two_m;
    const S potential = half_k * detail::squared_norm(q);
    return kinetic + potential;
  }
};

/// Central-force Hamiltonian H = |p|^2 / (2m) + U(|r|) (notes eq. 255 with V = U(r)).
/// U is a radial potential: a generic callable `U(r) -> S`.
template <class P, class U>
struct central_force_hamiltonian {
  P mass;
  U potential;
  central_force_hamiltonian(P m, U u) : mass(std::move(m)), potential(std::move(u)) {
    require_positive(mass, "central_force_hamiltonian", "mass");
  }
  template <class S>
  S operator()(const dynamic_vector<S>& q, const dynamic_vector<S>& p) const {
    using std::sqrt;
    const S r = sqrt(detail::squared_norm(q));
    const S u = potential(r);
    using R = real_type_t<S>;  // derived constants in the evaluation tier, never in P
    const S inv_two_m = lift<S>(R(1) / (R(2) * R(mass)));
    const S kinetic = detail::squared_norm(p) * inv_two_m;
    return kinetic + u;
  }
};

/// Power-law potential U(r) = k r^n for an integer n != 0 (Kepler: n = -1, k < 0).
template <class P>
struct power_law_potential {
  P k;
  int n;
  power_law_potential(P k_, int n_) : k(std::move(k_)), n(n_) {
    require_finite_value(k, "power_law_potential", "k");
    if (n == 0)
      throw domain_error("power_law_potential: exponent n must be a non-zero integer, got n = 0");
  }
  template <class S>
  S operator()(const S& r) const {
    S rn = lift<S>(1);
    for (int j = 0; j < (n < 0 ? -n : n); ++j) rn *= r;
    if (n < 0) rn = inverse(rn);
    const S ks = lift<S>(k);
    return ks * rn;
  }
};

}  // namespace mechcheck
