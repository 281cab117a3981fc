#pragma once
/// The classic test problems without closed forms, each with its source, selectable by name
/// (`mechcheck-audit -p pleiades`), their solutions certified references (reference_problem):
///
///   pleiades             seven stars in the plane, m_i = i, G = 1, t in [0, 3]: Hairer,
///                        Norsett & Wanner, Solving ODEs I (2nd ed.), II.10, p. 245; the Bari
///                        IVP test set's PLEI
///   arenstorf            the restricted three-body problem (Earth, Moon, a satellite) in the
///                        rotating frame, mu = 0.012277471, the periodic Arenstorf orbit over
///                        one period T = 17.0652165601579625588917206249: HNW I, II.0, p. 130
///   outer_solar_system   the Sun (with the inner planets) and Jupiter, Saturn, Uranus,
///                        Neptune, Pluto, 3D, AU and days, G = 2.95912208286e-4, over 20 000
///                        days: Hairer, Lubich & Wanner, Geometric Numerical Integration, I.2.4
///   henon_heiles_regular H = (|p|^2 + |q|^2)/2 + q1^2 q2 - q2^3/3 (Henon & Heiles 1964) at
///                        H = 0.0807 from q = (0, 0.1), p = (0.39, 0), over t = 50
///   henon_heiles_chaotic the same at H = 0.1621 from q = (0, -0.1), p = (0.56, 0) over
///                        t = 1000: past the horizon of certification (the reference says how
///                        many digits it has)
///   double_pendulum      two equal masses on equal rigid massless rods, m = l = g = 1, the
///                        Hamiltonian of the standard Lagrangian, from 0.5 rad each at rest,
///                        over t = 10
///
/// The systems are templated on their parameters' type P (the tier's, or mpfr50 for the
/// reference) and evaluate on any scalar (the tier, AD, mpfr50).

#include <algorithm>
#include <string>
#include <vector>

#include "mechcheck/audit/problems/reference_problem.hpp"
#include "mechcheck/core.hpp"

namespace mechcheck::audit {

/// N bodies under Newtonian gravity in `dim` dimensions: H = sum |p_i|^2 / 2 m_i - sum_{i<j}
/// G m_i m_j / |q_i - q_j|; separable (velocity p_i / m_i, force by pairs with opposite signs).
template <class P>
struct gravity_system {
  int dim = 2;
  std::vector<P> masses;
  P g = P(1);

  template <class Vec>
  void velocity(const Vec& p, Vec& dq) const {
    using S = typename Vec::Scalar;
    using R = real_type_t<S>;
    for (Eigen::Index i = 0; i < p.size(); ++i) dq(i) = p(i) * lift<S>(R(1) / R(masses[std::size_t(i / dim)]));
  }
  template <class Vec>
  void force(const Vec& q, Vec& dp) const {
    using S = typename Vec::Scalar;
    using R = real_type_t<S>;
    using std::sqrt;
    for (Eigen::Index i = 0; i < dp.size(); ++i) dp(i) = lift<S>(0);
    const Eigen::Index n = static_cast<Eigen::Index>(masses.size());
    for (Eigen::Index i = 0; i < n; ++i)
      for (Eigen::Index j = i + 1; j < n; ++j) {
        S r2 = lift<S>(0);
        for (int c = 0; c < dim; ++c) {
          const S d = q(dim * i + c) - q(dim * j + c);
          r2 += d * d;
        }
        const S r = sqrt(r2);
        const S k = lift<S>(R(g) * R(masses[std::size_t(i)]) * R(masses[std::size_t(j)])) / (r2 * r);
        for (int c = 0; c < dim; ++c) {
          const S f = k * (q(dim * i + c) - q(dim * j + c));
          dp(dim * i + c) -= f;
          dp(dim * j + c) += f;
        }
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
    using std::sqrt;
    S e = lift<S>(0);
    const Eigen::Index n = static_cast<Eigen::Index>(masses.size());
    for (Eigen::Index i = 0; i < p.size(); ++i) e += p(i) * p(i) * lift<S>(R(1) / (2 * R(masses[std::size_t(i / dim)])));
    for (Eigen::Index i = 0; i < n; ++i)
      for (Eigen::Index j = i + 1; j < n; ++j) {
        S r2 = lift<S>(0);
        for (int c = 0; c < dim; ++c) {
          const S d = q(dim * i + c) - q(dim * j + c);
          r2 += d * d;
        }
        e -= lift<S>(R(g) * R(masses[std::size_t(i)]) * R(masses[std::size_t(j)])) / sqrt(r2);
      }
    return e;
  }
};

/// The restricted three-body problem in the frame rotating with the primaries (Earth at
/// (-mu, 0), Moon at (1 - mu, 0)): H = |p|^2/2 + y p_x - x p_y - (1 - mu)/r1 - mu/r2, p =
/// (xdot - y, ydot + x); not separable.
template <class P>
struct arenstorf_system {
  P mu = P(0);
  template <class Vec>
  void vector_field(const Vec& q, const Vec& p, Vec& dq, Vec& dp) const {
    using S = typename Vec::Scalar;
    using R = real_type_t<S>;
    using std::sqrt;
    const S m = lift<S>(R(mu)), m1 = lift<S>(R(1) - R(mu));
    const S a = q(0) + m, b = q(0) - m1;
    const S r1s = a * a + q(1) * q(1), r2s = b * b + q(1) * q(1);
    const S d1 = r1s * sqrt(r1s), d2 = r2s * sqrt(r2s);
    dq(0) = p(0) + q(1);
    dq(1) = p(1) - q(0);
    dp(0) = p(1) - m1 * a / d1 - m * b / d2;
    dp(1) = -p(0) - m1 * q(1) / d1 - m * q(1) / d2;
  }
  template <class Vec>
  typename Vec::Scalar energy(const Vec& q, const Vec& p) const {
    using S = typename Vec::Scalar;
    using R = real_type_t<S>;
    using std::sqrt;
    const S m = lift<S>(R(mu)), m1 = lift<S>(R(1) - R(mu));
    const S a = q(0) + m, b = q(0) - m1;
    const S kinetic = (p(0) * p(0) + p(1) * p(1)) / lift<S>(R(2));
    const S rotation = q(1) * p(0) - q(0) * p(1);
    return kinetic + rotation - m1 / sqrt(a * a + q(1) * q(1)) - m / sqrt(b * b + q(1) * q(1));
  }
};

/// Henon-Heiles: H = (|p|^2 + |q|^2)/2 + q1^2 q2 - q2^3/3; separable.
struct henon_heiles_system {
  template <class Vec>
  void velocity(const Vec& p, Vec& dq) const {
    dq = p;
  }
  template <class Vec>
  void force(const Vec& q, Vec& dp) const {
    using S = typename Vec::Scalar;
    using R = real_type_t<S>;
    dp(0) = -(q(0) + lift<S>(R(2)) * q(0) * q(1));
    dp(1) = -(q(1) + q(0) * q(0) - q(1) * q(1));
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
    const S two = lift<S>(R(2)), three = lift<S>(R(3));
    return (p(0) * p(0) + p(1) * p(1) + q(0) * q(0) + q(1) * q(1)) / two + q(0) * q(0) * q(1) -
           q(1) * q(1) * q(1) / three;
  }
};

/// The double pendulum of equal masses and lengths, m = l = g = 1, in the angles from the
/// downward vertical: H = (p1^2 + 2 p2^2 - 2 p1 p2 cos d) / (2 (1 + sin^2 d)) - 2 cos q1 -
/// cos q2, d = q1 - q2 (the Legendre transform of L = |v1|^2/2 + |v2|^2/2 + 2 cos q1 +
/// cos q2, checked against mechcheck's Legendre transform in the tests). Its vector field
/// by AD; not separable.
struct double_pendulum_hamiltonian {
  template <class S>
  S operator()(const dynamic_vector<S>& q, const dynamic_vector<S>& p) const {
    using R = real_type_t<S>;
    using std::cos;
    using std::sin;
    const S d = q(0) - q(1), c = cos(d), s = sin(d);
    const S num = p(0) * p(0) + lift<S>(R(2)) * p(1) * p(1) - lift<S>(R(2)) * p(0) * p(1) * c;
    const S den = lift<S>(R(2)) * (lift<S>(R(1)) + s * s);
    return num / den - lift<S>(R(2)) * cos(q(0)) - cos(q(1));
  }
};

/// The names of the classic problems, in the order above.
const std::vector<std::string>& classic_problem_names();

/// The classic problem `name` in tier T (double and mpfr50 are compiled in the audit
/// library). Throws domain_error for an unknown name (naming the known ones).
template <class T>
problem<T> classic_problem(const std::string& name, const reference_settings& settings = {});

/// The problems an audit runs: the reference problems with exact solutions
/// (reference_problems), then the classic problems among `names` (in their order), whose
/// references are computed when the studies first ask for them.
template <class T>
std::vector<problem<T>> problems_named(const std::vector<std::string>& names, const reference_settings& settings = {}) {
  std::vector<problem<T>> out = reference_problems<T>();
  const auto& classic = classic_problem_names();
  for (const auto& n : classic)
    if (std::find(names.begin(), names.end(), n) != names.end()) out.push_back(classic_problem<T>(n, settings));
  return out;
}

extern template problem<double> classic_problem<double>(const std::string&, const reference_settings&);
extern template problem<mpfr50> classic_problem<mpfr50>(const std::string&, const reference_settings&);

}  // namespace mechcheck::audit
