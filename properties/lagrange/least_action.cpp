#include "lagrange/action.hpp"

namespace {
using namespace mechcheck::laws::lagrange;

/// Lecture 3: for paths q_a = q + a beta with beta(0) = beta(T) = 0,
///   dS/da = int (dL/dq beta + dL/dqdot betadot) dt                       (eqs 20-23)
///         = int (dL/dq - d/dt dL/dqdot) beta dt                           (eqs 24-25)
/// on any path, and it vanishes on the true one for every beta (eqs 19, 26).
struct least_action {
  static law_info info() {
    return {"lagrange.least_action",
            "Least action: with fixed end points dS/da = int (L_q beta + L_qdot betadot) dt = "
            "int (L_q - d/dt L_qdot) beta dt on any path, and 0 on the true path",
            {"16", "18", "19", "20", "21", "22", "23", "24", "25", "26"}};
  }
  template <class T>
  static void property() {
    using std::abs;
    using std::cos;
    using std::sin;
    const action_case c = random_action_case();
    const T duration = T(c.duration);
    const variation<T> beta = random_variation(duration);
    const T bump = T(*gen::dyadic(0.125, 0.5));  // q + bump sin(pi t / T): a wrong path
    with_true_path<T>(c, [&](const auto& lag, const auto& truth) {
      // The first variation and its scale (the sum of |terms|) along a path.
      const auto first_variation = [&](const auto& path) {
        const auto term = [&](const T& t, bool magnitude) {
          const path_point<T> x = path(t);
          const auto [lq, lv] = lagrangian_gradient(lag, x, t);
          const auto [b, bdot] = beta.at(t);
          const T a = lq * b, d = lv * bdot;
          return magnitude ? T(abs(a) + abs(d)) : T(a + d);
        };
        return std::pair{integrate<T>([&](const T& t) { return term(t, false); }, duration),
                         integrate<T>([&](const T& t) { return term(t, true); }, duration)};
      };
      const auto [on_truth, truth_scale] = first_variation(truth);
      check_zero("dS/da on the true path (eqs 19, 26)", on_truth, truth_scale, 64);

      const T w = boost::math::constants::pi<T>() / duration;
      const auto wrong = [&](const T& t) {
        path_point<T> x = truth(t);
        const T s = sin(T(w * t)), co = cos(T(w * t));
        x.q += bump * s;
        x.qdot += bump * w * co;
        x.qddot -= bump * w * w * s;
        return x;
      };
      const auto [on_wrong, wrong_scale] = first_variation(wrong);
      const T by_parts = integrate<T>(
          [&](const T& t) {
            const path_point<T> x = wrong(t);
            dynamic_vector<T> q(1), v(1), a(1);
            q << x.q;
            v << x.qdot;
            a << x.qddot;
            // euler_lagrange_residual = d/dt dL/dqdot - dL/dq
            const T el = mc::euler_lagrange_residual(lag, q, v, a, t)(0);
            return T(-el * beta.at(t).first);
          },
          duration);
      check_close("dS/da by parts on a path that is not a solution (eqs 24-25)", on_wrong,
                  by_parts, wrong_scale, 64);
    });
  }
};
MECHCHECK_LAW(least_action);

}  // namespace
