#include "rigid/bodies.hpp"

namespace {
using namespace mechcheck::laws::bodies;

struct parallel_axis_theorem {
  static law_info info() {
    return {"rigid.parallel_axis",
            "Parallel-axis theorem: I about c + b = I_cm + M(|b|^2 delta - b b^T), both ways",
            {"157", "158", "159", "160"}};
  }
  // Entries are sums over N points (and the centre of mass a weighted mean): k = 4N + 16
  // on the cloud's scale, for the direct tensor against the shifted one and back.
  template <class T>
  static void property() {
    const auto cloud = random_cloud<T>();
    const vector3<T> b = gen::draw_vector3<T>();
    const vector3<T> c = mc::centre_of_mass(cloud);
    const T m = cloud.total_mass();
    const matrix3<T> about_centre = mc::inertia_tensor(cloud, c);
    const matrix3<T> about_point = mc::inertia_tensor(cloud, vector3<T>(c + b));
    const T scale = cloud_scale(cloud, vector3<T>(c + b));
    const double k = 4.0 * cloud.masses.size() + 16;
    check_matrices("I(c + b) vs shift_from_centre", about_point,
                   mc::shift_from_centre(about_centre, m, b), scale, k);
    check_matrices("round trip shift_to_centre(shift_from_centre)",
                   mc::shift_to_centre(mc::shift_from_centre(about_centre, m, b), m, b),
                   about_centre, scale, k);
    mc::validate_inertia(about_point, "rigid.parallel_axis");  // must not fire on round-off
  }
};
MECHCHECK_LAW(parallel_axis_theorem);

}  // namespace
