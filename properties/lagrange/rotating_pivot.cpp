#include "lagrange/lagrange.hpp"

namespace {
using namespace mechcheck::laws::lagrange;

struct rotating_pivot {
  static law_info info() {
    return {"lagrange.rotating_pivot",
            "Pendulum on a rotating pivot: thetaddot + (g/l) sin(theta) = (R w^2/l) "
            "cos(theta + w t)",
            {"42", "44", "45", "47"}};
  }
  // The Lagrangian is built from the bob's velocity (eqs 44-45); check_against_eq47.
  template <class T>
  static void property() {
    check_against_eq47<T>("thetaddot vs eq 47", [](double m, double l, double g, double r,
                                                   double w) {
      return models::rotating_pivot_pendulum<double>{m, l, g, r, w};
    });
  }
};
MECHCHECK_LAW(rotating_pivot);

}  // namespace
