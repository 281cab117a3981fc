// The two families of mechcheck-audit in double: one translation unit, since they share the
// audit's instantiations in the tier (25 s of compiler time against 42-46 s for two).
#include "mechcheck/audit/steppers/builtin.hpp"
#include "mechcheck/audit/adapters/odeint.hpp"
#include "run_family.hpp"

namespace mechcheck::audit_tool {
family_result builtin_double(const request& r) {
  return run_family(audit::builtin_steppers<double>(), r);
}
family_result odeint_double(const request& r) {
  return run_family(audit::odeint::all_steppers<double>(), r);
}
}  // namespace mechcheck::audit_tool
