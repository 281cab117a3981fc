#include "integrators/integrators.hpp"

namespace {
using namespace mechcheck::laws::integrators;

struct non_symplectic_integrators {
  static law_info info() {
    return {"integrators.not_symplectic",
            "Explicit Euler and RK4 are not symplectic: on the nonlinear Kepler problem "
            "their defect |M J M^T - J| grows as h^2 and h^6",
            {"292", "302"}};
  }
  // Truncation model: defect(h) = C h^e (1 + O(h)); the fitted exponent
  // log2(defect(h)/defect(h/2)) is within 0.4 of e, and the defect is far above rounding
  // (> 10^6 eps): the law asserts the failure, and its rate. Euler: e = p + 1 = 2. RK4:
  // e = 6, one more than p + 1: the h^5 term of RK4's local error is a Hamiltonian
  // vector field, so the first non-canonical term is h^6 (measured in mpfr50 at
  // h = 1/16 ... 1/512: 5.885, 5.926, 5.967, 5.984, 5.992, 5.996).
  template <class T>
  static void property() {
    const auto z = kepler_state<T>();
    const mc::kepler_system<T> kepler(T(1), T(1));
    const auto check = [&]<template <class, class> class Method>(const char* name, int e,
                                                                 double hd) {
      const auto defect = [&](const T& h) {
        return symplectic_defect(step_jacobian<Method>(kepler, z, h));
      };
      check_exponent(std::string(name) + ": fitted exponent of the defect",
                     converged_exponent(defect, T(hd), e, lift<T>(1)), e);
    };
    check.template operator()<mc::explicit_euler>("explicit Euler", 2, 1.0 / 64);
    check.template operator()<mc::rk4>("RK4", 6, 1.0 / 8);
  }
};
MECHCHECK_LAW(non_symplectic_integrators);

}  // namespace
