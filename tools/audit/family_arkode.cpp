// ARKODE's built-in Butcher tables: run by ARKODE at fixed steps (black boxes, double), and
// the same coefficients through mechcheck's Runge-Kutta stepper (double and mpfr50), named
// arkode::<table>/tableau (built where SUNDIALS is found).
#include <map>
#include <mutex>
#include <string>

#include "mechcheck/audit/adapters/arkode.hpp"
#include "mechcheck/audit/steppers/black_box.hpp"
#include "mechcheck/audit/tableaus/tableau.hpp"
#include "mechcheck/audit/tableaus/tableau_file.hpp"
#include "run_family.hpp"

namespace mechcheck::audit_tool {
namespace {
/// ARKODE's tables are double (realtype), each coefficient a literal or an expression
/// evaluated in double: their claims hold to a few roundings of double, 16 ulps (2^-49
/// relative; KVAERNO_4_2_3's weights sum to 1 within 8), and their order conditions say to
/// what order they hold at that precision. Through mechcheck's stepper the algebra decides
/// (verdicts.hpp: with_algebra), as for a tableau file; in ARKODE's own runs its
/// contradiction stands, and otherwise the measurement (ARKODE's code could break what its
/// coefficients hold). A condition failing by 1e-12 sets an error floor that no run of the
/// audit's step range reaches in double: docs/findings/repro/arkode_dirk_weights.c measures
/// the same defects on the tables ARKODE loads, and the error they leave in ARKStep's runs.
/// The order conditions of a table (or its embedding) in mpfr100, evaluated once in the
/// process and only for a stepper the request selects (a table's analysis takes about 10 ms:
/// every table of ARKODE's at every start of the command took 1.3 s).
template <class R>
void add_stored_precision(audit::claims& c, const std::string& table, const butcher_tableau<R>& tab,
                          bool library_run) {
  static std::mutex mutex;
  static std::map<std::string, audit::order_condition_report<mpfr100>> analysed;
  const std::lock_guard<std::mutex> lock(mutex);
  auto it = analysed.find(table);
  if (it == analysed.end())
    it = analysed.emplace(table, audit::order_conditions(tab.template as<mpfr100>(), 10, 0x1p-49)).first;
  audit::add_algebraic_claims(c, it->second, "stored in double by ARKODE (realtype), within 16 ulps: 2^-49 relative");
  (library_run ? c.algebra_refutes : c.algebra_decides) = true;
}

template <class T>
std::vector<audit::stepper_under_audit<T>> tableau_steppers(const request& r) {
  std::vector<audit::stepper_under_audit<T>> out;
  for (const auto& t : audit::arkode::tables())
    for (const bool embedding : {false, true}) {
      if (embedding && t.d.empty()) continue;
      const std::string table = t.name + (embedding ? "/embedding" : "");
      butcher_tableau<double> tab{t.a, embedding ? t.d : t.b, t.c};
      audit::claims c;
      c.order = embedding ? t.p : t.q;
      if (!r.list_only && selected(r.patterns, "arkode::" + table + "/tableau")) add_stored_precision(c, table, tab, false);
      out.push_back(audit::tableau_stepper<T>(
          "arkode::" + t.name + (embedding ? "/embedding" : "") + "/tableau", tab, c,
          "SUNDIALS " + audit::arkode::version() + " table " + t.name +
              " as ARKODE stores it (double), through mechcheck's Runge-Kutta stepper; " +
              (embedding ? "its embedding, declared order p" : "declared order q")));
    }
  return out;
}
}  // namespace

family_result arkode_double(const request& r) {
  std::vector<audit::stepper_under_audit<double>> steppers;
  const double tolerance =
      r.newton_tolerance > 0 ? r.newton_tolerance : audit::arkode::default_newton_tolerance;
  const auto tables = audit::arkode::tables();
  for (auto box : audit::arkode::steppers(tables, tolerance)) {
    // The same table's order conditions: a contradiction of the coefficients, and the words
    // for an order measured above the declared one.
    if (!r.list_only && selected(r.patterns, box.name))
      for (const auto& t : tables)
        for (const bool embedding : {false, true})
          if (box.name == "arkode::" + t.name + (embedding ? "/embedding" : "") && (!embedding || !t.d.empty()))
            add_stored_precision(box.declared, t.name + (embedding ? "/embedding" : ""),
                                 butcher_tableau<double>{t.a, embedding ? t.d : t.b, t.c}, true);
    steppers.push_back(audit::black_box_stepper(box));
  }
  for (auto& s : tableau_steppers<double>(r)) steppers.push_back(std::move(s));
  return run_family(steppers, r);
}

family_result arkode_mpfr50(const request& r) { return run_family(tableau_steppers<mpfr50>(r), r); }
}  // namespace mechcheck::audit_tool
