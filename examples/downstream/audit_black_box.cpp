// A stepper behind a C call, audited as a black box: its step returns a status (C code
// cannot throw), it evaluates the problem through the ode_system callbacks the audit hands
// it, and the audit measures what it measures for any stepper (the symplectic condition by
// finite differences, with the resolution stated).
#include <iostream>
#include <vector>

#include <mechcheck/audit/steppers/black_box.hpp>
#include <mechcheck/audit/report.hpp>

namespace {
namespace audit = mechcheck::audit;

/// Classical RK4 on y' = f(t, y), in C style: 0 on success, the callback's status otherwise.
int rk4_step(double* y, double t, double h, void* ctx) {
  const audit::ode_system& ode = *static_cast<const audit::ode_system*>(ctx);
  const int n = ode.dimension;
  std::vector<double> k1(n), k2(n), k3(n), k4(n), z(n);
  const auto f = [&](double s, const double* x, double* out) { return ode.rhs(s, x, out, ode.self); };
  if (int rc = f(t, y, k1.data())) return rc;
  for (int i = 0; i < n; ++i) z[i] = y[i] + h / 2 * k1[i];
  if (int rc = f(t + h / 2, z.data(), k2.data())) return rc;
  for (int i = 0; i < n; ++i) z[i] = y[i] + h / 2 * k2[i];
  if (int rc = f(t + h / 2, z.data(), k3.data())) return rc;
  for (int i = 0; i < n; ++i) z[i] = y[i] + h * k3[i];
  if (int rc = f(t + h, z.data(), k4.data())) return rc;
  for (int i = 0; i < n; ++i) y[i] += h / 6 * (k1[i] + 2 * k2[i] + 2 * k3[i] + k4[i]);
  return 0;
}
}  // namespace

int main() {
  audit::black_box box;
  box.name = "my_c_rk4";
  box.origin = "examples/downstream/audit_black_box.cpp: classical RK4 behind a C call";
  box.declared.order = 4;
  box.declared.symplectic = false;
  box.create = [](const audit::ode_system& ode) -> void* { return new audit::ode_system(ode); };
  box.step_status = &rk4_step;
  box.destroy = [](void* ctx) { delete static_cast<audit::ode_system*>(ctx); };

  audit::audit_options options;
  options.problems = {"oscillator", "kepler_e0.5", "pendulum"};
  options.long_run_problems = {"kepler_e0.5"};
  options.long_run_steps = 10000;
  const audit::stepper_audit result = audit::audit_stepper(audit::black_box_stepper(box), options);
  audit::print_table(std::cout, {result});
  return result.claims_hold() ? 0 : 1;
}
