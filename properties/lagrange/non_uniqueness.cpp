#include "lagrange/lagrange.hpp"

namespace {
using namespace mechcheck::laws::lagrange;

/// L + d/dt f(q, t) for f(q, t) = sum_i (c_i q_i^2 t + d_i sin(q_i + t)), with the total
/// derivative written out (an AD layer more would exceed what Eigen's AutoDiffScalar
/// supports over multiprecision types inside an acceleration, which is already two deep):
///   df/dt = sum_i (2 c_i q_i qdot_i t + c_i q_i^2 + d_i cos(q_i + t) (qdot_i + 1)).
template <class L>
struct gauge_transformed {
  L lag;
  std::vector<double> c, d;
  template <class S>
  S operator()(const dynamic_vector<S>& q, const dynamic_vector<S>& qdot, const S& t) const {
    using std::cos;
    S df = lift<S>(0);
    for (Eigen::Index i = 0; i < q.size(); ++i) {
      const S ci = lift<S>(c[i]), di = lift<S>(d[i]);
      const S a = lift<S>(2) * ci * q(i) * qdot(i) * t;
      const S b = ci * q(i) * q(i);
      const S angle = q(i) + t;
      const S rate = qdot(i) + lift<S>(1);
      const S e = di * cos(angle) * rate;
      df += a;
      df += b;
      df += e;
    }
    const S l = lag(q, qdot, t);
    return l + df;
  }
};

/// a L.
template <class L>
struct scaled_lagrangian {
  L lag;
  double factor;
  template <class S>
  S operator()(const dynamic_vector<S>& q, const dynamic_vector<S>& qdot, const S& t) const {
    const S l = lag(q, qdot, t);
    return lift<S>(factor) * l;
  }
};

struct non_uniqueness {
  static law_info info() {
    return {"lagrange.non_uniqueness",
            "a L and L + df(q,t)/dt give the same equations of motion", {"17", "57"}};
    // The notes state this in lecture 3 (eqs 16-17) and use it in eq 57.
  }
  // The added terms change dL/dq and the mixed derivatives by amounts that cancel in the
  // solve; scale |a| + |W^-1| |df terms| ~ |a| + |d2f|(1 + |qdot|)^2: k = 32n + 32.
  template <class T>
  static void property() {
    const auto c = *gen::model_cases();
    RC_PRE(c.which != 3);  // the pendulums: n = 1, 2
    const double alpha = *gen::coefficient();
    with_model(c, [&](const auto& lag) {
      using L = std::decay_t<decltype(lag)>;
      const auto q = gen::to_tier<T>(c.q);
      const auto v = gen::to_tier<T>(c.qdot);
      const T t = T(c.t);
      const auto c = *rc::gen::container<std::vector<double>>(q.size(), gen::coefficient());
      const auto d = *rc::gen::container<std::vector<double>>(q.size(), gen::coefficient());
      const dynamic_vector<T> a = mc::accelerations(lag, q, v, t);
      const dynamic_vector<T> a_scaled =
          mc::accelerations(scaled_lagrangian<L>{lag, alpha}, q, v, t);
      const dynamic_vector<T> a_gauge = mc::accelerations(gauge_transformed<L>{lag, c, d}, q, v, t);
      const auto w = mc::lagrangian_jet_at(lag, q, v, t).kinetic;
      // The gauge term's second derivatives are bounded by 2|c|(1 + |q| + |t|) + |d|(1 + |qdot|).
      using std::abs;
      const T f_size = T(4) * (1 + inf_norm(q) + abs(t)) + T(2) * (1 + inf_norm(v));
      const T inv_w = w.inverse().norm();
      const T one_v = 1 + inf_norm(v);
      const T scale = at_least_one(T(inf_norm(a) + inv_w * f_size * one_v * one_v));
      const double k = 32.0 * q.size() + 32;
      check_vectors("qddot of a L", a_scaled, a, scale, k);
      check_vectors("qddot of L + df/dt", a_gauge, a, scale, k);
    });
  }
};
MECHCHECK_LAW(non_uniqueness);

}  // namespace
