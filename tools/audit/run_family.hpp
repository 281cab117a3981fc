#pragma once
// Runs the audits of one family in one tier (included by the family translation units).

#include <fnmatch.h>

#include "families.hpp"
#include "mechcheck/audit/audit.hpp"

namespace mechcheck::audit_tool {

inline bool matches(const std::vector<std::string>& patterns, const std::string& name) {
  if (patterns.empty()) return true;
  for (const auto& p : patterns)
    if (fnmatch(p.c_str(), name.c_str(), 0) == 0) return true;
  return false;
}

template <class T>
family_result run_family(const std::vector<audit::stepper_under_audit<T>>& steppers,
                         const request& r) {
  family_result out;
  const auto problems = audit::reference_problems<T>();
  for (const auto& s : steppers) {
    if (!matches(r.patterns, s.name)) continue;
    out.names.push_back(s.name);
    if (!r.list_only) out.audits.push_back(audit::audit_stepper(s, problems, r.options));
  }
  return out;
}

}  // namespace mechcheck::audit_tool
