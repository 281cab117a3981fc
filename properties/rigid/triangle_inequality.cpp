#include "rigid/bodies.hpp"

namespace {
using namespace mechcheck::laws::bodies;

struct triangle_inequality {
  static law_info info() {
    return {"rigid.triangle_inequality",
            "Principal moments satisfy I1 + I2 >= I3 (and are non-negative)",
            {"154", "155", "156"}};
  }
  // Eigenvalues to ~16 eps of |I|, tensor entries to (N + 4) eps of the scale: k = 4N + 32.
  template <class T>
  static void property() {
    const auto cloud = random_cloud<T>();
    const vector3<T> o = gen::draw_vector3<T>();
    const matrix3<T> inertia = mc::inertia_tensor(cloud, o);
    const vector3<T> mom = mc::principal_axes(inertia).moments;
    const T scale = cloud_scale(cloud, o);
    const double k = 4.0 * cloud.masses.size() + 32;
    const T slack = T(k) * mc::tier_epsilon<T>() * scale;
    RC_ASSERT(mom(0) + mom(1) >= mom(2) - slack);
    RC_ASSERT(mom(0) >= -slack);
    // I1 + I2 - I3 = 2 sum m z^2 in the principal frame (eq 155): check it exactly.
    const auto frame = mc::principal_axes(inertia);
    T z2 = lift<T>(0);
    for (std::size_t a = 0; a < cloud.masses.size(); ++a) {
      const T z = frame.axes.col(2).dot(vector3<T>(cloud.positions[a] - o));
      z2 += cloud.masses[a] * z * z;
    }
    check_close("I1 + I2 - I3 vs 2 sum m z^2 (eq 155)", T(mom(0) + mom(1) - mom(2)), T(2 * z2),
                scale, k);
  }
};
MECHCHECK_LAW(triangle_inequality);

}  // namespace
