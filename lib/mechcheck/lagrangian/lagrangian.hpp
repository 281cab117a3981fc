#pragma once
/// Lagrangian systems L(q, qdot, t) (notes lectures 1-3, 6-7).
///
/// A Lagrangian is a generic callable `L(q, qdot, t) -> S` over `dynamic_vector<S>` q and
/// qdot of one length n and a scalar t, for any scalar S (a tier or AD over one); the
/// rules of mechcheck/core/autodiff.hpp apply (return exactly S, name combined terms).
/// Everything here is computed from L by automatic differentiation.

#include <string>

#include <Eigen/LU>

#include "mechcheck/core.hpp"

namespace mechcheck {

/// L and its first and second derivatives at one state (q, qdot, t).
template <class T>
struct lagrangian_jet {
  T value;
  dynamic_vector<T> dq;           ///< dL/dq
  dynamic_vector<T> momenta;      ///< p = dL/dqdot (notes eq 51, corrected: see errata)
  T dt;                           ///< dL/dt (explicit)
  dynamic_matrix<T> kinetic;      ///< W = d2L/dqdot dqdot
  dynamic_matrix<T> mixed;        ///< C_ij = d2L/dqdot_i dq_j
  dynamic_vector<T> qdot_t;       ///< d2L/dqdot dt
};

namespace detail {
template <class T>
void require_state(const dynamic_vector<T>& q, const dynamic_vector<T>& qdot, const T& t,
                   const std::string& where, const std::string& second = "qdot") {
  if (q.size() != qdot.size())
    throw dimension_error(where + ": q has " + std::to_string(q.size()) + " components but " +
                          second + " has " + std::to_string(qdot.size()));
  if (const auto i = first_non_finite(q); i >= 0)
    throw non_finite_error(where + ": q[" + std::to_string(i) + "] = " + to_text(q(i)));
  if (const auto i = first_non_finite(qdot); i >= 0)
    throw non_finite_error(where + ": " + second + "[" + std::to_string(i) + "] = " +
                           to_text(qdot(i)));
  if (!is_finite(t)) throw non_finite_error(where + ": t = " + to_text(t));
}

/// require_state and a finite acceleration qddot of the same length.
template <class T>
void require_path(const dynamic_vector<T>& q, const dynamic_vector<T>& qdot,
                  const dynamic_vector<T>& qddot, const T& t, const std::string& where) {
  require_state(q, qdot, t, where);
  if (qddot.size() != q.size())
    throw dimension_error(where + ": q has " + std::to_string(q.size()) +
                          " components but qddot has " + std::to_string(qddot.size()));
  if (const auto i = first_non_finite(qddot); i >= 0)
    throw non_finite_error(where + ": qddot[" + std::to_string(i) + "] = " + to_text(qddot(i)));
}

template <class T>
std::string state_text(const dynamic_vector<T>& q, const dynamic_vector<T>& qdot, const T& t) {
  return "q = " + to_text(q) + ", qdot = " + to_text(qdot) + ", t = " + to_text(t);
}

/// z = (q, qdot, t) -> L(q, qdot, t)
template <class L>
struct stacked_lagrangian {
  const L& lag;
  Eigen::Index n;
  template <class S>
  S operator()(const dynamic_vector<S>& z) const {
    const dynamic_vector<S> q = z.head(n), qdot = z.segment(n, n);
    return lag(q, qdot, z(2 * n));
  }
};
}  // namespace detail

/// All first and second derivatives of L at (q, qdot, t), from one nested-AD evaluation.
/// Throws non_finite_error when L or a derivative is NaN or infinite.
template <class T, class L>
lagrangian_jet<T> lagrangian_jet_at(const L& lag, const dynamic_vector<T>& q,
                                    const dynamic_vector<T>& qdot, const T& t,
                                    const std::string& where = "lagrangian_jet") {
  detail::require_state(q, qdot, t, where);
  const Eigen::Index n = q.size();
  dynamic_vector<T> z(2 * n + 1);
  z << q, qdot, t;
  const auto e = second_order_expansion(detail::stacked_lagrangian<L>{lag, n}, z);
  if (!is_finite(e.value))
    throw non_finite_error(where + ": L = " + to_text(e.value) + " at " +
                           detail::state_text(q, qdot, t));
  if (const auto i = first_non_finite(e.gradient); i >= 0)
    throw non_finite_error(where + ": dL/dz[" + std::to_string(i) + "] = " +
                           to_text(e.gradient(i)) + " at " + detail::state_text(q, qdot, t));
  return {e.value,
          e.gradient.head(n),
          e.gradient.segment(n, n),
          e.gradient(2 * n),
          e.hessian.block(n, n, n, n),
          e.hessian.block(n, 0, n, n),
          e.hessian.block(n, 2 * n, n, 1)};
}

/// Generalized momenta p_i = dL/dqdot_i (notes eq 51 as corrected; eq 252).
template <class T, class L>
dynamic_vector<T> generalized_momenta(const L& lag, const dynamic_vector<T>& q,
                                      const dynamic_vector<T>& qdot, const T& t) {
  detail::require_state(q, qdot, t, "generalized_momenta");
  const Eigen::Index n = q.size();
  dynamic_vector<T> z(2 * n + 1);
  z << q, qdot, t;
  return gradient(detail::stacked_lagrangian<L>{lag, n}, z).segment(n, n);
}

/// Solve W x = rhs for the kinetic matrix W; singular_error when W is singular.
template <class T>
dynamic_vector<T> solve_kinetic(const dynamic_matrix<T>& w, const dynamic_vector<T>& rhs,
                                const std::string& where, const std::string& state) {
  const Eigen::FullPivLU<dynamic_matrix<T>> lu(w);
  if (!lu.isInvertible())
    throw singular_error(where + ": the kinetic matrix d2L/dqdot2 is singular (rank " +
                         std::to_string(lu.rank()) + " of " + std::to_string(w.rows()) +
                         ") at " + state);
  return lu.solve(rhs);
}

/// Accelerations from the Euler-Lagrange equations (notes eq 1, 244):
///   qddot = W^-1 (dL/dq - (d2L/dqdot dq) qdot - d2L/dqdot dt),   W = d2L/dqdot2.
/// Throws singular_error for a degenerate Lagrangian.
template <class T, class L>
dynamic_vector<T> accelerations(const L& lag, const dynamic_vector<T>& q,
                                const dynamic_vector<T>& qdot, const T& t) {
  const auto j = lagrangian_jet_at(lag, q, qdot, t, "accelerations");
  const dynamic_vector<T> rhs = j.dq - j.mixed * qdot - j.qdot_t;
  return solve_kinetic(j.kinetic, rhs, "accelerations", detail::state_text(q, qdot, t));
}

/// Residual of the Euler-Lagrange equations d/dt(dL/dqdot) - dL/dq along a path with
/// acceleration qddot at (q, qdot, t) (notes eq 1).
template <class T, class L>
dynamic_vector<T> euler_lagrange_residual(const L& lag, const dynamic_vector<T>& q,
                                          const dynamic_vector<T>& qdot,
                                          const dynamic_vector<T>& qddot, const T& t) {
  detail::require_path(q, qdot, qddot, t, "euler_lagrange_residual");
  const auto j = lagrangian_jet_at(lag, q, qdot, t, "euler_lagrange_residual");
  return j.kinetic * qddot + j.mixed * qdot + j.qdot_t - j.dq;
}

/// Energy function h = qdot . p - L (notes eq 68); conserved when dL/dt = 0.
template <class T, class L>
T energy_function(const L& lag, const dynamic_vector<T>& q, const dynamic_vector<T>& qdot,
                  const T& t) {
  detail::require_state(q, qdot, t, "energy_function");
  const auto p = generalized_momenta(lag, q, qdot, t);
  const T l = lag(q, qdot, t);
  return qdot.dot(p) - l;
}

}  // namespace mechcheck
