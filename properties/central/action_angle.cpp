#include "central/central.hpp"

namespace {
using namespace mechcheck::laws::central;

struct action_angle {
  static law_info info() {
    return {"central.action_angle",
            "Kepler action-angle variables: the radial action (quadrature) is "
            "k sqrt(mu/(2|E|)) - I_phi (eq 324), H = -mu k^2/(2 (I_r + I_phi)^2) (eq 325 "
            "corrected), and omega_r = omega_phi = 2 pi / T_r: equal frequencies, closed orbits",
            {"320", "321", "322", "323", "324", "325"}};
  }
  // Quadrature to ~eps: k = 64 on k sqrt(mu/|E|); H(I) by AD, few operations: k = 32.
  template <class T>
  static void property() {
    const auto c = random_constants<T>();
    const auto [r1, r2] = random_apsides<T>();
    const mc::radial_orbit<T> orbit(c.mu, T(-c.k), T(-1), r1, r2);
    using std::abs;
    using std::sqrt;
    const T energy = orbit.energy(), i_phi = orbit.angular_momentum();
    const T i_r = orbit.radial_action();
    const T total = c.k * sqrt(T(c.mu / (2 * abs(energy))));
    check_close("I_r (quadrature) vs eq 324", i_r, T(total - i_phi), total, 64);
    const auto h = [&]<class S>(const dynamic_vector<S>& x) -> S {
      using R = mc::real_type_t<S>;
      const S s = x(0) + x(1);
      const S s2 = s * s;
      return -lift<S>(R(c.mu) * R(c.k) * R(c.k) / 2) * mc::inverse(s2);
    };
    dynamic_vector<T> actions(2);
    actions << i_r, i_phi;
    check_close("H(I_r, I_phi) vs E", h(actions), energy, T(abs(energy)), 64);
    const dynamic_vector<T> omega = mc::gradient(h, actions);
    const T frequency = 2 * pi<T>() / orbit.radial_period();
    check_close("omega_r vs 2 pi/T_r", omega(0), frequency, frequency, 64);
    check_close("omega_phi vs omega_r", omega(1), omega(0), frequency, 16);
  }
};
MECHCHECK_LAW(action_angle);

}  // namespace
