// Tableaus from files (--tableau FILE): each one's stepper through mechcheck's Runge-Kutta
// stepper, named tableau::<name> (and tableau::<name>/embedding for a file with bhat),
// declaring what the file declares; and the steppers of --exec-stepper children.
#include "mechcheck/audit/steppers/black_box.hpp"
#include "mechcheck/audit/tableaus/tableau.hpp"
#include "mechcheck/audit/tableaus/tableau_file.hpp"
#include "run_family.hpp"

namespace mechcheck::audit_tool {
namespace {
template <class T>
std::vector<audit::stepper_under_audit<T>> steppers_of(const std::vector<audit::tableau_file>& files) {
  std::vector<audit::stepper_under_audit<T>> out;
  for (const auto& f : files)
    for (auto& s : audit::tableau_file_steppers<T>(f)) out.push_back(std::move(s));
  return out;
}
}  // namespace

family_result tableau_double(const request& r) { return run_family(steppers_of<double>(r.tableaus), r); }
family_result exec_double(const request& r) {
  std::vector<audit::stepper_under_audit<double>> steppers;
  for (const auto& box : r.exec_steppers) steppers.push_back(audit::black_box_stepper(box));
  return run_family(steppers, r);
}
family_result tableau_mpfr50(const request& r) { return run_family(steppers_of<mpfr50>(r.tableaus), r); }
}  // namespace mechcheck::audit_tool
