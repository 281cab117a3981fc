#include "integrators/integrators.hpp"

namespace {
using namespace mechcheck::laws::integrators;

struct symplectic_integrators {
  static law_info info() {
    return {"integrators.symplectic_condition",
            "One step of every symplectic integrator is a canonical map: M J M^T = J, "
            "det M = 1",
            {"285", "292", "300", "301", "302"}};
  }
  // Rounding in a map made of m force evaluations on n dof: k = 16 m n, with m = 1
  // (Euler), 1 (Verlet), 3, 9, 27 (compositions), 5 (SB3A), 2 s (Gauss-Legendre: converged
  // stages, each stage one evaluation and an s-term sum).
  template <class T>
  static void property() {
    const auto z = kepler_state<T>();
    const double hd = *gen::dyadic(1.0 / 64, 1.0 / 8);
    const T h = T(hd);
    const mc::kepler_system<T> kepler(T(1), T(1));
    const auto check = [&]<template <class, class> class Method>(const char* name, int evals) {
      const dynamic_matrix<T> m = step_jacobian<Method>(kepler, z, h);
      const T scale = m.squaredNorm();
      const double k = 16.0 * evals * 2;
      check_zero(std::string(name) + ": max|M J M^T - J|", symplectic_defect(m), scale, k);
      check_close(std::string(name) + ": det M", T(m.determinant()), lift<T>(1), scale * scale, k);
    };
    check.template operator()<mc::symplectic_euler>("symplectic Euler", 1);
    check.template operator()<mc::stormer_verlet>("Stormer-Verlet", 1);
    check.template operator()<yoshida4>("composition 4", 3);
    check.template operator()<yoshida6>("composition 6", 9);
    check.template operator()<yoshida8>("composition 8", 27);
    check.template operator()<mc::mclachlan4>("McLachlan SB3A", 5);
    check.template operator()<gauss1>("Gauss-Legendre 1", 2);
    check.template operator()<gauss2>("Gauss-Legendre 2", 4);
    check.template operator()<gauss3>("Gauss-Legendre 3", 6);
    check.template operator()<gauss4>("Gauss-Legendre 4", 8);
  }
};
MECHCHECK_LAW(symplectic_integrators);

}  // namespace
