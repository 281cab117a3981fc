#include "rigid/tops.hpp"

namespace {
using namespace mechcheck::laws::tops;

struct heavy_top_nutation {
  static law_info info() {
    return {"rigid.heavy_top_nutation",
            "Nutation: from a turning point, cos theta stays between the roots of "
            "E' = V_eff (eqs 238-242) and returns after the period of eq 243 "
            "(4 K(k)/sqrt(beta (u3 - u_low))); the integrated motion converges to both with "
            "order 8",
            {"238", "239", "240", "241", "242", "243"}};
  }
  // Gauss-Legendre 4 on Hamilton's equations of H. Truncation model: |(theta, p_theta)(T) - start| =
  // C h^8; the band holds up to the same error (taken from the finest run, times 4) plus
  // 64 eps.
  template <class T>
  static void property() {
    const auto top = random_heavy_top<T>();
    const T theta0 = T(*gen::dyadic(0.25, 2.875));
    const T phidot0 = T(*gen::dyadic(-1, 1));
    const T spin = T(*gen::dyadic(1, 4)) * (*rc::gen::arbitrary<bool>() ? 1 : -1);
    const auto band = top.nutation_from_turning_point(theta0, phidot0, spin);
    RC_PRE(band.u_high < T(0.96875) && band.u_low > T(-0.96875));  // away from the vertical
    RC_PRE(band.u_high - band.u_low > T(1) / 1024);  // a nutation, not a steady precession
    using std::cos;
    dynamic_vector<T> q0(3), v0(3);
    q0 << T(0), theta0, T(0);
    v0 << phidot0, T(0), T(spin - phidot0 * cos(theta0));
    const dynamic_vector<T> p0 = mc::generalized_momenta(top, q0, v0, lift<T>(0));
    struct run {
      T error, u_min, u_max, u_half;
    };
    const auto integrate = [&](long n) {
      mc::gauss_legendre<mc::heavy_top<T>, dynamic_vector<T>, 4> step{top};
      mc::phase_state<dynamic_vector<T>> x{q0, p0};
      const T dt = band.period / T(n);
      run r{0, 2, -2, 0};
      for (long i = 1; i <= n; ++i) {
        step(x, dt);
        const T u = cos(x.q(1));
        r.u_min = u < r.u_min ? u : r.u_min;
        r.u_max = u > r.u_max ? u : r.u_max;
        if (2 * i == n) r.u_half = u;
      }
      using std::abs;
      const T dtheta = abs(T(x.q(1) - theta0)), dp = abs(T(x.p(1) - p0(1))) / top.i1;
      r.error = dtheta > dp ? dtheta : dp;
      return r;
    };
    run finest{};
    const auto error = [&](const T& hh) {
      finest = integrate(steps_for(hh));  // hh: step as a fraction of the period
      return finest.error;
    };
    check_exponent("return after the eq 243 period: fitted order",
                   converged_exponent(error, T(1) / 16, 8, lift<T>(1)), 8);
    const T slack = 4 * finest.error + 64 * mc::tier_epsilon<T>();
    RC_ASSERT(finest.u_min >= band.u_low - slack);
    RC_ASSERT(finest.u_max <= band.u_high + slack);
    using std::abs;
    const T other = abs(T(band.u_low - cos(theta0))) < abs(T(band.u_high - cos(theta0)))
                        ? band.u_high
                        : band.u_low;
    check_model("cos theta at half period vs the other turning point", finest.u_half, other,
                lift<T>(1), slack);
  }
};
MECHCHECK_LAW(heavy_top_nutation);

}  // namespace
