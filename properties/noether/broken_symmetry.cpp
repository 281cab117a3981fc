#include "lagrange/lagrange.hpp"

namespace {
using namespace mechcheck::laws::lagrange;

using field_system =
    models::particle_system<double, gen::pair_potential, models::vertical_field<double>>;

struct broken_symmetry {
  static law_info info() {
    return {"noether.broken_symmetry",
            "In a field V(z), P_x, P_y and M_z are conserved while P_z and M_x, M_y change "
            "at the rate of the external force and torque",
            {"61", "65", "76"}};
  }
  // Rates by AD on shell against the external force -sum V'(z_i) and its torque (sums of
  // N terms): scale as in noether.charge_conservation plus the force and torque sizes,
  // k = 8N + 16.
  template <class T>
  static void property() {
    // Two or three particles: the field's force and torque on each, and every pair's
    // internal force cancelling, are all present at three; a fourth adds no new term, and the
    // Hessian solve of L, growing as (3N)^3, costs 2.4 times three's.
    const auto s = *gen::particle_samples(2, 3);
    const auto u = *gen::pair_potentials();
    const double fa = *gen::coefficient(), fb = *gen::coefficient();
    const field_system sys(s.masses, u, models::vertical_field<double>{fa, fb});
    const auto q = s.template positions<T>();
    const auto v = s.template velocities<T>();
    const T t = lift<T>(0);
    T force = lift<T>(0), torque_x = lift<T>(0), torque_y = lift<T>(0);
    for (Eigen::Index i = 0; i < s.particles(); ++i) {
      const T fz = -(T(fa) + 2 * T(fb) * q(3 * i + 2));  // -V'(z_i)
      force += fz;
      torque_x += q(3 * i + 1) * fz;   // (r x F)_x = y F_z
      torque_y -= q(3 * i) * fz;       // (r x F)_y = -x F_z
    }
    const double k = 8.0 * s.particles() + 16;
    const double axes[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    const T expected_p[3] = {lift<T>(0), lift<T>(0), force};
    const T expected_m[3] = {torque_x, torque_y, lift<T>(0)};
    // The accelerations on shell once for the six charges (a Hessian solve of L by AD each).
    const dynamic_vector<T> a = mc::accelerations(sys, q, v, t);
    for (int c = 0; c < 3; ++c) {
      const mc::translation_generator<double> tr{{axes[c][0], axes[c][1], axes[c][2]}};
      const auto [rp, sp] = charge_rate(sys, tr, mc::zero_function{}, q, v, t, a);
      check_close("dP_" + std::string(1, "xyz"[c]) + "/dt vs external force", rp, expected_p[c],
                  sp, k);
      const mc::rotation_generator<double> rot{{axes[c][0], axes[c][1], axes[c][2]}};
      const auto [rm, sm] = charge_rate(sys, rot, mc::zero_function{}, q, v, t, a);
      check_close("dM_" + std::string(1, "xyz"[c]) + "/dt vs external torque", rm, expected_m[c],
                  sm, k);
    }
    using std::abs;
    RC_CLASSIFY(abs(force) > 0, "P_z changes");
  }
};
MECHCHECK_LAW(broken_symmetry);

}  // namespace
