#include "central/central.hpp"

namespace {
using namespace mechcheck::laws::central;

struct so4_algebra {
  static law_info info() {
    return {"central.so4_algebra",
            "The Kepler symmetry algebra: {A_i, M_j} = eps_ijk A_k, {A_i, A_j} = -2 mu H "
            "eps_ijk M_k, {H, A_i} = 0; and H, M^2, M_z commute (Liouville-Arnold)",
            {"77", "281", "282", "283", "284"}};
  }
  // Brackets of quadratic and cubic functions of (q, p) with 1/|q| terms: k = 64 on
  // (|p|^2 + mu k/|q|)(|q||p| + 1)(|p| + 1)(|q| + 1)/mu.
  template <class T>
  static void property() {
    const auto c = random_constants<T>();
    const auto [r, v] = random_state<T>();
    const kepler_functions<T> f{c.mu, c.k};
    const mc::phase_point<T> x(dynamic_vector<T>(r), dynamic_vector<T>(c.mu * v));
    const T pn = c.mu * v.norm(), qn = r.norm();
    const T scale = (pn * pn + c.mu * c.k / qn) * (qn * pn + 1) * (pn + 1) * (qn + 1) / c.mu;
    const T h = f.hamiltonian()(x.q(), x.p());
    vector3<T> a, m;
    for (int i = 0; i < 3; ++i) {
      a(i) = f.lrl(i)(x.q(), x.p());
      m(i) = mc::angular_momentum{i}(x.q(), x.p());
    }
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        T am = lift<T>(0), aa = lift<T>(0);
        for (int k = 0; k < 3; ++k)
          if (const int e = mc::levi_civita(i, j, k); e != 0) {
            am += e * a(k);
            aa += e * (-2 * c.mu * h) * m(k);
          }
        const std::string ij = std::to_string(i + 1) + "," + std::to_string(j + 1);
        check_close("{A_i, M_j} (" + ij + ")",
                    mc::poisson_bracket(f.lrl(i), mc::angular_momentum{j}, x), am, scale, 64);
        check_close("{A_i, A_j} (" + ij + ")", mc::poisson_bracket(f.lrl(i), f.lrl(j), x), aa,
                    scale, 64);
      }
    check_zero("{H, M^2}", mc::poisson_bracket(f.hamiltonian(), mc::angular_momentum_squared{}, x),
               scale, 64);
    check_zero("{H, M_z}", mc::poisson_bracket(f.hamiltonian(), mc::angular_momentum{2}, x), scale,
               64);
    check_zero("{M^2, M_z}",
               mc::poisson_bracket(mc::angular_momentum_squared{}, mc::angular_momentum{2}, x),
               scale, 64);
  }
};
MECHCHECK_LAW(so4_algebra);

}  // namespace
