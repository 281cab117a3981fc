#include "robots/robots.hpp"

namespace {
using namespace mechcheck::laws::robots;

struct mass_matrix {
  static law_info info() {
    return {"robots.mass_matrix",
            "A robot's mass matrix M = d2T/dqdot2 is symmetric positive definite and T = qdot^T M qdot / 2 "
            "(T homogeneous of degree 2 in the velocities)",
            {"1", "134"}};
  }
  // M from nested AD of T: each entry a sum over the links (k = 64 n on the scale of its
  // terms, sum m r^2 + |I|);
  // T against qdot^T M qdot / 2: n^2 more products (k = 64 n + 2 n^2 on |M|_max |qdot|^2).
  template <class T>
  static void property() {
    const auto s = draw_robot<T>();
    const rb::motion_terms<T> e = rb::motion_terms_at(s.model, s.q, s.qdot);
    const dynamic_matrix<T>& m = e.mass_matrix;
    // The entries' terms before they cancel (a centre of mass near the axis): term_scales.
    const T scale = std::max<T>(max_abs(m), T(rb::term_scales(s.model, gen::to_tier<double>(s.c.q)).inertia));
    RC_ASSERT(scale > T(0));
    const double k = 64.0 * s.links;
    for (Eigen::Index i = 0; i < m.rows(); ++i)
      for (Eigen::Index j = i + 1; j < m.cols(); ++j)
        check_close("M(" + std::to_string(i) + "," + std::to_string(j) + ") = M(" + std::to_string(j) + "," +
                        std::to_string(i) + ")",
                    m(i, j), m(j, i), scale, k);
    const Eigen::LLT<dynamic_matrix<T>> llt(m);
    RC_ASSERT(llt.info() == Eigen::Success);
    using std::abs;
    T v2 = T(0);
    for (Eigen::Index i = 0; i < s.qdot.size(); ++i) v2 = std::max<T>(v2, T(abs(s.qdot(i))));
    const T quadratic = T(s.qdot.dot(m * s.qdot)) / 2;
    check_close("T = qdot^T M qdot / 2", e.kinetic, quadratic, T(scale * (v2 * v2 + 1)),
                k + 2.0 * s.links * s.links);
  }
};
MECHCHECK_LAW(mass_matrix);

}  // namespace
