#include "lagrange/lagrange.hpp"

namespace {
using namespace mechcheck::laws::lagrange;

/// The pendulum on the rotating disc with the pivot of eqs 42-43 as printed,
/// (R cos wt, R sin wt), and the bob at (x_p + l sin(theta), y_p - l cos(theta)) (eqs 44-45).
struct printed_pivot_43 {
  double m, l, g, r, w;
  template <class S>
  S operator()(const dynamic_vector<S>& q, const dynamic_vector<S>& qdot, const S& t) const {
    using std::cos;
    using std::sin;
    const S ms = lift<S>(m), ls = lift<S>(l), gs = lift<S>(g), rs = lift<S>(r), ws = lift<S>(w);
    const S wt = ws * t;
    const S vx_pivot = -(rs * ws * sin(wt)), vy_pivot = rs * ws * cos(wt);
    const S vx = vx_pivot + ls * qdot(0) * cos(q(0));
    const S vy = vy_pivot + ls * qdot(0) * sin(q(0));
    const S v2 = vx * vx + vy * vy;
    const S y = rs * sin(wt) - ls * cos(q(0));
    const S kinetic = ms * v2 * mc::half<S>();
    const S potential = ms * gs * y;
    return kinetic - potential;
  }
};

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
  // (R w^2 / l) 2 sin(theta) sin(wt) (check_against_eq47).
  template <class T>
  static void property() {
    check_against_eq47<T>("thetaddot with the printed pivot vs eq 47",
                          [](double m, double l, double g, double r, double w) {
                            return printed_pivot_43{m, l, g, r, w};
                          });
  }
};
MECHCHECK_LAW(erratum_43);

}  // namespace
