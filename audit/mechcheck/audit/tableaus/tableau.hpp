#pragma once
/// A Butcher tableau under audit: the generic Runge-Kutta stepper
/// (integrators/runge_kutta.hpp) with given coefficients, in tier T and on AD scalars (so
/// that its symplectic condition is measured to rounding).

#include <memory>
#include <string>
#include <vector>

#include "mechcheck/audit/audit.hpp"
#include "mechcheck/audit/tableaus/tableau_file.hpp"
#include "mechcheck/integrators/runge_kutta.hpp"

namespace mechcheck::audit {

/// The stepper of `tableau` (coefficients in any real type R, converted to T) declaring
/// `declared`. Throws what butcher_tableau::validate throws for a malformed tableau.
template <class T, class R>
stepper_under_audit<T> tableau_stepper(std::string name, const butcher_tableau<R>& tableau,
                                       claims declared, std::string origin) {
  auto t = std::make_shared<const butcher_tableau<T>>(tableau.template as<T>());
  t->validate("tableau_stepper: " + name);
  stepper_under_audit<T> s;
  s.name = std::move(name);
  s.origin = std::move(origin);
  s.declared = declared;
  s.make = [t](const erased_system<T>& system) -> step_function<T> {
    auto m = std::make_shared<runge_kutta<erased_system<T>, dynamic_vector<T>>>(system, *t);
    return [m](state<T>& x, const T& h) { (*m)(x, h); };
  };
  s.make_ad = [t](const erased_system<T>& system) -> step_function<ad<T>> {
    auto m = std::make_shared<runge_kutta<erased_system<T>, dynamic_vector<ad<T>>>>(system, *t);
    return [m](state<ad<T>>& x, const ad<T>& h) { (*m)(x, h); };
  };
  return s;
}

/// The steppers of a tableau file (tableau_file.hpp), as `mechcheck-audit --tableau` audits
/// them: tableau::<name> declaring the file's order, symplecticity and symmetry, and, for a
/// file with `bhat`, tableau::<name>/embedding declaring its embedding_order (audit both and
/// pass the pair to apply_embedded_reading); each carries what its order conditions give at
/// the precision the coefficients are given to (add_algebraic_claims), and where that
/// algebra decides a claim its verdict stands beside the measurement.
template <class T>
std::vector<stepper_under_audit<T>> tableau_file_steppers(const tableau_file& f) {
  std::vector<stepper_under_audit<T>> out;
  for (const bool embedding : {false, true}) {
    if (embedding && f.bhat.empty()) continue;
    butcher_tableau<mpfr100> t = f.tableau;
    if (embedding) t.b = f.bhat;
    claims c;
    c.order = embedding ? f.embedding_order : f.order;
    if (!embedding) {
      c.symplectic = f.symplectic;
      c.symmetric = f.symmetric;
    }
    add_algebraic_claims(c, order_conditions(t, orders_to_evaluate(f), f.precision), f.precision_words);
    // The stepper is the file's tableau: what its algebra decides, it decides (verdicts.hpp).
    c.algebra_decides = true;
    out.push_back(tableau_stepper<T>("tableau::" + f.name + (embedding ? "/embedding" : ""), t, c,
                                     f.path + (f.source.empty() ? "" : " (" + f.source + ")") +
                                         (embedding ? ", its embedding bhat" : "")));
  }
  return out;
}

}  // namespace mechcheck::audit
