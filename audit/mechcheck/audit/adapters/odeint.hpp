#pragma once
/// Boost.Odeint's fixed-step steppers under audit.
///
/// Each adapter runs an Odeint stepper on std::vector<S> states (S the tier, or ad<T> for
/// the symplectic condition, with Odeint's value and time types both S), one do_step per
/// audited step, and declares what Odeint declares: the order from the stepper's
/// `order_value` (for error steppers also `stepper_order_value`, the order of the
/// solution used for fixed steps), symplecticity where Odeint names the stepper
/// symplectic (the symplectic_* classes); nothing about time symmetry, which Odeint does
/// not state.
///
///   explicit_stepper<Family>   z' = f(z), z = (q, p): euler, runge_kutta4,
///                              runge_kutta_cash_karp54, runge_kutta_dopri5 (FSAL: the
///                              stepper keeps the last derivative between steps),
///                              modified_midpoint (2 sub-steps, Odeint's default);
///   symplectic_stepper<Family> the symplectic_nystroem form, a pair of functions
///                              dq/dt = dT/dp(p), dp/dt = -dU/dq(q): symplectic_euler,
///                              symplectic_rkn_sb3a_mclachlan, symplectic_rkn_sb3a_m4_mclachlan;
///   velocity_verlet_stepper    x'' = a(x) on (x, v): v = M^-1 p with the constant mass
///                              matrix read off the system's velocity map (skips systems
///                              whose velocity is not linear in p).
/// Separable-only steppers report the non-separable problems as skipped. The symplectic
/// condition (AD through the stepper) is measured in double: Odeint's coefficient
/// arithmetic does not compile on AD scalars over Boost.Multiprecision numbers.

#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <boost/numeric/odeint/stepper/euler.hpp>
#include <boost/numeric/odeint/stepper/modified_midpoint.hpp>
#include <boost/numeric/odeint/stepper/runge_kutta4.hpp>
#include <boost/numeric/odeint/stepper/runge_kutta_cash_karp54.hpp>
#include <boost/numeric/odeint/stepper/runge_kutta_dopri5.hpp>
#include <boost/numeric/odeint/stepper/symplectic_euler.hpp>
#include <boost/numeric/odeint/stepper/symplectic_rkn_sb3a_m4_mclachlan.hpp>
#include <boost/numeric/odeint/stepper/symplectic_rkn_sb3a_mclachlan.hpp>
#include <boost/numeric/odeint/stepper/velocity_verlet.hpp>

#include "mechcheck/audit/audit.hpp"

namespace mechcheck::audit::odeint {

namespace ode = boost::numeric::odeint;

template <class S>
using ovec = std::vector<S>;

/// Odeint's steppers on std::vector<S> with value and time type S.
template <class S>
using euler = ode::euler<ovec<S>, S, ovec<S>, S>;
template <class S>
using runge_kutta4 = ode::runge_kutta4<ovec<S>, S, ovec<S>, S>;
template <class S>
using runge_kutta_cash_karp54 = ode::runge_kutta_cash_karp54<ovec<S>, S, ovec<S>, S>;
template <class S>
using runge_kutta_dopri5 = ode::runge_kutta_dopri5<ovec<S>, S, ovec<S>, S>;
template <class S>
using modified_midpoint = ode::modified_midpoint<ovec<S>, S, ovec<S>, S>;
template <class S>
using symplectic_euler = ode::symplectic_euler<ovec<S>, ovec<S>, S, ovec<S>, ovec<S>, S>;
template <class S>
using symplectic_rkn_sb3a_mclachlan =
    ode::symplectic_rkn_sb3a_mclachlan<ovec<S>, ovec<S>, S, ovec<S>, ovec<S>, S>;
template <class S>
using symplectic_rkn_sb3a_m4_mclachlan =
    ode::symplectic_rkn_sb3a_m4_mclachlan<ovec<S>, ovec<S>, S, ovec<S>, ovec<S>, S>;
template <class S>
using velocity_verlet = ode::velocity_verlet<ovec<S>, ovec<S>, S, ovec<S>, S, S>;

namespace detail {
template <class S>
ovec<S> to_std(const dynamic_vector<S>& v) {
  return ovec<S>(v.data(), v.data() + v.size());
}
template <class S>
void from_std(const ovec<S>& v, dynamic_vector<S>& out) {
  for (std::size_t i = 0; i < v.size(); ++i) out(static_cast<Eigen::Index>(i)) = v[i];
}
template <class S>
dynamic_vector<S> as_eigen(const ovec<S>& v) {
  dynamic_vector<S> out(static_cast<Eigen::Index>(v.size()));
  from_std(v, out);
  return out;
}

/// The order Odeint declares for fixed steps: stepper_order_value for error steppers
/// (the order of the solution they advance), order_value otherwise.
template <class Stepper>
int declared_order() {
  if constexpr (requires { Stepper::stepper_order_value; })
    return static_cast<int>(Stepper::stepper_order_value);
  else
    return static_cast<int>(Stepper::order_value);
}

template <class Stepper>
std::string declared_text() {
  std::string s = "order_value = " + std::to_string(int(Stepper::order_value));
  if constexpr (requires { Stepper::stepper_order_value; })
    s += ", stepper_order_value = " + std::to_string(int(Stepper::stepper_order_value)) +
         ", error_order_value = " + std::to_string(int(Stepper::error_order_value));
  return s;
}

template <template <class> class Family, class S, class T>
step_function<S> make_explicit(const erased_system<T>& system) {
  auto stepper = std::make_shared<Family<S>>();
  auto z = std::make_shared<ovec<S>>();
  return [stepper, z, system](state<S>& x, const S& h) {
    // z = (q, p); the sizes may differ (a non-canonical system keeps its state in q).
    const Eigen::Index nq = x.q.size(), np = x.p.size();
    z->resize(static_cast<std::size_t>(nq + np));
    for (Eigen::Index i = 0; i < nq; ++i) (*z)[static_cast<std::size_t>(i)] = x.q(i);
    for (Eigen::Index i = 0; i < np; ++i) (*z)[static_cast<std::size_t>(nq + i)] = x.p(i);
    const auto rhs = [&system, nq, np](const ovec<S>& w, ovec<S>& dw, const S&) {
      dynamic_vector<S> q(nq), p(np), dq(nq), dp(np);
      for (Eigen::Index i = 0; i < nq; ++i) q(i) = w[static_cast<std::size_t>(i)];
      for (Eigen::Index i = 0; i < np; ++i) p(i) = w[static_cast<std::size_t>(nq + i)];
      system.vector_field(q, p, dq, dp);
      dw.resize(w.size());
      for (Eigen::Index i = 0; i < nq; ++i) dw[static_cast<std::size_t>(i)] = dq(i);
      for (Eigen::Index i = 0; i < np; ++i) dw[static_cast<std::size_t>(nq + i)] = dp(i);
    };
    stepper->do_step(rhs, *z, S(0), h);
    for (Eigen::Index i = 0; i < nq; ++i) x.q(i) = (*z)[static_cast<std::size_t>(i)];
    for (Eigen::Index i = 0; i < np; ++i) x.p(i) = (*z)[static_cast<std::size_t>(nq + i)];
  };
}

template <template <class> class Family, class S, class T>
step_function<S> make_symplectic(const erased_system<T>& system) {
  if (!system.separable())
    throw domain_error("odeint symplectic stepper: the system is not separable");
  auto stepper = std::make_shared<Family<S>>();
  return [stepper, system](state<S>& x, const S& h) {
    ovec<S> q = to_std(x.q), p = to_std(x.p);
    const auto velocity = [&system](const ovec<S>& pv, ovec<S>& dq) {
      dynamic_vector<S> out(static_cast<Eigen::Index>(pv.size()));
      system.velocity(as_eigen(pv), out);
      dq.assign(out.data(), out.data() + out.size());
    };
    const auto force = [&system](const ovec<S>& qv, ovec<S>& dp) {
      dynamic_vector<S> out(static_cast<Eigen::Index>(qv.size()));
      system.force(as_eigen(qv), out);
      dp.assign(out.data(), out.data() + out.size());
    };
    stepper->do_step(std::make_pair(velocity, force), std::make_pair(std::ref(q), std::ref(p)),
                     S(0), h);
    from_std(q, x.q);
    from_std(p, x.p);
  };
}

/// velocity_verlet on (x, v) with v = V p, V the (constant) matrix of the velocity map.
template <class S, class T>
step_function<S> make_velocity_verlet(const erased_system<T>& system, Eigen::Index n) {
  if (!system.separable())
    throw domain_error("odeint velocity_verlet: the system is not separable");
  // V column by column; linear when V (e_0 + ... + e_{n-1}) is the sum of the columns.
  dynamic_matrix<S> v_map(n, n);
  dynamic_vector<S> e = dynamic_vector<S>::Zero(n), col(n), all = dynamic_vector<S>::Ones(n);
  for (Eigen::Index j = 0; j < n; ++j) {
    e.setZero();
    e(j) = S(1);
    system.velocity(e, col);
    v_map.col(j) = col;
  }
  system.velocity(all, col);
  using std::abs;
  for (Eigen::Index i = 0; i < n; ++i)
    if (!(abs(S(col(i) - v_map.row(i).sum())) <= 64 * tier_epsilon<real_type_t<S>>() *
                                                     (1 + abs(S(col(i))))))
      throw domain_error("odeint velocity_verlet: needs a kinetic energy quadratic in p "
                         "(a constant mass matrix)");
  auto stepper = std::make_shared<velocity_verlet<S>>();
  auto inverse = std::make_shared<dynamic_matrix<S>>(v_map.inverse());
  auto vm = std::make_shared<dynamic_matrix<S>>(v_map);
  return [stepper, system, inverse, vm](state<S>& x, const S& h) {
    ovec<S> q = to_std(x.q);
    const dynamic_vector<S> v0 = (*vm) * x.p;
    ovec<S> v = to_std(v0);
    const auto accel = [&system, &vm](const ovec<S>& qv, const ovec<S>&, ovec<S>& a, const S&) {
      dynamic_vector<S> f(static_cast<Eigen::Index>(qv.size()));
      system.force(as_eigen(qv), f);
      const dynamic_vector<S> acc = (*vm) * f;
      a.assign(acc.data(), acc.data() + acc.size());
    };
    stepper->do_step(accel, std::make_pair(std::ref(q), std::ref(v)), S(0), h);
    from_std(q, x.q);
    const dynamic_vector<S> vv = as_eigen(v);
    x.p = (*inverse) * vv;
  };
}
}  // namespace detail

/// An Odeint explicit stepper of the form Family<S>::do_step(system, x, t, dt).
/// `ad_capable` false: the symplectic condition is not measured (Odeint's
/// modified_midpoint keeps function-static constants, which Eigen's AutoDiffScalar resizes
/// to the first problem's dimension and then mixes with another's).
template <template <class> class Family, class T>
stepper_under_audit<T> explicit_stepper(std::string name, std::string header,
                                        bool ad_capable = true) {
  stepper_under_audit<T> s;
  s.name = std::move(name);
  s.declared.order = detail::declared_order<Family<T>>();
  s.origin = "Boost.Odeint " + header + ": " + detail::declared_text<Family<T>>();
  s.make = [](const erased_system<T>& sys) { return detail::make_explicit<Family, T>(sys); };
  if constexpr (std::is_floating_point_v<T>)
    if (ad_capable)
      s.make_ad = [](const erased_system<T>& sys) {
        return detail::make_explicit<Family, ad<T>>(sys);
      };
  return s;
}

/// An Odeint symplectic Runge-Kutta-Nystrom stepper (symplectic by its name and docs).
template <template <class> class Family, class T>
stepper_under_audit<T> symplectic_stepper(std::string name, std::string header) {
  stepper_under_audit<T> s;
  s.name = std::move(name);
  s.declared.order = detail::declared_order<Family<T>>();
  s.declared.symplectic = true;
  s.origin = "Boost.Odeint " + header + ": " + detail::declared_text<Family<T>>() +
             "; symplectic by its name";
  s.make = [](const erased_system<T>& sys) { return detail::make_symplectic<Family, T>(sys); };
  if constexpr (std::is_floating_point_v<T>)
    s.make_ad = [](const erased_system<T>& sys) {
      return detail::make_symplectic<Family, ad<T>>(sys);
    };
  return s;
}

/// Odeint's velocity_verlet (order_value = 1 in its header).
template <class T>
stepper_under_audit<T> velocity_verlet_stepper(std::string name = "odeint::velocity_verlet") {
  stepper_under_audit<T> s;
  s.name = std::move(name);
  s.declared.order = detail::declared_order<velocity_verlet<T>>();
  s.origin = "Boost.Odeint velocity_verlet.hpp: " + detail::declared_text<velocity_verlet<T>>();
  // The dimension is known only at the first step: the adapter is made lazily.
  s.make = [](const erased_system<T>& sys) -> step_function<T> {
    auto inner = std::make_shared<step_function<T>>();
    return [sys, inner](state<T>& x, const T& h) {
      if (!*inner) *inner = detail::make_velocity_verlet<T>(sys, x.q.size());
      (*inner)(x, h);
    };
  };
  if constexpr (std::is_floating_point_v<T>)
    s.make_ad = [](const erased_system<T>& sys) -> step_function<ad<T>> {
      auto inner = std::make_shared<step_function<ad<T>>>();
      return [sys, inner](state<ad<T>>& x, const ad<T>& h) {
        if (!*inner) *inner = detail::make_velocity_verlet<ad<T>>(sys, x.q.size());
        (*inner)(x, h);
      };
    };
  return s;
}

/// symplectic_rkn_sb3a_mclachlan: two of its coefficients are double literals
/// (0.40518861839525227722, -0.28714404081652408900), and its header says so: "This method
/// cannot be used with multiprecision types since the coefficients are not defined
/// analytically". Its claims are held to the precision of double (2^-52 relative) in every
/// tier: in mpfr50 its order 4 holds to that precision, and the one-step error of those
/// digits is what the header warns of, not a contradiction.
template <class T>
stepper_under_audit<T> sb3a_stepper() {
  stepper_under_audit<T> s = symplectic_stepper<symplectic_rkn_sb3a_mclachlan, T>(
      "odeint::symplectic_rkn_sb3a_mclachlan", "symplectic_rkn_sb3a_mclachlan.hpp");
  s.declared.coefficient_precision = 0x1p-52;
  s.declared.coefficient_words =
      "two coefficients are double literals; the header: \"This method cannot be used with multiprecision types "
      "since the coefficients are not defined analytically\"";
  return s;
}

/// All of the above, in tier T.
template <class T>
std::vector<stepper_under_audit<T>> all_steppers() {
  return {
      explicit_stepper<euler, T>("odeint::euler", "euler.hpp"),
      explicit_stepper<runge_kutta4, T>("odeint::runge_kutta4", "runge_kutta4.hpp"),
      explicit_stepper<runge_kutta_cash_karp54, T>("odeint::runge_kutta_cash_karp54",
                                                   "runge_kutta_cash_karp54.hpp"),
      explicit_stepper<runge_kutta_dopri5, T>("odeint::runge_kutta_dopri5",
                                              "runge_kutta_dopri5.hpp"),
      explicit_stepper<modified_midpoint, T>("odeint::modified_midpoint", "modified_midpoint.hpp",
                                             false),
      velocity_verlet_stepper<T>(),
      symplectic_stepper<symplectic_euler, T>("odeint::symplectic_euler", "symplectic_euler.hpp"),
      sb3a_stepper<T>(),
      symplectic_stepper<symplectic_rkn_sb3a_m4_mclachlan, T>(
          "odeint::symplectic_rkn_sb3a_m4_mclachlan", "symplectic_rkn_sb3a_m4_mclachlan.hpp"),
  };
}

}  // namespace mechcheck::audit::odeint
