#pragma once
/// A Butcher tableau under audit: the generic Runge-Kutta stepper
/// (integrators/runge_kutta.hpp) with given coefficients, in tier T and on AD scalars (so
/// that its symplectic condition is measured to rounding).

#include <memory>
#include <string>

#include "mechcheck/audit/audit.hpp"
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

}  // namespace mechcheck::audit
