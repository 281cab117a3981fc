#pragma once
// The planar two-link arm and the free rigid body that the robots' tests and the dynamics
// audit's tests pin their references to, their closed forms, and a property run from
// MECHCHECK_SEED's seed.

#include <cmath>
#include <cstdlib>
#include <optional>
#include <sstream>
#include <string>
#include <utility>

#include <Eigen/Core>
#include <rapidcheck.h>

#include "mechcheck/robots.hpp"

namespace robots_test {
namespace rb = mechcheck::robots;

/// A property over `cases` random cases from MECHCHECK_SEED's seed (20261126 without it):
/// "" when it holds, else the shrunk counterexample's message (RapidCheck's report).
template <class F>
std::string seeded_check(int cases, F&& property) {
  rc::detail::TestParams params;
  params.maxSuccess = cases;
  const char* seed = std::getenv("MECHCHECK_SEED");
  params.seed = seed && *seed ? std::strtoull(seed, nullptr, 10) : 20261126;
  const rc::detail::TestResult outcome = rc::detail::checkTestable(std::forward<F>(property), rc::detail::TestMetadata{}, params);
  rc::detail::FailureResult failure;
  if (outcome.match(failure)) {
    std::ostringstream s;
    s << failure;
    return s.str();
  }
  rc::detail::GaveUpResult gave_up;
  if (outcome.match(gave_up)) return "gave up: " + gave_up.description;
  return "";
}

/// A planar two-link arm hinged about y, hanging along -z: link lengths l1 (the elbow at
/// (0, 0, -l1) in the upper arm's frame), centres of mass c1, c2 below their hinges,
/// moments about y I1, I2 (the others arbitrary).
inline rb::robot two_link_arm(double m1, double m2, double l1, double c1, double c2, double i1, double i2) {
  rb::robot r;
  r.name = "two_link_arm";
  r.links.push_back({"base", std::nullopt});
  rb::inertial a;
  a.mass = m1;
  a.origin.xyz = {0, 0, -c1};
  a.inertia = Eigen::Vector3d(0.5, i1, 0.25).asDiagonal();
  r.links.push_back({"upper", a});
  rb::inertial b = a;
  b.mass = m2;
  b.origin.xyz = {0, 0, -c2};
  b.inertia = Eigen::Vector3d(0.125, i2, 0.0625).asDiagonal();
  r.links.push_back({"fore", b});
  rb::joint shoulder;
  shoulder.name = "shoulder";
  shoulder.parent = "base";
  shoulder.child = "upper";
  shoulder.axis = {0, 1, 0};
  r.joints.push_back(shoulder);
  rb::joint elbow = shoulder;
  elbow.name = "elbow";
  elbow.parent = "upper";
  elbow.child = "fore";
  elbow.origin.xyz = {0, 0, -l1};
  r.joints.push_back(elbow);
  return r;
}

struct arm_closed_form {
  Eigen::Matrix2d m;
  Eigen::Vector2d h;
};

/// The arm's M and h (Spong, Hutchinson and Vidyasagar, Robot Modeling and Control, 7.4.2,
/// with angles about +y from the downward vertical): rotation about +y takes -z towards -x,
/// so a link's centre of mass is at height -c cos(angle) and V = -sum m g c cos(angle).
inline arm_closed_form arm_terms(double m1, double m2, double l1, double c1, double c2, double i1, double i2, double g,
                          const Eigen::Vector2d& q, const Eigen::Vector2d& qdot) {
  const double c = std::cos(q(1)), s = std::sin(q(1));
  arm_closed_form out;
  out.m(0, 0) = m1 * c1 * c1 + i1 + m2 * (l1 * l1 + c2 * c2 + 2 * l1 * c2 * c) + i2;
  out.m(0, 1) = out.m(1, 0) = m2 * (c2 * c2 + l1 * c2 * c) + i2;
  out.m(1, 1) = m2 * c2 * c2 + i2;
  const double k = m2 * l1 * c2 * s;
  out.h(0) = -k * (2 * qdot(0) * qdot(1) + qdot(1) * qdot(1)) + m1 * g * c1 * std::sin(q(0)) +
             m2 * g * (l1 * std::sin(q(0)) + c2 * std::sin(q(0) + q(1)));
  out.h(1) = k * qdot(0) * qdot(0) + m2 * g * c2 * std::sin(q(0) + q(1));
  return out;
}

/// A free rigid body (a floating base and no joints): mass 3, its centre of mass at c =
/// (0.25, -0.125, 0.5) and a full inertia I about it, both in its own frame, under a
/// gravity off the vertical.
/// The two-link arm (m1 2, m2 1.5, l1 1, c1 1/2, c2 3/8, i1 1/4, i2 1/16) on a floating base:
/// its base link given a torso of 5 kg, its centre of mass at (1/8, 0, 1/4), moments (1/2, 1/2,
/// 1/4).
inline rb::robot floating_two_link_arm() {
  rb::robot r = two_link_arm(2, 1.5, 1, 0.5, 0.375, 0.25, 0.0625);
  r.floating = true;
  rb::inertial torso;
  torso.mass = 5;
  torso.origin.xyz = {0.125, 0, 0.25};
  torso.inertia = Eigen::Vector3d(0.5, 0.5, 0.25).asDiagonal();
  r.links[0].body = torso;
  return r;
}

inline rb::robot free_body() {
  rb::robot r;
  r.name = "free_body";
  r.floating = true;
  rb::inertial b;
  b.mass = 3;
  b.origin.xyz = {0.25, -0.125, 0.5};
  b.inertia << 0.5, 0.0625, -0.03125, 0.0625, 0.375, 0.125, -0.03125, 0.125, 0.75;
  r.links.push_back({"body", b});
  r.gravity = {0.5, -1, -9.75};
  return r;
}

template <class T>
struct free_body_closed_form {
  mechcheck::dynamic_matrix<T> m;  ///< M, 6 x 6
  mechcheck::dynamic_vector<T> q;  ///< Q = M udot + h = (f; n)
};

/// The free body's M and Q at the base rotation R in its body twist u = (v; w) and its rate:
/// Newton and Euler about its origin, f = m (vdot + w x v + wdot x c + w x (w x c) - R^T g) and
/// n = I wdot + w x I w + c x f, and M = [m 1, -m [c]x; m [c]x, I + m (|c|^2 1 - c c^T)].
template <class T>
free_body_closed_form<T> free_body_terms(const rb::robot& r, const mechcheck::matrix3<T>& rotation,
                                         const mechcheck::dynamic_vector<T>& u, const mechcheck::dynamic_vector<T>& udot) {
  using mechcheck::matrix3;
  using mechcheck::vector3;
  const rb::inertial& b = *r.links.front().body;
  const vector3<T> v = u.head(3), w = u.tail(3), vd = udot.head(3), wd = udot.tail(3);
  const vector3<T> c = b.origin.xyz.cast<T>();
  const matrix3<T> inertia = b.inertia.cast<T>();
  const vector3<T> g_body = rotation.transpose() * r.gravity.cast<T>();
  const vector3<T> f = (vd + w.cross(v) + wd.cross(c) + w.cross(w.cross(c)) - g_body) * T(b.mass);
  const vector3<T> n = inertia * wd + w.cross(vector3<T>(inertia * w)) + c.cross(f);
  free_body_closed_form<T> out;
  out.q.resize(6);
  out.q << f, n;
  out.m = mechcheck::dynamic_matrix<T>::Zero(6, 6);
  matrix3<T> lever;
  lever << T(0), -c(2), c(1), c(2), T(0), -c(0), -c(1), c(0), T(0);
  out.m.block(0, 0, 3, 3) = matrix3<T>::Identity() * T(b.mass);
  out.m.block(0, 3, 3, 3) = -lever * T(b.mass);
  out.m.block(3, 0, 3, 3) = lever * T(b.mass);
  out.m.block(3, 3, 3, 3) = inertia + (matrix3<T>::Identity() * c.squaredNorm() - c * c.transpose()) * T(b.mass);
  return out;
}

}  // namespace robots_test
