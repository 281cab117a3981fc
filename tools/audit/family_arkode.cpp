// ARKODE's built-in Butcher tables: run by ARKODE at fixed steps (black boxes, double), and
// the same coefficients through mechcheck's Runge-Kutta stepper (double and mpfr50), named
// arkode::<table>/tableau (built where SUNDIALS is found).
#include "mechcheck/audit/arkode.hpp"
#include "mechcheck/audit/black_box.hpp"
#include "mechcheck/audit/tableau.hpp"
#include "run_family.hpp"

namespace mechcheck::audit_tool {
namespace {
template <class T>
std::vector<audit::stepper_under_audit<T>> tableau_steppers() {
  std::vector<audit::stepper_under_audit<T>> out;
  for (const auto& t : audit::arkode::tables())
    for (const bool embedding : {false, true}) {
      if (embedding && t.d.empty()) continue;
      butcher_tableau<double> tab{t.a, embedding ? t.d : t.b, t.c};
      audit::claims c;
      c.order = embedding ? t.p : t.q;
      out.push_back(audit::tableau_stepper<T>(
          "arkode::" + t.name + (embedding ? "/embedding" : "") + "/tableau", tab, c,
          "SUNDIALS " + audit::arkode::version() + " table " + t.name +
              " as ARKODE stores it (double), through mechcheck's Runge-Kutta stepper; " +
              (embedding ? "its embedding, declared order p" : "declared order q")));
    }
  return out;
}
}  // namespace

family_result arkode_double(const request& r) {
  std::vector<audit::stepper_under_audit<double>> steppers;
  const double tolerance =
      r.newton_tolerance > 0 ? r.newton_tolerance : audit::arkode::default_newton_tolerance;
  for (const auto& box : audit::arkode::steppers(audit::arkode::tables(), tolerance))
    steppers.push_back(audit::black_box_stepper(box));
  for (auto& s : tableau_steppers<double>()) steppers.push_back(std::move(s));
  return run_family(steppers, r);
}

family_result arkode_mpfr50(const request& r) { return run_family(tableau_steppers<mpfr50>(), r); }
}  // namespace mechcheck::audit_tool
