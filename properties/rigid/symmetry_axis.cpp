#include "rigid/bodies.hpp"

namespace {
using namespace mechcheck::laws::bodies;

struct symmetry_axis_is_principal {
  static law_info info() {
    return {"rigid.symmetry_axis",
            "An axis of symmetry is a principal axis: a cloud repeated under a rotation by "
            "120 degrees about n has n as an eigenvector, with the other two moments equal",
            {"142", "153"}};
  }
  // |I n x n| to ~8 eps of the scale after 3N-term sums: k = 8N + 32.
  template <class T>
  static void property() {
    const auto base = random_cloud<T>();
    // Any direction, by its spherical angles (no draw to discard: a rejection test on a
    // drawn vector's length discards most cases at RapidCheck's small early sizes).
    using std::cos;
    using std::sin;
    using std::sqrt;
    const T cos_theta = T(*gen::dyadic(-1, 1)), phi = T(*gen::dyadic(0, 6.25));
    const T sin_theta = sqrt(T(1 - cos_theta * cos_theta));
    const vector3<T> axis(sin_theta * cos(phi), sin_theta * sin(phi), cos_theta);
    const T angle = 2 * boost::math::constants::pi<T>() / 3;
    mc::point_cloud<T> cloud;
    for (int k = 0; k < 3; ++k) {
      const Eigen::AngleAxis<T> rot(T(k) * angle, axis);
      for (std::size_t a = 0; a < base.masses.size(); ++a) {
        cloud.masses.push_back(base.masses[a]);
        cloud.positions.push_back(rot * base.positions[a]);
      }
    }
    const matrix3<T> inertia = mc::inertia_tensor(cloud, vector3<T>(vector3<T>::Zero()));
    const T scale = cloud_scale(cloud, vector3<T>(vector3<T>::Zero()));
    const double k = 8.0 * cloud.masses.size() + 32;
    check_zero("|I n x n| for the symmetry axis n", T((inertia * axis).cross(axis).norm()), scale, k);
    RC_CLASSIFY(mc::classify(inertia, 1e4) != mc::top_kind::asymmetric, "symmetric top");
  }
};
MECHCHECK_LAW(symmetry_axis_is_principal);

}  // namespace
