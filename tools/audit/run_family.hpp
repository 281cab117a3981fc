#pragma once
// Runs the audits of one family in one tier (included by the family translation units).

#include "families.hpp"
#include "patterns.hpp"
#include "mechcheck/audit/audit.hpp"
#include "mechcheck/audit/problems/classic.hpp"

namespace mechcheck::audit_tool {

template <class T>
family_result run_family(const std::vector<audit::stepper_under_audit<T>>& steppers,
                         const request& r) {
  family_result out;
  // The classic problems named (-p, --long-run-problem) join the exact ones; their
  // references are shared by every family in the process and cached on disk.
  std::vector<std::string> named = r.options.problems;
  named.insert(named.end(), r.options.long_run_problems.begin(), r.options.long_run_problems.end());
  audit::reference_settings settings;
  settings.progress = r.options.progress;
  const auto problems = audit::problems_named<T>(named, settings);
  for (const auto& s : steppers) {
    if (!selected(r.patterns, s.name)) continue;
    out.names.push_back(s.name);
    if (!r.list_only) out.audits.push_back(audit::audit_stepper(s, problems, r.options));
  }
  for (auto& a : out.audits)
    for (const auto& c : out.audits)
      if (c.stepper == a.stepper + "/embedding" && c.tier == a.tier) audit::apply_embedded_reading(a, c);
  return out;
}

}  // namespace mechcheck::audit_tool
