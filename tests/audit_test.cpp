// The audit catches broken steppers: each deliberately broken variant below declares
// what the correct method declares (or more), and the matching claim must come out
// contradicted; the correct methods' claims must be confirmed.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <iostream>
#include <string>

#include "mechcheck/audit/audit.hpp"
#include "mechcheck/audit/report.hpp"
#include "mechcheck/integrators/steppers.hpp"

// A named namespace, not an anonymous one: the audit stores these types in closures of
// its (external) templates, and in the unity build GCC warns about anonymous types there.
namespace audit_test {
using namespace mechcheck;
namespace audit = mechcheck::audit;
using outcome = audit::verdict::outcome;

/// Kick-drift-kick with kick weights a and 1 - a (a = 1/2: Stormer-Verlet), the force's
/// sign `sign` (-1: the wrong sign), declaring Verlet's claims or `Order`.
template <class System, class Vec, int Order, int WeightNumerator, int Sign>
struct kick_drift_kick {
  static constexpr int order = Order;
  static constexpr bool symplectic = true;
  static constexpr bool symmetric = true;
  System system;
  void operator()(phase_state<Vec>& x, const typename Vec::Scalar& h) const {
    using S = typename Vec::Scalar;
    const S a = lift<S>(real_type_t<S>(WeightNumerator) / 64);
    const S first = a * h, second = (1 - a) * h;
    Vec f = x.q, v = x.p;
    system.force(x.q, f);
    x.p += Sign * first * f;
    system.velocity(x.p, v);
    x.q += h * v;
    system.force(x.q, f);
    x.p += Sign * second * f;
  }
};

template <class S, class V>
using verlet_as_declared = kick_drift_kick<S, V, 2, 32, 1>;
template <class S, class V>
using perturbed_weight = kick_drift_kick<S, V, 2, 33, 1>;  // kicks 33/64 and 31/64
template <class S, class V>
using wrong_sign = kick_drift_kick<S, V, 2, 32, -1>;
template <class S, class V>
using verlet_declaring_order_4 = kick_drift_kick<S, V, 4, 32, 1>;

/// RK4 with a swapped stage: the last stage is taken from k2 instead of k3.
template <class System, class Vec>
struct rk4_swapped_stage {
  static constexpr int order = 4;
  static constexpr bool symplectic = false;
  static constexpr bool symmetric = false;
  System system;
  void operator()(phase_state<Vec>& x, const typename Vec::Scalar& h) const {
    using S = typename Vec::Scalar;
    const S half_h = h / 2;
    Vec k1q = x.q, k1p = x.p, k2q = x.q, k2p = x.p, k3q = x.q, k3p = x.p, k4q = x.q, k4p = x.p;
    system.vector_field(x.q, x.p, k1q, k1p);
    system.vector_field(Vec(x.q + half_h * k1q), Vec(x.p + half_h * k1p), k2q, k2p);
    system.vector_field(Vec(x.q + half_h * k2q), Vec(x.p + half_h * k2p), k3q, k3p);
    system.vector_field(Vec(x.q + h * k2q), Vec(x.p + h * k2p), k4q, k4p);  // k2, not k3
    x.q += h / 6 * (k1q + 2 * k2q + 2 * k3q + k4q);
    x.p += h / 6 * (k1p + 2 * k2p + 2 * k3p + k4p);
  }
};

/// Classical RK4 declaring symplectic and symmetric.
template <class System, class Vec>
struct rk4_declaring_symplectic : rk4<System, Vec> {
  static constexpr bool symplectic = true;
  static constexpr bool symmetric = true;
};

/// The triple jump (Yoshida) with its weights rounded to double, declaring order 4. In
/// double it is order 4; in mpfr50 its order conditions fail at ~1e-17 and the one-step
/// error shows h^3 below h ~ 1e-8.
template <class System, class Vec>
struct triple_jump_double_weights {
  static constexpr int order = 4;
  static constexpr bool symplectic = true;
  static constexpr bool symmetric = true;
  System system;
  void operator()(phase_state<Vec>& x, const typename Vec::Scalar& h) const {
    using S = typename Vec::Scalar;
    const double w1d = 1 / (2 - std::cbrt(2.0));
    const S w1 = lift<S>(real_type_t<S>(w1d));
    const S w0 = 1 - 2 * w1;  // consistent: the weights sum to one in the tier
    const S ws[3] = {w1, w0, w1};
    for (const S& w : ws) {
      Vec f = x.q, v = x.p;
      system.force(x.q, f);
      x.p += (w * h / 2) * f;
      system.velocity(x.p, v);
      x.q += (w * h) * v;
      system.force(x.q, f);
      x.p += (w * h / 2) * f;
    }
  }
};

/// Kutta's third-order method (c = 0, 1/2, 1; a21 = 1/2, a31 = -1, a32 = 2; b = 1/6, 2/3,
/// 1/6) with b1 off by WeightError * 1e-12: the weights sum to 1 + that, so the method
/// converges to the flow of (1 + WeightError * 1e-12) times the vector field, not to the
/// solution.
template <class System, class Vec, int WeightError>
struct kutta3 {
  static constexpr int order = 3;
  static constexpr bool symplectic = false;
  static constexpr bool symmetric = false;
  System system;
  void operator()(phase_state<Vec>& x, const typename Vec::Scalar& h) const {
    using S = typename Vec::Scalar;
    using R = real_type_t<S>;
    const S b1 = lift<S>(R(1) / 6 + R(WeightError) / R(1e12)), b2 = lift<S>(R(2) / 3),
            b3 = lift<S>(R(1) / 6);
    Vec k1q = x.q, k1p = x.p, k2q = x.q, k2p = x.p, k3q = x.q, k3p = x.p;
    system.vector_field(x.q, x.p, k1q, k1p);
    system.vector_field(Vec(x.q + h / 2 * k1q), Vec(x.p + h / 2 * k1p), k2q, k2p);
    system.vector_field(Vec(x.q + h * (2 * k2q - k1q)), Vec(x.p + h * (2 * k2p - k1p)), k3q,
                        k3p);
    x.q += h * (b1 * k1q + b2 * k2q + b3 * k3q);
    x.p += h * (b1 * k1p + b2 * k2p + b3 * k3p);
  }
};
template <class S, class V>
using kutta3_exact = kutta3<S, V, 0>;
template <class S, class V>
using kutta3_off_1e11 = kutta3<S, V, 10>;

template <class T>
audit::audit_options quick() {
  audit::audit_options opt;
  opt.problems = {"oscillator", "kepler_e0.5"};
  opt.long_run_steps = 0;
  opt.timing = false;
  return opt;
}

template <template <class, class> class Method, class T = double>
audit::stepper_audit audit_of(const char* name) {
  return audit::audit_stepper(audit::method<Method, T>(name), quick<T>());
}

void expect(const audit::stepper_audit& a, const char* claim, outcome o) {
  const audit::verdict* v = a.find(claim);
  ASSERT_NE(v, nullptr) << claim;
  EXPECT_EQ(v->result, o) << a.stepper << " [" << a.tier << "] " << claim << ": declared "
                          << v->declared << ", measured " << v->measured << "; "
                          << v->evidence;
}

TEST(Audit, ConfirmsStormerVerlet) {
  const auto a = audit_of<verlet_as_declared>("verlet");
  expect(a, "order", outcome::confirmed);
  expect(a, "symplectic", outcome::confirmed);
  expect(a, "symmetric", outcome::confirmed);
  EXPECT_TRUE(a.claims_hold());
  for (const auto& p : a.problems) {
    // Rounding budgets: 16 (m + 1) 2n eps for the symplectic defect of a step of m = 2
    // evaluations on n = 2 degrees of freedom, 16 (2m + 1) eps for the symmetry defect.
    ASSERT_TRUE(p.symplectic && p.symmetric);
    EXPECT_EQ(p.evaluations_per_step, 2) << p.problem;
    EXPECT_EQ(p.symplectic->budget_eps, 16.0 * 3 * 4) << p.problem;
    EXPECT_EQ(p.symmetric->budget_eps, 16.0 * 5) << p.problem;
    // The local study stops at its floor 16 eps m: every run before the last is above it.
    for (std::size_t i = 0; i + 1 < p.local.points.size(); ++i)
      EXPECT_GE(p.local.points[i].error, 16 * 0x1p-52 * p.local.points[i].evaluations)
          << p.problem << " h = " << p.local.points[i].h;
  }
}

TEST(Audit, PerturbedWeightContradictsOrderAndSymmetry) {
  const auto a = audit_of<perturbed_weight>("perturbed weight");
  expect(a, "order", outcome::contradicted);
  expect(a, "symmetric", outcome::contradicted);
  expect(a, "symplectic", outcome::confirmed);  // still a composition of symplectic maps
}

TEST(Audit, WrongSignContradictsOrder) {
  const auto a = audit_of<wrong_sign>("wrong sign");
  expect(a, "order", outcome::contradicted);
}

TEST(Audit, OverclaimedOrderIsContradicted) {
  const auto a = audit_of<verlet_declaring_order_4>("verlet declaring 4");
  expect(a, "order", outcome::contradicted);
  EXPECT_NEAR(std::stod(a.find("order")->measured), 2.0, 0.1);
}

TEST(Audit, SwappedStageContradictsOrder) {
  const auto a = audit_of<rk4_swapped_stage>("rk4 swapped stage");
  expect(a, "order", outcome::contradicted);
}

TEST(Audit, RungeKuttaIsNotSymplecticNorSymmetric) {
  const auto a = audit_of<rk4_declaring_symplectic>("rk4 declaring symplectic");
  expect(a, "order", outcome::confirmed);
  expect(a, "symplectic", outcome::contradicted);
  expect(a, "symmetric", outcome::contradicted);
  // The defects' powers of h. Step(-h) after step(h) differs from the identity by
  // C h^5 + C (-h)^5 + O(h^6) = O(h^6) for any method of even order 4. M J M^T - J is
  // O(h^5) at least (M agrees with the exact, symplectic Jacobian to O(h^5)); on these
  // problems it is measured as h^6 (the oscillator: |R(ih)|^2 = 1 - h^6/72 + ...).
  for (const auto& p : a.problems) {
    ASSERT_TRUE(p.symplectic && p.symmetric) << p.problem;
    EXPECT_NEAR(p.symmetric->exponent.value, 6.0, 0.3) << p.problem;
    EXPECT_GE(p.symplectic->exponent.value, 4.7) << p.problem;
  }
}

TEST(Audit, ExplicitEulerSymplecticDefectIsQuadraticInH) {
  // M = I + h A with A J + J A^T = 0 for a Hamiltonian A: M J M^T - J = h^2 A J A^T.
  const auto a = audit_of<explicit_euler>("explicit_euler");
  expect(a, "symplectic", outcome::confirmed);
  for (const auto& p : a.problems) {
    ASSERT_TRUE(p.symplectic && !p.symplectic->within_rounding) << p.problem;
    EXPECT_NEAR(p.symplectic->exponent.value, 2.0, 0.1) << p.problem;
  }
}

TEST(Audit, DoubleRoundedCoefficientsPassInDoubleFailInMpfr50) {
  const auto d = audit_of<triple_jump_double_weights, double>("triple jump, double weights");
  expect(d, "order", outcome::confirmed);
  const auto m = audit_of<triple_jump_double_weights, mpfr50>("triple jump, double weights");
  expect(m, "order", outcome::contradicted);
}

TEST(Audit, AWeightOffBy1e11StallsAboveTheFloorInDouble) {
  audit::audit_options opt = quick<double>();
  opt.problems.clear();  // every problem
  const auto good = audit::audit_stepper(audit::method<kutta3_exact, double>("kutta3"), opt);
  expect(good, "order", outcome::confirmed);
  for (const auto& p : good.problems) EXPECT_FALSE(p.global.stalled) << p.problem;
  const auto bad = audit::audit_stepper(audit::method<kutta3_off_1e11, double>("kutta3 1e-11"), opt);
  expect(bad, "order", outcome::contradicted);
  EXPECT_EQ(bad.find("order")->measured, "stalls");
  int stalled = 0;
  for (const auto& p : bad.problems) {
    if (!p.global.stalled) continue;
    ++stalled;
    const audit::stall& s = *p.global.stalled;
    // The limit is ~1e-11 t |f| / |x| away: between 1e-12 and 1e-10, far above the floor.
    EXPECT_GT(s.error, 1e-12) << p.problem;
    EXPECT_LT(s.error, 1e-10) << p.problem;
    EXPECT_GE(s.margin, audit::floor_margin) << p.problem;
    EXPECT_GE(s.error, audit::stall_ratio * s.change) << p.problem;
  }
  EXPECT_GE(stalled, 1);
  EXPECT_NE(bad.find("order")->evidence.find("not to 0"), std::string::npos)
      << bad.find("order")->evidence;
  if (std::getenv("MECHCHECK_SHOW")) {
    std::cout << bad.find("order")->evidence << "\n";
    for (const auto& p : bad.problems)
      for (const auto& pt : p.global.points)
        std::cout << p.problem << " " << pt.h << " " << pt.error << " " << pt.change << " " << pt.evaluations << "\n";
  }
}

TEST(Audit, RefusesUnknownProblemsAndBadOptions) {
  auto opt = quick<double>();
  opt.problems = {"kepler_e0.7"};
  EXPECT_THROW(audit::audit_stepper(audit::method<verlet_as_declared, double>("v"), opt),
               domain_error);
  opt = quick<double>();
  opt.long_run_steps = -1;
  EXPECT_THROW(audit::audit_stepper(audit::method<verlet_as_declared, double>("v"), opt),
               domain_error);
}

TEST(Audit, ReportIsDeterministicWithoutTiming) {
  const auto a = audit_of<verlet_as_declared>("verlet");
  const auto b = audit_of<verlet_as_declared>("verlet");
  EXPECT_EQ(audit::to_json({a}), audit::to_json({b}));
  EXPECT_EQ(audit::to_markdown({a}), audit::to_markdown({b}));
  EXPECT_NE(audit::to_json({a}).find("\"claims_hold\": true"), std::string::npos);
}

}  // namespace audit_test
