// The two families of mechcheck-audit in mpfr50: one translation unit, since they share the
// audit's instantiations in the tier (25 s of compiler time against 42-46 s for two).
#include "mechcheck/audit/steppers/builtin.hpp"
#include "mechcheck/audit/adapters/odeint.hpp"
#include "run_family.hpp"

namespace mechcheck::audit_tool {
family_result builtin_mpfr50(const request& r) {
  return run_family(audit::builtin_steppers<mpfr50>(), r);
}
family_result odeint_mpfr50(const request& r) {
  return run_family(audit::odeint::all_steppers<mpfr50>(), r);
}
}  // namespace mechcheck::audit_tool
