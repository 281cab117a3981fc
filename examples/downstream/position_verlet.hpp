#pragma once
// Our integrator: position Verlet (drift-kick-drift), order 2, symplectic, symmetric.
// Any callable stepper(state, h) on a phase_state can be audited.

#include <mechcheck/integrators/systems.hpp>

namespace downstream {

template <class System, class Vec>
struct position_verlet {
  static constexpr int order = 2;
  static constexpr bool symplectic = true;
  static constexpr bool symmetric = true;
  System system;
  void operator()(mechcheck::phase_state<Vec>& x, const typename Vec::Scalar& h) const {
    Vec v = x.p, f = x.q;
    system.velocity(x.p, v);
    x.q += (h / 2) * v;
    system.force(x.q, f);
    x.p += h * f;
    system.velocity(x.p, v);
    x.q += (h / 2) * v;
  }
};

}  // namespace downstream
