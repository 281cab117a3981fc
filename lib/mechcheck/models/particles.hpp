#pragma once
/// N point masses in three dimensions with pair potentials and an optional external
/// field: q = (r_1, ..., r_N) stacked (length 3N),
///   L = sum_i m_i |rdot_i|^2 / 2 - sum_{i<j} U(|r_i - r_j|) - sum_i V(z_i)
/// (notes lectures 6-8: translations, rotations, time translation, broken symmetry), and
/// velocity_coupled_system, whose L is not quadratic in the velocities.

#include <cmath>
#include <string>
#include <vector>

#include "mechcheck/core.hpp"

namespace mechcheck::models {

/// U(r) = c r^k for an integer k != 0 (homogeneous of degree k).
template <class P>
struct power_law_pair {
  P c;
  int k;
  power_law_pair(P c_, int k_) : c(std::move(c_)), k(k_) {
    require_finite_value(c, "power_law_pair", "c");
    if (k == 0)
      throw domain_error("power_law_pair: exponent k must be a non-zero integer, got k = 0");
  }
  template <class S>
  S operator()(const S& r) const {
    S rk = lift<S>(1);
    for (int j = 0; j < (k < 0 ? -k : k); ++j) rk *= r;
    if (k < 0) rk = inverse(rk);
    const S cs = lift<S>(c);
    return cs * rk;
  }
};

/// Lennard-Jones-like U(r) = e ((s/r)^12 - 2 (s/r)^6), minimum -e at r = s.
template <class P>
struct lennard_jones_pair {
  P depth, size;
  lennard_jones_pair(P e, P s) : depth(std::move(e)), size(std::move(s)) {
    require_positive(depth, "lennard_jones_pair", "depth");
    require_positive(size, "lennard_jones_pair", "size");
  }
  template <class S>
  S operator()(const S& r) const {
    const S x = lift<S>(size) * inverse(r);
    const S x2 = x * x;
    const S x6 = x2 * x2 * x2;
    const S x12 = x6 * x6;
    const S two_x6 = lift<S>(2) * x6;
    const S bracket = x12 - two_x6;
    const S e = lift<S>(depth);
    return e * bracket;
  }
};

/// Morse-like U(r) = D (1 - exp(-a (r - r0)))^2 - D.
template <class P>
struct morse_pair {
  P depth, width, r0;
  morse_pair(P d, P a, P r) : depth(std::move(d)), width(std::move(a)), r0(std::move(r)) {
    require_positive(depth, "morse_pair", "depth");
    require_positive(width, "morse_pair", "width");
    require_positive(r0, "morse_pair", "r0");
  }
  template <class S>
  S operator()(const S& r) const {
    using std::exp;
    const S d = lift<S>(depth);
    const S arg = lift<S>(width) * (r - lift<S>(r0));
    const S e = exp(-arg);
    const S one_minus = lift<S>(1) - e;
    const S sq = one_minus * one_minus;
    const S du = d * sq;
    return du - d;
  }
};

/// No external field.
struct no_field {
  template <class S>
  S operator()(const S&) const {
    return lift<S>(0);
  }
};

/// External field along z: V(z) = a z + b z^2 (per unit of nothing: the same for every
/// particle). Breaks translations along z and rotations about x and y; keeps the rest.
template <class P>
struct vertical_field {
  P a, b;
  vertical_field(P a_, P b_) : a(std::move(a_)), b(std::move(b_)) {
    require_finite_value(a, "vertical_field", "a");
    require_finite_value(b, "vertical_field", "b");
  }
  template <class S>
  S operator()(const S& z) const {
    const S az = lift<S>(a) * z;
    const S bz2 = lift<S>(b) * z * z;
    return az + bz2;
  }
};

template <class P, class Pair, class Field = no_field>
struct particle_system {
  std::vector<P> masses;
  Pair pair;
  Field field{};

  particle_system(std::vector<P> m, Pair u, Field v = {})
      : masses(std::move(m)), pair(std::move(u)), field(std::move(v)) {
    for (std::size_t i = 0; i < masses.size(); ++i)
      require_positive(masses[i], "particle_system", ("mass " + std::to_string(i)).c_str());
  }

  Eigen::Index particles() const { return static_cast<Eigen::Index>(masses.size()); }
  Eigen::Index dof() const { return 3 * particles(); }

  template <class S>
  void require_size(const dynamic_vector<S>& q) const {
    if (q.size() != dof())
      throw dimension_error("particle_system: " + std::to_string(particles()) +
                            " particles need 3N = " + std::to_string(dof()) +
                            " coordinates, got " + std::to_string(q.size()));
  }

  template <class S>
  S kinetic(const dynamic_vector<S>& qdot) const {
    require_size(qdot);
    S t = lift<S>(0);
    for (Eigen::Index i = 0; i < particles(); ++i) {
      S v2 = lift<S>(0);
      for (int c = 0; c < 3; ++c) {
        const S vc = qdot(3 * i + c) * qdot(3 * i + c);
        v2 += vc;
      }
      const S ti = lift<S>(masses[i]) * v2 * half<S>();
      t += ti;
    }
    return t;
  }

  template <class S>
  S potential(const dynamic_vector<S>& q) const {
    using std::sqrt;
    require_size(q);
    S v = lift<S>(0);
    for (Eigen::Index i = 0; i < particles(); ++i) {
      const S vi = field(q(3 * i + 2));
      v += vi;
      for (Eigen::Index j = i + 1; j < particles(); ++j) {
        S d2 = lift<S>(0);
        for (int c = 0; c < 3; ++c) {
          const S dc = q(3 * i + c) - q(3 * j + c);
          const S dc2 = dc * dc;
          d2 += dc2;
        }
        const S u = pair(S(sqrt(d2)));
        v += u;
      }
    }
    return v;
  }

  template <class S>
  S operator()(const dynamic_vector<S>& q, const dynamic_vector<S>& qdot, const S&) const {
    const S t = kinetic(qdot);
    const S v = potential(q);
    return t - v;
  }
};

/// The kinetic term of one particle in a velocity_coupled_system.
enum class kinetic_form {
  relativistic,  ///< -m sqrt(1 - |v|^2), units with c = 1; defined for |v| < 1
  quartic        ///< m |v|^2 / 2 + beta m |v|^4 / 4, beta >= 0
};

/// N particles whose Lagrangian is not quadratic in the velocities (the Legendre transform
/// of notes eqs 244-257 is for any L): each particle's kinetic term is relativistic or
/// quartic (kinetic_form), and each pair is coupled through its velocities as in Darwin's
/// Lagrangian besides its potential U(r),
///   L = sum_a K(m_a, v_a) + sum_{a<b} [kappa / (2 r) (v_a.v_b + (v_a.n)(v_b.n)) - U(r)],
/// r = |r_a - r_b|, n = (r_a - r_b) / r. Closed: invariant under translations, rotations
/// and time translation; not under Galilean boosts. The kinetic matrix d2L/dqdot2 is
/// positive definite while |kappa| / r_min stays below the smallest mass over N - 1.
/// Evaluating a relativistic particle at |v| >= 1 throws domain_error.
template <class P, class Pair>
struct velocity_coupled_system {
  std::vector<P> masses;
  Pair pair;
  kinetic_form form;
  P beta, kappa;

  velocity_coupled_system(std::vector<P> m, Pair u, kinetic_form f, P beta_, P kappa_)
      : masses(std::move(m)), pair(std::move(u)), form(f), beta(std::move(beta_)),
        kappa(std::move(kappa_)) {
    for (std::size_t i = 0; i < masses.size(); ++i)
      require_positive(masses[i], "velocity_coupled_system", ("mass " + std::to_string(i)).c_str());
    require_non_negative(beta, "velocity_coupled_system", "beta");
    require_finite_value(kappa, "velocity_coupled_system", "kappa");
  }

  Eigen::Index particles() const { return static_cast<Eigen::Index>(masses.size()); }
  Eigen::Index dof() const { return 3 * particles(); }

  template <class S>
  S operator()(const dynamic_vector<S>& q, const dynamic_vector<S>& qdot, const S&) const {
    using std::sqrt;
    if (q.size() != dof() || qdot.size() != dof())
      throw dimension_error("velocity_coupled_system: " + std::to_string(particles()) +
                            " particles need 3N = " + std::to_string(dof()) +
                            " coordinates and velocities, got " + std::to_string(q.size()) +
                            " and " + std::to_string(qdot.size()));
    S l = lift<S>(0);
    for (Eigen::Index a = 0; a < particles(); ++a) {
      S v2 = lift<S>(0);
      for (int c = 0; c < 3; ++c) {
        const S vc = qdot(3 * a + c) * qdot(3 * a + c);
        v2 += vc;
      }
      const S m = lift<S>(masses[a]);
      if (form == kinetic_form::relativistic) {
        if (!(innermost_value(v2) < 1))
          throw domain_error("velocity_coupled_system: relativistic particle " +
                             std::to_string(a) + " has |v|^2 = " + to_text(v2) +
                             ", not below c^2 = 1");
        const S root = sqrt(S(lift<S>(1) - v2));
        const S k = m * root;
        l -= k;
      } else {
        const S quadratic = m * v2 * half<S>();
        const S quartic = lift<S>(beta) * m * v2 * v2 / lift<S>(4);
        l += quadratic;
        l += quartic;
      }
      for (Eigen::Index b = a + 1; b < particles(); ++b) {
        S d2 = lift<S>(0), vv = lift<S>(0), vad = lift<S>(0), vbd = lift<S>(0);
        for (int c = 0; c < 3; ++c) {
          const S dc = q(3 * a + c) - q(3 * b + c);
          const S dc2 = dc * dc;
          d2 += dc2;
          const S vab = qdot(3 * a + c) * qdot(3 * b + c);
          vv += vab;
          const S vac = qdot(3 * a + c) * dc;
          vad += vac;
          const S vbc = qdot(3 * b + c) * dc;
          vbd += vbc;
        }
        const S r = sqrt(d2);
        const S along = vad * vbd / d2;
        const S bracket = vv + along;
        const S two_r = lift<S>(2) * r;
        const S coupling = lift<S>(kappa) * bracket / two_r;
        const S u = pair(r);
        l += coupling;
        l -= u;
      }
    }
    return l;
  }
};

}  // namespace mechcheck::models
