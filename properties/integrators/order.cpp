#include "integrators/integrators.hpp"

namespace {
using namespace mechcheck::laws::integrators;

/// State at time 1 after `steps` steps.
template <template <class, class> class Method, class System, class T>
dynamic_vector<T> state_at_one(const System& system, const dynamic_vector<T>& z, long steps) {
  const Eigen::Index n = z.size() / 2;
  Method<System, dynamic_vector<T>> method{system};
  mc::phase_state<dynamic_vector<T>> x{z.head(n), z.tail(n)};
  mc::integrate(method, x, T(1) / T(steps), steps);
  dynamic_vector<T> out(2 * n);
  out << x.q, x.p;
  return out;
}

/// Richardson convergence study of the global error at time 1: e(h) = |y_h - y_{h/2}|.
template <template <class, class> class Method, class System, class T>
std::optional<T> fitted_order(const System& system, const dynamic_vector<T>& z, long steps,
                              int p) {
  const auto error = [&](const T& h) {
    const long n = mc::audit::steps_for(h);
    return T((state_at_one<Method>(system, z, n) - state_at_one<Method>(system, z, 2 * n)).norm());
  };
  return converged_exponent(error, T(T(1) / T(steps)), p, T(z.norm() + 1));
}

struct integrator_orders {
  static law_info info() {
    return {"integrators.order",
            "Every integrator converges with its order p: 1 (Euler), 2 (Verlet), 4/6/8 "
            "(compositions), 4 (RK4, McLachlan's SB3A), 2s (Gauss-Legendre s = 1..4)",
            {"250", "258", "260", "261", "262"}};
  }
  // Truncation model e(h) = C h^p (1 + O(h)) for the pendulum over t in [0, 1]; the
  // Richardson exponent from h, h/2, h/4 settles within 0.4 of p before rounding decides
  // (converged_exponent).
  template <class T>
  static void property() {
    const double m = *gen::dyadic(0.5, 2), l = *gen::dyadic(0.5, 2), g = *gen::dyadic(0.5, 2);
    const mc::pendulum_system<T> pendulum{T(m), T(l), T(g)};
    dynamic_vector<T> z(2);
    z << T(*gen::dyadic(-2, 2)), T(*gen::dyadic(-1, 1));
    const auto check = [&]<template <class, class> class Method>(const char* name, int p,
                                                                 long steps) {
      check_exponent(std::string(name) + ": fitted order",
                     fitted_order<Method>(pendulum, z, steps, p), p);
    };
    check.template operator()<mc::explicit_euler>("explicit Euler", 1, 256);
    check.template operator()<mc::symplectic_euler>("symplectic Euler", 1, 256);
    check.template operator()<mc::stormer_verlet>("Stormer-Verlet", 2, 32);
    check.template operator()<mc::rk4>("RK4", 4, 32);
    check.template operator()<yoshida4>("composition 4", 4, 16);
    check.template operator()<yoshida6>("composition 6", 6, 8);
    check.template operator()<yoshida8>("composition 8", 8, 8);
    check.template operator()<mc::mclachlan4>("McLachlan SB3A", 4, 16);
    check.template operator()<gauss1>("Gauss-Legendre 1", 2, 32);
    check.template operator()<gauss2>("Gauss-Legendre 2", 4, 8);
    check.template operator()<gauss3>("Gauss-Legendre 3", 6, 4);
    check.template operator()<gauss4>("Gauss-Legendre 4", 8, 2);
  }
};
MECHCHECK_LAW(integrator_orders);

}  // namespace
