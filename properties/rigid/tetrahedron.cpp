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
    std::array<vector3<T>, 4> v;
    for (auto& x : v) x = gen::draw_vector3<T>();
    const vector3<T> e1 = v[1] - v[0], e2 = v[2] - v[0], e3 = v[3] - v[0];
    using std::abs;
    RC_PRE(abs(T(e1.cross(e2).dot(e3))) > T(1) / 64);  // not flat
    T scale = lift<T>(0);
    for (const auto& x : v) scale += m * x.squaredNorm();
    check_matrices("tetrahedron closed form vs Gauss point masses",
                   mc::inertia_tensor(mc::reference::tetrahedron_points(m, v), vector3<T>(vector3<T>::Zero())),
                   mc::reference::tetrahedron_inertia(m, v), scale, 64);
  }
};
MECHCHECK_LAW(tetrahedron_tensor);

}  // namespace
