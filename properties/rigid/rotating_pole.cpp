#include "rigid/bodies.hpp"

namespace {
using namespace mechcheck::laws::bodies;

/// Lecture 13, eqs 118-119: two masses m at distance r from an axis z, on a pole
/// perpendicular to it, turning at Omega about z: each moves at v = Omega x r, and
/// M_z = sum m (r x v)_z = 2 m r^2 Omega = I_z Omega, I_z the zz entry of the inertia
/// tensor (eq 138) of the two points.
struct rotating_pole {
  static law_info info() {
    return {"rigid.rotating_pole",
            "Two masses on a pole turning about z: M_z = sum m (r x (Omega x r))_z = 2 m r^2 "
            "Omega = I_z Omega",
            {"118", "119"}};
  }
  // Cross products of a few roundings each: scale 2 m r^2 |Omega|, budget 16.
  template <class T>
  static void property() {
    using std::abs;
    using std::cos;
    using std::sin;
    const T m = T(*gen::positive()), r = T(*gen::positive()), angle = T(*gen::coordinate());
    const T omega = T(*gen::dyadic(-4, 4));
    const vector3<T> arm(r * cos(angle), r * sin(angle), lift<T>(0));
    const vector3<T> spin(lift<T>(0), lift<T>(0), omega);
    vector3<T> momentum = vector3<T>::Zero();
    for (const vector3<T>& x : {arm, vector3<T>(-arm)}) momentum += m * x.cross(spin.cross(x));
    const mc::point_cloud<T> cloud{{m, m}, {arm, vector3<T>(-arm)}};
    const T iz = mc::inertia_tensor(cloud, vector3<T>(vector3<T>::Zero()))(2, 2);
    const T scale = 2 * m * r * r * abs(omega);
    check_close("M_z against I_z Omega (eq 118)", momentum(2), T(iz * omega), scale, 16);
    check_close("M_z against 2 m r^2 Omega (eq 119)", momentum(2), T(2 * m * r * r * omega), scale,
                16);
  }
};
MECHCHECK_LAW(rotating_pole);

}  // namespace
