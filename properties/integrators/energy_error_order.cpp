#include "integrators/integrators.hpp"

namespace {
using namespace mechcheck::laws::integrators;

/// max |H(t) - H(0)| over t in [0, T] with step h.
template <template <class, class> class Method, class System, class T>
T max_energy_error(const System& system, const dynamic_vector<T>& z, const T& h, long steps) {
  const Eigen::Index n = z.size() / 2;
  Method<System, dynamic_vector<T>> method{system};
  mc::phase_state<dynamic_vector<T>> x{z.head(n), z.tail(n)};
  const T e0 = system.energy(x.q, x.p);
  T worst = lift<T>(0);
  for (long i = 0; i < steps; ++i) {
    method(x, h);
    using std::abs;
    const T e = abs(T(system.energy(x.q, x.p) - e0));
    worst = worst > e ? worst : e;
  }
  return worst;
}

struct symplectic_energy_error {
  static law_info info() {
    return {"integrators.energy_error_order",
            "A symplectic method of order p keeps the energy error bounded at O(h^p): "
            "the fitted exponent of max|H - H0| over a fixed time is p",
            {"263", "264"}};
  }
  // Truncation model: max|H - H0| = C h^p (1 + O(h)) over t in [0, 4] (no secular
  // drift); the exponent from h and h/2 settles within 0.4 of p (converged_exponent).
  template <class T>
  static void property() {
    const auto z = kepler_state<T>();
    const mc::kepler_system<T> kepler(T(1), T(1));
    const auto check = [&]<template <class, class> class Method>(const char* name, int p,
                                                                 long steps) {
      const auto error = [&](const T& h) {
        using std::round;
        const long n = static_cast<long>(static_cast<double>(round(T(4 / h))));
        return max_energy_error<Method>(kepler, z, h, n);
      };
      check_exponent(std::string(name) + ": fitted exponent of the energy error",
                     converged_exponent(error, T(T(4) / T(steps)), p, lift<T>(1)), p);
    };
    check.template operator()<mc::stormer_verlet>("Stormer-Verlet", 2, 128);
    check.template operator()<yoshida4>("composition 4", 4, 64);
    check.template operator()<mc::mclachlan4>("McLachlan SB3A", 4, 64);
    check.template operator()<gauss2>("Gauss-Legendre 2", 4, 32);
  }
};
MECHCHECK_LAW(symplectic_energy_error);

}  // namespace
