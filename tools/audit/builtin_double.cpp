#include "mechcheck/audit/builtin.hpp"
#include "run_family.hpp"

namespace mechcheck::audit_tool {
family_result builtin_double(const request& r) {
  return run_family(audit::builtin_steppers<double>(), r);
}
}  // namespace mechcheck::audit_tool
