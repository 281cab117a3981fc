// MuJoCo's equations of motion as dynamics_libraries (adapters/mujoco.hpp).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "mechcheck/audit/adapters/detail/mujoco_load.hpp"
#include "mechcheck/audit/adapters/mujoco.hpp"
#include "mechcheck/audit/problems/urdf.hpp"
#include "mechcheck/robots/dynamics.hpp"

namespace mechcheck::audit::mujoco {

namespace {
std::string num(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.17g", x);
  return buf;
}
std::string nums(const double* x, int n) {
  std::string out;
  for (int i = 0; i < n; ++i) out += (i ? " " : "") + num(x[i]);
  return out;
}

/// A link's inertial (the tensor turned into the body frame, R_o I R_o^T, about the centre of
/// mass: fullinertia); nothing for a massless link.
void inertial_xml(const robots::link& l, std::string& out) {
  if (!l.body) return;
  const Eigen::Matrix3d ro = robots::pose_rotation<double>(l.body->origin);
  const Eigen::Matrix3d i = ro * l.body->inertia * ro.transpose();
  const double full[6] = {i(0, 0), i(1, 1), i(2, 2), (i(0, 1) + i(1, 0)) / 2, (i(0, 2) + i(2, 0)) / 2,
                          (i(1, 2) + i(2, 1)) / 2};
  out += "<inertial pos=\"" + nums(l.body->origin.xyz.data(), 3) + "\" mass=\"" + num(l.body->mass) +
         "\" fullinertia=\"" + nums(full, 6) + "\"/>";
}

/// A body's MJCF: its frame (the joint's origin: pos, quat w x y z of URDF's rpy), its
/// inertial (the tensor turned into the body frame, R_o I R_o^T, about the centre of mass:
/// fullinertia), its joint (hinge or slide along the axis, at the body's origin; none for a
/// fixed joint: welded), its children.
void body_xml(const robots::robot& r, const robots::tree& t, int link, int joint, std::string& out) {
  const robots::link& l = r.links[std::size_t(link)];
  if (joint >= 0) {
    const robots::joint& j = r.joints[std::size_t(joint)];
    const Eigen::Quaterniond q(robots::pose_rotation<double>(j.origin));
    const double quat[4] = {q.w(), q.x(), q.y(), q.z()};
    out += "<body name=\"" + l.name + "\" pos=\"" + nums(j.origin.xyz.data(), 3) + "\" quat=\"" + nums(quat, 4) + "\">";
    inertial_xml(l, out);
    if (j.type != robots::joint_type::fixed)
      out += std::string("<joint name=\"") + j.name + "\" type=\"" +
             (j.type == robots::joint_type::prismatic ? "slide" : "hinge") + "\" pos=\"0 0 0\" axis=\"" +
             nums(j.axis.data(), 3) + "\" armature=\"" + num(j.armature) + "\" damping=\"" + num(j.damping) + "\"/>";
  }
  for (std::size_t k = 0; k < r.joints.size(); ++k)
    if (t.parent_link[k] == link) body_xml(r, t, t.child_link[k], static_cast<int>(k), out);
  if (joint >= 0) out += "</body>";
}

}  // namespace

std::string robot_mjcf(const robots::robot& r) {
  const robots::tree t = robots::validate(r);
  std::string out = "<mujoco model=\"" + r.name +
                    "\"><compiler angle=\"radian\" inertiafromgeom=\"false\"/><option gravity=\"" +
                    nums(r.gravity.data(), 3) + "\"/><worldbody>";
  if (!r.floating) {
    body_xml(r, t, t.root, -1, out);
    return out + "</worldbody></mujoco>";
  }
  // A floating base: the root link a body of its own with a freejoint at its origin.
  const robots::link& root = r.links[std::size_t(t.root)];
  out += "<body name=\"" + root.name + "\"><freejoint name=\"" + root.name + "_free\"/>";
  inertial_xml(root, out);
  for (std::size_t k = 0; k < r.joints.size(); ++k)
    if (t.parent_link[k] == t.root) body_xml(r, t, t.child_link[k], static_cast<int>(k), out);
  return out + "</body></worldbody></mujoco>";
}

robots::robot robot_of(const mjModel* m, const std::vector<int>& dof_of_coordinate) {
  const int n = static_cast<int>(dof_of_coordinate.size());
  const auto body_name = [m](int b) {
    const char* name = mj_id2name(m, mjOBJ_BODY, b);
    return name && *name ? std::string(name) : "body" + std::to_string(b);
  };
  robots::robot r;
  r.name = "mujoco";
  for (int i = 0; i < 3; ++i) r.gravity(i) = m->opt.gravity[i];
  // A floating base: the world's one child carries a free joint, and is the root link.
  r.floating = m->nbody > 1 && m->body_jntnum[1] == 1 && m->jnt_type[m->body_jntadr[1]] == mjJNT_FREE;
  std::vector<robots::joint> moving(static_cast<std::size_t>(n)), fixed;
  for (int b = r.floating ? 1 : 0; b < m->nbody; ++b) {
    robots::link l;
    l.name = body_name(b);
    if (b > 0 && m->body_mass[b] > 0) {
      robots::inertial in;
      in.mass = m->body_mass[b];
      for (int i = 0; i < 3; ++i) in.origin.xyz(i) = m->body_ipos[3 * b + i];
      mjtNum rot[9];
      mju_quat2Mat(rot, m->body_iquat + 4 * b);
      const Eigen::Matrix3d r_i = Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>(rot);
      in.inertia = r_i * Eigen::Vector3d(m->body_inertia + 3 * b).asDiagonal() * r_i.transpose();
      l.body = in;
    }
    r.links.push_back(l);
    if (b == 0 || (r.floating && b == 1)) continue;
    robots::joint j;
    j.parent = body_name(m->body_parentid[b]);
    j.child = l.name;
    for (int i = 0; i < 3; ++i) j.origin.xyz(i) = m->body_pos[3 * b + i];
    mjtNum rot[9];
    mju_quat2Mat(rot, m->body_quat + 4 * b);
    // MuJoCo's quaternion as it holds it (its roll-pitch-yaw for URDF alone).
    j.origin.quaternion = Eigen::Vector4d(m->body_quat[4 * b], m->body_quat[4 * b + 1], m->body_quat[4 * b + 2],
                                          m->body_quat[4 * b + 3]);
    j.origin.rpy = robots::rpy_of(Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>(rot));
    if (m->body_jntnum[b] > 1)
      throw error("mujoco: body " + l.name + " has " + std::to_string(m->body_jntnum[b]) + " joints");
    if (m->body_jntnum[b] == 0) {
      j.type = robots::joint_type::fixed;
      j.name = l.name + "_weld";
      fixed.push_back(j);
      continue;
    }
    const int id = m->body_jntadr[b];
    if (m->jnt_type[id] != mjJNT_HINGE && m->jnt_type[id] != mjJNT_SLIDE)
      throw error("mujoco: joint " + std::string(mj_id2name(m, mjOBJ_JOINT, id)) + " is neither a hinge nor a slide");
    for (int i = 0; i < 3; ++i)
      if (m->jnt_pos[3 * id + i] != 0) throw error("mujoco: joint " + std::string(mj_id2name(m, mjOBJ_JOINT, id)) +
                                                   " is not at its body's origin");
    j.name = mj_id2name(m, mjOBJ_JOINT, id);
    j.type = m->jnt_type[id] == mjJNT_SLIDE ? robots::joint_type::prismatic : robots::joint_type::continuous;
    for (int i = 0; i < 3; ++i) j.axis(i) = m->jnt_axis[3 * id + i];
    j.armature = m->dof_armature[m->jnt_dofadr[id]];
    j.damping = m->dof_damping[m->jnt_dofadr[id]];
    const auto at = std::find(dof_of_coordinate.begin(), dof_of_coordinate.end(), m->jnt_dofadr[id]);
    if (at == dof_of_coordinate.end()) throw error("mujoco: joint " + j.name + " is none of the robot's coordinates");
    moving[std::size_t(at - dof_of_coordinate.begin())] = j;
  }
  r.joints = moving;
  r.joints.insert(r.joints.end(), fixed.begin(), fixed.end());
  return r;
}

namespace {
/// MuJoCo's freejoint against the state's floating base (dynamics_state): its qpos is the
/// same (position, quaternion w x y z); its qvel has the linear velocity in the world, R v_b,
/// and the angular one in the body, w_b (base_map).
constexpr base_convention freejoint_velocity{false, true, false};

class mujoco_model final : public dynamics_model {
 public:
  /// kinematics: the model's bodies are the robot's links by name (its MJCF, not MuJoCo's
  /// URDF import, which fuses links joined by fixed joints).
  mujoco_model(const robots::robot& r, const std::string& xml, bool kinematics) : floating_(r.floating) {
    const robots::tree t = robots::validate(r);
    n_ = t.dofs;
    const int base = floating_ ? 6 : 0;
    try {
      m_.reset(load(xml));
    } catch (const error& e) {
      throw robot_refused(std::string("mujoco: ") + e.what());
    }
    for (int i = 0; i < 3; ++i) m_->opt.gravity[i] = r.gravity(i);  // URDF has none
    d_.reset(mj_makeData(m_.get()));
    if (m_->nv != n_ + base)
      throw robot_refused("mujoco: the model has " + std::to_string(m_->nv) + " degrees of freedom, the robot " +
                          std::to_string(n_ + base));
    qpos_.assign(std::size_t(n_ + (floating_ ? 7 : 0)), 0);
    dof_.assign(std::size_t(n_ + base), 0);
    if (floating_) {
      const std::string name = r.links[std::size_t(t.root)].name + "_free";
      const int id = mj_name2id(m_.get(), mjOBJ_JOINT, name.c_str());
      if (id < 0 || m_->jnt_type[id] != mjJNT_FREE) throw robot_refused("mujoco: the model has no free joint " + name);
      for (int i = 0; i < 7; ++i) qpos_[std::size_t(i)] = m_->jnt_qposadr[id] + i;
      for (int i = 0; i < 6; ++i) dof_[std::size_t(i)] = m_->jnt_dofadr[id] + i;
    }
    for (std::size_t j = 0; j < r.joints.size(); ++j) {
      if (t.coordinate[j] < 0) continue;
      const int id = mj_name2id(m_.get(), mjOBJ_JOINT, r.joints[j].name.c_str());
      if (id < 0) throw robot_refused("mujoco: the model has no joint " + r.joints[j].name);
      qpos_[std::size_t(t.coordinate[j] + (floating_ ? 7 : 0))] = m_->jnt_qposadr[id];
      dof_[std::size_t(t.coordinate[j] + base)] = m_->jnt_dofadr[id];
    }
    if (!kinematics) return;
    // A fixed root is the world body, whose mass MuJoCo drops: the centre of mass's quantities
    // are MuJoCo's for a robot whose root carries none.
    const auto& root_body = r.links[std::size_t(t.root)].body;
    root_mass_dropped_ = !floating_ && root_body && root_body->mass > 0;
    // Each link's body: a fixed base's root is the world body (0), welded where the robot is.
    for (std::size_t l = 0; l < r.links.size(); ++l) {
      const int id = !floating_ && static_cast<int>(l) == t.root ? 0 : mj_name2id(m_.get(), mjOBJ_BODY, r.links[l].name.c_str());
      if (id < 0) throw robot_refused("mujoco: the model has no body " + r.links[l].name);
      body_.push_back(id);
    }
  }

  std::optional<robots::robot> held_robot() const override {
    const std::vector<int> dofs(dof_.begin() + (floating_ ? 6 : 0), dof_.end());
    return robot_of(m_.get(), dofs);
  }

  std::optional<Eigen::MatrixXd> mass_matrix(const Eigen::VectorXd& q) override {
    set(q, Eigen::VectorXd::Zero(nv()));
    mj_forward(m_.get(), d_.get());
    return full_mass_matrix();
  }
  std::optional<Eigen::VectorXd> bias(const Eigen::VectorXd& q, const Eigen::VectorXd& qdot) override {
    set(q, qdot);
    mj_forward(m_.get(), d_.get());
    // h = qfrc_bias - qfrc_passive: the joints' damping is a passive force (-damping qvel),
    // which mj_inverse and mj_forward count and qfrc_bias does not.
    Eigen::VectorXd h = read(d_->qfrc_bias);
    h -= read(d_->qfrc_passive);
    return frame_.bias_from_library(h, full_mass_matrix());
  }
  std::optional<Eigen::VectorXd> inverse(const Eigen::VectorXd& q, const Eigen::VectorXd& qdot,
                                         const Eigen::VectorXd& qddot) override {
    set(q, qdot);
    const Eigen::VectorXd qacc = frame_.acceleration_to_library(qddot);
    for (int i = 0; i < nv(); ++i) d_->qacc[dof_[std::size_t(i)]] = qacc(i);
    mj_inverse(m_.get(), d_.get());
    return frame_.from_library(read(d_->qfrc_inverse));
  }
  std::optional<Eigen::VectorXd> forward(const Eigen::VectorXd& q, const Eigen::VectorXd& qdot,
                                         const Eigen::VectorXd& tau) override {
    set(q, qdot);
    const Eigen::VectorXd applied = frame_.to_library(tau);
    for (int i = 0; i < nv(); ++i) d_->qfrc_applied[dof_[std::size_t(i)]] = applied(i);
    mj_forward(m_.get(), d_.get());
    return frame_.acceleration_from_library(read(d_->qacc));
  }
  /// xpos and xmat (row-major) after mj_kinematics.
  std::optional<Eigen::MatrixXd> frame_poses(const Eigen::VectorXd& q) override {
    if (body_.empty()) return std::nullopt;
    set(q, Eigen::VectorXd::Zero(nv()));
    mj_kinematics(m_.get(), d_.get());
    Eigen::MatrixXd out(12, static_cast<Eigen::Index>(body_.size()));
    for (std::size_t l = 0; l < body_.size(); ++l) {
      const mjtNum* x = d_->xpos + 3 * body_[l];
      const mjtNum* r = d_->xmat + 9 * body_[l];
      const auto col = static_cast<Eigen::Index>(l);
      for (int i = 0; i < 3; ++i) out(i, col) = x[i];
      for (int c = 0; c < 3; ++c)
        for (int i = 0; i < 3; ++i) out(3 + 3 * c + i, col) = r[3 * i + c];
    }
    return out;
  }
  /// mj_jacBody (jacp over jacr: the body frame's origin, xpos, and the body's rotation, both
  /// in the world) after mj_kinematics and mj_comPos, which it needs (cdof, subtree_com); its
  /// columns MuJoCo's velocities, each row through the base's convention (J = J_mj T).
  std::optional<Eigen::MatrixXd> frame_jacobians(const Eigen::VectorXd& q) override { return jacobians(q, mj_jacBody); }
  /// mj_jacBodyCom: at each body's centre of mass (xipos), as frame_jacobians.
  std::optional<Eigen::MatrixXd> link_com_jacobians(const Eigen::VectorXd& q) override {
    return jacobians(q, mj_jacBodyCom);
  }
  /// The two above, by MuJoCo's function `jacobian` of a body.
  std::optional<Eigen::MatrixXd> jacobians(const Eigen::VectorXd& q,
                                           void (*jacobian)(const mjModel*, const mjData*, mjtNum*, mjtNum*, int)) {
    if (body_.empty()) return std::nullopt;
    place(q);
    const std::size_t nv_mj = std::size_t(m_->nv);
    std::vector<mjtNum> jacp(3 * nv_mj), jacr(3 * nv_mj);
    Eigen::MatrixXd out(6 * static_cast<Eigen::Index>(body_.size()), nv());
    for (std::size_t l = 0; l < body_.size(); ++l) {
      jacobian(m_.get(), d_.get(), jacp.data(), jacr.data(), body_[l]);
      for (int row = 0; row < 6; ++row) {
        const mjtNum* j = (row < 3 ? jacp.data() : jacr.data()) + std::size_t(row % 3) * nv_mj;
        Eigen::VectorXd in_mj(nv());
        for (int i = 0; i < nv(); ++i) in_mj(i) = j[dof_[std::size_t(i)]];
        out.row(6 * static_cast<Eigen::Index>(l) + row) = frame_.from_library(in_mj).transpose();
      }
    }
    return out;
  }
  /// subtree_com of the world body (every body's) after mj_kinematics and mj_comPos.
  std::optional<Eigen::VectorXd> centre_of_mass(const Eigen::VectorXd& q) override {
    if (!offers_com()) return std::nullopt;
    place(q);
    return Eigen::VectorXd(Eigen::Map<const Eigen::Vector3d>(d_->subtree_com));
  }
  /// mj_jacSubtreeCom of the world body after mj_kinematics and mj_comPos, its rows through the
  /// base's convention as the Jacobians'.
  std::optional<Eigen::MatrixXd> com_jacobian(const Eigen::VectorXd& q) override {
    if (!offers_com()) return std::nullopt;
    place(q);
    const std::size_t nv_mj = std::size_t(m_->nv);
    std::vector<mjtNum> jacp(3 * nv_mj);
    mj_jacSubtreeCom(m_.get(), d_.get(), jacp.data(), 0);
    Eigen::MatrixXd out(3, nv());
    for (int row = 0; row < 3; ++row) {
      Eigen::VectorXd in_mj(nv());
      for (int i = 0; i < nv(); ++i) in_mj(i) = jacp[std::size_t(row) * nv_mj + std::size_t(dof_[std::size_t(i)])];
      out.row(row) = frame_.from_library(in_mj).transpose();
    }
    return out;
  }
  /// Column k: the world body's subtree_linvel times its subtree mass and subtree_angmom (about
  /// subtree_com) after mj_subtreeVel at qvel = e_k (mj_kinematics, mj_comPos and mj_comVel
  /// first, whose cvel it reads), its rows through the base's convention.
  std::optional<Eigen::MatrixXd> centroidal_momentum_matrix(const Eigen::VectorXd& q) override {
    if (!offers_com()) return std::nullopt;
    place(q);
    Eigen::MatrixXd in_mj(6, nv());
    for (int k = 0; k < nv(); ++k) {
      mju_zero(d_->qvel, m_->nv);
      d_->qvel[dof_[std::size_t(k)]] = 1;
      mj_comVel(m_.get(), d_.get());
      mj_subtreeVel(m_.get(), d_.get());
      for (int i = 0; i < 3; ++i) {
        in_mj(i, k) = d_->subtree_linvel[i] * m_->body_subtreemass[0];
        in_mj(3 + i, k) = d_->subtree_angmom[i];
      }
    }
    Eigen::MatrixXd out(6, nv());
    for (int row = 0; row < 6; ++row) out.row(row) = frame_.from_library(Eigen::VectorXd(in_mj.row(row).transpose())).transpose();
    return out;
  }

 private:
  int nv() const { return static_cast<int>(dof_.size()); }
  /// The bodies placed at q, at rest: mj_kinematics, then mj_comPos (cdof, subtree_com).
  void place(const Eigen::VectorXd& q) {
    set(q, Eigen::VectorXd::Zero(nv()));
    mj_kinematics(m_.get(), d_.get());
    mj_comPos(m_.get(), d_.get());
  }
  bool offers_com() const { return !body_.empty() && !root_mass_dropped_ && m_->body_subtreemass[0] > 0; }
  /// The state, and nothing of an earlier call left: the applied forces, the accelerations
  /// and the warnings cleared (mj_resetData would clear the whole arena, about 0.25 ms a call).
  void set(const Eigen::VectorXd& q, const Eigen::VectorXd& u) {
    mju_zero(d_->qfrc_applied, m_->nv);
    mju_zero(d_->qacc, m_->nv);
    for (auto& w : d_->warning) w.number = 0;
    for (std::size_t i = 0; i < qpos_.size(); ++i) d_->qpos[qpos_[i]] = q(Eigen::Index(i));
    frame_ = floating_ ? base_map(freejoint_velocity, base_rotation(q), u) : base_map();
    const Eigen::VectorXd qvel = frame_.to_library(u);
    for (int i = 0; i < nv(); ++i) d_->qvel[dof_[std::size_t(i)]] = qvel(i);
  }
  /// M in the state's layout: T^T M_mj T (base_map).
  Eigen::MatrixXd full_mass_matrix() const {
    std::vector<mjtNum> dense(std::size_t(m_->nv) * std::size_t(m_->nv));
    mj_fullM(m_.get(), dense.data(), d_->qM);
    Eigen::MatrixXd out(nv(), nv());
    for (int i = 0; i < nv(); ++i)
      for (int j = 0; j < nv(); ++j) out(i, j) = dense[std::size_t(dof_[std::size_t(i)] * m_->nv + dof_[std::size_t(j)])];
    return frame_.from_library(out);
  }
  Eigen::VectorXd read(const mjtNum* x) const {
    Eigen::VectorXd out(nv());
    for (int i = 0; i < nv(); ++i) out(i) = x[dof_[std::size_t(i)]];
    if (d_->warning[mjWARN_BADQACC].number > 0) throw error("mujoco: a bad acceleration (mjWARN_BADQACC)");
    return out;
  }
  struct model_deleter {
    void operator()(mjModel* m) const { mj_deleteModel(m); }
  };
  struct data_deleter {
    void operator()(mjData* d) const { mj_deleteData(d); }
  };
  std::unique_ptr<mjModel, model_deleter> m_;
  std::unique_ptr<mjData, data_deleter> d_;
  int n_ = 0;
  bool floating_ = false;
  base_map frame_;  ///< the freejoint's velocity convention at the state's base rotation
  /// The state's components at MuJoCo's: qpos_[i] the qpos address of q(i), dof_[i] the qvel
  /// (and force, acceleration) address of u(i).
  std::vector<int> qpos_, dof_;
  std::vector<int> body_;  ///< each link's body (none: the model offers no kinematics)
  bool root_mass_dropped_ = false;  ///< a fixed root with a body (the world body's mass MuJoCo drops)
};
}  // namespace

namespace {
/// MuJoCo's conventions the adapter sets or accounts for, named in each library's origin.
const char* const conventions =
    "; qfrc_bias is Coriolis, centrifugal and gravity (M qacc + qfrc_bias = qfrc_applied, the sign of h); "
    "inertia about the centre of mass (body_ipos); a joint's armature (added to M's diagonal) and damping "
    "(qfrc_passive = -damping qvel, counted in h as qfrc_bias - qfrc_passive) as the robot gives them; no "
    "friction loss (a constraint of MuJoCo's, not held here) and no spring";

/// The floating base through the freejoint's convention (freejoint_velocity above).
const char* const freejoint =
    "; a floating base as a body with a freejoint (qpos: position, then quaternion w x y z, as the state's; qvel: the "
    "linear velocity in the world, R v_b, and the angular one in the body, w_b; qacc their rates, so that qacc's "
    "linear part is R (vdot_b + w_b x v_b); forces, M and the Jacobians' columns through the same map)";

dynamics_library library(std::string name, std::string origin, std::function<std::string(const robots::robot&)> model,
                         bool kinematics) {
  dynamics_library l;
  l.name = std::move(name);
  l.origin = "MuJoCo " + version() + ": " + std::move(origin) + conventions;
  l.load = [model, kinematics](const robots::robot& r) -> std::unique_ptr<dynamics_model> {
    return std::make_unique<mujoco_model>(r, model(r), kinematics);
  };
  l.sets_damping = true;
  return l;
}
}  // namespace

dynamics_library dynamics() {
  dynamics_library l = library("mujoco",
                 "mj_fullM of qM, qfrc_bias and qacc after mj_forward, qfrc_inverse after mj_inverse, on a model "
                 "built as MJCF (each link a body at its joint's origin, its inertia turned into the body frame as "
                 "fullinertia, hinge and slide joints, no limits or geoms); each link's frame as xpos and xmat after "
                 "mj_kinematics, its Jacobian by mj_jacBody after mj_kinematics and mj_comPos, and at its centre of mass by mj_jacBodyCom; the centre of mass as the "
                 "world body's subtree_com, J_c by mj_jacSubtreeCom of the world body, A_G column by column as its "
                 "subtree mass times subtree_linvel and subtree_angmom after mj_comVel and mj_subtreeVel at qvel "
                 "= e_k (not offered where a fixed root carries a body: the root is the world body, whose mass "
                 "MuJoCo drops)",
                 robot_mjcf, true);
  l.sets_armature = true;
  l.origin += freejoint;
  l.no_floating_base.clear();
  return l;
}

dynamics_library urdf_dynamics() {
  dynamics_library l = library("mujoco-urdf",
                 "the same functions on the model MuJoCo's own URDF import builds (mj_loadXML of the robot's URDF, "
                 "whose joint limits of +-1e9 are never reached; gravity set on mjModel::opt; its <dynamics "
                 "damping> read as the joint's damping, and friction left out of the file: the import makes it a "
                 "friction loss; URDF has no armature, and a robot with one is refused)",
                 [](const robots::robot& r) {
                   robots::robot without_friction = r;
                   for (robots::joint& j : without_friction.joints) j.friction = 0;
                   return to_urdf(without_friction);
                 },
                 false);
  l.no_floating_base = "its adapter writes no floating joint for MuJoCo's URDF import";
  l.no_joint_terms = "URDF has no armature";
  return l;
}

}  // namespace mechcheck::audit::mujoco
