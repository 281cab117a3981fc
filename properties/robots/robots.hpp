#pragma once
/// Robots: the equations of motion of a kinematic tree from its Lagrangian (notes lectures
/// 1-3, eqs 1-27; the links' inertia, lectures 13-16). The laws run on random robots
/// (generators.hpp: random_robots, robot_cases) in every tier.
///
/// Tolerance model: T and V are sums over the n links of products along the tree: each
/// level composes a 3x3 rotation (3-term dot products) and a cross product, so a link's
/// terms carry about 8 n roundings; M and h come from nested AD of that sum. k = 64 n on
/// the scale of the terms before they cancel (robots::term_scales: sum m lever^2 + |I| for
/// M, times |qdot|^2 for the velocity terms, sum m |g| lever for gravity), and the
/// forward dynamics through a Cholesky solve adds cond(M).

#include <algorithm>
#include <cmath>
#include <vector>

#include "mechcheck/harness/generators.hpp"
#include "mechcheck/harness/law.hpp"

namespace mechcheck::laws::robots {

namespace mc = mechcheck;
namespace gen = mechcheck::generators;
namespace rb = mechcheck::robots;
using mc::dynamic_matrix;
using mc::dynamic_vector;
using mc::matrix3;
using mc::vector3;
using mc::harness::check_close;
using mc::harness::check_zero;
using mc::harness::law_info;

/// A random robot of at most 4 links with its state, in T (4 keeps the mpfr50 tier's
/// nested AD within seconds a case).
template <class T>
struct robot_sample {
  gen::robot_case c;
  rb::robot_model<T> model;
  dynamic_vector<T> q, qdot, qddot, tau;
  int links;
  explicit robot_sample(gen::robot_case rc)
      : c(std::move(rc)), model(c.robot), q(gen::to_tier<T>(c.q)), qdot(gen::to_tier<T>(c.qdot)),
        qddot(gen::to_tier<T>(c.qddot)), tau(gen::to_tier<T>(c.tau)), links(model.dofs()) {
    const std::size_t joints = c.robot.joints.size();
    RC_TAG(std::to_string(joints) + (joints == 1 ? " joint" : " joints"));
  }
};

/// The links' total momentum P and angular momentum about the world's origin, sum (R I R^T
/// omega + m x x v), summed link by link from their states: the laws' own sum, apart from
/// robots::detail::momenta_of.
template <class T>
struct summed_momenta {
  vector3<T> linear = vector3<T>::Zero(), about_origin = vector3<T>::Zero();
  summed_momenta(const rb::robot_model<T>& m, const std::vector<rb::link_state<T>>& links) {
    for (std::size_t l = 0; l < links.size(); ++l) {
      if (!(m.mass[l] > 0)) continue;
      const vector3<T> r = links[l].rotation * m.com[l];
      const vector3<T> x = links[l].origin + r, v = links[l].velocity + links[l].omega.cross(r);
      about_origin += links[l].rotation * (m.inertia[l] * (links[l].rotation.transpose() * links[l].omega)) +
                      m.mass[l] * x.cross(v);
      linear += m.mass[l] * v;
    }
  }
};

template <class T>
robot_sample<T> draw_robot() {
  return robot_sample<T>(*gen::robot_cases(4));
}

/// A random robot of at most max_links links whose every moving joint draws an armature and a
/// damping (gen::draw_joint_terms): one generated value, so that a counterexample prints the
/// robot with its terms.
inline rc::Gen<gen::robot_case> dressed_robot_cases(int max_links = 4) {
  return rc::gen::exec([max_links] {
    gen::robot_case c = *gen::robot_cases(max_links);
    gen::draw_joint_terms(c.robot, true, true);
    return c;
  });
}

/// vee of the antisymmetric part of A: (A - A^T)/2 = [w]x.
template <class T>
mc::vector3<T> vee_antisymmetric(const mc::matrix3<T>& a) {
  return mc::vector3<T>(a(2, 1) - a(1, 2), a(0, 2) - a(2, 0), a(1, 0) - a(0, 1)) / T(2);
}

/// The rotation of a pose written as 12 numbers (a point, then R row by row).
template <class T>
mc::matrix3<T> rotation_of(const dynamic_vector<T>& pose) {
  mc::matrix3<T> r;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) r(i, j) = pose(3 + 3 * i + j);
  return r;
}

template <class T>
T max_abs(const dynamic_matrix<T>& m) {
  T out = T(0);
  using std::abs;
  for (Eigen::Index i = 0; i < m.size(); ++i) out = std::max<T>(out, T(abs(m(i))));
  return out;
}

}  // namespace mechcheck::laws::robots
