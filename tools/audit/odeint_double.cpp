#include "mechcheck/audit/odeint.hpp"
#include "run_family.hpp"

namespace mechcheck::audit_tool {
family_result odeint_double(const request& r) {
  return run_family(audit::odeint::all_steppers<double>(), r);
}
}  // namespace mechcheck::audit_tool
