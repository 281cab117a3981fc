#include "robots/robots.hpp"

namespace {
using namespace mechcheck::laws::robots;

struct base_frame {
  static law_info info() {
    return {"robots.base_frame",
            "A robot's kinetic energy, mass matrix and velocity terms h(q, qdot) - g(q) do not depend on where "
            "its base stands: moved by any rotation and translation (a fixed joint under a new root), T, M and "
            "h - g are unchanged",
            {"134"}};
  }
  // The moved robot's links have other world positions and rotations at every q, so the
  // kinematics run on other numbers; T is a scalar of the motion relative to an inertial
  // frame. Gravity stays the world's, so V and g do change. Both computations round as M and
  // h do: k = 2 x 64 n (one more level in the tree) on the terms' scale (term_scales of
  // the first robot; the velocity terms times |qdot|^2, plus the gravity h - g cancels).
  template <class T>
  static void property() {
    const auto s = draw_robot<T>();
    rb::robot moved = s.c.robot;
    rb::joint base;
    base.name = "base_pose";
    base.type = rb::joint_type::fixed;
    base.parent = "moved_world";
    base.child = s.model.description.links[std::size_t(s.model.tree.root)].name;
    for (int i = 0; i < 3; ++i) {
      base.origin.xyz(i) = *gen::dyadic(-2, 2);
      base.origin.rpy(i) = *gen::dyadic(-3.14, 3.14);
    }
    moved.links.insert(moved.links.begin(), rb::link{"moved_world", std::nullopt});
    moved.joints.push_back(base);
    const rb::robot_model<T> other(moved);
    const Eigen::Index n = s.q.size();
    const dynamic_vector<T> zero = dynamic_vector<T>::Zero(n);
    const rb::motion_terms<T> a = rb::motion_terms_at(s.model, s.q, s.qdot);
    const rb::motion_terms<T> b = rb::motion_terms_at(other, s.q, s.qdot);
    const dynamic_vector<T> va = a.bias - rb::bias_forces(s.model, s.q, zero);
    const dynamic_vector<T> vb = b.bias - rb::bias_forces(other, s.q, zero);
    using std::abs;
    T vmax = T(0);
    for (Eigen::Index i = 0; i < n; ++i) vmax = std::max<T>(vmax, T(abs(s.qdot(i))));
    const rb::term_scale ts = rb::term_scales(s.model, gen::to_tier<double>(s.c.q));
    const T inertia = T(ts.inertia + ts.mass);
    const double k = 128.0 * s.links;
    check_close("T", b.kinetic, a.kinetic, T(inertia * vmax * vmax), k);
    for (Eigen::Index i = 0; i < n; ++i) {
      for (Eigen::Index j = 0; j < n; ++j)
        check_close("M(" + std::to_string(i) + "," + std::to_string(j) + ")", b.mass_matrix(i, j),
                    a.mass_matrix(i, j), inertia, k);
      check_close("(h - g)(" + std::to_string(i) + ")", vb(i), va(i), T(inertia * vmax * vmax + T(ts.gravity)), k);
    }
  }
};
MECHCHECK_LAW(base_frame);

}  // namespace
