#pragma once
/// Auditing a stepper: what it does on reference problems with exact solutions, against
/// what it declares.
///
/// For every problem a stepper can take (splitting methods need a separable H), in one
/// tier T, the audit measures
///   - the global order: the error at t_end against the exact solution while the step
///     halves, fitted over the halvings above the rounding floor (audit/studies.hpp);
///   - the local order: the error of one step from the initial state, against the exact
///     solution, down to the rounding floor (p + 1 for a method of order p); in a
///     high-precision tier this resolves coefficients that are right only to a lower
///     precision (their error term appears at small h);
///   - symplecticity (canonical problems): max |M J M^T - J| of one step, M by AD through
///     the stepper, in eps units against a rounding budget, or the power of h it scales
///     with;
///   - time symmetry: step(-h) after step(h) returns to the start within a rounding
///     budget, or the defect's power of h;
///   - the long run: the growth exponent of the energy error over many steps (bounded,
///     random walk t^1/2, linear drift or worse) and of every first integral's drift
///     (angular momentum, the Laplace-Runge-Lenz vector, |M|^2 of the top), or that it is
///     preserved to rounding;
///   - cost: force or vector-field evaluations per step (counted), time per step, and
///     the work-precision points of the global study.
/// The result is a plain value (audit/report.hpp prints it, writes JSON and Markdown);
/// each claim the stepper declares (order, symplectic, symmetric) is confirmed or
/// contradicted with its evidence.
///
/// A stepper is audited through stepper_under_audit<T>: a name, the claims, and how to
/// make it on erased_system<T> for scalars T and ad<T> (the AD one gives Jacobians).
/// `method<Method>(name)` adapts the library's form `Method<System, Vec>{system}`, whose
/// static members order/symplectic/symmetric are the claims.

#include <algorithm>
#include <bit>
#include <chrono>
#include <cmath>
#include <functional>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "mechcheck/audit/finite_differences.hpp"
#include "mechcheck/audit/problems/exact.hpp"
#include "mechcheck/audit/result.hpp"
#include "mechcheck/audit/studies.hpp"
#include "mechcheck/audit/symplectic.hpp"
#include "mechcheck/audit/verdicts.hpp"
#include "mechcheck/core.hpp"

namespace mechcheck::audit {

template <class S>
using step_function = std::function<void(state<S>&, const S&)>;

/// A stepper under audit in tier T.
template <class T>
struct stepper_under_audit {
  std::string name;
  claims declared;
  std::string origin;  ///< where it and its claims come from (shown in the report)
  std::function<step_function<T>(const erased_system<T>&)> make;
  /// The same stepper on ad<T> scalars (for the symplectic condition); empty if the
  /// stepper cannot run on AD scalars.
  std::function<step_function<ad<T>>(const erased_system<T>&)> make_ad;
  /// Without make_ad: take the step's Jacobian by finite differences (black boxes,
  /// finite_differences.hpp), with the resolution their error model gives.
  bool finite_differences = false;
  /// What the method needs of a problem (a canonical split, a separable H): the problems
  /// that do not fit are skipped with the reason, never judged.
  method_structure structure;
};

namespace detail {
template <class M>
claims claims_of() {
  claims c;
  if constexpr (requires { M::order; }) c.order = static_cast<int>(M::order);
  if constexpr (requires { M::symplectic; }) c.symplectic = static_cast<bool>(M::symplectic);
  if constexpr (requires { M::symmetric; }) c.symmetric = static_cast<bool>(M::symmetric);
  if constexpr (requires { M::bounded_energy; })
    c.energy = M::bounded_energy ? energy_behaviour::bounded : energy_behaviour::drift;
  return c;
}

/// A method with a static member `separable` (true) evaluates velocity and force apart:
/// it needs a canonical, separable problem.
template <class M>
method_structure structure_of() {
  method_structure s;
  if constexpr (requires { M::separable; }) s.canonical = s.separable = static_cast<bool>(M::separable);
  return s;
}

template <template <class, class> class Method, class S, class T>
step_function<S> make_step(const erased_system<T>& system) {
  using M = Method<erased_system<T>, dynamic_vector<S>>;
  auto stepper = std::make_shared<M>(M{system});
  return [stepper](state<S>& x, const S& h) { (*stepper)(x, h); };
}
}  // namespace detail

/// A stepper of the library's form Method<System, Vec> (constructed as Method{system}),
/// its claims read from the static members order, symplectic, symmetric and bounded_energy
/// (true: bounded, false: drift), its structure from `separable`.
template <template <class, class> class Method, class T>
stepper_under_audit<T> method(std::string name) {
  stepper_under_audit<T> s;
  s.name = std::move(name);
  // Where the claims come from, not whose the stepper is: a user's stepper is not stamped
  // with mechcheck's name (builtin_steppers prefixes its own).
  s.origin = "static members order, symplectic, symmetric";
  s.declared = detail::claims_of<Method<erased_system<T>, dynamic_vector<T>>>();
  s.structure = detail::structure_of<Method<erased_system<T>, dynamic_vector<T>>>();
  s.make = [](const erased_system<T>& sys) { return detail::make_step<Method, T>(sys); };
  s.make_ad = [](const erased_system<T>& sys) { return detail::make_step<Method, ad<T>>(sys); };
  return s;
}

/// Thrown by erased_system when a stepper asks a non-separable system for its force.
namespace detail {
inline bool is_not_separable(const std::exception& e) {
  return std::string(e.what()).find("is not separable") != std::string::npos;
}

template <class T>
double to_double(const T& x) {
  return static_cast<double>(x);
}

template <class T>
T distance(const state<T>& a, const state<T>& b) {
  using std::sqrt;
  return sqrt(T((a.q - b.q).squaredNorm() + (a.p - b.p).squaredNorm()));
}

template <class T>
double eps_of() {
  return static_cast<double>(tier_epsilon<T>());
}

/// The relative uncertainty of the problem's solution at t: 0 for a closed form.
template <class T>
double uncertainty_at(const problem<T>& pr, const T& t) {
  return pr.exact_uncertainty ? pr.exact_uncertainty(t) : 0.0;
}

/// Global order: the halving study (studies.hpp) of runs over [0, t_end] from steps0 / 4
/// steps up to max_steps, each run's error against the exact solution at t_end, and the
/// change of the final state from the previous run (the stall detection's evidence).
/// A certified reference (problem::exact_uncertainty u) floors the study as a tier of
/// epsilon max(eps, u) would.
template <class T>
order_study global_order(const stepper_under_audit<T>& s, const problem<T>& pr,
                         const audit_options& opt) {
  const state<T> reference = pr.exact(pr.t_end);
  const double floor_eps = std::max(eps_of<T>(), uncertainty_at(pr, pr.t_end));
  std::optional<state<T>> previous;
  const auto run = [&](long n) {
    study_run r;
    pr.system.reset_evaluations();
    state<T> x = pr.initial;
    const T h = pr.t_end / T(n);
    try {
      auto step = s.make(pr.system);
      for (long i = 0; i < n; ++i) step(x, h);
    } catch (const std::exception& e) {
      r.ok = false;
      r.note = "h = " + to_text(h) + ": " + e.what();
      previous.reset();
      return r;
    }
    r.evaluations = static_cast<double>(pr.system.evaluations());
    r.error = to_double(T(distance(x, reference) / pr.scale));
    if (previous) r.change = to_double(T(distance(x, *previous) / pr.scale));
    previous = x;
    return r;
  };
  const long max_steps = opt.max_study_steps > 0 ? static_cast<long>(opt.max_study_steps)
                        : std::is_floating_point_v<T> ? 1L << 16
                                                      : 1L << 14;
  order_study study = halving_study(run, std::max<long>(2, pr.steps0 / 4), max_steps, floor_eps,
                                    [&](long n) { return to_double(T(pr.t_end / T(n))); },
                                    !std::is_floating_point_v<T>);
  if (floor_eps > eps_of<T>()) study.reference_floor = floor_eps;
  return study;
}

/// Local order: the error of one step from the initial state against the exact solution,
/// h halving from h_local down to the rounding floor (a step of m evaluations rounds at
/// ~ m eps): p + 1 for a method of order p.
template <class T>
order_study local_order(const stepper_under_audit<T>& s, const problem<T>& pr,
                        const audit_options& opt) {
  order_study study;
  double eps = eps_of<T>();
  T h = 8 * pr.h_local;  // high orders reach the floor within a few halvings of h_local
  for (int k = 0; k <= opt.max_local_halvings; ++k, h /= 2) {
    eps = std::max(eps, uncertainty_at(pr, h));  // a certified reference's floor
    pr.system.reset_evaluations();
    state<T> x = pr.initial;
    try {
      s.make(pr.system)(x, h);
    } catch (const std::exception& e) {
      study.note = "h = " + to_text(h) + ": " + e.what();
      continue;
    }
    const double evals = static_cast<double>(pr.system.evaluations());
    const double error = to_double(T(distance(x, pr.exact(h)) / pr.scale));
    study.points.push_back({to_double(h), error, evals});
    if (error < local_floor(eps, evals)) break;
  }
  fit_local(study, eps);
  if (eps > eps_of<T>()) study.reference_floor = eps;
  return study;
}

/// A defect d(h) that vanishes to rounding for the claimed property: tested at h_local,
/// h_local/2 and h_local/4 against the budget; when over it, followed down by halvings
/// until within the budget, and its power of h fitted.
template <class T, class Defect>
defect_study defect_of(const problem<T>& pr, const audit_options& opt, Defect&& defect,
                       double budget_eps) {
  defect_study d;
  d.budget_eps = budget_eps;
  T h = pr.h_local;
  bool over = false;
  for (int k = 0; k < 3; ++k, h /= 2) {
    const auto [value, scale] = defect(h);
    const double eps_units = to_double(T(value / (tier_epsilon<T>() * scale)));
    d.worst_eps = std::max(d.worst_eps, eps_units);
    d.points.push_back({to_double(h), to_double(T(value / scale)), 0});
    over = over || !(eps_units <= budget_eps);
  }
  d.within_rounding = !over;
  if (d.within_rounding) {
    d.points.clear();
    return d;
  }
  for (int k = 3; k <= opt.max_local_halvings; ++k, h /= 2) {
    const auto [value, scale] = defect(h);
    const double eps_units = to_double(T(value / (tier_epsilon<T>() * scale)));
    d.points.push_back({to_double(h), to_double(T(value / scale)), 0});
    if (eps_units <= budget_eps) break;
  }
  d.exponent = fit_halvings(d.points, 16 * budget_eps * eps_of<T>());
  return d;
}

/// max |M J M^T - J| of one step at the initial state, on the scale |M|^2; budget
/// 16 (m + 1) 2n eps for a step of m evaluations on n degrees of freedom.
template <class T>
defect_study symplectic_condition(const stepper_under_audit<T>& s, const problem<T>& pr,
                                  const audit_options& opt, double evaluations_per_step) {
  const Eigen::Index n = pr.initial.q.size();
  dynamic_vector<T> z(2 * n);
  z << pr.initial.q, pr.initial.p;
  const auto defect = [&](const T& h) -> std::pair<T, T> {
    const auto make = [&s, &pr]<class S>() { return s.make_ad(pr.system); };
    const dynamic_matrix<T> m = step_jacobian_of(make, z, h, n);
    return {symplectic_defect(m), T(m.squaredNorm())};
  };
  return defect_of(pr, opt, defect, 16.0 * (evaluations_per_step + 1) * 2.0 * double(n));
}

/// The symplectic condition of a stepper that cannot run on AD scalars: M by finite
/// differences (finite_differences.hpp; rounding of one step 4 (m + 1) eps |Z|), at
/// h_local, h_local/2 and h_local/4. Its error E per entry bounds the defect's error by
/// |E J M^T + M J E^T| <= 2 (2n) max|E| max|M|: the resolution. A defect above it at any of
/// the three steps is followed down by halvings (as defect_of does) and its power of h
/// fitted; below it at all three, "no defect above the resolution". For one degree of
/// freedom det M - 1 is reported too (area preservation), with resolution 4 max|M| max|E|.
template <class T>
defect_study symplectic_condition_fd(const stepper_under_audit<T>& s, const problem<T>& pr,
                                     const audit_options& opt, double evaluations_per_step) {
  using std::abs;
  const Eigen::Index n = pr.initial.q.size();
  dynamic_vector<T> z(2 * n);
  z << pr.initial.q, pr.initial.p;
  struct measured {
    double defect, resolution;  // relative to |M|^2
    double det_minus_one = 0, det_resolution = 0;
  };
  const auto measure = [&](const T& h) {
    const std::function<dynamic_vector<T>(const dynamic_vector<T>&)> map =
        [&](const dynamic_vector<T>& w) {
          state<T> x{dynamic_vector<T>(w.head(n)), dynamic_vector<T>(w.tail(n))};
          auto step = s.make(pr.system);
          step(x, h);
          dynamic_vector<T> out(2 * n);
          out << x.q, x.p;
          return out;
        };
    const fd_jacobian<T> fd =
        finite_difference_jacobian<T>(map, z, 4 * (evaluations_per_step + 1));
    const double scale = to_double(T(fd.value.squaredNorm()));
    const double m_max = to_double(T(fd.value.cwiseAbs().maxCoeff()));
    const double e_max = fd.error.maxCoeff();
    measured r;
    r.defect = to_double(symplectic_defect(fd.value)) / scale;
    r.resolution = 2.0 * double(2 * n) * e_max * m_max / scale;
    if (n == 1) {
      r.det_minus_one = to_double(T(fd.value.determinant() - 1));
      r.det_resolution = 4 * m_max * e_max;
    }
    return r;
  };
  defect_study d;
  T h = pr.h_local;
  bool over = false;
  for (int k = 0; k < 3; ++k, h /= 2) {
    const measured m = measure(h);
    if (k == 0 && n == 1) {
      d.area_defect = m.det_minus_one;
      d.area_resolution = m.det_resolution;
    }
    d.resolution = std::max(d.resolution, m.resolution);
    d.worst_eps = std::max(d.worst_eps, m.defect / eps_of<T>());
    d.worst_relative = std::max(d.worst_relative, m.defect);
    d.points.push_back({to_double(h), m.defect, 0});
    over = over || !(m.defect <= m.resolution);
  }
  d.budget_eps = d.resolution / eps_of<T>();
  d.within_rounding = !over;
  if (d.within_rounding) {
    d.points.clear();
    return d;
  }
  for (int k = 3; k <= opt.max_local_halvings; ++k, h /= 2) {
    const measured m = measure(h);
    d.points.push_back({to_double(h), m.defect, 0});
    if (m.defect <= m.resolution) break;
  }
  d.exponent = fit_halvings(d.points, 4 * d.resolution);
  return d;
}

/// |step(-h) step(h) x0 - x0| on the scale |x0|; budget 16 (2m + 1) eps.
template <class T>
defect_study time_symmetry(const stepper_under_audit<T>& s, const problem<T>& pr,
                           const audit_options& opt, double evaluations_per_step) {
  const auto defect = [&](const T& h) -> std::pair<T, T> {
    state<T> x = pr.initial;
    auto step = s.make(pr.system);
    step(x, h);
    step(x, T(-h));
    return {distance(x, pr.initial), pr.scale};
  };
  return defect_of(pr, opt, defect, 16.0 * (2 * evaluations_per_step + 1));
}

/// The long run: `steps` steps of h_long, the drift of every invariant recorded.
template <class T>
long_run run_long(const stepper_under_audit<T>& s, const problem<T>& pr,
                  const audit_options& opt) {
  long_run run;
  run.steps = opt.long_run_steps;
  run.h = to_double(pr.h_long);
  std::vector<T> start, scale;
  for (const auto& inv : pr.invariants) {
    using std::abs;
    const T v = inv.value(pr.initial.q, pr.initial.p);
    start.push_back(v);
    scale.push_back(inv.scale > 0 ? inv.scale : abs(v) > 0 ? T(abs(v)) : pr.scale);
  }
  std::vector<growth_recorder> growth(pr.invariants.size());
  state<T> x = pr.initial;
  pr.system.reset_evaluations();
  auto step = s.make(pr.system);
  const auto t0 = std::chrono::steady_clock::now();
  long long done = 0;
  try {
    for (long long i = 1; i <= run.steps; ++i) {
      step(x, pr.h_long);
      done = i;
      // Every step of the first 2^9, then 256 evenly spaced samples of each window
      // [2^w, 2^(w+1)): the windows' RMS (and the growth exponent) are estimated as
      // well, at a fraction of the cost of evaluating the invariants at every step.
      const auto stride = static_cast<long long>(
          std::max(1ULL, std::bit_floor(static_cast<unsigned long long>(i)) >> 8));
      if (i % stride != 0) continue;
      for (std::size_t k = 0; k < pr.invariants.size(); ++k) {
        using std::abs;
        const T d = abs(T(pr.invariants[k].value(x.q, x.p) - start[k])) / scale[k];
        growth[k].add(static_cast<long>(i), to_double(d));
      }
    }
  } catch (const std::exception& e) {
    run.failure = "step " + std::to_string(done + 1) + ": " + e.what();
  }
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (done > 0) {
    run.evaluations_per_step = static_cast<double>(pr.system.evaluations()) / double(done);
    if (opt.timing) run.seconds_per_step = seconds / double(done);
  }
  // Rounding alone: one rounding per evaluation and per step, as a random walk, with
  // margin 8: the invariant is preserved by the method when its drift stays below this.
  const auto rounding = [&](double steps) {
    return 8 * eps_of<T>() * (run.evaluations_per_step + 1) * std::sqrt(std::max(steps, 1.0));
  };
  const double budget = rounding(double(done));
  const double time_scale = pr.time_scale > 0 ? pr.time_scale : to_double(pr.t_end);
  for (std::size_t k = 0; k < pr.invariants.size(); ++k) {
    drift d;
    d.name = pr.invariants[k].name;
    d.max_relative = growth[k].max_error();
    d.budget_relative = budget;
    d.preserved = run.failure.empty() && d.max_relative <= budget;
    d.window_rms = growth[k].window_rms();
    // The growth class past the start-up transient (classify_growth): each window's time and
    // its own rounding budget as the floor.
    const std::vector<double> steps_w = growth[k].window_steps();
    std::vector<double> time(steps_w.size()), floor(steps_w.size());
    for (std::size_t w = 0; w < steps_w.size(); ++w) {
      time[w] = steps_w[w] * run.h;
      floor[w] = rounding(steps_w[w]);
    }
    const growth_class g = classify_growth(time, d.window_rms, floor, time_scale, double(done) * run.h, "problem");
    // An error of order one has saturated (the orbit escaped, the angle wrapped): its
    // growth exponent then says nothing about the method (invariant_class).
    d.kind = invariant_class(d.max_relative, d.preserved, g.kind);
    if (d.kind == g.kind) d.exponent = g.exponent;
    run.invariants.push_back(d);
  }
  return run;
}

inline bool selected(const std::vector<std::string>& names, const std::string& name) {
  if (names.empty()) return true;
  for (const auto& n : names)
    if (n == name) return true;
  return false;
}
}  // namespace detail

/// Audit a stepper in tier T on the given problems.
template <class T>
stepper_audit audit_stepper(const stepper_under_audit<T>& s,
                            const std::vector<problem<T>>& problems,
                            const audit_options& opt = {}) {
  // A name that matches no problem would silently audit nothing: refuse it.
  for (const auto* names : {&opt.problems, &opt.long_run_problems})
    for (const auto& name : *names)
      if (std::none_of(problems.begin(), problems.end(),
                       [&](const problem<T>& p) { return p.name == name; })) {
        std::string known;
        for (const auto& p : problems) known += " " + p.name;
        throw domain_error("audit_stepper: no problem named '" + name + "' (known:" + known +
                           ")");
      }
  if (opt.long_run_steps < 0 || (opt.max_study_steps != 0 && opt.max_study_steps < 2) ||
      opt.max_local_halvings < 1)
    throw domain_error("audit_stepper: long_run_steps must be >= 0 (got " +
                       std::to_string(opt.long_run_steps) + "), max_study_steps 0 or >= 2 (got " +
                       std::to_string(opt.max_study_steps) + "), max_local_halvings >= 1 (got " +
                       std::to_string(opt.max_local_halvings) + ")");
  const auto t0 = std::chrono::steady_clock::now();
  stepper_audit out;
  out.stepper = s.name;
  out.origin = s.origin;
  out.tier = std::string(tier_traits<T>::name);
  out.digits = tier_digits<T>();
  out.declared = s.declared;
  out.structure = s.structure;
  for (const auto& pr : problems) {
    if (!detail::selected(opt.problems, pr.name)) continue;
    problem_audit pa;
    pa.problem = pr.name;
    // A problem the method declares it cannot run is skipped with the reason.
    if (s.structure.canonical && !pr.canonical) {
      pa.skipped = "needs a canonical (q, p) split (declared); " + pr.name + " is not canonical";
      out.problems.push_back(pa);
      continue;
    }
    if (s.structure.separable && !pr.separable) {
      pa.skipped = "needs a separable H = |p|^2/2 + V(q) (declared); " + pr.name + " is not separable";
      out.problems.push_back(pa);
      continue;
    }
    if (opt.progress) opt.progress(s.name + " [" + out.tier + "] on " + pr.name);
    // Can the stepper take the problem? One step tells (a splitting without a declared
    // structure asks a non-separable system for its force). Any other failure of that step
    // (an implicit solve that does not converge at h_local) is recorded, and the studies
    // run: they step down from coarse steps and skip the runs that fail.
    try {
      state<T> x = pr.initial;
      pr.system.reset_evaluations();
      s.make(pr.system)(x, pr.h_local);
      pa.evaluations_per_step = static_cast<double>(pr.system.evaluations());
    } catch (const std::exception& e) {
      if (detail::is_not_separable(e)) {
        pa.skipped = "needs a separable H";
        out.problems.push_back(pa);
        continue;
      }
      pa.failures.push_back("the first step at h = " + to_text(pr.h_local) + ": " + e.what());
    }
    // A study whose step throws (a third-party error code, an implicit solve that fails,
    // a backward step a method refuses) is recorded as a failure, never left to end the
    // audit; its claim reads as not measured on this problem.
    const auto guarded = [&pa](const char* what, auto&& study) {
      try {
        study();
      } catch (const std::exception& e) {
        pa.failures.push_back(std::string(what) + ": " + e.what());
      }
    };
    guarded("global order", [&] { pa.global = detail::global_order(s, pr, opt); });
    guarded("local order", [&] { pa.local = detail::local_order(s, pr, opt); });
    if (pr.exact_uncertainty) {
      using std::log10;
      const double u = pr.exact_uncertainty(pr.t_end);
      pa.reference_digits = u > 0 ? -std::log10(u) : std::numeric_limits<double>::infinity();
      pa.reference_uncertainty = std::max({u, pa.global.reference_floor, pa.local.reference_floor});
    }
    // A first step that failed left no count: take the local study's finest step's.
    if (pa.evaluations_per_step == 0 && !pa.local.points.empty())
      pa.evaluations_per_step = pa.local.points.back().evaluations;
    if (pr.canonical && s.make_ad)
      guarded("symplectic condition", [&] {
        pa.symplectic = detail::symplectic_condition(s, pr, opt, pa.evaluations_per_step);
      });
    else if (pr.canonical && s.finite_differences)
      guarded("symplectic condition", [&] {
        pa.symplectic = detail::symplectic_condition_fd(s, pr, opt, pa.evaluations_per_step);
      });
    guarded("time symmetry", [&] {
      pa.symmetric = detail::time_symmetry(s, pr, opt, pa.evaluations_per_step);
    });
    if (detail::selected(opt.long_run_problems, pr.name) && opt.long_run_steps > 0) {
      if (pr.long_run_refused.empty())
        guarded("long run", [&] { pa.run = detail::run_long(s, pr, opt); });
      else
        pa.failures.push_back("long run: not run on " + pr.name + ": " + pr.long_run_refused);
    }
    out.problems.push_back(std::move(pa));
  }
  out.verdicts = judge(out.declared, out.problems, detail::eps_of<T>());
  if (opt.timing)
    out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

/// Audit a stepper in tier T on every reference problem.
template <class T>
stepper_audit audit_stepper(const stepper_under_audit<T>& s, const audit_options& opt = {}) {
  return audit_stepper(s, reference_problems<T>(), opt);
}

// In double and mpfr50, the tiers mechcheck-audit runs, the audit and the reference
// problems are compiled once, in the audit library (audit_double.cpp, audit_mpfr50.cpp): a
// program auditing its stepper compiles the stepper only (about 8 s less a tier). Other
// tiers instantiate them where they are used.
extern template std::vector<problem<double>> reference_problems<double>();
extern template stepper_audit audit_stepper<double>(const stepper_under_audit<double>&,
                                                    const std::vector<problem<double>>&,
                                                    const audit_options&);
extern template stepper_audit audit_stepper<double>(const stepper_under_audit<double>&,
                                                    const audit_options&);
extern template std::vector<problem<mpfr50>> reference_problems<mpfr50>();
extern template stepper_audit audit_stepper<mpfr50>(const stepper_under_audit<mpfr50>&,
                                                    const std::vector<problem<mpfr50>>&,
                                                    const audit_options&);
extern template stepper_audit audit_stepper<mpfr50>(const stepper_under_audit<mpfr50>&,
                                                    const audit_options&);

}  // namespace mechcheck::audit
