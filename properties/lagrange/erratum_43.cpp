#include "lagrange/lagrange.hpp"

namespace {
using namespace mechcheck::laws::lagrange;

struct erratum_43 {
  static law_info info() {
    return {"lagrange.erratum_43",
            "Printed eq 43 puts the pivot at y_p = R sin(wt), against eq 45 and eq 47",
            {"43"},
            mc::harness::expectation::falsified,
            "printed: y_p = R sin(wt); correct (the pivot of eq 45, y = -R sin(wt) - "
            "l cos(theta), and of eq 47): y_p = -R sin(wt), the disc turning clockwise"};
  }
  // With the printed pivot Euler-Lagrange gives thetaddot = -(g/l) sin(theta) +
  // (R w^2 / l) cos(theta - wt), not eq 47's cos(theta + wt): the two differ by
  // (R w^2 / l) 2 sin(theta) sin(wt) (check_against_eq47). The printed pivot
  // (R cos wt, R sin wt) is the model's, (R cos wt, -R sin wt), with the disc turning the
  // other way: the model at -w.
  template <class T>
  static void property() {
    check_against_eq47<T>("thetaddot with the printed pivot vs eq 47",
                          [](double m, double l, double g, double r, double w) {
                            return models::rotating_pivot_pendulum<double>{m, l, g, r, -w};
                          });
  }
};
MECHCHECK_LAW(erratum_43);

}  // namespace
