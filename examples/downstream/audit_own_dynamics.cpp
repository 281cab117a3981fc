// Audit our own equations of motion: a planar two-link arm's mass matrix and bias forces in
// closed form, templated on the scalar, held to the exact Lagrangian of the arm read from
// two_link_arm.urdf in double, float128 and mpfr50; and the same formulas behind C calls
// (what a library in C or behind a C API offers), in double. Any robot that is not such an
// arm is refused by name. We fail when a residual exceeds its budget.
#include <cmath>
#include <cstdio>
#include <iostream>
#include <string>

#include <mechcheck/audit/dynamics/dynamics.hpp>
#include <mechcheck/audit/problems/urdf.hpp>
#include <mechcheck/audit/dynamics/user_dynamics.hpp>

namespace downstream {

namespace mc = mechcheck;
namespace rb = mechcheck::robots;

/// The arm's numbers, read from a description: two revolute joints about z, each link's
/// centre of mass on its x axis, gravity in the plane (along -y).
struct arm_numbers {
  double m1, c1, i1, l1, m2, c2, i2, g;
};

arm_numbers read_arm(const rb::robot& r) {
  const auto refuse = [&](const std::string& why) { throw mc::audit::robot_refused("two_link_arm: " + why); };
  if (r.joints.size() != 2 || r.links.size() != 3) refuse("not two joints and three links");
  for (const rb::joint& j : r.joints) {
    if (j.type != rb::joint_type::revolute && j.type != rb::joint_type::continuous) refuse("joint " + j.name + " does not turn");
    if (j.axis != Eigen::Vector3d::UnitZ() || !j.origin.rpy.isZero()) refuse("joint " + j.name + " is not about z");
  }
  if (!r.joints[0].origin.xyz.isZero() || r.joints[1].origin.xyz.tail(2).norm() != 0)
    refuse("the elbow is not on the first link's x axis");
  if (r.gravity(0) != 0 || r.gravity(2) != 0) refuse("gravity is not along y");
  arm_numbers a{};
  for (int k = 1; k <= 2; ++k) {
    const auto& body = r.links[std::size_t(k)].body;
    if (!body || body->origin.xyz.tail(2).norm() != 0 || !body->origin.rpy.isZero())
      refuse("link " + r.links[std::size_t(k)].name + "'s centre of mass is not on its x axis");
    (k == 1 ? a.m1 : a.m2) = body->mass;
    (k == 1 ? a.c1 : a.c2) = body->origin.xyz(0);
    (k == 1 ? a.i1 : a.i2) = body->inertia(2, 2);
  }
  a.l1 = r.joints[1].origin.xyz(0);
  a.g = -r.gravity(1);
  return a;
}

/// M(q) and h(q, qdot) of the arm, in any scalar T (the textbook's closed form).
template <class T>
struct two_link_arm {
  arm_numbers a;
  explicit two_link_arm(const rb::robot& r) : a(read_arm(r)) {}

  mc::dynamic_matrix<T> mass_matrix(const mc::dynamic_vector<T>& q) const {
    using std::cos;
    const T m2 = T(a.m2), c2 = T(a.c2), l1 = T(a.l1), c1 = T(a.c1);
    const T k = m2 * l1 * c2 * cos(q(1));
    mc::dynamic_matrix<T> m(2, 2);
    m(0, 0) = T(a.i1) + T(a.i2) + T(a.m1) * c1 * c1 + m2 * (l1 * l1 + c2 * c2) + 2 * k;
    m(0, 1) = m(1, 0) = T(a.i2) + m2 * c2 * c2 + k;
    m(1, 1) = T(a.i2) + m2 * c2 * c2;
    return m;
  }

  mc::dynamic_vector<T> bias(const mc::dynamic_vector<T>& q, const mc::dynamic_vector<T>& qdot) const {
    using std::cos;
    using std::sin;
    const T m2 = T(a.m2), c2 = T(a.c2), l1 = T(a.l1), g = T(a.g);
    const T s = m2 * l1 * c2 * sin(q(1));
    const T outer = g * m2 * c2 * cos(T(q(0) + q(1)));
    mc::dynamic_vector<T> h(2);
    h(0) = -s * (2 * qdot(0) * qdot(1) + qdot(1) * qdot(1)) + g * (T(a.m1) * T(a.c1) + m2 * l1) * cos(q(0)) + outer;
    h(1) = s * qdot(0) * qdot(0) + outer;
    return h;
  }
};

// The same arm behind C calls: a handle from the URDF text, statuses for results.
void* arm_load(const char* urdf, const double* gravity, char* why, int why_size) {
  try {
    rb::robot r = mc::audit::parse_urdf(urdf);
    r.gravity = Eigen::Vector3d(gravity[0], gravity[1], gravity[2]);
    return new two_link_arm<double>(r);
  } catch (const std::exception& e) {
    std::snprintf(why, std::size_t(why_size), "%s", e.what());
    return nullptr;
  }
}
void arm_unload(void* handle) { delete static_cast<two_link_arm<double>*>(handle); }
int arm_mass_matrix(void* handle, int n, const double* q, double* m) {
  if (n != 2) return 1;
  const Eigen::Map<const Eigen::VectorXd> x(q, 2);
  Eigen::Map<Eigen::MatrixXd>(m, 2, 2) = static_cast<two_link_arm<double>*>(handle)->mass_matrix(x);
  return 0;
}
int arm_bias(void* handle, int n, const double* q, const double* qdot, double* h) {
  if (n != 2) return 1;
  const Eigen::Map<const Eigen::VectorXd> x(q, 2), v(qdot, 2);
  Eigen::Map<Eigen::VectorXd>(h, 2) = static_cast<two_link_arm<double>*>(handle)->bias(x, v);
  return 0;
}

}  // namespace downstream

int main(int argc, char** argv) {
  namespace audit = mechcheck::audit;
  const std::string file = argc > 1 ? argv[1] : "two_link_arm.urdf";
  mechcheck::robots::robot arm = audit::read_urdf(file);
  arm.gravity = Eigen::Vector3d(0, -9.81, 0);  // URDF has no gravity: the arm hangs in its plane
  audit::dynamics_options options;
  options.robots = 50;  // states of the arm

  const audit::templated_dynamics<downstream::two_link_arm> templated{
      "two_link_arm", "examples/downstream/audit_own_dynamics.cpp: M and h in closed form, templated"};
  std::vector<audit::dynamics_campaign> campaigns = templated.run_every_tier(options, &arm);

  audit::c_dynamics c;
  c.name = "two_link_arm_c";
  c.origin = "examples/downstream/audit_own_dynamics.cpp: the same formulas behind C calls";
  c.load = &downstream::arm_load;
  c.unload = &downstream::arm_unload;
  c.mass_matrix = &downstream::arm_mass_matrix;
  c.bias = &downstream::arm_bias;
  campaigns.push_back(audit::run_dynamics_on(audit::c_dynamics_library(c), arm, options));

  audit::print_dynamics(std::cout, campaigns);
  bool agree = true;
  for (const auto& k : campaigns) agree = agree && k.agrees() && k.refused == 0;
  return agree ? 0 : 1;
}
