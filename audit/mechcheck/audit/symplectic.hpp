#pragma once
/// The symplectic condition of a step map (notes eqs 285, 300-302): one step of a
/// canonical method, z = (q, p) -> Z(z), has a Jacobian M = dZ/dz with M J M^T = J. The
/// Jacobian is taken by forward AD through the stepper itself (the stepper runs on
/// ad<T> scalars), so the defect max |M J M^T - J| is the method's, to rounding.

#include <cmath>

#include "mechcheck/core.hpp"
#include "mechcheck/integrators/systems.hpp"

namespace mechcheck::audit {

/// The symplectic form J = [[0, I], [-I, 0]] of eq 300.
template <class T>
dynamic_matrix<T> symplectic_form(Eigen::Index n) {
  dynamic_matrix<T> j = dynamic_matrix<T>::Zero(2 * n, 2 * n);
  for (Eigen::Index i = 0; i < n; ++i) {
    j(i, n + i) = lift<T>(1);
    j(n + i, i) = lift<T>(-1);
  }
  return j;
}

/// max |M J M^T - J| (eq 302).
template <class T>
T symplectic_defect(const dynamic_matrix<T>& m) {
  const Eigen::Index n = m.rows() / 2;
  const dynamic_matrix<T> j = symplectic_form<T>(n);
  const dynamic_matrix<T> d = m * j * m.transpose() - j;
  return d.cwiseAbs().maxCoeff();
}

/// Jacobian of one step at z = (q, p), q the first nq entries, with step h.
/// `make.template operator()<S>()` returns a fresh stepper on phase_state<dynamic_vector<S>>
/// for S = ad<T>.
template <class T, class Make>
dynamic_matrix<T> step_jacobian_of(const Make& make, const dynamic_vector<T>& z, const T& h,
                                   Eigen::Index nq) {
  const Eigen::Index np = z.size() - nq;
  const auto step = [&make, &h, nq, np]<class S>(const dynamic_vector<S>& w) -> dynamic_vector<S> {
    auto method = make.template operator()<S>();
    phase_state<dynamic_vector<S>> x{w.head(nq), w.tail(np)};
    method(x, lift<S>(h));
    dynamic_vector<S> out(nq + np);
    out << x.q, x.p;
    return out;
  };
  return jacobian(step, z);
}

/// Jacobian of one step of Method<System, Vec> at z = (q, p) (equal halves) with step h.
template <template <class, class> class Method, class System, class T>
dynamic_matrix<T> step_jacobian(const System& system, const dynamic_vector<T>& z, const T& h) {
  const auto make = [&system]<class S>() { return Method<System, dynamic_vector<S>>{system}; };
  return step_jacobian_of(make, z, h, z.size() / 2);
}

}  // namespace mechcheck::audit
