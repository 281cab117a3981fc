#include "central/central.hpp"

namespace {
using namespace mechcheck::laws::central;

struct two_body_reduction {
  static law_info info() {
    return {"central.two_body_reduction",
            "Two bodies with U(|r1 - r2|): L = 1/2 M V^2 + 1/2 mu rdot^2 - U(r) with the "
            "reduced mass, r1, r2 recovered from the centre and r, and the Euler-Lagrange "
            "accelerations of eq 94 give mu rddot = -U'(r) r/r",
            {"94", "95", "96", "97"}};
  }
  // Sums of a few products (k = 16 on the kinetic scale m |v|^2); the accelerations come
  // from a 6x6 solve of the AD Hessian of eq 94 (diagonal): k = 32 on k/r^2 scale.
  template <class T>
  static void property() {
    const T m1 = T(*gen::positive()), m2 = T(*gen::positive()), strength = T(*gen::positive());
    const auto [r, v] = random_state<T>();
    const vector3<T> centre = gen::draw_vector3<T>(), centre_v = gen::draw_vector3<T>();
    const auto [r1, r2] = mc::from_relative(m1, m2, centre, r);
    const auto [v1, v2] = mc::from_relative(m1, m2, centre_v, v);
    const auto rel = mc::to_relative(m1, m2, r1, r2, v1, v2);
    const T scale = (m1 + m2) * (r.squaredNorm() + v.squaredNorm() + centre.squaredNorm() +
                                 centre_v.squaredNorm() + 1);
    for (int i = 0; i < 3; ++i) {
      check_close("centre_" + std::to_string(i), rel.centre(i), centre(i), scale, 16);
      check_close("r_" + std::to_string(i), rel.r(i), r(i), scale, 16);
    }
    const T mu = mc::reduced_mass(m1, m2);
    const T kinetic = m1 * v1.squaredNorm() / 2 + m2 * v2.squaredNorm() / 2;
    const T reduced = (m1 + m2) * centre_v.squaredNorm() / 2 + mu * v.squaredNorm() / 2;
    check_close("1/2 m1 v1^2 + 1/2 m2 v2^2 vs 1/2 M V^2 + 1/2 mu v^2 (eq 97)", kinetic, reduced,
                scale, 16);
    // Euler-Lagrange accelerations of eq 94 with U = -k / |r1 - r2|.
    const auto lag = [&]<class S>(const dynamic_vector<S>& q, const dynamic_vector<S>& qd,
                                  const S&) -> S {
      using std::sqrt;
      using R = mc::real_type_t<S>;
      S t = lift<S>(0), d2 = lift<S>(0);
      for (int i = 0; i < 3; ++i) {
        const S a = qd(i) * qd(i), b = qd(3 + i) * qd(3 + i), d = q(i) - q(3 + i);
        const S ta = lift<S>(R(m1) / 2) * a, tb = lift<S>(R(m2) / 2) * b, dd = d * d;
        t += ta;
        t += tb;
        d2 += dd;
      }
      const S u = -lift<S>(R(strength)) * mc::inverse(S(sqrt(d2)));
      return t - u;
    };
    dynamic_vector<T> q(6), qd(6);
    q << r1, r2;
    qd << v1, v2;
    const dynamic_vector<T> a = mc::accelerations(lag, q, qd, lift<T>(0));
    const T rn = r.norm();
    const T force_scale = strength / (mu * rn * rn) + 1;
    for (int i = 0; i < 3; ++i)
      check_close("rddot_" + std::to_string(i) + " vs -k r/(mu r^3)", T(a(i) - a(3 + i)),
                  T(-strength * r(i) / (mu * rn * rn * rn)), force_scale, 32);
  }
};
MECHCHECK_LAW(two_body_reduction);

}  // namespace
