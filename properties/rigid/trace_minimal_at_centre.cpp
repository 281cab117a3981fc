#include "rigid/bodies.hpp"

namespace {
using namespace mechcheck::laws::bodies;

struct trace_minimal_at_centre {
  static law_info info() {
    return {"rigid.trace_minimal_at_centre",
            "The trace of the inertia tensor is smallest about the centre of mass: "
            "tr I(c + b) = tr I_cm + 2 M |b|^2",
            {"138", "160"}};
  }
  // Traces sum 3N terms: k = 4N + 16.
  template <class T>
  static void property() {
    const auto cloud = random_cloud<T>();
    const vector3<T> b = gen::draw_vector3<T>();
    const vector3<T> c = mc::centre_of_mass(cloud);
    const T tc = mc::inertia_tensor(cloud, c).trace();
    const T tb = mc::inertia_tensor(cloud, vector3<T>(c + b)).trace();
    const T scale = cloud_scale(cloud, vector3<T>(c + b));
    check_close("tr I(c + b) - tr I_cm vs 2 M |b|^2", T(tb - tc),
                T(2 * cloud.total_mass() * b.squaredNorm()), scale,
                4.0 * cloud.masses.size() + 16);
    RC_ASSERT(tb >= tc - T(4 * cloud.masses.size() + 16) * mc::tier_epsilon<T>() * scale);
  }
};
MECHCHECK_LAW(trace_minimal_at_centre);

}  // namespace
