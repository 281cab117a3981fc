// GSL's one-step types as black boxes, in double (built where GSL is found).
#include "mechcheck/audit/steppers/black_box.hpp"
#include "mechcheck/audit/adapters/gsl.hpp"
#include "run_family.hpp"

namespace mechcheck::audit_tool {
family_result gsl_double(const request& r) {
  std::vector<audit::stepper_under_audit<double>> steppers;
  const double tolerance =
      r.newton_tolerance > 0 ? r.newton_tolerance : audit::gsl::default_newton_tolerance;
  for (const auto& box : audit::gsl::one_step_types(tolerance))
    steppers.push_back(audit::black_box_stepper(box));
  return run_family(steppers, r);
}
}  // namespace mechcheck::audit_tool
