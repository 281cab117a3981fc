#include "robots/robots.hpp"

namespace {
using namespace mechcheck::laws::robots;

struct christoffel {
  static law_info info() {
    return {"robots.christoffel",
            "Mdot - 2C is skew-symmetric, C(q, qdot) the matrix of the velocity terms h(q, qdot) - g(q) = C qdot "
            "(Christoffel symbols of M): C + C^T = Mdot, Mdot = sum_k dM/dq_k qdot_k",
            {"1"}};
  }
  // Two computations that share only the kinematics. C from the equations of motion: the
  // velocity terms Q(v) = h(q, v) - g(q) are quadratic in v (Christoffel symbols), so C x is
  // their bilinear form, (Q(qdot + x) - Q(qdot) - Q(x)) / 2, each h a nested-AD jet of L.
  // Mdot from T alone: T(q, v) = v^T M(q) v / 2, so M_ij = T(e_i + e_j) - T(e_i) - T(e_j)
  // (M_ii = 2 T(e_i)), and its q-gradient by first-order AD gives dM/dq_k. The jets round as
  // M and h do (64 n on their terms), the polarizations combine three of them: k = 192 n +
  // 8 n^2 on the terms' scale (term_scales: inertia and mass times (|qdot| + 1)^2, plus the
  // gravity that h - g cancels).
  template <class T>
  static void property() {
    const auto s = draw_robot<T>();
    const rb::robot_model<T>& m = s.model;
    const Eigen::Index n = s.q.size();
    const dynamic_vector<T> zero = dynamic_vector<T>::Zero(n);
    const dynamic_vector<T> g = rb::bias_forces(m, s.q, zero);
    const auto velocity_terms = [&](const dynamic_vector<T>& v) -> dynamic_vector<T> {
      return rb::bias_forces(m, s.q, v) - g;
    };
    const dynamic_vector<T> at_qdot = velocity_terms(s.qdot);
    dynamic_matrix<T> c(n, n);
    for (Eigen::Index j = 0; j < n; ++j) {
      dynamic_vector<T> e = zero;
      e(j) = T(1);
      c.col(j) = (velocity_terms(dynamic_vector<T>(s.qdot + e)) - at_qdot - velocity_terms(e)) / T(2);
    }
    // dT(q, v)/dq by first-order AD, v held.
    const rb::robot_lagrangian<T> lag{&m};
    const auto kinetic_gradient = [&](const dynamic_vector<T>& v) {
      return mc::gradient(
          [&](const dynamic_vector<mc::ad<T>>& q) {
            dynamic_vector<mc::ad<T>> rate(n);
            for (Eigen::Index i = 0; i < n; ++i) rate(i) = mc::lift<mc::ad<T>>(v(i));
            return lag.energies(q, rate).first;
          },
          s.q);
    };
    std::vector<dynamic_vector<T>> single(static_cast<std::size_t>(n));
    for (Eigen::Index i = 0; i < n; ++i) {
      dynamic_vector<T> e = zero;
      e(i) = T(1);
      single[std::size_t(i)] = kinetic_gradient(e);
    }
    dynamic_matrix<T> mdot(n, n);
    for (Eigen::Index i = 0; i < n; ++i) {
      mdot(i, i) = T(2) * T(single[std::size_t(i)].dot(s.qdot));
      for (Eigen::Index j = i + 1; j < n; ++j) {
        dynamic_vector<T> e = zero;
        e(i) = T(1);
        e(j) = T(1);
        const dynamic_vector<T> dm = kinetic_gradient(e) - single[std::size_t(i)] - single[std::size_t(j)];
        mdot(i, j) = mdot(j, i) = T(dm.dot(s.qdot));
      }
    }
    using std::abs;
    T vmax = T(0);
    for (Eigen::Index i = 0; i < n; ++i) vmax = std::max<T>(vmax, T(abs(s.qdot(i))));
    const rb::term_scale ts = rb::term_scales(m, gen::to_tier<double>(s.c.q));
    const T scale = T(ts.inertia + ts.mass) * (vmax + 1) * (vmax + 1) + T(ts.gravity);
    const double k = 192.0 * s.links + 8.0 * s.links * s.links;
    const dynamic_matrix<T> skew = mdot - T(2) * c;
    for (Eigen::Index i = 0; i < n; ++i)
      for (Eigen::Index j = i; j < n; ++j)
        check_zero("(Mdot - 2C)(" + std::to_string(i) + "," + std::to_string(j) + ") + (Mdot - 2C)(" +
                       std::to_string(j) + "," + std::to_string(i) + ")",
                   T(skew(i, j) + skew(j, i)), scale, k);
  }
};
MECHCHECK_LAW(christoffel);

}  // namespace
