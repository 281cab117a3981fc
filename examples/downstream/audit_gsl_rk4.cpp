// Audit a library's stepper through an adapter installed with mechcheck: GSL's rk4, from the
// package's gsl component (find_package(mechcheck COMPONENTS gsl): mechcheck::audit_gsl).
#include <iostream>

#include <mechcheck/audit/adapters/gsl.hpp>
#include <mechcheck/audit/audit.hpp>
#include <mechcheck/audit/report.hpp>

int main() {
  namespace audit = mechcheck::audit;
  for (const audit::black_box& box : audit::gsl::one_step_types()) {
    if (box.name != "gsl::rk4") continue;
    audit::audit_options options;
    options.problems = {"oscillator", "kepler_e0.5"};
    options.long_run_steps = 10000;
    const audit::stepper_audit result =
        audit::audit_stepper(audit::black_box_stepper(box), audit::reference_problems<double>(), options);
    audit::print_table(std::cout, {result});
    std::cout << "GSL " << audit::gsl::version() << ": " << box.origin << "\n";
    return result.claims_hold() ? 0 : 1;
  }
  std::cerr << "audit_gsl_rk4: GSL has no rk4\n";
  return 1;
}
