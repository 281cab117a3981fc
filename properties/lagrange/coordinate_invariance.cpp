#include "lagrange/lagrange.hpp"

namespace {
using namespace mechcheck::laws::lagrange;

struct coordinate_invariance {
  static law_info info() {
    return {"lagrange.coordinate_invariance",
            "The spring pendulum in (x, theta) and in Cartesian coordinates moves alike",
            {"7", "8", "9", "10", "11", "12", "14", "15"}};
  }
  // Cartesian accelerations against J qddot + qdot^T Hess(X) qdot of the polar ones:
  // two 2x2 solves and sums of 2-4 products, scale |a| + |J||qddot| + |Hess||qdot|^2:
  // k = 64.
  template <class T>
  static void property() {
    const double m = *gen::positive(), k = *gen::positive(), l = *gen::dyadic(1, 3),
                 g = *gen::positive();
    const models::spring_pendulum<double> polar{m, k, l, g};
    const models::spring_pendulum_cartesian<double> cartesian{m, k, l, g};
    dynamic_vector<T> q(2), v(2);
    q << T(*gen::dyadic_towards_zero(0.5)), T(*gen::coordinate());
    v << T(*gen::coordinate()), T(*gen::coordinate());
    const T t = lift<T>(0);
    const dynamic_vector<T> a_polar = mc::accelerations(polar, q, v, t);
    const auto position = [&polar]<class S>(const dynamic_vector<S>& x) -> dynamic_vector<S> {
      return polar.position(x);
    };
    const dynamic_matrix<T> jac = mc::jacobian(position, q);
    const dynamic_vector<T> x = polar.position(q);
    const dynamic_vector<T> xdot = jac * v;
    const dynamic_vector<T> a_cart = mc::accelerations(cartesian, x, xdot, t);
    dynamic_vector<T> predicted = jac * a_polar;
    T curvature = lift<T>(0);
    for (int c = 0; c < 2; ++c) {
      const auto component = [&position, c]<class S>(const dynamic_vector<S>& y) -> S {
        return position(y)(c);
      };
      const dynamic_matrix<T> hess = mc::hessian(component, q);
      predicted(c) += v.dot(hess * v);
      const T hn = hess.norm();
      curvature = curvature > hn ? curvature : hn;
    }
    const T scale = at_least_one(T(inf_norm(a_cart) + jac.norm() * inf_norm(a_polar) +
                                   curvature * v.squaredNorm()));
    check_vectors("Cartesian acceleration vs mapped polar acceleration", a_cart, predicted,
                  scale, 64);
  }
};
MECHCHECK_LAW(coordinate_invariance);

}  // namespace
