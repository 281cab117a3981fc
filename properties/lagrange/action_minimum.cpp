#include "lagrange/action.hpp"

namespace {
using namespace mechcheck::laws::lagrange;

/// The oscillator's action is a minimum only for short times (lecture 3's "least"): the
/// second variation d2S/da2 = int (m betadot^2 - k beta^2) dt is, for
/// beta = sum_n c_n sin(n pi t / T), sum_n c_n^2 (T/2) (m (n pi / T)^2 - k): positive for
/// every beta while T < pi / w (before the first conjugate point), negative for
/// beta = sin(pi t / T) after it. The integrand comes from the Hessian of L by AD.
struct action_minimum {
  static law_info info() {
    return {"lagrange.action_minimum",
            "The oscillator's action is a minimum for T < pi/w and not beyond: d2S/da2 = "
            "sum c_n^2 (T/2)(m (n pi/T)^2 - k)",
            {"claim:action_minimum_short_times"}};
  }
  template <class T>
  static void property() {
    using std::sqrt;
    const double m = *gen::positive(), k = *gen::positive();
    const T w = sqrt(T(T(k) / T(m)));
    const T duration = T(*gen::dyadic(0.25, 4)) / w;
    const variation<T> beta = random_variation(duration);
    const models::oscillator<double> lag(m, k);
    const auto second_variation = [&](const variation<T>& b) {
      return integrate<T>(
          [&](const T& t) {
            const auto hess = mc::hessian(
                [&]<class S>(const dynamic_vector<S>& z) -> S {
                  dynamic_vector<S> q(1), v(1);
                  q << z(0);
                  v << z(1);
                  return lag(q, v, lift<S>(t));
                },
                dynamic_vector<T>((dynamic_vector<T>(2) << lift<T>(0), lift<T>(0)).finished()));
            const auto [bb, bdot] = b.at(t);
            return T(hess(0, 0) * bb * bb + 2 * hess(0, 1) * bb * bdot + hess(1, 1) * bdot * bdot);
          },
          duration);
    };
    const T pi = boost::math::constants::pi<T>();
    T closed = lift<T>(0), scale = lift<T>(0);
    for (int n = 1; n <= 3; ++n) {
      const T c2 = beta.c[n - 1] * beta.c[n - 1], rate = n * pi / duration;
      closed += c2 * duration / 2 * (T(m) * rate * rate - T(k));
      scale += c2 * duration / 2 * (T(m) * rate * rate + T(k));
    }
    const T value = second_variation(beta);
    check_close("d2S/da2 against sum c_n^2 (T/2)(m (n pi/T)^2 - k)", value, closed, scale, 64);
    const variation<T> first_mode{{lift<T>(1), lift<T>(0), lift<T>(0)}, duration};
    const T lowest = second_variation(first_mode);
    if (w * duration < pi) {
      RC_ASSERT(value > 0);  // every beta: each term of the sum is positive
    } else {
      RC_ASSERT(lowest < 0);  // past the conjugate point sin(pi t / T) lowers the action
    }
  }
};
MECHCHECK_LAW(action_minimum);

}  // namespace
