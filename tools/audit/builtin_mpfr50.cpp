#include "mechcheck/audit/builtin.hpp"
#include "run_family.hpp"

namespace mechcheck::audit_tool {
family_result builtin_mpfr50(const request& r) {
  return run_family(audit::builtin_steppers<mpfr50>(), r);
}
}  // namespace mechcheck::audit_tool
