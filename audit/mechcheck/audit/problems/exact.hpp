#pragma once
/// Reference problems for auditing a stepper, each with an exact solution:
///   oscillator    H = (|p|^2 + |q|^2)/2 on two degrees of freedom: the exact flow;
///   kepler_e0.5,  H = |p|^2/2 - 1/|q| in the plane, eccentricity 0.5 and 0.9: the
///   kepler_e0.9   analytic orbit from Kepler's equation (central/kepler.hpp);
///   pendulum      H = p^2/2 - cos q from (1/2, 1): the Jacobi elliptic solution;
///   free_top      Euler's equations for I = (1, 2, 3): the Jacobi elliptic solution
///                 (a Lie-Poisson system, state M: not canonical, no splitting);
///   twist         H = (q^2 + p^2)^2/4: non-separable, for methods that need only the
///                 vector field (the exact rotation at rate q^2 + p^2).
/// A stepper sees every problem through one type, erased_system<T>, so that auditing it
/// on all of them instantiates the stepper once per scalar (T and ad<T>), not once per
/// problem. The system counts its force and vector-field evaluations.

#include <functional>
#include <memory>
#include <string>
#include <type_traits>
#include <vector>

#include <boost/math/constants/constants.hpp>

#include "mechcheck/central/kepler.hpp"
#include "mechcheck/core.hpp"
#include "mechcheck/integrators/systems.hpp"
#include "mechcheck/reference/pendulum.hpp"
#include "mechcheck/reference/tops.hpp"
#include "mechcheck/reference/twist.hpp"
#include "mechcheck/rigid_body/free_body.hpp"

namespace mechcheck::audit {

template <class T>
using state = phase_state<dynamic_vector<T>>;

/// A Hamiltonian system behind one type, for the scalars T and ad<T> on dynamic vectors:
/// what the audited steppers are instantiated with. Copies share the evaluation counter.
template <class T>
class erased_system {
 public:
  /// Some problems (the free top) have a non-canonical state of unequal parts.
  static constexpr bool canonical = false;
  template <class S>
  using vec = dynamic_vector<S>;

  /// Wraps a system with vector_field (and velocity/force when `separable`) and energy.
  template <class System>
  erased_system(const System& system, bool separable)
      : separable_(separable), counter_(std::make_shared<long long>(0)) {
    real_ = make_table<T>(system, separable);
    ad_ = make_table<ad<T>>(system, separable);
  }

  bool separable() const { return separable_; }
  /// Force and vector-field evaluations since construction (or the last reset).
  long long evaluations() const { return *counter_; }
  void reset_evaluations() const { *counter_ = 0; }

  /// Evaluates on dynamic vectors of T and ad<T> only (a generic caller can ask).
  template <class Vec>
  static constexpr bool takes = std::is_same_v<typename Vec::Scalar, T> || std::is_same_v<typename Vec::Scalar, ad<T>>;

  template <class Vec>
    requires takes<Vec>
  void velocity(const Vec& p, Vec& dq) const {
    table_for<Vec>().velocity(p, dq);
  }
  template <class Vec>
    requires takes<Vec>
  void force(const Vec& q, Vec& dp) const {
    ++*counter_;
    table_for<Vec>().force(q, dp);
  }
  template <class Vec>
    requires takes<Vec>
  void vector_field(const Vec& q, const Vec& p, Vec& dq, Vec& dp) const {
    ++*counter_;
    table_for<Vec>().field(q, p, dq, dp);
  }
  /// The vector field without counting it (for Jacobians taken by AD for an implicit
  /// black box: those are not the method's evaluations).
  template <class Vec>
    requires takes<Vec>
  void vector_field_uncounted(const Vec& q, const Vec& p, Vec& dq, Vec& dp) const {
    table_for<Vec>().field(q, p, dq, dp);
  }
  template <class Vec>
    requires takes<Vec>
  typename Vec::Scalar energy(const Vec& q, const Vec& p) const {
    return table_for<Vec>().energy(q, p);
  }

 private:
  template <class S>
  struct table {
    std::function<void(const vec<S>&, vec<S>&)> velocity, force;
    std::function<void(const vec<S>&, const vec<S>&, vec<S>&, vec<S>&)> field;
    std::function<S(const vec<S>&, const vec<S>&)> energy;
  };

  template <class S, class System>
  static std::shared_ptr<const table<S>> make_table(const System& system, bool separable) {
    auto t = std::make_shared<table<S>>();
    if constexpr (requires(const vec<S>& a, vec<S>& b) {
                    system.velocity(a, b);
                    system.force(a, b);
                  }) {
      if (separable) {
        t->velocity = [system](const vec<S>& p, vec<S>& dq) { system.velocity(p, dq); };
        t->force = [system](const vec<S>& q, vec<S>& dp) { system.force(q, dp); };
      }
    }
    t->field = [system](const vec<S>& q, const vec<S>& p, vec<S>& dq, vec<S>& dp) {
      system.vector_field(q, p, dq, dp);
    };
    t->energy = [system](const vec<S>& q, const vec<S>& p) -> S { return system.energy(q, p); };
    if (!t->velocity) {
      const auto refuse = [](const auto&, auto&) {
        throw domain_error("erased_system: the system is not separable (no velocity/force)");
      };
      t->velocity = refuse;
      t->force = refuse;
    }
    return t;
  }

  template <class Vec>
  const auto& table_for() const {
    using S = typename Vec::Scalar;
    static_assert(std::is_same_v<Vec, vec<S>>, "erased_system: states are dynamic vectors");
    if constexpr (std::is_same_v<S, T>) {
      return *real_;
    } else {
      static_assert(std::is_same_v<S, ad<T>>, "erased_system: scalars are T and ad<T>");
      return *ad_;
    }
  }

  bool separable_;
  std::shared_ptr<long long> counter_;
  std::shared_ptr<const table<T>> real_;
  std::shared_ptr<const table<ad<T>>> ad_;
};

/// A conserved quantity of a problem.
template <class T>
struct invariant {
  std::string name;
  std::function<T(const dynamic_vector<T>&, const dynamic_vector<T>&)> value;
  T scale = T(0);  ///< its natural size; 0: |value at the start| (or the state's scale)
};

/// A reference problem in tier T.
template <class T>
struct problem {
  std::string name;
  std::string description;
  bool separable = true;   ///< H = T(p) + V(q), T = |p|^2/2 (splitting methods apply)
  bool canonical = true;   ///< (q, p) canonical: the symplectic condition applies
  erased_system<T> system;
  state<T> initial;
  /// The exact state at time t of the solution through `initial`.
  std::function<state<T>(const T&)> exact;
  T t_end;      ///< end time of the global-order study
  long steps0;  ///< steps of the study's first (coarsest) run over [0, t_end]
  T h_local;    ///< the local-order, symplecticity and symmetry studies' first step
  T h_long;     ///< step of the long run
  T scale;      ///< size of the state, for rounding floors
  std::vector<invariant<T>> invariants;  ///< the energy first
  /// The relative uncertainty of exact(t): empty or 0 for a closed form; 10^-digits for a
  /// reference certified to that many digits (problems/reference_solution.hpp). The studies
  /// take it as a floor and resolve nothing within 100 times it.
  std::function<double(const T&)> exact_uncertainty;
  std::string source;  ///< where the problem comes from (a paper, its parameters)
  /// Non-empty: no long run on this problem, and why (close encounters a fixed step does
  /// not resolve: its energy would say nothing of a method's claim).
  std::string long_run_refused;
  /// The problem's slowest period (its time scale): the long run's growth is fitted past one
  /// of it, and a long run shorter than ten of it is not resolvable (classify_growth). 0: t_end
  /// (one period where the global study spans one).
  double time_scale = 0;
};

namespace detail {
template <class T>
state<T> make_state(std::initializer_list<T> q, std::initializer_list<T> p) {
  state<T> x{dynamic_vector<T>(static_cast<Eigen::Index>(q.size())),
             dynamic_vector<T>(static_cast<Eigen::Index>(p.size()))};
  Eigen::Index i = 0;
  for (const T& v : q) x.q(i++) = v;
  i = 0;
  for (const T& v : p) x.p(i++) = v;
  return x;
}

template <class T>
T state_scale(const state<T>& x) {
  using std::sqrt;
  return sqrt(T(x.q.squaredNorm() + x.p.squaredNorm()));
}

template <class T>
invariant<T> energy_of(const erased_system<T>& system) {
  return {"energy", [system](const dynamic_vector<T>& q, const dynamic_vector<T>& p) {
            return system.energy(q, p);
          }};
}

/// Planar angular momentum q_0 p_1 - q_1 p_0.
template <class T>
invariant<T> planar_angular_momentum() {
  return {"angular momentum",
          [](const dynamic_vector<T>& q, const dynamic_vector<T>& p) -> T {
            return q(0) * p(1) - q(1) * p(0);
          }};
}

/// The twist's closed-form system (see reference/twist.hpp).
struct twist_system {
  template <class Vec>
  void vector_field(const Vec& q, const Vec& p, Vec& dq, Vec& dp) const {
    using S = typename Vec::Scalar;
    const S qq = q(0) * q(0), pp = p(0) * p(0);
    const S r2 = qq + pp;
    dq(0) = r2 * p(0);
    dp(0) = -(r2 * q(0));
  }
  template <class Vec>
  typename Vec::Scalar energy(const Vec& q, const Vec& p) const {
    return reference::twist_hamiltonian(q(0), p(0));
  }
};
}  // namespace detail

/// Isotropic oscillator H = (|p|^2 + |q|^2)/2, q0 = (1, 0), p0 = (1/4, 3/4).
template <class T>
problem<T> oscillator_problem() {
  const harmonic_oscillator_system<T> sys{T(1), T(1)};
  erased_system<T> system(sys, true);
  const state<T> x0 = detail::make_state<T>({T(1), T(0)}, {T(1) / 4, T(3) / 4});
  auto exact = [x0](const T& t) {
    using std::cos;
    using std::sin;
    return state<T>{dynamic_vector<T>(x0.q * cos(t) + x0.p * sin(t)),
                    dynamic_vector<T>(x0.p * cos(t) - x0.q * sin(t))};
  };
  const T pi = boost::math::constants::pi<T>();
  problem<T> pr{"oscillator", "H = (|p|^2 + |q|^2)/2, two degrees of freedom, exact flow",
                true, true, system, x0, exact, T(2 * pi), 16, T(1) / 2, T(pi / 16),
                detail::state_scale(x0), {}};
  pr.invariants = {detail::energy_of(system), detail::planar_angular_momentum<T>()};
  return pr;
}

/// Planar Kepler problem H = |p|^2/2 - 1/|q| (a = 1, period 2 pi) of eccentricity e,
/// started at true anomaly 1 (not an apsis: a symmetric point of the flow hides
/// leading error terms).
template <class T>
problem<T> kepler_problem(const T& e, std::string name) {
  const kepler_constants<T> c(T(1), T(1));
  orbit_elements<T> el{T(1 - e * e), e, T(0), T(0), T(0), T(1)};
  const auto [r0, v0] = state_from_elements(c, el);
  const state<T> x0 = detail::make_state<T>({r0(0), r0(1)}, {v0(0), v0(1)});
  const kepler_orbit<T> orbit(c, r0, v0);
  auto exact = [orbit](const T& t) {
    const auto [r, v] = orbit.state_at(t);
    return detail::make_state<T>({r(0), r(1)}, {v(0), v(1)});
  };
  const kepler_system<T> sys(T(1), T(1));
  erased_system<T> system(sys, true);
  const T pi = boost::math::constants::pi<T>();
  using std::pow;
  using std::sqrt;
  // Steps resolve the pericentre passage, which takes ~ (1 - e)^(3/2) of the period.
  const T peri = pow(T(1 - e), T(3) / 2);
  const long steps0 = static_cast<long>(std::ceil(16.0 / static_cast<double>(peri)));
  problem<T> pr{name,
                "planar Kepler, eccentricity " + to_text(e) + ", analytic orbit (one period)",
                true, true, system, x0, exact, T(2 * pi), steps0, T(peri / 4),
                T(2 * pi * peri / 64), detail::state_scale(x0), {}};
  pr.invariants = {detail::energy_of(system), detail::planar_angular_momentum<T>()};
  // The components of A on the scale |A| = mu k e (one of them may start at 0).
  for (int i = 0; i < 2; ++i)
    pr.invariants.push_back({std::string("LRL vector A_") + char('x' + i),
                             [i](const dynamic_vector<T>& q, const dynamic_vector<T>& p) -> T {
                               dynamic_vector<T> q3(3), p3(3);
                               q3 << q(0), q(1), T(0);
                               p3 << p(0), p(1), T(0);
                               return lrl_vector(q3, p3, T(1), T(1))(i);
                             },
                             e});
  return pr;
}

/// Pendulum H = p^2/2 - cos q from theta0 = 1/2, p0 = 1 (k^2 = sin^2(1/4) + 1/4,
/// amplitude 1.18 rad; not a turning point, where leading error terms of symmetric
/// methods vanish).
template <class T>
problem<T> pendulum_problem() {
  const reference::pendulum_motion<T> motion(T(1), T(1), T(1), T(1) / 2, T(1));
  auto exact = [motion](const T& t) {
    const auto [theta, p] = motion.state_at(t);
    return detail::make_state<T>({theta}, {p});
  };
  const pendulum_system<T> sys{T(1), T(1), T(1)};
  erased_system<T> system(sys, true);
  const state<T> x0 = detail::make_state<T>({T(1) / 2}, {T(1)});
  problem<T> pr{"pendulum", "H = p^2/2 - cos q from (1/2, 1), Jacobi elliptic solution",
                true, true, system, x0, exact, motion.period(), 16, T(1) / 2,
                T(motion.period() / 32), detail::state_scale(x0), {}};
  pr.invariants = {detail::energy_of(system)};
  return pr;
}

/// Free asymmetric top, I = (1, 2, 3), M(0) = (1, 1/4, 3/4) in body axes: state q = M,
/// no p (Lie-Poisson, not canonical; only vector-field methods apply).
template <class T>
problem<T> free_top_problem() {
  const vector3<T> moments(T(1), T(2), T(3));
  const free_rigid_body<T> body(moments);
  const vector3<T> m0(T(1), T(1) / 4, T(3) / 4);
  const vector3<T> w0 = m0.cwiseQuotient(moments);
  auto exact = [moments, w0](const T& t) {
    const vector3<T> w = reference::asymmetric_top_angular_velocity(moments, w0, t);
    const vector3<T> m = w.cwiseProduct(moments);
    return state<T>{dynamic_vector<T>(m), dynamic_vector<T>(0)};
  };
  erased_system<T> system(body, false);
  const state<T> x0{dynamic_vector<T>(m0), dynamic_vector<T>(0)};
  problem<T> pr{"free_top", "Euler's equations, I = (1, 2, 3), Jacobi elliptic solution",
                false, false, system, x0, exact, T(4), 16, T(1) / 2, T(1) / 16,
                detail::state_scale(x0), {}};
  pr.invariants = {detail::energy_of(system),
                   {"|M|^2", [](const dynamic_vector<T>& q, const dynamic_vector<T>&) -> T {
                      return q.squaredNorm();
                    }}};
  pr.time_scale = static_cast<double>(reference::asymmetric_top_period(moments, w0));  // M's period in the body
  return pr;
}

/// The twist H = (q^2 + p^2)^2/4 from q0 = 1, p0 = 1/2 (rate 5/4).
template <class T>
problem<T> twist_problem() {
  const state<T> x0 = detail::make_state<T>({T(1)}, {T(1) / 2});
  auto exact = [x0](const T& t) {
    const auto [q, p] = reference::twist_flow(x0.q(0), x0.p(0), t);
    return detail::make_state<T>({q}, {p});
  };
  erased_system<T> system(detail::twist_system{}, false);
  problem<T> pr{"twist", "H = (q^2 + p^2)^2/4: non-separable, exact rotation at rate q^2 + p^2",
                false, true, system, x0, exact, T(4), 16, T(1) / 2, T(1) / 16,
                detail::state_scale(x0), {}};
  pr.invariants = {detail::energy_of(system)};
  pr.time_scale = 2 * boost::math::constants::pi<double>() / 1.25;  // the rotation's period at rate 5/4
  return pr;
}

/// Every reference problem, in the order above.
template <class T>
std::vector<problem<T>> reference_problems() {
  return {oscillator_problem<T>(), kepler_problem<T>(T(1) / 2, "kepler_e0.5"),
          kepler_problem<T>(T(9) / 10, "kepler_e0.9"), pendulum_problem<T>(),
          free_top_problem<T>(), twist_problem<T>()};
}

}  // namespace mechcheck::audit
