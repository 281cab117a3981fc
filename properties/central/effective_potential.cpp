#include "central/central.hpp"

namespace {
using namespace mechcheck::laws::central;

/// U_eff(r) = M^2 / (2 mu r^2) - k / r as printed in eq 101 with U = -k/r (eq 112 with
/// M_z^2), for AD.
template <class T>
struct effective_potential_function {
  T mu, k, m;
  template <class S>
  S operator()(const dynamic_vector<S>& x) const {
    using R = mc::real_type_t<S>;
    const S inv_r = mc::inverse(x(0));
    const S inv_r2 = inv_r * inv_r;
    const S c = lift<S>(R(m) * R(m) / (2 * R(mu))) * inv_r2;
    const S u = lift<S>(R(k)) * inv_r;
    return c - u;
  }
};

struct effective_potential {
  static law_info info() {
    return {"central.effective_potential",
            "In the orbital plane H = 1/2 mu (rdot^2 + r^2 phidot^2) + U = 1/2 mu rdot^2 + "
            "U_eff with M = mu r^2 phidot; for U = -k/r, U_eff is stationary (a minimum) at "
            "the circular radius M^2/(mu k)",
            {"98", "99", "100", "101", "102", "112"}};
  }
  // Few-term sums: k = 16 on mu (rdot^2 + r^2 phidot^2) + k/r; U_eff' (AD) at r_c is a
  // difference of two terms of size k/r_c^2: k = 16 on that.
  template <class T>
  static void property() {
    const auto c = random_constants<T>();
    const T r = T(*gen::dyadic(0.25, 4)), rdot = T(*gen::dyadic(-2, 2)),
            phidot = T(*gen::dyadic(-2, 2));
    RC_PRE(phidot != 0);
    const T m = c.mu * r * r * phidot;
    const T h = c.mu * (rdot * rdot + r * r * phidot * phidot) / 2 - c.k / r;
    const T scale = c.mu * (rdot * rdot + r * r * phidot * phidot) + c.k / r;
    check_close("H vs 1/2 mu rdot^2 + U_eff (eq 102)", h,
                T(c.mu * rdot * rdot / 2 + c.effective_potential(m, r)), scale, 16);
    const effective_potential_function<T> ueff{c.mu, c.k, m};
    const T rc = c.circular_radius(m);
    dynamic_vector<T> x(1);
    x << rc;
    const T slope = mc::gradient(ueff, x)(0);
    check_zero("U_eff'(M^2/(mu k))", slope, T(c.k / (rc * rc)), 16);
    RC_ASSERT(mc::hessian(ueff, x)(0, 0) > 0);
  }
};
MECHCHECK_LAW(effective_potential);

}  // namespace
