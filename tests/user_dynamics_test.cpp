// Equations of motion of one's own (user_dynamics.hpp): a templated library judged in every
// tier, so that one computing in double is caught in float128 and mpfr50; a dropped
// centrifugal term caught in each; a C library's statuses, refusals and sizes as typed
// errors.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>

#include "mechcheck/audit/dynamics/user_dynamics.hpp"

namespace user_dynamics_test {
using namespace mechcheck;
namespace rb = mechcheck::robots;
namespace audit = mechcheck::audit;

/// A planar arm about z, hanging in gravity along -y: the elbow at (l1, 0, 0), the centres
/// of mass at (c, 0, 0) of their links.
rb::robot planar_arm() {
  rb::robot r;
  r.name = "planar_arm";
  r.gravity = {0, -9.81, 0};
  rb::inertial upper;
  upper.mass = 2;
  upper.origin.xyz = {0.5, 0, 0};
  upper.inertia = Eigen::Vector3d(0.125, 0.25, 0.25).asDiagonal();
  rb::inertial fore = upper;
  fore.mass = 1.5;
  fore.origin.xyz = {0.375, 0, 0};
  fore.inertia = Eigen::Vector3d(0.03125, 0.0625, 0.0625).asDiagonal();
  r.links = {{"base", std::nullopt}, {"upper", upper}, {"fore", fore}};
  rb::joint shoulder;
  shoulder.name = "shoulder";
  shoulder.parent = "base";
  shoulder.child = "upper";
  shoulder.axis = {0, 0, 1};
  rb::joint elbow = shoulder;
  elbow.name = "elbow";
  elbow.parent = "upper";
  elbow.child = "fore";
  elbow.origin.xyz = {1, 0, 0};
  r.joints = {shoulder, elbow};
  return r;
}

enum class variant { right, in_double, no_centrifugal };

/// The arm's closed form (angles about +z from +x), in S; `v` makes it wrong.
template <class T, variant v>
struct arm {
  double m1, m2, l1, c1, c2, i1, i2, g;
  explicit arm(const rb::robot& r)
      : m1(r.links[1].body->mass), m2(r.links[2].body->mass), l1(r.joints[1].origin.xyz(0)),
        c1(r.links[1].body->origin.xyz(0)), c2(r.links[2].body->origin.xyz(0)), i1(r.links[1].body->inertia(2, 2)),
        i2(r.links[2].body->inertia(2, 2)), g(-r.gravity(1)) {
    if (r.joints.size() != 2) throw audit::robot_refused("arm: not two joints");
  }
  template <class S>
  dynamic_matrix<S> mass(const dynamic_vector<S>& q) const {
    using std::cos;
    const S k = S(m2) * S(l1) * S(c2) * cos(q(1));
    dynamic_matrix<S> m(2, 2);
    m(0, 0) = S(i1) + S(i2) + S(m1) * S(c1) * S(c1) + S(m2) * (S(l1) * S(l1) + S(c2) * S(c2)) + 2 * k;
    m(0, 1) = m(1, 0) = S(i2) + S(m2) * S(c2) * S(c2) + k;
    m(1, 1) = S(i2) + S(m2) * S(c2) * S(c2);
    return m;
  }
  template <class S>
  dynamic_vector<S> forces(const dynamic_vector<S>& q, const dynamic_vector<S>& qdot) const {
    using std::cos;
    using std::sin;
    const S s = S(m2) * S(l1) * S(c2) * sin(q(1)), outer = S(g) * S(m2) * S(c2) * cos(S(q(0) + q(1)));
    const S centrifugal = v == variant::no_centrifugal ? S(0) : S(qdot(1) * qdot(1));
    dynamic_vector<S> h(2);
    h(0) = -s * (2 * qdot(0) * qdot(1) + centrifugal) + S(g) * (S(m1) * S(c1) + S(m2) * S(l1)) * cos(q(0)) + outer;
    h(1) = s * qdot(0) * qdot(0) + outer;
    return h;
  }
  dynamic_matrix<T> mass_matrix(const dynamic_vector<T>& q) const {
    if constexpr (v == variant::in_double) return mass<double>(q.template cast<double>()).template cast<T>();
    else return mass<T>(q);
  }
  dynamic_vector<T> bias(const dynamic_vector<T>& q, const dynamic_vector<T>& qdot) const {
    if constexpr (v == variant::in_double)
      return forces<double>(q.template cast<double>(), qdot.template cast<double>()).template cast<T>();
    else return forces<T>(q, qdot);
  }
};
template <class T>
using right_arm = arm<T, variant::right>;
template <class T>
using arm_in_double = arm<T, variant::in_double>;
template <class T>
using arm_without_centrifugal = arm<T, variant::no_centrifugal>;

audit::dynamics_options states(int n) {
  audit::dynamics_options o;
  o.robots = n;
  o.seed = 7;
  return o;
}

bool all_within(const audit::dynamics_campaign& c) { return c.agrees() && c.refused == 0; }

TEST(user_dynamics, a_templated_library_is_judged_in_every_tier) {
  const rb::robot r = planar_arm();
  const audit::templated_dynamics<right_arm> right{"arm", "closed form"};
  for (const auto& c : right.run_every_tier(states(10), &r)) {
    EXPECT_TRUE(all_within(c)) << c.library << ": " << c.disagreement << c.note;
    for (const auto& f : c.figures)
      if (f.quantity == audit::dynamics_quantity::mass_matrix || f.quantity == audit::dynamics_quantity::bias)
        EXPECT_EQ(f.checked, 10) << c.library;
  }
  // Computing in double and converting: within in double, caught in float128 and mpfr50 (an
  // error of 2^-53 is 2^60 eps of float128).
  const auto in_double = audit::templated_dynamics<arm_in_double>{"arm_in_double", "double inside"}.run_every_tier(
      states(10), &r);
  ASSERT_EQ(in_double.size(), 3u);
  EXPECT_TRUE(all_within(in_double[0])) << in_double[0].disagreement;
  EXPECT_FALSE(in_double[1].agrees());
  EXPECT_FALSE(in_double[2].agrees());
  // A dropped centrifugal term is caught in every tier, shrunk to a state with qdot_2 != 0.
  for (const auto& c : audit::templated_dynamics<arm_without_centrifugal>{"arm_no_centrifugal", "wrong"}.run_every_tier(
           states(10), &r)) {
    EXPECT_FALSE(c.agrees()) << c.library;
    EXPECT_NE(c.disagreement.find("bias forces"), std::string::npos) << c.disagreement;
  }
}

/// The arm's kinematics in closed form beside its dynamics: the frames of base, upper arm and
/// forearm (Rz(q1) at the origin, Rz(q1 + q2) at the elbow (l1 cos q1, l1 sin q1, 0)), their
/// Jacobians (the elbow moves with the shoulder at e_z x elbow) and Jdot qdot (the elbow's
/// centripetal -qdot1^2 elbow); in double inside where asked.
template <class T, bool in_double>
struct kinematic_arm : arm<T, variant::right> {
  using arm<T, variant::right>::arm;
  using S = std::conditional_t<in_double, double, T>;
  static S angle(const dynamic_vector<T>& q, int k) { return S(q(k)); }
  dynamic_matrix<T> frame_poses(const dynamic_vector<T>& q) const {
    using std::cos;
    using std::sin;
    dynamic_matrix<T> out = dynamic_matrix<T>::Zero(12, 3);
    const S a1 = angle(q, 0), a12 = S(angle(q, 0) + angle(q, 1));
    const S angles[3] = {S(0), a1, a12};
    for (int l = 0; l < 3; ++l) {
      out(3, l) = T(cos(angles[l])), out(4, l) = T(sin(angles[l]));    // x column
      out(6, l) = T(-sin(angles[l])), out(7, l) = T(cos(angles[l]));   // y column
      out(11, l) = T(1);                                               // z column
    }
    out(0, 2) = T(S(this->l1) * cos(a1));
    out(1, 2) = T(S(this->l1) * sin(a1));
    return out;
  }
  dynamic_matrix<T> frame_jacobians(const dynamic_vector<T>& q) const {
    using std::cos;
    using std::sin;
    dynamic_matrix<T> out = dynamic_matrix<T>::Zero(18, 2);
    const S a1 = angle(q, 0);
    out(11, 0) = T(1);
    out(12, 0) = T(-S(this->l1) * sin(a1)), out(13, 0) = T(S(this->l1) * cos(a1)), out(17, 0) = T(1);
    out(17, 1) = T(1);
    return out;
  }
  dynamic_vector<T> frame_bias_accelerations(const dynamic_vector<T>& q, const dynamic_vector<T>& qdot) const {
    using std::cos;
    using std::sin;
    dynamic_vector<T> out = dynamic_vector<T>::Zero(18);
    const S a1 = angle(q, 0), w = S(qdot(0));
    out(12) = T(-S(this->l1) * cos(a1) * w * w);
    out(13) = T(-S(this->l1) * sin(a1) * w * w);
    return out;
  }
  /// The centres of mass x1 = c1 e(q1), x2 = l1 e(q1) + c2 e(q1 + q2), e(a) = (cos a, sin a, 0),
  /// and their derivatives d1, d2 (3 x 2): the arm's c, J_c and A_G (spins i about z; the
  /// orbits' angular momentum about c along z, r_x v_y - r_y v_x).
  struct mass_terms {
    dynamic_vector<S> x1, x2, c;
    dynamic_matrix<S> d1, d2;
  };
  mass_terms masses(const dynamic_vector<T>& q) const {
    using std::cos;
    using std::sin;
    const S a1 = angle(q, 0), a12 = S(angle(q, 0) + angle(q, 1));
    const S c1 = S(this->c1), c2 = S(this->c2), l1 = S(this->l1), m1 = S(this->m1), m2 = S(this->m2);
    mass_terms t;
    t.x1 = dynamic_vector<S>::Zero(3), t.x2 = dynamic_vector<S>::Zero(3);
    t.d1 = dynamic_matrix<S>::Zero(3, 2), t.d2 = dynamic_matrix<S>::Zero(3, 2);
    t.x1(0) = c1 * cos(a1), t.x1(1) = c1 * sin(a1);
    t.x2(0) = l1 * cos(a1) + c2 * cos(a12), t.x2(1) = l1 * sin(a1) + c2 * sin(a12);
    t.d1(0, 0) = -c1 * sin(a1), t.d1(1, 0) = c1 * cos(a1);
    t.d2(0, 0) = -l1 * sin(a1) - c2 * sin(a12), t.d2(1, 0) = l1 * cos(a1) + c2 * cos(a12);
    t.d2(0, 1) = -c2 * sin(a12), t.d2(1, 1) = c2 * cos(a12);
    t.c = (t.x1 * m1 + t.x2 * m2) / (m1 + m2);
    return t;
  }
  /// Each link's Jacobian at its centre of mass: (dx/dq; e_z), the base's zero.
  dynamic_matrix<T> link_com_jacobians(const dynamic_vector<T>& q) const {
    const mass_terms t = masses(q);
    dynamic_matrix<S> out = dynamic_matrix<S>::Zero(18, 2);
    out.block(6, 0, 3, 2) = t.d1;
    out(11, 0) = S(1);
    out.block(12, 0, 3, 2) = t.d2;
    out(17, 0) = out(17, 1) = S(1);
    return out.template cast<T>();
  }
  dynamic_vector<T> centre_of_mass(const dynamic_vector<T>& q) const {
    return masses(q).c.template cast<T>();
  }
  dynamic_matrix<T> com_jacobian(const dynamic_vector<T>& q) const {
    const mass_terms t = masses(q);
    return dynamic_matrix<S>((t.d1 * S(this->m1) + t.d2 * S(this->m2)) / S(this->m1 + this->m2)).template cast<T>();
  }
  dynamic_matrix<T> centroidal_momentum_matrix(const dynamic_vector<T>& q) const {
    const mass_terms t = masses(q);
    const S m1 = S(this->m1), m2 = S(this->m2);
    dynamic_matrix<S> a = dynamic_matrix<S>::Zero(6, 2);
    a.topRows(3) = t.d1 * m1 + t.d2 * m2;
    const dynamic_vector<S> r1 = t.x1 - t.c, r2 = t.x2 - t.c;
    for (int k = 0; k < 2; ++k)
      a(5, k) = (k == 0 ? S(this->i1) : S(0)) + S(this->i2) + m1 * (r1(0) * t.d1(1, k) - r1(1) * t.d1(0, k)) +
                m2 * (r2(0) * t.d2(1, k) - r2(1) * t.d2(0, k));
    return a.template cast<T>();
  }
};
template <class T>
using arm_with_kinematics = kinematic_arm<T, false>;
template <class T>
using arm_with_kinematics_in_double = kinematic_arm<T, true>;

TEST(user_dynamics, a_templated_librarys_kinematics_are_judged_in_every_tier) {
  // Frames, Jacobians, Jdot qdot, the centre of mass, J_c and A_G found by their signatures
  // and held to forward kinematics in each tier; computed in double inside, caught in float128
  // and mpfr50.
  const rb::robot r = planar_arm();
  const auto kinematic = {audit::dynamics_quantity::frame_poses,    audit::dynamics_quantity::frame_jacobians,
                          audit::dynamics_quantity::frame_bias_accelerations, audit::dynamics_quantity::link_com_jacobians,
                          audit::dynamics_quantity::centre_of_mass,
                          audit::dynamics_quantity::com_jacobian,   audit::dynamics_quantity::centroidal_momentum_matrix};
  for (const auto& c : audit::templated_dynamics<arm_with_kinematics>{"arm", "closed form"}.run_every_tier(states(10), &r)) {
    EXPECT_TRUE(all_within(c)) << c.library << ": " << c.disagreement << c.note;
    for (const auto& f : c.figures)
      if (std::find(kinematic.begin(), kinematic.end(), f.quantity) != kinematic.end())
        EXPECT_EQ(f.checked, 10) << c.library << ": " << audit::dynamics_quantity_name(f.quantity);
  }
  const auto in_double = audit::templated_dynamics<arm_with_kinematics_in_double>{"arm_in_double", "double inside"}
                             .run_every_tier(states(10), &r);
  ASSERT_EQ(in_double.size(), 3u);
  EXPECT_TRUE(all_within(in_double[0])) << in_double[0].disagreement;
  for (int tier = 1; tier < 3; ++tier) {
    EXPECT_FALSE(in_double[std::size_t(tier)].agrees());
    const std::string& why = in_double[std::size_t(tier)].disagreement;
    EXPECT_TRUE(std::any_of(kinematic.begin(), kinematic.end(), [&](audit::dynamics_quantity q) {
      return why.find(std::string(audit::dynamics_quantity_name(q)) + ":") != std::string::npos;
    })) << why;
  }
}

// A C library: the arm in double behind C calls, with a status to return.
int status_to_return = 0;
void* c_load(const char* urdf, const double* gravity, char* why, int why_size) {
  if (std::strstr(urdf, "planar_arm") == nullptr) {
    std::snprintf(why, std::size_t(why_size), "only the planar arm");
    return nullptr;
  }
  rb::robot r = planar_arm();
  r.gravity = Eigen::Vector3d(gravity[0], gravity[1], gravity[2]);
  return new right_arm<double>(r);
}
void c_unload(void* h) { delete static_cast<right_arm<double>*>(h); }
int c_mass(void* h, int n, const double* q, double* m) {
  if (status_to_return) return status_to_return;
  Eigen::Map<Eigen::MatrixXd>(m, n, n) = static_cast<right_arm<double>*>(h)->mass_matrix(Eigen::Map<const Eigen::VectorXd>(q, n));
  return 0;
}

TEST(user_dynamics, a_c_library_is_judged_and_its_statuses_and_refusals_are_typed) {
  audit::c_dynamics c;
  c.name = "c_arm";
  c.load = &c_load;
  c.unload = &c_unload;
  c.mass_matrix = &c_mass;
  const audit::dynamics_library library = audit::c_dynamics_library(c);
  audit::dynamics_state x;
  x.q = Eigen::Vector2d(0.3, -0.7);
  x.qdot = Eigen::Vector2d(1.1, 0.4);
  x.qddot = Eigen::Vector2d(-0.5, 2.0);
  x.tau = Eigen::Vector2d(3.0, -1.0);
  const audit::dynamics_check ok = audit::check_dynamics(library, planar_arm(), x);
  ASSERT_EQ(ok.residuals.size(), 1u);  // the mass matrix only: the other functions are null
  EXPECT_TRUE(ok.residuals[0].within()) << ok.residuals[0].residual;
  rb::robot other = planar_arm();
  other.name = "another";
  const audit::dynamics_check refused = audit::check_dynamics(library, other, x);
  EXPECT_NE(refused.refused.find("c_arm refused robot another: only the planar arm"), std::string::npos)
      << refused.refused;
  status_to_return = 3;
  try {
    audit::check_dynamics(library, planar_arm(), x);
    ADD_FAILURE() << "a status was not reported";
  } catch (const audit::library_failure& e) {
    const std::string want = "c_arm: mass_matrix returned status 3 at q = (0.29999999999999999, -0.69999999999999996)";
    EXPECT_NE(std::string(e.what()).find(want), std::string::npos) << e.what();
  }
  status_to_return = 0;
  audit::c_dynamics no_load = c;
  no_load.load = nullptr;
  EXPECT_THROW(audit::c_dynamics_library(no_load), domain_error);
}

}  // namespace user_dynamics_test
