// Our own law: position Verlet is time-reversible. A step of h then a step of -h returns
// to the start up to rounding, for the oscillator from any state, in every tier.
#include <mechcheck/harness/checks.hpp>
#include <mechcheck/harness/generators.hpp>
#include <mechcheck/harness/law.hpp>
#include <mechcheck/integrators/systems.hpp>

#include "position_verlet.hpp"

namespace {
namespace mc = mechcheck;
namespace gen = mechcheck::generators;

struct position_verlet_reversible {
  static mc::harness::law_info info() {
    return {"downstream.position_verlet_reversible",
            "position Verlet: step(-h) after step(h) is the identity (up to rounding)",
            {}};
  }
  // Each half returns through about 6 roundings of the state's size: budget 32 eps.
  template <class T>
  static void property() {
    const double q0 = *gen::coordinate(), p0 = *gen::coordinate();
    const double m = *gen::positive(), k = *gen::positive();
    const T h = T(*gen::dyadic(1.0 / 64, 1.0 / 2)) / 3;  // not dyadic: the steps round
    using V = mc::dynamic_vector<T>;
    downstream::position_verlet<mc::harmonic_oscillator_system<T>, V> step{{T(m), T(k)}};
    mc::phase_state<V> x{V::Constant(1, T(q0)), V::Constant(1, T(p0))};
    const auto start = x;
    step(x, h);
    step(x, T(-h));
    using std::abs;
    const T scale = T(1) + abs(start.q(0)) + abs(start.p(0));
    mc::harness::check_close("q after h, -h", x.q(0), start.q(0), scale, 32);
    mc::harness::check_close("p after h, -h", x.p(0), start.p(0), scale, 32);
  }
};
MECHCHECK_LAW(position_verlet_reversible);

}  // namespace
