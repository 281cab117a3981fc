// Black-box steppers: the library's own steppers behind the C call get the symplectic
// verdicts their methods deserve from finite differences, with the resolution stated; the
// finite-difference error model bounds the true error (against AD); bad input and failing
// steps are typed errors.

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "mechcheck/audit/audit.hpp"
#include "mechcheck/audit/steppers/black_box.hpp"
#include "mechcheck/audit/finite_differences.hpp"
#include "mechcheck/audit/tableaus/tableau.hpp"
#include "mechcheck/integrators.hpp"

namespace black_box_test {
using namespace mechcheck;
namespace audit = mechcheck::audit;
using outcome = audit::verdict::outcome;

template <class S, class V>
using gauss_legendre2 = gauss_legendre<S, V, 2>;

audit::audit_options quick() {
  audit::audit_options opt;
  opt.problems = {"oscillator", "kepler_e0.5", "pendulum"};
  opt.long_run_steps = 0;
  opt.timing = false;
  return opt;
}

template <template <class, class> class Method>
audit::stepper_audit black_box_audit(const char* name) {
  return audit::audit_stepper(
      audit::black_box_stepper(audit::library_stepper_as_black_box<Method>(name)), quick());
}

void expect(const audit::stepper_audit& a, const char* claim, outcome o) {
  const audit::verdict* v = a.find(claim);
  ASSERT_NE(v, nullptr) << claim;
  EXPECT_EQ(v->result, o) << a.stepper << " " << claim << ": declared " << v->declared
                          << ", measured " << v->measured << "; " << v->evidence;
}

TEST(black_box, symplectic_methods_show_no_defect_above_the_resolution) {
  for (const auto& a : {black_box_audit<stormer_verlet>("verlet (black box)"),
                        black_box_audit<symplectic_euler>("symplectic Euler (black box)"),
                        black_box_audit<gauss_legendre2>("Gauss-Legendre 2 (black box)")}) {
    expect(a, "symplectic", outcome::confirmed);
    expect(a, "order", outcome::confirmed);
    for (const auto& p : a.problems) {
      ASSERT_TRUE(p.symplectic) << a.stepper << " " << p.problem;
      EXPECT_TRUE(p.symplectic->within_rounding) << a.stepper << " " << p.problem;
      // The resolution the error model gives: ~1e-11 on these unit-scale problems.
      EXPECT_GT(p.symplectic->resolution, 0) << a.stepper;
      EXPECT_LT(p.symplectic->resolution, 1e-9) << a.stepper << " " << p.problem;
      EXPECT_NE(a.find("symplectic")->evidence.find("no defect above"), std::string::npos);
      if (p.problem == "pendulum") {  // one degree of freedom: the area too
        ASSERT_TRUE(p.symplectic->area_defect);
        EXPECT_LE(std::abs(*p.symplectic->area_defect), *p.symplectic->area_resolution)
            << a.stepper;
      }
    }
  }
}

TEST(black_box, rk4_and_explicit_euler_are_not_symplectic) {
  for (const auto& a : {black_box_audit<rk4>("rk4 (black box)"),
                        black_box_audit<explicit_euler>("explicit Euler (black box)")}) {
    expect(a, "symplectic", outcome::confirmed);  // declared false, measured a defect
    for (const auto& p : a.problems) {
      ASSERT_TRUE(p.symplectic);
      EXPECT_FALSE(p.symplectic->within_rounding) << a.stepper << " " << p.problem;
      EXPECT_GT(p.symplectic->worst_relative, 10 * p.symplectic->resolution);
    }
  }
  // Euler's defect h^2 A J A^T (as with AD), RK4's at least h^5.
  const auto euler = black_box_audit<explicit_euler>("explicit Euler (black box)");
  for (const auto& p : euler.problems) EXPECT_NEAR(p.symplectic->exponent.value, 2.0, 0.15) << p.problem;
  const auto pendulum = euler.problems.back();
  ASSERT_TRUE(pendulum.symplectic->area_defect);
  EXPECT_GT(std::abs(*pendulum.symplectic->area_defect), 100 * *pendulum.symplectic->area_resolution);
}

TEST(black_box, a_symplectic_euler_black_box_runs_only_where_it_applies_and_its_claims_hold) {
  // The default audit's problems (all six) and a long run on Kepler e = 0.5. The box takes
  // its velocity and force from the right-hand side's q and p parts: it declares that it
  // needs a canonical, separable problem, and the twist (non-separable) and the free top
  // (not canonical) are skipped with the reason.
  audit::audit_options opt;
  opt.long_run_problems = {"kepler_e0.5"};
  opt.long_run_steps = 20000;
  opt.timing = false;
  const audit::black_box box = audit::library_stepper_as_black_box<symplectic_euler>("symplectic Euler");
  ASSERT_TRUE(box.structure.canonical && box.structure.separable);
  const auto a = audit::audit_stepper(audit::black_box_stepper(box), opt);
  EXPECT_TRUE(a.claims_hold());
  for (const auto& v : a.verdicts)
    if (v.result != outcome::not_declared)
      EXPECT_EQ(v.result, outcome::confirmed) << v.claim << ": " << v.evidence;
  int skipped = 0;
  for (const auto& p : a.problems)
    if (!p.skipped.empty()) {
      ++skipped;
      EXPECT_TRUE(p.problem == "twist" || p.problem == "free_top") << p.problem;
      EXPECT_NE(p.skipped.find("(declared)"), std::string::npos) << p.skipped;
    }
  EXPECT_EQ(skipped, 2);
  // The wrong variant: the same box without its structure is run on the twist, where the
  // right-hand side's parts are not velocity and force, and its order is contradicted.
  audit::black_box undeclared = box;
  undeclared.structure = {};
  audit::audit_options twist = opt;
  twist.problems = {"twist"};
  twist.long_run_problems = {};
  twist.long_run_steps = 0;
  const auto b = audit::audit_stepper(audit::black_box_stepper(undeclared), twist);
  EXPECT_FALSE(b.claims_hold());
}

TEST(black_box, a_black_box_keeps_the_verdicts_of_its_method_run_directly) {
  const auto direct = audit::audit_stepper(audit::method<rk4, double>("rk4"), quick());
  const auto boxed = black_box_audit<rk4>("rk4 (black box)");
  for (const char* claim : {"order", "symplectic", "symmetric"})
    EXPECT_EQ(direct.find(claim)->result, boxed.find(claim)->result) << claim;
  for (std::size_t i = 0; i < direct.problems.size(); ++i)
    EXPECT_EQ(direct.problems[i].global.points.size(), boxed.problems[i].global.points.size());
}

TEST(finite_differences, the_error_model_bounds_the_true_error) {
  // Against the AD Jacobian of the same step: every entry within its stated error, and
  // the stated error not vacuous (below 1e-9 on these problems).
  const auto problems = audit::reference_problems<double>();
  for (const auto& pr : {problems[0], problems[1], problems[3]}) {
    const Eigen::Index n = pr.initial.q.size();
    dynamic_vector<double> z(2 * n);
    z << pr.initial.q, pr.initial.p;
    const double h = pr.h_local;
    const std::function<dynamic_vector<double>(const dynamic_vector<double>&)> map =
        [&](const dynamic_vector<double>& w) {
          phase_state<dynamic_vector<double>> x{w.head(n), w.tail(n)};
          rk4<audit::erased_system<double>, dynamic_vector<double>>{pr.system}(x, h);
          dynamic_vector<double> out(2 * n);
          out << x.q, x.p;
          return out;
        };
    const auto fd = audit::finite_difference_jacobian<double>(map, z, 4 * 5);
    const auto make = [&pr]<class S>() {
      return rk4<audit::erased_system<double>, dynamic_vector<S>>{pr.system};
    };
    const dynamic_matrix<double> exact = audit::step_jacobian_of(make, z, h, n);
    for (Eigen::Index i = 0; i < exact.rows(); ++i)
      for (Eigen::Index j = 0; j < exact.cols(); ++j) {
        EXPECT_LE(std::abs(fd.value(i, j) - exact(i, j)), fd.error(i, j))
            << pr.name << " (" << i << "," << j << ")";
        EXPECT_LT(fd.error(i, j), 1e-9) << pr.name;
      }
  }
}

/// A C step function that does nothing but set y[0] to NaN.
void nan_step(double* y, double, double, void*) { y[0] = std::numeric_limits<double>::quiet_NaN(); }

TEST(black_box, bad_input_and_failing_steps_are_typed_errors) {
  audit::black_box none;
  none.name = "no step";
  EXPECT_THROW(audit::black_box_stepper(none), domain_error);
  audit::black_box unnamed = audit::library_stepper_as_black_box<rk4>("x");
  unnamed.name.clear();
  EXPECT_THROW(audit::black_box_stepper(unnamed), domain_error);

  const auto pr = audit::oscillator_problem<double>();
  auto step = audit::black_box_stepper(audit::library_stepper_as_black_box<rk4>("rk4")).make(pr.system);
  audit::state<double> x = pr.initial;
  EXPECT_THROW(step(x, 0.0), non_finite_error);
  EXPECT_THROW(step(x, std::nan("")), non_finite_error);
  x.q(0) = std::numeric_limits<double>::infinity();
  EXPECT_THROW(step(x, 0.1), non_finite_error);

  audit::black_box broken;
  broken.name = "nan step";
  broken.step = &nan_step;
  auto bad = audit::black_box_stepper(broken).make(pr.system);
  audit::state<double> y = pr.initial;
  try {
    bad(y, 0.1);
    bad(y, 0.1);
    FAIL() << "no error";
  } catch (const non_finite_error& e) {
    EXPECT_NE(std::string(e.what()).find("nan step: diverged at step 1 at t = 0"), std::string::npos) << e.what();
  }
  // A failing step becomes failed runs in the audit, not a crash, and never a skip (a
  // skip is a problem the method declares it cannot run): every study fails, every claim
  // reads "not measured".
  const auto a = audit::audit_stepper(audit::black_box_stepper(broken), quick());
  for (const auto& p : a.problems) {
    EXPECT_TRUE(p.skipped.empty()) << p.problem;
    ASSERT_FALSE(p.failures.empty()) << p.problem;
    EXPECT_NE(p.failures.front().find("the first step"), std::string::npos) << p.failures.front();
    EXPECT_EQ(p.global.fit.used, 0);
  }
  for (const auto& v : a.verdicts) EXPECT_NE(v.result, outcome::contradicted) << v.claim;
}

/// Velocity Verlet in C that takes its halves from ode_system's velocity and force (the
/// calling convention of a splitting method): one force a step after the first, as the
/// library's stormer_verlet counts.
int c_verlet(double* y, double, double h, void* ctx) {
  const auto& ode = *static_cast<const audit::ode_system*>(ctx);
  const int nq = ode.nq, np = ode.dimension - ode.nq;
  std::vector<double> f(static_cast<std::size_t>(np)), v(static_cast<std::size_t>(nq));
  if (!ode.force || ode.force(0, y, f.data(), ode.self) != 0) return 7;
  for (int i = 0; i < np; ++i) y[nq + i] += h / 2 * f[std::size_t(i)];
  if (ode.velocity(0, y + nq, v.data(), ode.self) != 0) return 8;
  for (int i = 0; i < nq; ++i) y[i] += h * v[std::size_t(i)];
  if (ode.force(0, y, f.data(), ode.self) != 0) return 7;
  for (int i = 0; i < np; ++i) y[nq + i] += h / 2 * f[std::size_t(i)];
  return 0;
}

audit::black_box c_verlet_box() {
  audit::black_box b;
  b.name = "c_verlet";
  b.declared.order = 2;
  b.structure = {true, true};
  b.create = [](const audit::ode_system& ode) -> void* { return new audit::ode_system(ode); };
  b.step_status = &c_verlet;
  b.destroy = [](void* ctx) { delete static_cast<audit::ode_system*>(ctx); };
  return b;
}

TEST(black_box, a_splitting_method_in_c_takes_its_force_apart_and_is_counted_as_the_library_counts) {
  audit::audit_options opt = quick();
  opt.problems = {"kepler_e0.5", "pendulum"};
  const auto boxed = audit::audit_stepper(audit::black_box_stepper(c_verlet_box()), opt);
  const auto library = audit::audit_stepper(audit::method<stormer_verlet, double>("stormer_verlet"), opt);
  ASSERT_EQ(boxed.problems.size(), library.problems.size());
  for (std::size_t i = 0; i < boxed.problems.size(); ++i) {
    // Two forces a step (the box does not reuse the last one), one for the library's FSAL
    // Verlet: the force calls are what is counted, not the whole right-hand side's 3.
    EXPECT_EQ(boxed.problems[i].evaluations_per_step, 2.0) << boxed.problems[i].problem;
    EXPECT_LE(library.problems[i].evaluations_per_step, 2.0) << library.problems[i].problem;
  }
  expect(boxed, "order", outcome::confirmed);
}

TEST(black_box, a_c_step_reports_failure_by_its_status_and_the_run_ends_there_named) {
  audit::black_box b = c_verlet_box();
  b.step_status = [](double*, double, double, void*) { return 42; };
  const auto stepper = audit::black_box_stepper(b);
  const auto problems = audit::reference_problems<double>();
  const auto& pr = problems.front();
  auto step = stepper.make(pr.system);
  audit::state<double> x = pr.initial;
  try {
    step(x, 0.125);
    ADD_FAILURE() << "a step returning 42 was taken";
  } catch (const convergence_error& e) {
    EXPECT_NE(std::string(e.what()).find("c_verlet: step 1 at t = 0, h = 0.125 returned status 42"), std::string::npos)
        << e.what();
  }
  // One step function, not two, not none.
  audit::black_box both = c_verlet_box();
  both.step = [](double*, double, double, void*) {};
  EXPECT_THROW(audit::black_box_stepper(both), domain_error);
}

}  // namespace black_box_test
