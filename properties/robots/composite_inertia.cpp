#include "robots/robots.hpp"

namespace {
using namespace mechcheck::laws::robots;

struct composite_inertia {
  static law_info info() {
    return {"robots.composite_inertia",
            "M's diagonal is each joint's composite inertia: about a revolute axis a through the joint's "
            "origin, the sum over the links it carries of a^T (R I R^T + m (|r|^2 1 - r r^T)) a, r from the "
            "origin to the link's centre of mass (the inertia turned into the world, eq 142, and moved by "
            "the parallel-axis theorem, eq 160); along a prismatic axis, their total mass",
            {"142", "160"}};
  }
  // With every other joint held, q_k turns (or slides) the links it carries as one rigid
  // body, so M(k,k) = 2 T at qdot = e_k is that body's moment of inertia about the axis (or
  // its mass). M comes from nested AD of T built from the links' velocities; the composite
  // inertia from their positions and rotations alone. Each side sums the n links' terms of
  // size m r^2 + |I| after about 8 n roundings: k = 64 n on term_scales' inertia.
  template <class T>
  static void property() {
    const auto s = draw_robot<T>();
    const rb::robot_model<T>& m = s.model;
    const dynamic_matrix<T> mass = rb::motion_terms_at(m, s.q, s.qdot).mass_matrix;
    const std::vector<rb::link_state<T>> links = rb::link_states(m, s.q, s.qdot);
    const std::size_t nl = m.description.links.size(), nj = m.description.joints.size();
    std::vector<int> parent_joint(nl, -1);
    for (std::size_t j = 0; j < nj; ++j) parent_joint[std::size_t(m.tree.child_link[j])] = static_cast<int>(j);
    // Whether joint j lies on link l's path to the root (j carries l).
    const auto carries = [&](std::size_t j, std::size_t l) {
      for (int at = parent_joint[l]; at >= 0; at = parent_joint[std::size_t(m.tree.parent_link[std::size_t(at)])])
        if (std::size_t(at) == j) return true;
      return false;
    };
    const T scale = T(rb::term_scales(m, gen::to_tier<double>(s.c.q)).inertia);
    for (std::size_t j = 0; j < nj; ++j) {
      const int k = m.tree.coordinate[j];
      if (k < 0) continue;
      const rb::link_state<T>& joint_link = links[std::size_t(m.tree.child_link[j])];
      // The axis in the world: the child's frame turns about it, so R a is a in the joint frame.
      const mc::vector3<T> a = joint_link.rotation * m.axis[j];
      T expected = T(0);
      for (std::size_t l = 0; l < nl; ++l) {
        if (!(m.mass[l] > 0) || !carries(j, l)) continue;
        if (m.description.joints[j].type == rb::joint_type::prismatic) {
          expected += m.mass[l];
          continue;
        }
        const mc::matrix3<T>& r_l = links[l].rotation;
        const mc::vector3<T> r = links[l].origin + r_l * m.com[l] - joint_link.origin;
        const mc::matrix3<T> turned = r_l * m.inertia[l] * r_l.transpose();
        const mc::matrix3<T> about_origin =
            turned + m.mass[l] * (r.squaredNorm() * mc::matrix3<T>::Identity() - r * r.transpose());
        expected += a.dot(about_origin * a);
      }
      RC_TAG(rb::joint_type_name(m.description.joints[j].type));
      check_close("M(" + std::to_string(k) + "," + std::to_string(k) + ") = composite inertia of joint " +
                      m.description.joints[j].name,
                  mass(k, k), expected, scale, 64.0 * s.links);
    }
  }
};
MECHCHECK_LAW(composite_inertia);

}  // namespace
