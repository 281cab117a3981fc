#include "mechcheck/audit/odeint.hpp"
#include "run_family.hpp"

namespace mechcheck::audit_tool {
family_result odeint_mpfr50(const request& r) {
  return run_family(audit::odeint::all_steppers<mpfr50>(), r);
}
}  // namespace mechcheck::audit_tool
