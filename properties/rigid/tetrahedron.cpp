#include "rigid/bodies.hpp"

namespace {
using namespace mechcheck::laws::bodies;

struct tetrahedron_tensor {
  static law_info info() {
    return {"rigid.tetrahedron",
            "A tetrahedron (no symmetry): the closed form equals its exact Gauss point-mass "
            "equivalent, and it is an asymmetric top in general",
            {"138", "141"}};
  }
  // Sums of 4-10 products of vertex coordinates: k = 64 on M sum |v|^2.
  template <class T>
  static void property() {
    const T m = T(*gen::positive());
    // Not flat by construction: edges v_i - v_0 = s_i e_i + d_i with s_i in [1/2, 2] and
    // |d_i| components <= 1/8 form a strictly diagonally dominant matrix (|det| >= 1/512),
    // then the whole body is rotated (no rejection: that discards most small early cases).
    std::array<vector3<T>, 4> v;
    v[0] = gen::draw_vector3<T>();
    const Eigen::AngleAxis<T> turn(T(*gen::dyadic(0, 6.25)),
                                   vector3<T>(T(*gen::dyadic(0.25, 1)), T(*gen::dyadic(-1, 1)),
                                              T(*gen::dyadic(-1, 1))).normalized());
    for (int i = 1; i <= 3; ++i) {
      vector3<T> edge;
      for (int c = 0; c < 3; ++c) edge(c) = T(*gen::dyadic(-0.125, 0.125));
      edge(i - 1) += T(*gen::dyadic(0.5, 2));
      v[i] = v[0] + turn * edge;
    }
    T scale = lift<T>(0);
    for (const auto& x : v) scale += m * x.squaredNorm();
    check_matrices("tetrahedron closed form vs Gauss point masses",
                   mc::inertia_tensor(mc::reference::tetrahedron_points(m, v), vector3<T>(vector3<T>::Zero())),
                   mc::reference::tetrahedron_inertia(m, v), scale, 64);
  }
};
MECHCHECK_LAW(tetrahedron_tensor);

}  // namespace
