#pragma once
/// A user's model as an audit problem.
///
/// A model is its dynamics -- a Hamiltonian H(q, p), a Lagrangian L(q, qdot) or a vector
/// field f(y), each a functor templated on its scalar -- an initial state and an end time
/// (model_setup, as exact text), and optionally its first integrals F(q, p) (one functor
/// returning them all, named by setup.integral_names) and holonomic constraints g(q) = 0.
/// model_problem<T>() makes it a problem<T> that audit_stepper (and any black box) runs
/// on: its reference is certified in mpfr50 (problems/reference_solution.hpp: two
/// Gauss-Legendre solutions that agree to >= 35 digits, or the digits they do agree to,
/// which the audit takes as its floor), cached on disk by the model's definition.
///
/// Before any of that, in mpfr50, at the start and at `check_points` points drawn (seeded)
/// within `check_radius` of it:
///   - H (or f), and its vector field, are finite at the start;
///   - every declared first integral F is conserved: {F, H} = 0 (dF/dy . f = 0 for a
///     vector field) within 2^16 eps(mpfr50) of the sum of the magnitudes of its terms --
///     the counterexample (the point, the value, in that scale) otherwise;
///   - the constraints hold at the start, in position g(q0) = 0 and velocity dg/dq qdot = 0;
///   - a Hamiltonian is separable (H(qa, pa) + H(qb, pb) - H(qa, pb) - H(qb, pa) = 0 at
///     pairs of drawn points) unless the setup says which it is; a separable model gets
///     the velocity and force that splitting methods need.
/// A failure is a model_error naming the model, the check and the value. The long run then
/// tracks the energy, each integral and each constraint.

#include <cmath>
#include <cstdlib>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "mechcheck/audit/problems/reference_problem.hpp"
#include "mechcheck/core.hpp"
#include "mechcheck/core/format.hpp"
#include "mechcheck/hamiltonian/legendre.hpp"
#include "mechcheck/integrators/systems.hpp"
#include "mechcheck/poisson/bracket.hpp"

namespace mechcheck::audit {

/// A model that cannot be audited as given: the message names the model, the check and
/// the value.
class model_error : public error {
 public:
  using error::error;
};

/// No declared first integrals.
struct no_integrals {
  template <class S>
  dynamic_vector<S> operator()(const dynamic_vector<S>&, const dynamic_vector<S>&) const {
    return dynamic_vector<S>(0);
  }
};

/// No constraints.
struct no_constraints {
  template <class S>
  dynamic_vector<S> operator()(const dynamic_vector<S>&) const {
    return dynamic_vector<S>(0);
  }
};

/// What makes a model a problem, besides its dynamics. Numbers are exact text ("0.5",
/// "1/3", "-2.5e-3"), so that every tier poses the same problem and the reference's cache
/// key names it.
struct model_setup {
  std::string name;         ///< names the problem (-p), the reports and every error
  std::string description;
  std::string source;       ///< where the model comes from
  /// The model's parameters as text: part of the reference cache's key, so change it with
  /// any parameter (a reference of the old model is otherwise taken for the new one).
  std::string parameters;
  std::string revision = "1";
  std::vector<std::string> q0;  ///< the initial coordinates (a vector field: its state)
  /// The initial momenta (Hamiltonian) or velocities (Lagrangian); empty for a vector field.
  std::vector<std::string> p0;
  /// End time of the global order study, and the time scale of the long run's growth class
  /// (a run under ten of it is not resolvable; problem::time_scale): best one period.
  std::string t_end = "1";
  std::string h_local;      ///< first step of the local studies; empty: t_end / 8
  std::string h_long;       ///< step of the long run; empty: t_end / 256
  long steps0 = 16;         ///< the global study's coarsest run
  std::vector<std::string> integral_names;  ///< one per component of the integrals functor
  std::vector<std::string> constraint_names;  ///< one per component of the constraints functor
  std::optional<bool> separable;  ///< nothing: found out (see the header)
  int check_points = 64;          ///< drawn points of the conservation checks
  double check_radius = 0.1;      ///< their distance from the start, relative to max(|x0|, 1)
  unsigned long long seed = 1;    ///< of the drawn points
};

template <class H, class F = no_integrals, class G = no_constraints>
struct hamiltonian_model {
  model_setup setup;
  H hamiltonian;  ///< S operator()(const dynamic_vector<S>& q, const dynamic_vector<S>& p) const
  F integrals{};  ///< dynamic_vector<S> operator()(q, p) const
  G constraints{};  ///< dynamic_vector<S> operator()(q) const
};

template <class L, class F = no_integrals, class G = no_constraints>
struct lagrangian_model {
  model_setup setup;
  L lagrangian;   ///< S operator()(const dynamic_vector<S>& q, const dynamic_vector<S>& qdot) const
  F integrals{};  ///< in (q, qdot): dynamic_vector<S> operator()(q, qdot) const
  G constraints{};
};

template <class V, class F = no_integrals>
struct vector_field_model {
  model_setup setup;
  V field;        ///< dynamic_vector<S> operator()(const dynamic_vector<S>& y) const
  F integrals{};  ///< in y: dynamic_vector<S> operator()(y, p) const, p empty
};

namespace detail {

/// L(q, qdot) as the library's L(q, qdot, t).
template <class L>
struct autonomous_lagrangian {
  L lag;
  template <class S>
  S operator()(const dynamic_vector<S>& q, const dynamic_vector<S>& v, const S&) const {
    return lag(q, v);
  }
};

/// A Lagrangian's integrals F(q, qdot) as functions of (q, p).
template <class L, class F>
struct integrals_in_momenta {
  autonomous_lagrangian<L> lag;
  F integrals;
  template <class S>
  dynamic_vector<S> operator()(const dynamic_vector<S>& q, const dynamic_vector<S>& p) const {
    return integrals(q, velocities_from_momenta(lag, q, p, lift<S>(0)));
  }
};

/// Component k of a vector-valued phase-space function, as a phase-space function.
template <class F>
struct component {
  const F& f;
  Eigen::Index k;
  template <class S>
  S operator()(const dynamic_vector<S>& q, const dynamic_vector<S>& p) const {
    return f(q, p)(k);
  }
};

/// A Hamiltonian as a system; separable: the velocity dH/dp at fixed q_any and the force
/// -dH/dq at fixed p_any (H = T(p) + V(q): either anchor gives the same).
template <class H, class P>
struct model_system {
  H hamiltonian;
  bool separable = false;
  dynamic_vector<P> q_any, p_any;

  template <class S>
  static dynamic_vector<S> lifted(const dynamic_vector<P>& v) {
    using R = real_type_t<S>;
    dynamic_vector<S> out(v.size());
    for (Eigen::Index i = 0; i < v.size(); ++i) out(i) = lift<S>(static_cast<R>(v(i)));
    return out;
  }
  template <class Vec>
  void velocity(const Vec& p, Vec& dq) const {
    using S = typename Vec::Scalar;
    const dynamic_vector<S> ps = p;
    const auto g = phase_gradient(hamiltonian, phase_point<S>(lifted<S>(q_any), ps), "model", "H").second;
    for (Eigen::Index i = 0; i < p.size(); ++i) dq(i) = g(p.size() + i);
  }
  template <class Vec>
  void force(const Vec& q, Vec& dp) const {
    using S = typename Vec::Scalar;
    const dynamic_vector<S> qs = q;
    const auto g = phase_gradient(hamiltonian, phase_point<S>(qs, lifted<S>(p_any)), "model", "H").second;
    for (Eigen::Index i = 0; i < q.size(); ++i) dp(i) = -g(i);
  }
  template <class Vec>
  void vector_field(const Vec& q, const Vec& p, Vec& dq, Vec& dp) const {
    hamiltonian_system<H>{hamiltonian}.vector_field(q, p, dq, dp);
  }
  template <class Vec>
  typename Vec::Scalar energy(const Vec& q, const Vec& p) const {
    const dynamic_vector<typename Vec::Scalar> qs = q, ps = p;
    return hamiltonian(qs, ps);
  }
};

/// A vector field y' = f(y) as a (non-canonical) system: state q = y, p empty; its energy
/// the integral named "energy" where there is one, else 0.
template <class V, class F>
struct field_system {
  static constexpr bool canonical = false;  // the state is y alone (guards.hpp)
  V field;
  F integrals;
  Eigen::Index energy_index = -1;
  template <class Vec>
  void vector_field(const Vec& q, const Vec&, Vec& dq, Vec&) const {
    const dynamic_vector<typename Vec::Scalar> y = q;
    dq = field(y);
  }
  template <class Vec>
  typename Vec::Scalar energy(const Vec& q, const Vec& p) const {
    using S = typename Vec::Scalar;
    if (energy_index < 0) return lift<S>(0);
    const dynamic_vector<S> y = q, none = p;
    return integrals(y, none)(energy_index);
  }
};

inline std::string point_text(const dynamic_vector<mpfr50>& q, const dynamic_vector<mpfr50>& p) {
  std::string out = "q = (";
  for (Eigen::Index i = 0; i < q.size(); ++i) out += (i ? ", " : "") + to_text(static_cast<double>(q(i)));
  out += "), p = (";
  for (Eigen::Index i = 0; i < p.size(); ++i) out += (i ? ", " : "") + to_text(static_cast<double>(p(i)));
  return out + ")";
}

/// The drawn points: x0 + r u, u uniform in [-1, 1] per component, r = radius max(|x0|, 1).
inline std::vector<std::pair<dynamic_vector<mpfr50>, dynamic_vector<mpfr50>>> drawn_points(
    const state<mpfr50>& x0, const model_setup& s) {
  std::mt19937_64 rng(s.seed);
  std::uniform_real_distribution<double> u(-1, 1);
  const mpfr50 r = mpfr50(s.check_radius) * std::max(state_norm(x0), mpfr50(1));
  std::vector<std::pair<dynamic_vector<mpfr50>, dynamic_vector<mpfr50>>> out;
  for (int k = 0; k < s.check_points; ++k) {
    dynamic_vector<mpfr50> q = x0.q, p = x0.p;
    for (Eigen::Index i = 0; i < q.size(); ++i) q(i) += r * mpfr50(u(rng));
    for (Eigen::Index i = 0; i < p.size(); ++i) p(i) += r * mpfr50(u(rng));
    out.emplace_back(std::move(q), std::move(p));
  }
  return out;
}

/// 2^16 eps(mpfr50): the conservation and separability checks' budget, relative to the
/// magnitudes of the terms (rounding in mpfr50 of gradients by AD, with room for the
/// cancellation inside a model's own evaluation; a non-conserved integral is off by
/// O(1) of that scale).
inline mpfr50 check_budget() { return mpfr50(65536) * std::numeric_limits<mpfr50>::epsilon(); }

/// {F_k, H} = 0 at the drawn points, each integral k (see the header).
template <class H, class F>
void check_integrals(const model_setup& s, const H& h, const F& integrals, const state<mpfr50>& x0) {
  const Eigen::Index count = integrals(x0.q, x0.p).size();
  if (static_cast<std::size_t>(count) != s.integral_names.size())
    throw model_error("model '" + s.name + "': its integrals functor returns " + std::to_string(count) +
                      " values but integral_names has " + std::to_string(s.integral_names.size()));
  if (count == 0) return;
  const Eigen::Index n = x0.q.size();
  int tested = 0;
  for (const auto& [q, p] : drawn_points(x0, s)) {
    const phase_point<mpfr50> x(q, p);
    dynamic_vector<mpfr50> dh;
    try {
      dh = phase_gradient(h, x, "model", "H").second;
    } catch (const non_finite_error&) {
      continue;  // a drawn point at a singularity of H: no test there
    }
    ++tested;
    for (Eigen::Index k = 0; k < count; ++k) {
      const auto df = phase_gradient(component<F>{integrals, k}, x, "model", s.integral_names[std::size_t(k)]).second;
      mpfr50 bracket = 0, scale = 0;
      for (Eigen::Index i = 0; i < n; ++i) {
        bracket += df(i) * dh(n + i) - df(n + i) * dh(i);
        scale += abs(mpfr50(df(i) * dh(n + i))) + abs(mpfr50(df(n + i) * dh(i)));
      }
      if (abs(bracket) > check_budget() * scale)
        throw model_error("model '" + s.name + "': the declared first integral '" + s.integral_names[std::size_t(k)] +
                          "' is not conserved: {F, H} = " + to_text(static_cast<double>(bracket)) + " at " +
                          point_text(q, p) + ", " + to_text(static_cast<double>(bracket / scale)) +
                          " of the magnitude of its terms (conserved: within " +
                          to_text(static_cast<double>(check_budget())) + ")");
    }
  }
  if (tested == 0)  // never a check passed by testing nothing
    throw model_error("model '" + s.name + "': H is not finite at any of the " + std::to_string(s.check_points) +
                      " points drawn within " + to_text(s.check_radius) + " of the start: the integrals are untested");
}

/// H(qa, pa) + H(qb, pb) - H(qa, pb) - H(qb, pa) = 0 at consecutive pairs of drawn points.
template <class H>
bool separable_at_drawn_points(const model_setup& s, const H& h, const state<mpfr50>& x0) {
  const auto points = drawn_points(x0, s);
  for (std::size_t k = 0; k + 1 < points.size(); k += 2) {
    const auto& [qa, pa] = points[k];
    const auto& [qb, pb] = points[k + 1];
    try {
      const mpfr50 a = h(qa, pa), b = h(qb, pb), c = h(qa, pb), d = h(qb, pa);
      if (abs(mpfr50(a + b - c - d)) > check_budget() * (abs(a) + abs(b) + abs(c) + abs(d))) return false;
    } catch (const error&) {
      return false;
    }
  }
  return true;
}

/// The constraints at the start: g(q0) = 0 and dg/dq qdot0 = 0, within 2^16 eps(mpfr50) of
/// max(|q0|, 1) and of max(|q0|, 1) |qdot0| (see the header).
template <class G>
void check_constraints(const model_setup& s, const G& g, const dynamic_vector<mpfr50>& q0,
                       const dynamic_vector<mpfr50>& qdot0) {
  const dynamic_vector<mpfr50> value = g(q0);
  if (static_cast<std::size_t>(value.size()) != s.constraint_names.size())
    throw model_error("model '" + s.name + "': its constraints functor returns " + std::to_string(value.size()) +
                      " values but constraint_names has " + std::to_string(s.constraint_names.size()));
  using std::sqrt;
  const mpfr50 size = std::max(mpfr50(sqrt(mpfr50(q0.squaredNorm()))), mpfr50(1));
  const mpfr50 speed = sqrt(mpfr50(qdot0.squaredNorm()));
  for (Eigen::Index k = 0; k < value.size(); ++k) {
    const std::string& name = s.constraint_names[std::size_t(k)];
    if (!is_finite(value(k)) || abs(value(k)) > check_budget() * size)
      throw model_error("model '" + s.name + "': the initial state is off the constraint manifold: " + name +
                        "(q0) = " + to_text(static_cast<double>(value(k))) + " (within " +
                        to_text(static_cast<double>(check_budget() * size)) + " on it)");
    const auto row = gradient([&g, k]<class A>(const dynamic_vector<A>& q) -> A { return g(q)(k); }, q0);
    const mpfr50 rate = row.dot(qdot0);
    if (!is_finite(rate) || abs(rate) > check_budget() * size * std::max(speed, mpfr50(1)))
      throw model_error("model '" + s.name + "': the initial velocity leaves the constraint manifold: d" + name +
                        "/dt = " + to_text(static_cast<double>(rate)) + " at the start");
  }
}

inline std::string default_step(const model_setup& s, const std::string& given, int divisor) {
  if (!given.empty()) return given;
  const mpfr100 t = read_coefficient(s.t_end, s.name + ": t_end").value;
  return scientific_text(mpfr100(t / divisor), 60);
}

inline problem_definition definition_of(const model_setup& s) {
  if (s.name.empty()) throw model_error("model: the setup has no name");
  problem_definition d;
  d.name = s.name;
  d.description = s.description.empty() ? "the model " + s.name + " (certified reference)" : s.description;
  d.source = s.source;
  d.parameters = s.parameters;
  d.revision = "model-" + s.revision;
  d.q0 = s.q0;
  d.p0 = s.p0;
  d.t_end = s.t_end;
  d.h_local = default_step(s, s.h_local, 8);
  d.h_long = default_step(s, s.h_long, 256);
  d.steps0 = s.steps0;
  return d;
}

template <class T, class Fn>
std::vector<invariant<T>> model_invariants(const model_setup& s, const Fn& integrals, bool has_energy) {
  std::vector<invariant<T>> out;
  for (std::size_t k = 0; k < s.integral_names.size(); ++k) {
    if (has_energy && s.integral_names[k] == "energy") continue;  // the energy comes first already
    out.push_back({s.integral_names[k], [integrals, k](const dynamic_vector<T>& q, const dynamic_vector<T>& p) -> T {
                     return integrals(q, p)(static_cast<Eigen::Index>(k));
                   }});
  }
  return out;
}

/// Parses the setup's state in mpfr50 (through T: the problem T poses), checking sizes and
/// finiteness.
template <class T>
state<mpfr50> start_of(const model_setup& s, bool canonical) {
  if (s.check_points < 1 || !(s.check_radius > 0) || !std::isfinite(s.check_radius) || s.steps0 < 1)
    throw model_error("model '" + s.name + "': check_points must be >= 1 (got " + std::to_string(s.check_points) +
                      "), check_radius finite and > 0 (got " + to_text(s.check_radius) + "), steps0 >= 1 (got " +
                      std::to_string(s.steps0) + ")");
  if (s.q0.empty()) throw model_error("model '" + s.name + "': no initial state (q0 is empty)");
  if (canonical && s.p0.size() != s.q0.size())
    throw model_error("model '" + s.name + "': q0 has " + std::to_string(s.q0.size()) + " components but p0 has " +
                      std::to_string(s.p0.size()));
  if (!canonical && !s.p0.empty())
    throw model_error("model '" + s.name + "': a vector field's state is q0 alone (p0 has " +
                      std::to_string(s.p0.size()) + " components)");
  try {
    return {widened(vector_from_text<T>(s.q0, s.name + ": q0")), widened(vector_from_text<T>(s.p0, s.name + ": p0"))};
  } catch (const domain_error& e) {
    throw model_error("model '" + s.name + "': " + e.what());
  }
}

/// H and its vector field finite at the start.
template <class Field>
void check_start(const model_setup& s, const state<mpfr50>& x0, const mpfr50& energy, Field&& field) {
  if (!is_finite(energy))
    throw model_error("model '" + s.name + "': H is not finite at the start: H = " + to_text(static_cast<double>(energy)) +
                      " at " + point_text(x0.q, x0.p));
  dynamic_vector<mpfr50> dq(x0.q.size()), dp(x0.p.size());
  try {
    field(x0.q, x0.p, dq, dp);
  } catch (const non_finite_error& e) {
    throw model_error("model '" + s.name + "': the vector field is not finite at the start: " + e.what());
  }
  for (Eigen::Index i = 0; i < dq.size(); ++i)
    if (!is_finite(dq(i)))
      throw model_error("model '" + s.name + "': the vector field is not finite at the start: dq[" + std::to_string(i) +
                        "] = " + to_text(static_cast<double>(dq(i))) + " at " + point_text(x0.q, x0.p));
  for (Eigen::Index i = 0; i < dp.size(); ++i)
    if (!is_finite(dp(i)))
      throw model_error("model '" + s.name + "': the vector field is not finite at the start: dp[" + std::to_string(i) +
                        "] = " + to_text(static_cast<double>(dp(i))) + " at " + point_text(x0.q, x0.p));
}

/// The Hamiltonian model's problem (shared by the Lagrangian one, with its momenta).
template <class T, class H, class F, class G>
problem<T> hamiltonian_problem(const model_setup& s, const H& h, const F& integrals, const G& constraints,
                               const state<mpfr50>& x0, const dynamic_vector<mpfr50>& qdot0,
                               const reference_settings& settings) {
  const model_system<H, mpfr50> probe{h, false, x0.q, x0.p};
  mpfr50 energy;
  try {
    energy = h(x0.q, x0.p);
  } catch (const error& e) {
    throw model_error("model '" + s.name + "': H cannot be evaluated at the start: " + e.what());
  }
  check_start(s, x0, energy, [&](const auto& q, const auto& p, auto& dq, auto& dp) { probe.vector_field(q, p, dq, dp); });
  check_constraints(s, constraints, x0.q, qdot0);
  check_integrals(s, h, integrals, x0);
  const bool separable = s.separable ? *s.separable : separable_at_drawn_points(s, h, x0);
  problem_definition d = definition_of(s);
  d.p0.clear();
  for (Eigen::Index i = 0; i < x0.p.size(); ++i) d.p0.push_back(scientific_text(x0.p(i), 60));
  d.separable = separable;
  const model_system<H, T> system{h, separable, narrowed<T>(x0).q, narrowed<T>(x0).p};
  const model_system<H, mpfr50> reference{h, separable, x0.q, x0.p};
  std::vector<invariant<T>> invariants{{"energy", [system](const dynamic_vector<T>& q, const dynamic_vector<T>& p) -> T {
                                          return system.energy(q, p);
                                        }}};
  const bool has_energy = true;
  for (auto& i : model_invariants<T>(s, integrals, has_energy)) invariants.push_back(std::move(i));
  for (std::size_t k = 0; k < s.constraint_names.size(); ++k) {
    const T size = std::max(T(narrowed<T>(x0).q.norm()), T(1));
    invariants.push_back({s.constraint_names[k],
                          [constraints, k](const dynamic_vector<T>& q, const dynamic_vector<T>&) -> T {
                            return constraints(q)(static_cast<Eigen::Index>(k));
                          },
                          size});
  }
  return reference_problem<T>(d, system, reference, std::move(invariants), settings);
}
}  // namespace detail

/// The problem of a Hamiltonian model in tier T (see the header); throws model_error.
template <class T, class H, class F, class G>
problem<T> model_problem(const hamiltonian_model<H, F, G>& m, const reference_settings& settings = {}) {
  const state<mpfr50> x0 = detail::start_of<T>(m.setup, true);
  dynamic_vector<mpfr50> qdot0(x0.q.size()), pdot0(x0.p.size());
  if (!m.setup.constraint_names.empty()) hamiltonian_system<H>{m.hamiltonian}.vector_field(x0.q, x0.p, qdot0, pdot0);
  return detail::hamiltonian_problem<T>(m.setup, m.hamiltonian, m.integrals, m.constraints, x0, qdot0, settings);
}

/// The problem of a Lagrangian model in tier T: H by the Legendre transform (notes eqs
/// 245-255), the initial momenta p = dL/dqdot from the velocities (eq 51), the integrals in
/// (q, qdot) through qdot(q, p). Throws model_error.
template <class T, class L, class F, class G>
problem<T> model_problem(const lagrangian_model<L, F, G>& m, const reference_settings& settings = {}) {
  const state<mpfr50> start = detail::start_of<T>(m.setup, true);  // p holds the velocities
  const detail::autonomous_lagrangian<L> lag{m.lagrangian};
  state<mpfr50> x0{start.q, {}};
  try {
    x0.p = generalized_momenta(lag, start.q, start.p, mpfr50(0));
  } catch (const error& e) {
    throw model_error("model '" + m.setup.name + "': the momenta at the start: " + e.what());
  }
  const legendre_hamiltonian<detail::autonomous_lagrangian<L>> h{lag};
  const detail::integrals_in_momenta<L, F> integrals{lag, m.integrals};
  return detail::hamiltonian_problem<T>(m.setup, h, integrals, m.constraints, x0, start.p, settings);
}

/// The problem of a vector-field model in tier T: not canonical (no symplectic study, no
/// splitting); the integral named "energy", if any, is its energy. Throws model_error.
template <class T, class V, class F>
problem<T> model_problem(const vector_field_model<V, F>& m, const reference_settings& settings = {}) {
  const model_setup& s = m.setup;
  const state<mpfr50> x0 = detail::start_of<T>(s, false);
  Eigen::Index energy_index = -1;
  for (std::size_t k = 0; k < s.integral_names.size(); ++k)
    if (s.integral_names[k] == "energy") energy_index = static_cast<Eigen::Index>(k);
  const detail::field_system<V, F> system{m.field, m.integrals, energy_index};
  detail::check_start(s, x0, energy_index >= 0 ? system.energy(x0.q, x0.p) : mpfr50(0),
                      [&](const auto& q, const auto& p, auto& dq, auto& dp) {
                        dq = m.field(dynamic_vector<mpfr50>(q));
                        static_cast<void>(p);
                        static_cast<void>(dp);
                      });
  // dF/dt = dF/dy . f(y) at the drawn points.
  const Eigen::Index count = m.integrals(x0.q, x0.p).size();
  if (static_cast<std::size_t>(count) != s.integral_names.size())
    throw model_error("model '" + s.name + "': its integrals functor returns " + std::to_string(count) +
                      " values but integral_names has " + std::to_string(s.integral_names.size()));
  for (const auto& [q, p] : detail::drawn_points(x0, s)) {
    dynamic_vector<mpfr50> f;
    try {
      f = m.field(q);
    } catch (const error&) {
      continue;
    }
    for (Eigen::Index k = 0; k < count; ++k) {
      const auto g = gradient([&m, k]<class A>(const dynamic_vector<A>& y) -> A {
        return m.integrals(y, dynamic_vector<A>(0))(k);
      }, q);
      mpfr50 rate = 0, scale = 0;
      for (Eigen::Index i = 0; i < q.size(); ++i) {
        rate += g(i) * f(i);
        scale += abs(mpfr50(g(i) * f(i)));
      }
      if (abs(rate) > detail::check_budget() * scale)
        throw model_error("model '" + s.name + "': the declared first integral '" + s.integral_names[std::size_t(k)] +
                          "' is not conserved: dF/dt = " + to_text(static_cast<double>(rate)) + " at " +
                          detail::point_text(q, p) + ", " + to_text(static_cast<double>(rate / scale)) +
                          " of the magnitude of its terms");
    }
  }
  problem_definition d = detail::definition_of(s);
  d.canonical = false;
  const detail::field_system<V, F> reference{m.field, m.integrals, energy_index};
  std::vector<invariant<T>> invariants;
  if (energy_index >= 0)
    invariants.push_back({"energy", [system](const dynamic_vector<T>& q, const dynamic_vector<T>& p) -> T {
                            return system.energy(q, p);
                          }});
  for (auto& i : detail::model_invariants<T>(s, m.integrals, energy_index >= 0)) invariants.push_back(std::move(i));
  return reference_problem<T>(d, system, reference, std::move(invariants), settings);
}

}  // namespace mechcheck::audit
