#include "integrators/integrators.hpp"

namespace {
using namespace mechcheck::laws::integrators;

/// One-step errors of Method on the oscillator against its exact flow, h = h0, h0/2, ...
/// until the error reaches the rounding floor, fitted as in the audit (median of the last
/// three exponents above `resolvable`). Returns nothing when no halving was resolvable.
template <template <class, class> class Method, class T>
std::optional<T> local_order(const mc::harmonic_oscillator_system<T>& osc,
                             const mc::reference::oscillator_flow<T>& flow,
                             const dynamic_vector<T>& q0, const dynamic_vector<T>& p0,
                             double floor) {
  std::vector<mc::audit::study_point> points;
  T h = T(1) / 4;
  for (int k = 0; k < 80; ++k, h /= 2) {
    Method<mc::harmonic_oscillator_system<T>, dynamic_vector<T>> method{osc};
    mc::phase_state<dynamic_vector<T>> x{q0, p0};
    method(x, h);
    const auto exact = flow(q0, p0, h);
    const T error = T((x.q - exact.q()).norm() + (x.p - exact.p()).norm());
    points.push_back({static_cast<double>(h), static_cast<double>(error), 0});
    if (static_cast<double>(error) < floor) break;
  }
  const auto fit = mc::audit::fit_halvings(points, 16 * floor);
  if (fit.used == 0) return std::nullopt;
  return T(fit.value);
}

/// Local order in the tiers beyond double. The one-step error of a method of order p is
/// C h^(p+1) (1 + O(h)); in a tier of 33 or 50 digits the halvings go on until h^(p+1)
/// reaches that tier's rounding, so a coefficient right only to double precision (an
/// order condition off by ~1e-17) leaves an h^3 or h^2 term that takes over at small h and
/// the fitted exponent drops below p + 1. (Odeint's SB3A, whose two coefficients are
/// double literals, measures 3.00 here in mpfr50; its order is 4.)
struct local_orders {
  using tiers = std::tuple<mc::float128, mc::mpfr50>;

  static law_info info() {
    return {"integrators.local_order",
            "One step of a method of order p errs by C h^(p+1) down to the tier's rounding "
            "(coefficients right to the tier's precision, not to double's)",
            {"250", "258", "260", "261", "262"}};
  }
  // Truncation model: one-step error C h^(p+1) against the exact oscillator flow; the
  // exponent over the last three halvings above 16 x the floor (16 eps x 64 evaluations,
  // relative to |z| ~ 1) must be within 0.4 of p + 1.
  template <class T>
  static void property() {
    const double m = *gen::dyadic(0.5, 2), k = *gen::dyadic(0.5, 2);
    const mc::harmonic_oscillator_system<T> osc{T(m), T(k)};
    const mc::reference::oscillator_flow<T> flow{T(m), T(k)};
    dynamic_vector<T> q0(1), p0(1);
    q0 << T(*gen::dyadic(0.5, 2));
    p0 << T(*gen::dyadic(-1, 1));
    const double floor = 16 * 64 * static_cast<double>(std::numeric_limits<T>::epsilon());
    const auto check = [&]<template <class, class> class Method>(const char* name, int p) {
      check_exponent(std::string(name) + ": fitted local order",
                     local_order<Method>(osc, flow, q0, p0, floor), p + 1);
    };
    check.template operator()<mc::explicit_euler>("explicit Euler", 1);
    check.template operator()<mc::symplectic_euler>("symplectic Euler", 1);
    check.template operator()<mc::stormer_verlet>("Stormer-Verlet", 2);
    check.template operator()<mc::rk4>("RK4", 4);
    check.template operator()<yoshida4>("composition 4", 4);
    check.template operator()<yoshida6>("composition 6", 6);
    check.template operator()<yoshida8>("composition 8", 8);
    check.template operator()<mc::mclachlan4>("McLachlan SB3A", 4);
    check.template operator()<gauss1>("Gauss-Legendre 1", 2);
    check.template operator()<gauss2>("Gauss-Legendre 2", 4);
    check.template operator()<gauss3>("Gauss-Legendre 3", 6);
    check.template operator()<gauss4>("Gauss-Legendre 4", 8);
  }
};
MECHCHECK_LAW(local_orders);

}  // namespace
