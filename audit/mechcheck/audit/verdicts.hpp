#pragma once
/// Verdicts: a declared claim against the measurements of every problem, in the vocabulary
/// of result.hpp (confirmed, contradicted, not resolvable, reading, exceeds, to the
/// precision given, not declared, not measured). Every audit judges through these rules:
/// the stepper audit (audit.hpp), black boxes and tableaus through it, and the engines
/// (engines.cpp), per observable class.
///
/// The order of a method is its worst case over the problems it can run. A fit is
///   settled   when it has two or three exponents within 0.3 of each other: it can confirm;
///   decisive  when it has three exponents within 0.1: only a decisive fit can contradict.
/// Two exponents cannot show whether they still move (a pre-asymptotic fit of a tenth-order
/// method reached the rounding floor of double after two halvings at 9.44), and a local fit
/// whose three exponents still rise towards p + 1 (3.66, 3.67, 3.84 for a third-order
/// table) is pre-asymptotic: neither decides against a clean global order.
///
/// For a declared order p, read as the global order:
///   - contradicted when a global study stalls above its rounding floor (the method
///     converges to a wrong limit), or a decisive global fit lies below p - 0.25, or a
///     decisive local fit below p + 1 - 0.25 -- unless another reading the words allow
///     (order_reading) holds, which makes it a reading;
///   - exceeds when every resolved global fit is above p + 0.75 (settled or not) and every
///     settled local fit above p + 1.75 (with what the order conditions say, where there is
///     a tableau);
///   - confirmed when a settled global fit reaches p - 0.25 (a problem may show more:
///     symplectic Euler is of order 2 on the oscillator);
///   - not resolvable otherwise, with what the study would need.
/// A claim that fails at the tier's floors but holds at the floors of one error of the size
/// of the coefficients' declared precision (a tier of that epsilon, one evaluation: a
/// coefficient errs once, not once an evaluation) is "to the precision given" -- unless the
/// order conditions of a tableau fail beyond that precision.

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "mechcheck/audit/result.hpp"
#include "mechcheck/audit/studies.hpp"

namespace mechcheck::audit {

/// The bands and spreads of the order verdicts.
namespace rules {
inline constexpr double below_band = 0.25;    ///< a fit below p - 0.25 is below p
inline constexpr double above_band = 0.75;    ///< a fit above p + 0.75 is above p
inline constexpr double settled_spread = 0.3;
inline constexpr double decisive_spread = 0.1;
/// A random walk of the energy error within this many rounding budgets is rounding
/// (Brouwer's law), not the method's drift.
inline constexpr double rounding_walk_budgets = 100;
}  // namespace rules

/// At least two exponents within 0.3: a fit that can confirm a claim.
inline bool settled(const fitted_exponent& f) {
  return f.used >= 2 && f.spread <= rules::settled_spread;
}
/// Three exponents within 0.1: a fit that can contradict a claim.
inline bool decisive(const fitted_exponent& f) {
  return f.used >= 3 && f.spread <= rules::decisive_spread;
}

namespace detail {
inline std::string fixed(double x, int digits = 2) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", digits, x);
  return buf;
}
inline std::string sci(double x) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.2e", x);
  return buf;
}

inline std::string describe_fit(const char* what, const fitted_exponent& f) {
  return std::string(what) + " " + fixed(f.value) + " (spread " + fixed(f.spread) + ", " +
         std::to_string(f.used) + " halvings" +
         (decisive(f) ? ")" : settled(f) ? ", settled, not decisive)" : ", not settled)");
}

/// What the measurements say of one reading of an order: expected global order g and
/// local order l (g + 1).
struct order_assessment {
  bool stalled = false, below = false, above = false, consistent = false;
  bool some_fit_not_above = false;  ///< a resolved global fit (settled or not) at or below g + 0.75
  bool any_fit = false;                   ///< some fit or stall was resolved
  std::vector<double> settled_global, settled_local;
  std::string evidence;
  int fewest_halvings_to_floor = 99;      ///< not-decisive fits that ended at the floor
  std::string floor_problems;
  /// Those of them whose floor was a certified reference's, not the tier's.
  std::string reference_problems;
  /// Problems with no global fit because their reference's floor lies above the errors.
  std::string unresolved_by_reference;
  /// Problems whose error sat at the rounding floor from the coarsest runs on (no halving
  /// above it): integrated to rounding, they say nothing of the order.
  std::string exact_problems;
};

inline order_assessment assess_order(const std::vector<problem_audit>& ps, double g, double l,
                                     bool with_evidence, const std::string& label) {
  order_assessment a;
  for (const auto& pa : ps) {
    if (!pa.skipped.empty()) continue;
    std::string ev = pa.problem + ": ";
    const fitted_exponent& gf = pa.global.fit;
    const fitted_exponent& lf = pa.local.fit;
    if (gf.used > 0) {
      a.any_fit = true;
      if (!(gf.value > g + rules::above_band)) a.some_fit_not_above = true;
      ev += describe_fit("global", gf);
      if (settled(gf)) {
        a.settled_global.push_back(gf.value);
        if (gf.value >= g - rules::below_band) a.consistent = true;
      }
      if (gf.value < g - rules::below_band) {
        if (decisive(gf)) {
          a.below = true;
          ev += " <- below " + label;
        } else if (settled(gf)) {
          ev += " (below " + label + ", not decisive)";
        }
        if (!decisive(gf) && gf.floor_h && gf.used < 3) {
          a.fewest_halvings_to_floor = std::min(a.fewest_halvings_to_floor, gf.used);
          a.floor_problems += (a.floor_problems.empty() ? "" : ", ") + pa.problem;
          if (pa.global.reference_floor > 0)
            a.reference_problems += (a.reference_problems.empty() ? "" : ", ") + pa.problem + " (" +
                                    fixed(pa.reference_digits.value_or(0), 1) + " digits)";
        }
      }
    } else {
      ev += "global not resolved";
      if (pa.global.reference_floor > 0) {
        ev += " (the reference is certified to " + fixed(pa.reference_digits.value_or(0), 1) + " digits)";
        a.unresolved_by_reference += (a.unresolved_by_reference.empty() ? "" : ", ") + pa.problem + " (" +
                                     fixed(pa.reference_digits.value_or(0), 1) + " digits)";
      } else if (gf.floor_h && !pa.global.points.empty() && pa.global.points.size() <= 2) {
        a.exact_problems += (a.exact_problems.empty() ? "" : ", ") + pa.problem;
      }
    }
    if (pa.global.stalled) {
      const stall& st = *pa.global.stalled;
      a.stalled = true;
      a.any_fit = true;
      ev += ", converges to " + sci(st.error) + ", not to 0 (at h = " + sci(st.h) +
            " the runs agree to " + sci(st.change) + "; floor eps sqrt(evaluations) = " +
            sci(st.floor) + ", error " + sci(st.margin) + " floors)";
    }
    if (lf.used > 0) {
      a.any_fit = true;
      ev += ", " + describe_fit("local", lf);
      if (settled(lf)) a.settled_local.push_back(lf.value);
      if (lf.value < l - rules::below_band) {
        if (decisive(lf)) {
          a.below = true;
          ev += " <- below " + fixed(l, 0);
        } else if (settled(lf)) {
          ev += " (below " + fixed(l, 0) + ", not decisive)";
        }
      }
    }
    if (with_evidence) a.evidence += ev + "; ";
  }
  if (!a.settled_global.empty() && !a.settled_local.empty()) {
    const double least_g = *std::min_element(a.settled_global.begin(), a.settled_global.end());
    const double least_l = *std::min_element(a.settled_local.begin(), a.settled_local.end());
    // An excess needs every resolved global fit above (an unsettled one below the band on
    // another problem is not evidence of a higher order) and every settled local fit.
    a.above = least_g > g + rules::above_band && least_l > l + rules::above_band && !a.some_fit_not_above;
  }
  return a;
}

inline std::string reading_name(order_reading r, int p) {
  switch (r) {
    case order_reading::global:
      return "global order " + std::to_string(p) + " (the propagated solution's error as h^" +
             std::to_string(p) + ")";
    case order_reading::local_error:
      return "the error of one step is O(h^" + std::to_string(p) + "): global order " +
             std::to_string(p - 1);
    case order_reading::embedded:
      return "order " + std::to_string(p) + " of the embedded formula that gives the error estimate";
  }
  return "?";
}

inline std::string least_text(const order_assessment& a) {
  if (a.stalled) return "stalls";
  if (a.settled_global.empty()) return "-";
  return fixed(*std::min_element(a.settled_global.begin(), a.settled_global.end()));
}

/// The order verdict at the floors the studies were fitted with.
inline verdict judge_order_as_fitted(const claims& c, const std::vector<problem_audit>& ps,
                                     double eps) {
  using outcome = verdict::outcome;
  verdict v;
  v.claim = "order";
  v.declared = c.order ? std::to_string(*c.order) : "-";
  const int p = c.order ? *c.order : 0;
  const order_assessment a = assess_order(ps, p, p + 1, true, c.order ? std::to_string(p) : "-");
  v.evidence = a.evidence;
  v.measured = least_text(a);
  // Nothing declared: the measurement is reported, whatever it resolved.
  if (!c.order) {
    v.result = outcome::not_declared;
    return v;
  }
  if (!a.any_fit) {
    // Runs that ran and resolved no halving say the study cannot decide; no run at all
    // (every problem skipped or failed) is not measured.
    const bool ran = std::any_of(ps.begin(), ps.end(), [](const problem_audit& pa) {
      return pa.skipped.empty() && (!pa.global.points.empty() || !pa.local.points.empty());
    });
    v.result = ran || !a.unresolved_by_reference.empty() ? outcome::not_resolvable : outcome::not_measured;
    if (!a.unresolved_by_reference.empty())
      v.needs = "references certified to more digits (a shorter horizon): on " + a.unresolved_by_reference +
                " the reference's uncertainty lies above the errors the runs reach";
    else if (ran && !a.exact_problems.empty())
      v.needs = "a problem whose error lies above rounding: " + a.exact_problems +
                " integrated to rounding from the coarsest run on";
    else if (ran)
      v.needs = "errors above the floors: coarser runs, or a precision with a lower floor";
    return v;
  }
  const claim_reading primary{reading_name(order_reading::global, p), v.measured,
                              !a.stalled && !a.below && !a.above && a.consistent};
  if (primary.holds) {
    v.result = outcome::confirmed;
    return v;
  }
  // The other readings the declaration's words allow, each measured.
  std::vector<claim_reading> others;
  for (const order_reading r : c.order_readings) {
    if (r != order_reading::local_error) continue;  // embedded: apply_embedded_reading
    const order_assessment b = assess_order(ps, p - 1, p, false, std::to_string(p - 1));
    others.push_back({reading_name(r, p),
                      "global " + least_text(b) + ", local " +
                          (b.settled_local.empty()
                               ? std::string("-")
                               : fixed(*std::min_element(b.settled_local.begin(), b.settled_local.end()))),
                      !b.stalled && !b.below && !b.above && b.consistent});
  }
  const bool other_holds =
      std::any_of(others.begin(), others.end(), [](const claim_reading& r) { return r.holds; });
  if (a.stalled || a.below || a.above) {
    if (other_holds) {
      v.result = outcome::reading;
      v.readings.push_back(primary);
      for (const auto& r : others) v.readings.push_back(r);
      return v;
    }
    if (a.stalled || a.below) {
      v.result = outcome::contradicted;
      return v;
    }
    v.result = outcome::exceeds;
    v.evidence += "every settled fit is above the declared order";
    if (c.algebraic_order)
      v.evidence += "; the order conditions of its coefficients: " + c.algebraic_words +
                    (*c.algebraic_order == p
                         ? " -- the method is of order " + std::to_string(p) +
                               "; these problems do not show its leading error terms"
                         : "");
    return v;
  }
  v.result = outcome::not_resolvable;
  if (!a.unresolved_by_reference.empty() && a.settled_global.empty()) {
    v.needs = "references certified to more digits (a shorter horizon): on " + a.unresolved_by_reference +
              " the reference's uncertainty lies above the errors the runs reach";
  } else if (!a.exact_problems.empty() && a.settled_global.empty() && a.fewest_halvings_to_floor == 99) {
    v.needs = "a problem the method does not integrate to rounding: on " + a.exact_problems +
              " the error is at the rounding floor from the coarsest runs";
  } else if (a.fewest_halvings_to_floor < 3) {
    v.needs = "a decisive fit needs three halvings above the rounding floor; on " + a.floor_problems +
              " the floor came after " + std::to_string(a.fewest_halvings_to_floor) +
              (!a.reference_problems.empty()
                   ? ": references certified to more digits (a shorter horizon) on " + a.reference_problems
               : eps > 1e-20 ? ": a tier with a lower floor (-t mpfr50)"
                             : ": a longer study");
  } else {
    v.needs = "fits of three exponents within " + fixed(rules::decisive_spread, 1) +
              ": a longer study (more halvings), or a problem whose error terms settle sooner";
  }
  return v;
}
}  // namespace detail

/// The order verdict (see the header): at the tier's floors, then -- where the coefficients
/// declare a precision coarser than the tier's -- at the floors of a tier of that epsilon.
inline verdict judge_order(const claims& c, const std::vector<problem_audit>& ps, double eps) {
  verdict v = detail::judge_order_as_fitted(c, ps, eps);
  const bool failed = v.result == verdict::outcome::contradicted ||
                      v.result == verdict::outcome::not_resolvable;
  if (!failed || !c.coefficient_precision || !(*c.coefficient_precision > 16 * eps)) return v;
  // Where there is a tableau, its order conditions decide whether the coefficients hold the
  // order to the precision they are given to: failing beyond it (a coefficient typed to 12
  // digits in a table stored in double), the contradiction stands, whatever the floors.
  if (c.algebraic_order && c.order && *c.algebraic_order < *c.order) {
    v.evidence += "the order conditions of its coefficients: " + c.algebraic_words;
    return v;
  }
  const double coarse = *c.coefficient_precision;
  std::vector<problem_audit> refitted = ps;
  // Coefficients off by up to `coarse` err once, by a fixed amount, not once an
  // evaluation: the floors of one evaluation in a tier of that epsilon.
  for (auto& pa : refitted) {  // never below a certified reference's floor
    fit_global(pa.global, std::max(coarse, pa.global.reference_floor), 1);
    fit_local(pa.local, std::max(coarse, pa.local.reference_floor), 1);
  }
  claims plain = c;
  plain.coefficient_precision.reset();
  const verdict at_precision = detail::judge_order_as_fitted(plain, refitted, coarse);
  // Confirmed at those floors: to the precision given. Not resolvable there: where the
  // order conditions hold to that precision they decide (the studies have too little range
  // above an error of that size to show the order); without a tableau, the study cannot
  // tell. Contradicted there: the contradiction stands.
  if (at_precision.result == verdict::outcome::contradicted) return v;
  const bool unresolved = at_precision.result != verdict::outcome::confirmed;  // no fit, or none settled
  if (unresolved && !c.algebraic_order) {
    verdict out = v;
    out.result = verdict::outcome::not_resolvable;
    out.needs = "the failure lies within the coefficients' precision (" + detail::sci(coarse) +
                "); above errors of that size " +
                (at_precision.needs.empty() ? std::string("no halving is resolved: coarser runs") : at_precision.needs);
    return out;
  }
  verdict out = at_precision;
  out.needs.clear();
  out.result = verdict::outcome::to_precision_given;
  out.evidence = "coefficients given to " + detail::sci(coarse) +
                 (c.coefficient_words.empty() ? "" : " (" + c.coefficient_words + ")") +
                 (c.algebraic_words.empty() ? "" : "; their order conditions: " + c.algebraic_words) +
                 "; at the floors of one error of that size: " + at_precision.evidence +
                 "at the tier's own floors (" + outcome_text(v.result) + "): " + v.evidence;
  return out;
}

/// A yes/no property (symplectic, symmetric): the defect within its rounding budget (AD)
/// or below its resolution (finite differences) on every problem measured. Where the
/// coefficients are given to a relative precision `coarse` coarser than the tier's (16 eps),
/// a defect within the budget of a tier of that epsilon is what such coefficients allow.
///   declared yes: confirmed when within everywhere; to the precision given when within
///     what the coefficients allow; contradicted by a defect above that;
///   declared no (a statement that the property is absent): confirmed by a defect above
///     what the coefficients allow on some problem; a defect within the tier's rounding
///     budget (AD) is not resolvable in a tier coarser than 1e-20 (a lower floor would
///     resolve it: -t mpfr50), contradicted in a finer one (the property holds); a
///     defect within what the coefficients allow is not resolvable; by finite differences
///     not resolvable (a high-order method's defect may lie below their resolution).
template <class Member>
verdict judge_property(const char* name, const std::optional<bool>& claim,
                       const std::vector<problem_audit>& ps, Member member, double eps = 0,
                       std::optional<double> coarse = {}) {
  using outcome = verdict::outcome;
  verdict v;
  v.claim = name;
  v.declared = claim ? (*claim ? "yes" : "no") : "-";
  const bool precision_counts = coarse && eps > 0 && *coarse > 16 * eps;
  bool any = false, all_within = true, all_within_given = true, by_fd = false;
  double coarsest = 0;
  std::string evidence;
  for (const auto& p : ps) {
    const std::optional<defect_study>& d = p.*member;
    if (!p.skipped.empty() || !d) continue;
    any = true;
    all_within = all_within && d->within_rounding;
    // At the floors of a tier whose epsilon is the coefficients' precision.
    const bool within_given = d->within_rounding || (precision_counts && d->resolution == 0 &&
                                                     d->worst_eps * eps / *coarse <= d->budget_eps);
    all_within_given = all_within_given && within_given;
    if (d->resolution > 0) {
      by_fd = true;
      coarsest = std::max(coarsest, d->resolution);
      evidence += p.problem + ": " +
                  (d->within_rounding ? "no defect above " + detail::sci(d->resolution)
                                      : "defect " + detail::sci(d->worst_relative) +
                                            " above the resolution " + detail::sci(d->resolution)) +
                  " (finite differences)";
      if (d->area_defect)
        evidence += ", det M - 1 = " + detail::sci(*d->area_defect) + " (resolution " +
                    detail::sci(*d->area_resolution) + ")";
    } else {
      evidence += p.problem + ": " + detail::sci(d->worst_eps) + " eps (budget " +
                  detail::sci(d->budget_eps) + ")";
      if (!d->within_rounding && within_given)
        evidence += ", " + detail::sci(d->worst_eps * eps / *coarse) + " in units of the coefficients' precision " +
                    detail::sci(*coarse) + ": within what they allow";
    }
    if (!d->within_rounding && d->exponent.used > 0)
      evidence += ", ~ h^" + detail::fixed(d->exponent.value, 1);
    evidence += "; ";
  }
  v.measured = !any ? "-" : !all_within_given ? "no" : all_within ? (by_fd ? "yes" : "to rounding") : "to the precision given";
  v.evidence = evidence;
  if (!claim) {
    v.result = outcome::not_declared;
  } else if (!any) {
    v.result = outcome::not_measured;
  } else if (*claim) {
    v.result = all_within ? outcome::confirmed : all_within_given ? outcome::to_precision_given : outcome::contradicted;
  } else if (!all_within_given) {
    v.result = outcome::confirmed;
  } else if (by_fd) {
    v.result = outcome::not_resolvable;
    v.needs = "a defect below the finite differences' resolution (" + detail::sci(coarsest) +
              ") cannot be told from none: the Jacobian by AD, or a larger step";
  } else if (!all_within) {
    v.result = outcome::not_resolvable;
    v.needs = "coefficients given to more digits: the defect lies within what coefficients given to " +
              detail::sci(*coarse) + " allow";
  } else if (eps > 1e-20) {
    v.result = outcome::not_resolvable;
    v.needs = "a tier with a lower rounding floor (-t mpfr50): the defect lies within this tier's rounding budget";
  } else {
    v.result = outcome::contradicted;  // a declared "no" states absence (docs/audit.md, "A declared no")
    v.evidence += "within the rounding budget on every problem measured, though declared not";
  }
  return v;
}

/// A declared energy behaviour against the growth class of the energy error in every long
/// run: "bounded" holds for a preserved or bounded energy, or a random walk within
/// rules::rounding_walk_budgets of the rounding budget (Brouwer's law); a linear drift or
/// faster, or an energy error of order one, contradicts it. "drift" holds for a drift and
/// is exceeded by a bounded energy.
inline verdict judge_energy(const claims& c, const std::vector<problem_audit>& ps) {
  using outcome = verdict::outcome;
  verdict v;
  v.claim = "energy";
  v.declared = !c.energy ? "-" : *c.energy == energy_behaviour::bounded ? "bounded" : "drift";
  bool any = false, bounded = true, drifts = false, undecided = false;
  std::string evidence, worst = "-";
  for (const auto& p : ps) {
    // The energy comes first where a problem has one (a model of a vector field may not).
    if (!p.skipped.empty() || !p.run || p.run->invariants.empty() || p.run->invariants.front().name != "energy")
      continue;
    const drift& e = p.run->invariants.front();
    if (!p.run->failure.empty()) {
      // A run cut short (a step that failed, a state that diverged) never reads as a
      // clearance: an error of order one before it stopped is lost, else it is undecided.
      any = true;
      bounded = false;
      evidence += p.problem + ": the long run stopped after " + std::to_string(p.run->steps) + " steps (" +
                  p.run->failure + "), its energy error up to " + detail::sci(e.max_relative) + "; ";
      if (!(e.max_relative < 0.25)) {
        drifts = true;
        worst = lost_class;
      } else {
        undecided = true;
        if (worst == "-" || worst.rfind("bounded", 0) == 0) worst = "cut short";
      }
      continue;
    }
    any = true;
    evidence += p.problem + ": " + e.kind + " (max " + detail::sci(e.max_relative) +
                (e.exponent ? ", t^" + detail::fixed(*e.exponent) : std::string()) + ", rounding budget " +
                detail::sci(e.budget_relative) + "); ";
    const bool kept = e.preserved || e.kind == "bounded";
    const bool rounding_walk = e.kind == "random walk" &&
                               e.max_relative <= rules::rounding_walk_budgets * e.budget_relative;
    const bool grows = e.kind == "linear drift" || e.kind == "faster than linear" || e.kind == lost_class;
    if (kept || rounding_walk) {
      if (worst == "-") worst = rounding_walk ? "bounded (rounding walks)" : "bounded";
    } else if (grows) {
      bounded = false;
      drifts = true;
      worst = e.kind;
    } else {
      undecided = true;  // a random walk above rounding, or no exponent resolved
      bounded = false;
      if (worst == "-" || worst.rfind("bounded", 0) == 0) worst = e.kind;
    }
  }
  v.measured = worst;
  v.evidence = evidence;
  if (!c.energy) {
    v.result = outcome::not_declared;
  } else if (!any) {
    v.result = outcome::not_measured;
  } else if (*c.energy == energy_behaviour::bounded) {
    v.result = bounded ? outcome::confirmed : drifts ? outcome::contradicted : outcome::not_resolvable;
  } else {
    v.result = drifts ? outcome::confirmed : bounded ? outcome::exceeds : outcome::not_resolvable;
  }
  if (v.result == outcome::not_resolvable)
    v.needs = "a growth class above rounding: a longer run, or a larger step";
  static_cast<void>(undecided);
  return v;
}

/// Where a stepper is a tableau (claims::algebra_decides), the algebra's verdict on a
/// claim stands and the measurement is quoted beside it; where it is a library's own
/// implementation of one (claims::algebra_refutes), the algebra's contradiction stands and
/// otherwise the measurement. Where the two differ, the evidence
/// says so and why the measurement did not decide: the algebra is exact arithmetic on the
/// coefficients at the precision they are given to, the measurement a fit or a defect on a
/// few problems in one tier, bounded by its floors.
inline verdict with_algebra(const verdict& measured, const claims& c) {
  using outcome = verdict::outcome;
  if (!c.algebra_decides && !c.algebra_refutes) return measured;
  const auto a = std::find_if(c.algebraic.begin(), c.algebraic.end(),
                              [&](const verdict& x) { return x.claim == measured.claim; });
  if (a == c.algebraic.end() || a->result == outcome::not_declared) return measured;
  if (!c.algebra_decides && a->result != outcome::contradicted) return measured;
  verdict v = *a;
  v.measured = a->measured + " (algebra)";
  // Confirmed and "to the precision given" say the same of a claim: the two agree.
  const auto holds = [](outcome o) { return o == outcome::confirmed || o == outcome::to_precision_given; };
  // "To the precision given" is the algebra's word for conditions that hold to the
  // coefficients' precision and no further. A measurement confirmed at the tier's own
  // floors did not resolve that precision (a defect of that size would have shown as a
  // stall or a defect above the floors, and judge_order would have said "to the precision
  // given"): it confirms the claim, and the algebra's residual is quoted beside it.
  if (a->result == outcome::to_precision_given && measured.result == outcome::confirmed) {
    v = measured;
    v.evidence = "measured: " + measured.evidence + " The coefficients' algebra: " + a->evidence +
                 " (to the precision given; the measurement does not resolve that precision)";
    return v;
  }
  const bool differ = a->result != measured.result && !(holds(a->result) && holds(measured.result));
  v.evidence = "the coefficients' algebra decides: " + a->evidence + ". The stepper measured: " +
               outcome_text(measured.result) + (measured.needs.empty() ? "" : " (needs " + measured.needs + ")") +
               ", measured " + measured.measured + " -- " + measured.evidence;
  if (differ)
    v.evidence += std::string(" The two differ: ") +
                  (measured.result == verdict::outcome::not_measured
                       ? "nothing was measured"
                       : "the measurement cannot resolve what the algebra decides exactly (its floors, its "
                         "problems' leading error terms, a fit over a finite range)");
  return v;
}

/// Every verdict of a stepper: order, symplectic, symmetric, energy (in that order).
inline std::vector<verdict> judge(const claims& declared, const std::vector<problem_audit>& ps,
                                  double eps) {
  return {with_algebra(judge_order(declared, ps, eps), declared),
          with_algebra(judge_property("symplectic", declared.symplectic, ps, &problem_audit::symplectic, eps,
                                      declared.coefficient_precision),
                       declared),
          with_algebra(judge_property("symmetric", declared.symmetric, ps, &problem_audit::symmetric, eps,
                                      declared.coefficient_precision),
                       declared),
          judge_energy(declared, ps)};
}

/// The embedded reading of an order (order_reading::embedded): the declared p read as the
/// order of the embedded formula, measured by the audit of the target's companion that
/// propagates that formula. When the first reading does not hold and the companion's order
/// verdict (declared p) is confirmed, `main`'s order verdict becomes a reading with both.
inline void apply_embedded_reading(stepper_audit& main, const stepper_audit& companion) {
  if (std::find(main.declared.order_readings.begin(), main.declared.order_readings.end(),
                order_reading::embedded) == main.declared.order_readings.end())
    return;
  for (auto& v : main.verdicts) {
    if (v.claim != "order" || !main.declared.order) continue;
    const verdict* e = companion.find("order");
    if (!e) return;
    if (v.result == verdict::outcome::confirmed || v.result == verdict::outcome::not_measured) return;
    const int p = *main.declared.order;
    const bool holds = e->result == verdict::outcome::confirmed && e->declared == std::to_string(p);
    if (!holds) return;
    v.readings = {{detail::reading_name(order_reading::global, p), v.measured, false},
                  {detail::reading_name(order_reading::embedded, p),
                   e->measured + " (" + companion.stepper + ")", true}};
    v.result = verdict::outcome::reading;
    v.evidence += "embedded formula (" + companion.stepper + "): " + e->evidence;
  }
}

}  // namespace mechcheck::audit
