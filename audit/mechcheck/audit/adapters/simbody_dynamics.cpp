// Simbody's equations of motion as a dynamics_library (adapters/simbody.hpp).
#include <exception>
#include <memory>
#include <string>
#include <vector>

#include "mechcheck/audit/adapters/detail/simbody_bridge.hpp"
#include "mechcheck/audit/adapters/detail/simbody_setup.hpp"
#include "mechcheck/audit/adapters/simbody.hpp"
#include "mechcheck/robots/dynamics.hpp"

namespace mechcheck::audit::simbody {

namespace {
namespace bridge = simbody_bridge;

void copy(const Eigen::Matrix3d& m, double* out) {
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) out[3 * i + j] = m(i, j);
}
void copy(const Eigen::Vector3d& v, double* out) {
  for (int i = 0; i < 3; ++i) out[i] = v(i);
}

}  // namespace

simbody_bridge::robot_setup setup_of(const robots::robot& r, const robots::tree& t, coordinate_order& coordinates) {
  simbody_bridge::robot_setup s;
  copy(r.gravity, s.gravity);
  std::vector<int> body_of(r.links.size(), -1);
  const auto add = [&](int link, int parent, const robots::joint* j) {
    simbody_bridge::robot_setup::body b;
    b.parent = parent;
    b.link = link;
    if (j) {
      b.joint = j->type == robots::joint_type::prismatic ? 1 : j->type == robots::joint_type::fixed ? 2 : 0;
      copy(robots::pose_rotation<double>(j->origin), b.rotation);
      copy(j->origin.xyz, b.position);
      copy(j->axis, b.axis);
      b.damping = j->damping;
    }
    if (const auto& in = r.links[std::size_t(link)].body) {
      const Eigen::Matrix3d ro = robots::pose_rotation<double>(in->origin);
      b.mass = in->mass;
      copy(in->origin.xyz, b.com);
      copy(Eigen::Matrix3d(ro * in->inertia * ro.transpose()), b.inertia);
    }
    body_of[std::size_t(link)] = static_cast<int>(s.bodies.size());
    s.bodies.push_back(b);
  };
  add(t.root, -1, nullptr);
  if (r.floating) s.bodies.front().joint = 3;  // a Free mobilizer from the ground
  for (const int k : t.order) {
    add(t.child_link[std::size_t(k)], body_of[std::size_t(t.parent_link[std::size_t(k)])], &r.joints[std::size_t(k)]);
    if (t.coordinate[std::size_t(k)] >= 0) coordinates.order.push_back(t.coordinate[std::size_t(k)]);
  }
  return s;
}

namespace {
/// Simbody's Free mobilizer against the state's floating base: its u are the angular velocity
/// then the linear one, both in the ground's frame (MobilizedBody_Free.h: w_FM and v_FM
/// expressed in F, F the ground's frame and M the root's), base_map.
constexpr base_convention free_velocity{true, true, true};

class model final : public dynamics_model {
 public:
  explicit model(const robots::robot& r) : floating_(r.floating) {
    const robots::tree t = robots::validate(r);
    const bridge::robot_setup s = setup_of(r, t, coordinates_);
    for (const auto& b : s.bodies) link_of_.push_back(b.link);
    links_ = static_cast<Eigen::Index>(r.links.size());
    n_ = t.dofs;
    try {
      d_ = std::make_unique<bridge::robot_dynamics>(s);
    } catch (const std::exception& e) {
      throw robot_refused("simbody: " + one_line(e.what()));
    }
    if (d_->size() != n_ + base())
      throw error("simbody: the system has " + std::to_string(d_->size()) + " mobilities, the robot " +
                  std::to_string(n_ + base()));
  }
  std::optional<Eigen::MatrixXd> mass_matrix(const Eigen::VectorXd& q) override {
    const Eigen::VectorXd qs = positions(q);
    const int nu = n_ + base();
    Eigen::MatrixXd m(nu, nu);
    guarded("calcM", [&] { d_->mass_matrix(qs.data(), m.data()); });
    m.transposeInPlace();  // the bridge writes row-major; Eigen's default is column-major
    return frame(q, Eigen::VectorXd::Zero(nu)).from_library(out(m));
  }
  std::optional<Eigen::VectorXd> bias(const Eigen::VectorXd& q, const Eigen::VectorXd& qdot) override {
    const base_map f = frame(q, qdot);
    const Eigen::VectorXd qs = positions(q), us = in(f.to_library(qdot));
    Eigen::VectorXd h(n_ + base());
    guarded("calcResidualForceIgnoringConstraints", [&] { d_->bias(qs.data(), us.data(), h.data()); });
    return f.bias_from_library(out(h), floating_ ? *mass_matrix(q) : Eigen::MatrixXd());
  }
  std::optional<Eigen::VectorXd> inverse(const Eigen::VectorXd& q, const Eigen::VectorXd& qdot,
                                         const Eigen::VectorXd& qddot) override {
    const base_map f = frame(q, qdot);
    const Eigen::VectorXd qs = positions(q), us = in(f.to_library(qdot)), a = in(f.acceleration_to_library(qddot));
    Eigen::VectorXd tau(n_ + base());
    guarded("calcResidualForceIgnoringConstraints", [&] { d_->inverse(qs.data(), us.data(), a.data(), tau.data()); });
    return f.from_library(out(tau));
  }
  std::optional<Eigen::VectorXd> forward(const Eigen::VectorXd& q, const Eigen::VectorXd& qdot,
                                         const Eigen::VectorXd& tau) override {
    const base_map f = frame(q, qdot);
    const Eigen::VectorXd qs = positions(q), us = in(f.to_library(qdot)), force = in(f.to_library(tau));
    Eigen::VectorXd a(n_ + base());
    guarded("calcAccelerationIgnoringConstraints", [&] { d_->forward(qs.data(), us.data(), force.data(), a.data()); });
    return f.acceleration_from_library(out(a));
  }
  /// Each body's getBodyTransform.
  std::optional<Eigen::MatrixXd> frame_poses(const Eigen::VectorXd& q) override {
    const Eigen::VectorXd qs = positions(q);
    std::vector<double> x(12 * link_of_.size());
    guarded("getBodyTransform", [&] { d_->frames(qs.data(), x.data()); });
    Eigen::MatrixXd poses(12, links_);
    for (std::size_t b = 0; b < link_of_.size(); ++b)
      poses.col(link_of_[b]) = Eigen::Map<const Eigen::VectorXd>(x.data() + 12 * b, 12);
    return poses;
  }
  /// calcFrameJacobian at each body's origin: rows (angular; linear) in the ground stacked
  /// (v; omega); a floating base's columns read through the Free mobilizer's u as its forces
  /// are (a row is a covector: T^T row).
  std::optional<Eigen::MatrixXd> frame_jacobians(const Eigen::VectorXd& q) override { return jacobians(q, false); }
  /// calcFrameJacobian at each body's mass centre (a station on it), as frame_jacobians.
  std::optional<Eigen::MatrixXd> link_com_jacobians(const Eigen::VectorXd& q) override { return jacobians(q, true); }
  Eigen::MatrixXd jacobians(const Eigen::VectorXd& q, bool at_com) const {
    const Eigen::MatrixXd j = library_jacobians(q, at_com);
    const base_map f = frame(q, Eigen::VectorXd::Zero(j.cols()));
    Eigen::MatrixXd jac(j.rows(), j.cols());
    for (Eigen::Index r = 0; r < j.rows(); ++r) jac.row(r) = f.from_library(Eigen::VectorXd(j.row(r).transpose())).transpose();
    return jac;
  }
  /// calcBiasForFrameJacobian at each body's origin: JFDot u at Simbody's udot = 0; the state's
  /// udot = 0 is Simbody's T (0 + turn) on a floating base (the Free mobilizer's linear
  /// velocity is in the ground: its rate carries R (w_b x v_b)), added through JF.
  std::optional<Eigen::VectorXd> frame_bias_accelerations(const Eigen::VectorXd& q, const Eigen::VectorXd& qdot) override {
    const base_map f = frame(q, qdot);
    const Eigen::VectorXd qs = positions(q), us = in(f.to_library(qdot));
    Eigen::VectorXd bias(6 * static_cast<Eigen::Index>(link_of_.size()));
    guarded("calcBiasForFrameJacobian", [&] { d_->frame_biases(qs.data(), us.data(), bias.data()); });
    Eigen::VectorXd a = ordered(bias);
    if (floating_)
      a += library_jacobians(q) * f.acceleration_to_library(Eigen::VectorXd::Zero(qdot.size()));
    return a;
  }
  /// calcSystemMassCenterLocationInGround: every body's (a welded root's too).
  std::optional<Eigen::VectorXd> centre_of_mass(const Eigen::VectorXd& q) override {
    const Eigen::VectorXd qs = positions(q);
    Eigen::Vector3d c;
    guarded("calcSystemMassCenterLocationInGround", [&] { d_->centre_of_mass(qs.data(), c.data()); });
    return Eigen::VectorXd(c);
  }
  /// calcSystemMassCenterVelocityInGround at u = e_k: column k in Simbody's u, read through
  /// the Free mobilizer's map as the Jacobians are.
  std::optional<Eigen::MatrixXd> com_jacobian(const Eigen::VectorXd& q) override {
    return library_momenta(q).topRows(3);
  }
  /// calcSystemCentralMomentum at u = e_k: (linear; angular about the mass centre), Simbody's
  /// SpatialVec (angular; linear) turned over.
  std::optional<Eigen::MatrixXd> centroidal_momentum_matrix(const Eigen::VectorXd& q) override {
    return library_momenta(q).bottomRows(6);
  }

 private:
  /// The bridge's central_momenta, its columns the robot's mobilities through the base's map.
  Eigen::MatrixXd library_momenta(const Eigen::VectorXd& q) const {
    const Eigen::VectorXd qs = positions(q);
    const int nu = n_ + base();
    Eigen::Matrix<double, 9, Eigen::Dynamic, Eigen::RowMajor> h(9, nu);
    guarded("calcSystemCentralMomentum", [&] { d_->central_momenta(qs.data(), h.data()); });
    const base_map f = frame(q, Eigen::VectorXd::Zero(nu));
    Eigen::MatrixXd cols(9, nu);
    for (Eigen::Index r = 0; r < 9; ++r)
      cols.row(r) = f.from_library(out(Eigen::VectorXd(h.row(r).transpose()))).transpose();
    return cols;
  }
  static std::string one_line(const char* text) {
    std::string s;
    for (const char* c = text; *c; ++c) s += *c == '\n' ? ' ' : *c;
    return s.size() > 240 ? s.substr(0, 240) + "..." : s;
  }
  template <class F>
  static void guarded(const char* what, F&& f) {
    try {
      f();
    } catch (const std::exception& e) {
      throw error(std::string("simbody: ") + what + ": " + one_line(e.what()));
    }
  }
  int base() const { return floating_ ? 6 : 0; }
  base_map frame(const Eigen::VectorXd& q, const Eigen::VectorXd& u) const {
    return floating_ ? base_map(free_velocity, base_rotation(q), u) : base_map();
  }
  /// q in the bridge's order: a floating base's pose first as it is, then the joints'.
  Eigen::VectorXd positions(const Eigen::VectorXd& q) const {
    if (!floating_) return coordinates_.to_library(q);
    Eigen::VectorXd out(q.size());
    out << q.head<7>(), coordinates_.to_library(Eigen::VectorXd(q.tail(n_)));
    return out;
  }
  /// Mobilities in the bridge's order (a floating base's six first, in Simbody's layout),
  /// from the robot's, and back.
  Eigen::VectorXd in(const Eigen::VectorXd& x) const {
    if (!floating_) return coordinates_.to_library(x);
    Eigen::VectorXd y(x.size());
    y << x.head<6>(), coordinates_.to_library(Eigen::VectorXd(x.tail(n_)));
    return y;
  }
  Eigen::VectorXd out(const Eigen::VectorXd& y) const {
    if (!floating_) return coordinates_.from_library(y);
    Eigen::VectorXd x(y.size());
    x << y.head<6>(), coordinates_.from_library(Eigen::VectorXd(y.tail(n_)));
    return x;
  }
  Eigen::MatrixXd out(const Eigen::MatrixXd& m) const {
    coordinate_order all;
    for (int i = 0; i < base(); ++i) all.order.push_back(i);
    for (const int c : coordinates_.order) all.order.push_back(c + base());
    return all.from_library(m);
  }

  /// Rows 6 body's (angular; linear) as the robot's links' (v; omega).
  Eigen::MatrixXd ordered(const Eigen::MatrixXd& rows) const {
    Eigen::MatrixXd out = Eigen::MatrixXd::Zero(6 * links_, rows.cols());
    for (std::size_t b = 0; b < link_of_.size(); ++b) {
      const Eigen::Index from = 6 * static_cast<Eigen::Index>(b), to = 6 * link_of_[b];
      out.middleRows(to, 3) = rows.middleRows(from + 3, 3);
      out.middleRows(to + 3, 3) = rows.middleRows(from, 3);
    }
    return out;
  }
  /// calcFrameJacobian's rows as ordered's, its columns the robot's mobilities (a floating
  /// base's six first, in Simbody's layout).
  Eigen::MatrixXd library_jacobians(const Eigen::VectorXd& q, bool at_com = false) const {
    const Eigen::VectorXd qs = positions(q);
    const int nu = n_ + base();
    const auto rows = 6 * static_cast<Eigen::Index>(link_of_.size());
    Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> j(rows, nu);
    guarded("calcFrameJacobian", [&] { d_->frame_jacobians(qs.data(), j.data(), at_com); });
    Eigen::MatrixXd cols(rows, nu);
    for (Eigen::Index r = 0; r < rows; ++r) cols.row(r) = out(Eigen::VectorXd(j.row(r).transpose())).transpose();
    return ordered(cols);
  }

  std::unique_ptr<bridge::robot_dynamics> d_;
  std::vector<int> link_of_;      ///< the robot's link of each of the bridge's bodies
  Eigen::Index links_ = 0;
  coordinate_order coordinates_;  ///< the bridge's moving joints
  int n_ = 0;
  bool floating_ = false;
};
}  // namespace

dynamics_library dynamics() {
  dynamics_library l;
  l.name = "simbody";
  l.origin = "Simbody " + version() +
             " (libsimbody-dev): SimbodyMatterSubsystem::calcM; calcResidualForceIgnoringConstraints (f_residual = "
             "M udot + f_inertial - f_applied) at udot = 0 for the bias and at qddot for inverse dynamics, and "
             "calcAccelerationIgnoringConstraints for forward dynamics, the applied forces the system's at "
             "Stage::Dynamics (Force::Gravity's body forces, a Force::MobilityLinearDamper's -c u on each joint "
             "with damping c) and tau; no rotor inertia (Simbody has none: a robot with an armature is "
             "refused); the system built from the description: a Body::Rigid per link with "
             "MassProperties about its origin (the central inertia R_o I R_o^T shifted by "
             "Inertia::shiftFromMassCenter), a MobilizedBody::Pin or Slider whose frames F (at the joint's "
             "origin) and M turn z (Pin) or x (Slider) onto the axis, a Weld for a fixed joint and the root; u = "
             "qdot for both mobilizers; a floating root on a MobilizedBody::Free from the ground (its q set by "
             "setQToFitTransform of the base's pose; its u the angular then the linear velocity, both in the "
             "ground's frame, R w_b and R v_b, their rates R wdot_b and R (vdot_b + w_b x v_b); forces and M "
             "through the same map); each link's frame by MobilizedBody::getBodyTransform, its Jacobian by "
             "calcFrameJacobian at the body's origin and at its mass centre (rows (angular; linear) in the ground; a "
             "floating base's columns through the same map), Jdot qdot by calcBiasForFrameJacobian (at Simbody's udot = 0, plus "
             "JF times the state's udot = 0 in Simbody's u on a floating base); the centre of mass by "
             "calcSystemMassCenterLocationInGround (every body's, the welded root's too), J_c and A_G column by "
             "column from calcSystemMassCenterVelocityInGround and calcSystemCentralMomentum at u = e_k (through "
             "the same map)";
  l.no_floating_base.clear();
  l.sets_damping = true;
  l.no_joint_terms = "Simbody has no rotor inertia (its mobilizers carry none; a damper is a force element)";
  l.load = [](const robots::robot& r) -> std::unique_ptr<dynamics_model> { return std::make_unique<model>(r); };
  return l;
}

}  // namespace mechcheck::audit::simbody
