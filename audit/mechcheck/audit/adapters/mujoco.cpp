#include "mechcheck/audit/adapters/mujoco.hpp"
#include "mechcheck/audit/adapters/detail/mujoco_load.hpp"

#include <mujoco/mujoco.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include <Eigen/Geometry>

namespace mechcheck::audit::mujoco {

namespace {
/// MuJoCo's error handler exits the process by default: ours throws instead (MuJoCo's own
/// Python bindings do the same), and its warnings are kept for the run to report.
thread_local std::string last_warning;
void on_error(const char* msg) { throw error(std::string("MuJoCo error: ") + msg); }
void on_warning(const char* msg) { last_warning = msg; }

/// The run whose mj_step is under way on this thread (for the passive-force callback).
thread_local const scenario* stepping = nullptr;
void central_force(const mjModel*, mjData* d) {
  if (stepping && stepping->gravitation != 0) {  // free bodies: each one's free joint, in order
    const std::vector<link>& b = stepping->links;
    for (std::size_t k = 0; k < b.size(); ++k)
      for (std::size_t j = k + 1; j < b.size(); ++j) {
        const Eigen::Vector3d xk(d->qpos + 7 * k), xj(d->qpos + 7 * j);
        const Eigen::Vector3d r = xj - xk;
        const Eigen::Vector3d f = stepping->gravitation * b[k].mass * b[j].mass / (r.norm() * r.squaredNorm()) * r;
        for (int i = 0; i < 3; ++i) d->qfrc_passive[6 * k + std::size_t(i)] += f(i), d->qfrc_passive[6 * j + std::size_t(i)] -= f(i);
      }
    return;
  }
  if (!stepping || stepping->central == 0) return;
  const Eigen::Vector3d x(d->qpos[0], d->qpos[1], d->qpos[2]);  // free joint: the centre of mass
  const Eigen::Vector3d f = -stepping->mass * stepping->central / (x.norm() * x.squaredNorm()) * x;
  for (int i = 0; i < 3; ++i) d->qfrc_passive[i] += f(i);  // the free joint's world-frame force
}
}  // namespace

void install_handlers() {
  static const bool done = [] {
    mju_user_error = &on_error;
    mju_user_warning = &on_warning;
    mjcb_passive = &central_force;
    return true;
  }();
  static_cast<void>(done);
}

mjModel* load(const std::string& xml) {
  install_handlers();
  auto vfs = std::make_unique<mjVFS>();
  mj_defaultVFS(vfs.get());
  if (mj_makeEmptyFileVFS(vfs.get(), "scenario.xml", static_cast<int>(xml.size())) != 0)
    throw error("MuJoCo: mj_makeEmptyFileVFS failed");
  const int i = mj_findFileVFS(vfs.get(), "scenario.xml");
  std::memcpy(vfs->filedata[i], xml.data(), xml.size());
  char message[1000] = "";
  mjModel* m = mj_loadXML("scenario.xml", vfs.get(), message, sizeof message);
  mj_deleteVFS(vfs.get());
  if (!m) throw error(std::string("MuJoCo: mj_loadXML failed: ") + message);
  return m;
}

namespace {

const char* integrator_xml(int integrator) {
  return integrator == mjINT_EULER ? "Euler" : integrator == mjINT_RK4 ? "RK4" : "implicit";
}

/// The MJCF of a scenario (see the header for the mapping).
std::string mjcf(const scenario& s, int integrator) {
  char buf[1024];
  const char* joint = s.joint == joint_kind::free      ? "<freejoint/>"
                      : s.joint == joint_kind::hinge_y ? "<joint type=\"hinge\" axis=\"0 1 0\"/>"
                                                       : "<joint type=\"ball\"/>";
  std::snprintf(buf, sizeof buf,
                "<mujoco><compiler angle=\"radian\"/><option timestep=\"0.01\" gravity=\"0 0 %.17g\" "
                "integrator=\"%s\"/><worldbody><body>%s<inertial pos=\"%.17g %.17g %.17g\" mass=\"%.17g\" "
                "diaginertia=\"%.17g %.17g %.17g\"/></body></worldbody></mujoco>",
                -s.gravity, integrator_xml(integrator), joint, s.com(0), s.com(1), s.com(2), s.mass,
                s.inertia(0), s.inertia(1), s.inertia(2));
  return buf;
}

std::string numbers(const std::vector<double>& xs) {
  std::string out;
  char buf[32];
  for (double x : xs) {
    std::snprintf(buf, sizeof buf, "%s%.17g", out.empty() ? "" : " ", x);
    out += buf;
  }
  return out;
}
std::string vec(const Eigen::Vector3d& v) { return numbers({v(0), v(1), v(2)}); }

/// The MJCF of a multibody scenario: a chain as nested bodies each with a hinge about y
/// (its loop closure as an equality `connect` of the last link's point to the world,
/// MuJoCo's default soft-constraint parameters), free bodies each with a free joint.
/// qpos of a hinge is its angle from the parent's frame (ref: the angle at which the body
/// sits in the model).
std::string mjcf_multibody(const scenario& s, int integrator) {
  std::string xml = "<mujoco><compiler angle=\"radian\"/><option timestep=\"0.01\" gravity=\"0 0 " +
                    numbers({-s.gravity}) + "\" integrator=\"" + integrator_xml(integrator) + "\"/><worldbody>";
  const auto inertial = [](const link& l) {
    return "<inertial pos=\"" + vec(l.com) + "\" mass=\"" + numbers({l.mass}) + "\" diaginertia=\"" + vec(l.inertia) +
           "\"/>";
  };
  if (s.structure == body_structure::chain) {
    for (std::size_t k = 0; k < s.links.size(); ++k)
      // Each body placed at its start (its joint's ref the start angle): MuJoCo computes a
      // connect's point on the world in the model's configuration, qpos0 = ref.
      xml += "<body name=\"link" + std::to_string(k) + "\" pos=\"" + vec(s.links[k].hinge) + "\" axisangle=\"0 1 0 " +
             numbers({s.links[k].angle0}) + "\"><joint type=\"hinge\" axis=\"0 1 0\" ref=\"" +
             numbers({s.links[k].angle0}) + "\"/>" + inertial(s.links[k]);
    for (std::size_t k = 0; k < s.links.size(); ++k) xml += "</body>";
    xml += "</worldbody>";
    if (s.loop)
      xml += "<equality><connect body1=\"link" + std::to_string(s.links.size() - 1) + "\" anchor=\"" +
             vec(s.loop->point) + "\"/></equality>";
  } else {
    for (const link& l : s.links) xml += "<body><freejoint/>" + inertial(l) + "</body>";
    xml += "</worldbody>";
  }
  return xml + "</mujoco>";
}

/// The restitution of a soft contact: MuJoCo's solref (timeconst, dampratio) makes the
/// contact's reference dynamics a damped oscillator, whose rebound over an impact is
/// exp(-zeta pi / sqrt(1 - zeta^2)); the damping ratio that gives e is
/// zeta = -ln e / sqrt(pi^2 + ln^2 e) (1 for e = 0: MuJoCo's default, critical damping).
double damping_ratio(double e) {
  if (e <= 0) return 1;
  const double l = std::log(e);
  return -l / std::sqrt(M_PI * M_PI + l * l);
}

/// The MJCF of a contact scenario (contact.hpp): the ground a plane geom turned by the slope
/// about y; each body a free body with its explicit inertial and one geom of its shape (a
/// cylinder's axis, MuJoCo's z, turned onto the body's y); every geom with friction
/// "mu 0 0" and condim 3 (sliding friction alone; condim 1, frictionless, where mu = 0):
/// MuJoCo combines two geoms' friction by their maximum, so every contact has mu. A
/// restitution e > 0 through solref's damping ratio (damping_ratio), the time constant
/// MuJoCo's default 0.02 s. The cone pyramidal (MuJoCo's default) or elliptic.
std::string mjcf_contact(const scenario& s, int integrator, bool elliptic) {
  const contact_setup& c = *s.contact;
  const std::string surface =
      std::string(" condim=\"") + (c.mu > 0 ? "3" : "1") + "\" friction=\"" + numbers({c.mu > 0 ? c.mu : 1, 0, 0}) +
      "\"" + (c.restitution > 0 ? " solref=\"" + numbers({0.02, damping_ratio(c.restitution)}) + "\"" : std::string());
  std::string xml = "<mujoco><compiler angle=\"radian\"/><option timestep=\"0.01\" gravity=\"0 0 " +
                    numbers({-s.gravity}) + "\" integrator=\"" + integrator_xml(integrator) + "\" cone=\"" +
                    (elliptic ? "elliptic" : "pyramidal") + "\"/><worldbody>";
  if (c.ground)
    xml += "<geom name=\"ground\" type=\"plane\" size=\"0 0 1\" euler=\"0 " + numbers({c.slope}) + " 0\"" + surface + "/>";
  for (const contact_body& b : c.bodies) {
    xml += "<body><freejoint/><inertial pos=\"0 0 0\" mass=\"" + numbers({b.mass}) + "\" diaginertia=\"" + vec(b.inertia) +
           "\"/>";
    switch (b.shape) {
      case contact_shape::box: xml += "<geom type=\"box\" size=\"" + vec(b.size) + "\"" + surface + "/>"; break;
      case contact_shape::sphere: xml += "<geom type=\"sphere\" size=\"" + numbers({b.size(0)}) + "\"" + surface + "/>"; break;
      case contact_shape::cylinder:
        xml += "<geom type=\"cylinder\" size=\"" + numbers({b.size(0), b.size(1)}) + "\" euler=\"" +
               numbers({-M_PI / 2, 0, 0}) + "\"" + surface + "/>";
        break;
    }
    xml += "</body>";
  }
  return xml + "</worldbody></mujoco>";
}

void put_quaternion(const Eigen::Matrix3d& r, double* q) {
  const Eigen::Quaterniond e(r);
  q[0] = e.w(), q[1] = e.x(), q[2] = e.y(), q[3] = e.z();
}

/// A contact scenario as a file MuJoCo loads on its own: mjcf_contact at h = 1/60 (the
/// contact audit's default step) with the start as the keyframe "start" (qpos: each free
/// joint's position and quaternion; qvel: its velocity and its body-frame angular velocity).
/// `simulate` or mj_resetDataKeyframe(m, d, 0) and mj_step reproduce the run.
std::string mjcf_contact_case(const scenario& s, bool elliptic) {
  std::string xml = mjcf_contact(s, mjINT_EULER, elliptic);
  const std::string step = "timestep=\"0.01\"";
  xml.replace(xml.find(step), step.size(), "timestep=\"" + numbers({1.0 / 60}) + "\"");
  std::vector<double> qpos, qvel;
  for (const contact_body& b : s.contact->bodies) {
    double q[4];
    put_quaternion(b.rotation0, q);
    const Eigen::Vector3d w_body = b.rotation0.transpose() * b.omega0;
    for (int i = 0; i < 3; ++i) qpos.push_back(b.position0(i));
    for (int i = 0; i < 4; ++i) qpos.push_back(q[i]);
    for (int i = 0; i < 3; ++i) qvel.push_back(b.velocity0(i));
    for (int i = 0; i < 3; ++i) qvel.push_back(w_body(i));
  }
  xml.replace(xml.rfind("</mujoco>"), 9,
              "<keyframe><key name=\"start\" qpos=\"" + numbers(qpos) + "\" qvel=\"" + numbers(qvel) + "\"/></keyframe></mujoco>");
  return xml;
}

/// The fourth-order Runge-Kutta method on MuJoCo's state with the orientation integrated
/// as a Runge-Kutta-Munthe-Kaas method: the same four evaluations as mj_RungeKutta (one
/// mj_forward per stage), the stage orientation q0 exp(Theta_j) with Theta_j = h sum_l
/// a_jl k_l, and each stage's body-frame angular velocity w_j taken through the dexp^-1
/// series, k_j = w_j + (1/2) Theta_j x w_j + (1/12) Theta_j x (Theta_j x w_j) (terms to
/// degree p - 2 = 2 suffice for order 4); hinge angles and positions as in classical RK4.
/// mj_integratePos applies q exp(dt v) to the quaternion of every ball and free joint with
/// v in the body frame, which is what Theta needs.
void rk4_dexp_corrected(const mjModel* m, mjData* d, double h) {
  const int nq = m->nq, nv = m->nv;
  const std::vector<double> q0(d->qpos, d->qpos + nq), v0(d->qvel, d->qvel + nv);
  const double t0 = d->time;
  static constexpr double a[4][3] = {{0, 0, 0}, {0.5, 0, 0}, {0, 0.5, 0}, {0, 0, 1}};
  static constexpr double b[4] = {1.0 / 6, 1.0 / 3, 1.0 / 3, 1.0 / 6}, c[4] = {0, 0.5, 0.5, 1};
  std::vector<std::vector<double>> k(4, std::vector<double>(std::size_t(nv))), acc = k;
  std::vector<double> mix(static_cast<std::size_t>(nv));
  for (int j = 0; j < 4; ++j) {
    // The stage's positions and velocities.
    std::fill(mix.begin(), mix.end(), 0.0);
    std::vector<double> v = v0;
    for (int l = 0; l < j; ++l)
      for (int i = 0; i < nv; ++i) {
        mix[std::size_t(i)] += a[j][l] * k[std::size_t(l)][std::size_t(i)];
        v[std::size_t(i)] += h * a[j][l] * acc[std::size_t(l)][std::size_t(i)];
      }
    std::copy(q0.begin(), q0.end(), d->qpos);
    mj_integratePos(m, d->qpos, mix.data(), h);
    std::copy(v.begin(), v.end(), d->qvel);
    d->time = t0 + c[j] * h;
    mj_forward(m, d);
    std::copy(d->qacc, d->qacc + nv, acc[std::size_t(j)].begin());
    // The stage's position velocity: qvel, with every rotation's dexp^-1 correction.
    k[std::size_t(j)] = v;
    for (int jn = 0; jn < m->njnt; ++jn) {
      const int type = m->jnt_type[jn];
      if (type != mjJNT_BALL && type != mjJNT_FREE) continue;
      const int adr = m->jnt_dofadr[jn] + (type == mjJNT_FREE ? 3 : 0);
      const Eigen::Vector3d theta = h * Eigen::Map<const Eigen::Vector3d>(mix.data() + adr);
      const Eigen::Vector3d w = Eigen::Map<const Eigen::Vector3d>(v.data() + adr);
      const Eigen::Vector3d corrected = w + theta.cross(w) / 2 + theta.cross(theta.cross(w)) / 12;
      for (int i = 0; i < 3; ++i) k[std::size_t(j)][std::size_t(adr + i)] = corrected(i);
    }
  }
  std::fill(mix.begin(), mix.end(), 0.0);
  std::vector<double> v = v0;
  for (int j = 0; j < 4; ++j)
    for (int i = 0; i < nv; ++i) {
      mix[std::size_t(i)] += b[j] * k[std::size_t(j)][std::size_t(i)];
      v[std::size_t(i)] += h * b[j] * acc[std::size_t(j)][std::size_t(i)];
    }
  std::copy(q0.begin(), q0.end(), d->qpos);
  mj_integratePos(m, d->qpos, mix.data(), h);
  std::copy(v.begin(), v.end(), d->qvel);
  d->time = t0 + h;
}

/// MuJoCo's own integrators, or mechcheck's RK4 with the dexp^-1 correction on top of
/// mj_forward (integrator_dexp).
constexpr int integrator_dexp = -1;

class run final : public engine_run {
 public:
  run(const scenario& s, int integrator, bool elliptic = false)
      : s_(s),
        name_(integrator == integrator_dexp ? std::string("mujoco::RK4/dexp_corrected")
                                            : std::string("mujoco::") + integrator_xml(integrator) + (elliptic ? "/elliptic" : "")),
        dexp_(integrator == integrator_dexp) {
    if (dexp_) integrator = mjINT_RK4;
    if (s.structure == body_structure::contact) {
      start_contact(integrator, elliptic);
      return;
    }
    if (elliptic) throw scenario_refused(name_ + ": a friction cone changes nothing without contact: contact scenarios only");
    if (s.central != 0 && s.joint != joint_kind::free)
      throw scenario_refused(name_ + ": the central force is applied to a free body only");
    if (s.structure == body_structure::robot) {
      start_robot(*s.robot, integrator);
      return;
    }
    model_ = load(s.structure == body_structure::one_body ? mjcf(s, integrator) : mjcf_multibody(s, integrator));
    data_ = mj_makeData(model_);
    if (!data_) throw error(name_ + ": mj_makeData failed");
    if (s.structure != body_structure::one_body) {
      for (std::size_t k = 0; k < s.links.size(); ++k) {
        const link& l = s.links[k];
        if (s.structure == body_structure::chain) {
          data_->qpos[k] = l.angle0;
          data_->qvel[k] = l.rate0;
        } else {
          for (int i = 0; i < 3; ++i) data_->qpos[7 * k + std::size_t(i)] = l.position0(i);
          put_quaternion(Eigen::Matrix3d::Identity(), data_->qpos + 7 * k + 3);
          for (int i = 0; i < 3; ++i)
            data_->qvel[6 * k + std::size_t(i)] = l.velocity0(i), data_->qvel[6 * k + 3 + std::size_t(i)] = 0;
        }
      }
      mj_forward(model_, data_);
      return;
    }
    const Eigen::Vector3d w_body = s.rotation0.transpose() * s.omega0;
    switch (s.joint) {
      case joint_kind::free:
        for (int i = 0; i < 3; ++i) data_->qpos[i] = s.position0(i), data_->qvel[i] = s.velocity0(i);
        put_quaternion(s.rotation0, data_->qpos + 3);
        for (int i = 0; i < 3; ++i) data_->qvel[3 + i] = w_body(i);
        break;
      case joint_kind::hinge_y:
        data_->qpos[0] = std::atan2(s.rotation0(0, 2), s.rotation0(0, 0));
        data_->qvel[0] = s.omega0(1);
        break;
      case joint_kind::ball:
        put_quaternion(s.rotation0, data_->qpos);
        for (int i = 0; i < 3; ++i) data_->qvel[i] = w_body(i);
        break;
    }
    mj_forward(model_, data_);
  }
  ~run() override {
    if (data_) mj_deleteData(data_);
    if (model_) mj_deleteModel(model_);
  }
  run(const run&) = delete;
  run& operator=(const run&) = delete;

  void step(double h) override {
    if (!(h != 0 && std::isfinite(h))) throw domain_error(name_ + ": the step must be finite and non-zero, got " + to_text(h));
    ++steps_;
    model_->opt.timestep = h;
    last_warning.clear();
    struct guard {
      explicit guard(const scenario* s) { stepping = s; }
      ~guard() { stepping = nullptr; }
      guard(const guard&) = delete;
      guard& operator=(const guard&) = delete;
    } g(&s_);
    try {
      if (dexp_)
        rk4_dexp_corrected(model_, data_, h);
      else
        mj_step(model_, data_);
    } catch (const error& e) {
      throw convergence_error(name_ + ": step " + std::to_string(steps_) + ": " + e.what());
    }
    for (int i = 0; i < mjNWARNING; ++i)
      if (data_->warning[i].number > 0)
        throw convergence_error(name_ + ": step " + std::to_string(steps_) + ": MuJoCo warning " +
                                std::to_string(i) + (last_warning.empty() ? "" : ": " + last_warning));
    for (int i = 0; i < model_->nq; ++i)
      if (!std::isfinite(data_->qpos[i]))
        throw non_finite_error(name_ + ": step " + std::to_string(steps_) + ": qpos[" + std::to_string(i) + "] is not finite");
  }

  std::string model_differs() const override {
    if (!s_.loop) return {};
    return "MuJoCo closes the loop with a soft equality constraint (connect, default solref 0.02 1: a time "
           "constant of 0.02 s, documented in MuJoCo's Modeling chapter, section Solver parameters): it integrates a "
           "compliant linkage, not the rigid one";
  }

  std::optional<robots::robot> held_robot() const override {
    if (s_.structure != body_structure::robot) return std::nullopt;
    robots::robot r = robot_of(model_, dof_of_);
    r.name = s_.robot->robot.name;
    return r;
  }

  body_reading read() const override {
    // The positions and velocities of the state mj_step left (its xpos and cvel are those
    // of the step's start); mj_step recomputes them all before the next step.
    mj_kinematics(model_, data_);
    mj_comPos(model_, data_);
    mj_comVel(model_, data_);
    body_reading r;
    if (s_.structure == body_structure::robot) {  // the robot's coordinates from MuJoCo's joints
      const Eigen::Index n = static_cast<Eigen::Index>(qpos_of_.size());
      const int bq = base_q(), bv = base_v();
      r.joint_q.resize(bq + n);
      r.joint_v.resize(bv + n);
      for (Eigen::Index i = 0; i < n; ++i)
        r.joint_q(bq + i) = data_->qpos[qpos_of_[std::size_t(i)]], r.joint_v(bv + i) = data_->qvel[dof_of_[std::size_t(i)]];
      if (bq > 0) {  // the freejoint's state in the start's layout (start_robot)
        for (int i = 0; i < 7; ++i) r.joint_q(i) = data_->qpos[free_qpos_ + i];
        const Eigen::Vector3d v = base_rotation(r.joint_q).transpose() *
                                  Eigen::Map<const Eigen::Vector3d>(data_->qvel + free_dof_);
        r.joint_v.head(3) = v;
        for (int i = 0; i < 3; ++i) r.joint_v(3 + i) = data_->qvel[free_dof_ + 3 + i];
      }
      return r;
    }
    if (s_.structure != body_structure::one_body) {
      for (int b = 1; b < model_->nbody; ++b) {
        body_frame f;
        f.rotation = Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>(data_->xmat + 9 * b);
        f.position = Eigen::Map<const Eigen::Vector3d>(data_->xipos + 3 * b);
        double v[6];
        mj_objectVelocity(model_, data_, mjOBJ_BODY, b, v, 0);
        f.omega = Eigen::Map<const Eigen::Vector3d>(v);
        f.velocity = Eigen::Map<const Eigen::Vector3d>(v + 3);
        r.links.push_back(f);
      }
      if (s_.structure == body_structure::chain) {  // the hinges' qpos and qvel, in order
        r.joint_q = Eigen::Map<const Eigen::VectorXd>(data_->qpos, model_->nq);
        r.joint_v = Eigen::Map<const Eigen::VectorXd>(data_->qvel, model_->nv);
      }
      return r;
    }
    r.rotation = Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>(data_->xmat + 9);
    r.position = Eigen::Map<const Eigen::Vector3d>(data_->xipos + 3);
    double v[6];
    mj_objectVelocity(model_, data_, mjOBJ_BODY, 1, v, 0);  // (angular, linear) at xipos, world axes
    r.omega = Eigen::Map<const Eigen::Vector3d>(v);
    r.velocity = Eigen::Map<const Eigen::Vector3d>(v + 3);
    if (s_.joint == joint_kind::hinge_y) {  // the hinge's qpos and qvel: what MuJoCo integrates
      r.joint_q = Eigen::VectorXd::Constant(1, data_->qpos[0]);
      r.joint_v = Eigen::VectorXd::Constant(1, data_->qvel[0]);
    }
    return r;
  }

 private:
  /// A contact scenario: its MJCF, each body's free joint set to its start.
  void start_contact(int integrator, bool elliptic) {
    model_ = load(mjcf_contact(s_, integrator, elliptic));
    data_ = mj_makeData(model_);
    if (!data_) throw error(name_ + ": mj_makeData failed");
    const contact_setup& c = *s_.contact;
    for (std::size_t k = 0; k < c.bodies.size(); ++k) {
      const contact_body& b = c.bodies[k];
      double* q = data_->qpos + 7 * k;
      double* v = data_->qvel + 6 * k;
      for (int i = 0; i < 3; ++i) q[i] = b.position0(i), v[i] = b.velocity0(i);
      put_quaternion(b.rotation0, q + 3);
      const Eigen::Vector3d w_body = b.rotation0.transpose() * b.omega0;
      for (int i = 0; i < 3; ++i) v[3 + i] = w_body(i);
    }
    mj_forward(model_, data_);
  }

  /// A robot scenario: the model of robot_mjcf (the dynamics adapter's, mujoco_dynamics.cpp)
  /// with the integrator set on mjModel::opt, each coordinate at its joint's qpos and dof.
  void start_robot(const robot_start& r, int integrator) {
    try {
      model_ = load(robot_mjcf(r.robot));
    } catch (const error& e) {  // a model MuJoCo's compiler refuses (an inertia at the triangle bound)
      std::string why = e.what();
      std::replace(why.begin(), why.end(), '\n', ' ');
      throw scenario_refused(name_ + ": " + why);
    }
    model_->opt.integrator = integrator;
    data_ = mj_makeData(model_);
    if (!data_) throw error(name_ + ": mj_makeData failed");
    const robots::tree t = robots::validate(r.robot);
    qpos_of_.assign(std::size_t(t.dofs), 0);
    dof_of_ = qpos_of_;
    for (std::size_t j = 0; j < r.robot.joints.size(); ++j) {
      const int c = t.coordinate[j];
      if (c < 0) continue;
      const int id = mj_name2id(model_, mjOBJ_JOINT, r.robot.joints[j].name.c_str());
      if (id < 0) throw error(name_ + ": the model has no joint " + r.robot.joints[j].name);
      qpos_of_[std::size_t(c)] = model_->jnt_qposadr[id];
      dof_of_[std::size_t(c)] = model_->jnt_dofadr[id];
      data_->qpos[model_->jnt_qposadr[id]] = r.q0(base_q() + c);
      data_->qvel[model_->jnt_dofadr[id]] = r.qdot0(base_v() + c);
    }
    if (r.robot.floating) {
      // The freejoint (robot_mjcf): qpos the base's position and quaternion w x y z as the
      // start's; qvel the base's linear velocity in the world, R v_b, then w_b in the body.
      const std::string free = r.robot.links[std::size_t(t.root)].name + "_free";
      const int id = mj_name2id(model_, mjOBJ_JOINT, free.c_str());
      if (id < 0) throw error(name_ + ": the model has no joint " + free);
      free_qpos_ = model_->jnt_qposadr[id];
      free_dof_ = model_->jnt_dofadr[id];
      for (int i = 0; i < 7; ++i) data_->qpos[free_qpos_ + i] = r.q0(i);
      const Eigen::Vector3d v = base_rotation(r.q0) * r.qdot0.head(3);
      for (int i = 0; i < 3; ++i) data_->qvel[free_dof_ + i] = v(i), data_->qvel[free_dof_ + 3 + i] = r.qdot0(3 + i);
    }
    mj_forward(model_, data_);
  }
  int base_q() const { return s_.robot->robot.floating ? 7 : 0; }
  int base_v() const { return s_.robot->robot.floating ? 6 : 0; }

  scenario s_;
  std::string name_;
  bool dexp_ = false;
  std::vector<int> qpos_of_, dof_of_;  ///< a robot's coordinates: their qpos and dof addresses
  int free_qpos_ = 0, free_dof_ = 0;     ///< a floating robot's freejoint: its qpos and dof addresses
  mjModel* model_ = nullptr;
  mjData* data_ = nullptr;
  long long steps_ = 0;
};
}  // namespace

std::string version() {
  const int v = mj_version();
  return std::to_string(v / 100) + "." + std::to_string(v / 10 % 10) + "." + std::to_string(v % 10);
}

engine_shapes shapes() {
  engine_shapes e;
  e.engine = "mujoco";
  e.origin = "MuJoCo " + version() + ": a body without <inertial> whose geoms carry the mass (inertiafromgeom); "
             "mjModel::body_inertia after mj_loadXML";
  e.moments = [](const shape& s) -> Eigen::Vector3d {
    char geoms[512], asset[512] = "";
    const double* z = s.size.data();
    if (s.name == "box")
      std::snprintf(geoms, sizeof geoms, "<geom type=\"box\" size=\"%.17g %.17g %.17g\" mass=\"%.17g\"/>", z[0] / 2,
                    z[1] / 2, z[2] / 2, s.mass);
    else if (s.name == "sphere")
      std::snprintf(geoms, sizeof geoms, "<geom type=\"sphere\" size=\"%.17g\" mass=\"%.17g\"/>", z[0], s.mass);
    else if (s.name == "cylinder" || s.name == "capsule")
      std::snprintf(geoms, sizeof geoms, "<geom type=\"%s\" size=\"%.17g %.17g\" mass=\"%.17g\"/>", s.name.c_str(),
                    z[0], z[1] / 2, s.mass);
    else if (s.name == "ellipsoid")
      std::snprintf(geoms, sizeof geoms, "<geom type=\"ellipsoid\" size=\"%.17g %.17g %.17g\" mass=\"%.17g\"/>",
                    z[0], z[1], z[2], s.mass);
    else if (s.name == "two_spheres")
      std::snprintf(geoms, sizeof geoms,
                    "<geom type=\"sphere\" size=\"%.17g\" pos=\"%.17g 0 0\" mass=\"%.17g\"/>"
                    "<geom type=\"sphere\" size=\"%.17g\" pos=\"%.17g 0 0\" mass=\"%.17g\"/>",
                    z[0], z[1], s.mass / 2, z[0], -z[1], s.mass / 2);
    else if (s.name == "convex_hull") {  // a mesh of the hull's points (MuJoCo keeps them as float)
      std::snprintf(asset, sizeof asset,
                    "<asset><mesh name=\"hull\" vertex=\"%.17g 0 %.17g %.17g 0 %.17g 0 %.17g %.17g 0 %.17g %.17g\"/></asset>",
                    z[0], z[2], -z[0], z[2], z[1], -z[2], -z[1], -z[2]);
      std::snprintf(geoms, sizeof geoms, "<geom type=\"mesh\" mesh=\"hull\" mass=\"%.17g\"/>", s.mass);
    } else
      throw scenario_refused("mujoco: MuJoCo 2.2.2 has no " + s.name + " geom");
    mjModel* m = load(std::string("<mujoco>") + asset + "<worldbody><body><freejoint/>" + geoms + "</body></worldbody></mujoco>");
    const Eigen::Vector3d out(m->body_inertia[3], m->body_inertia[4], m->body_inertia[5]);
    mj_deleteModel(m);
    return out;
  };
  return e;
}

namespace {
/// What MuJoCo's documentation says of its contact (XML reference, option/cone and
/// geom/friction; Computation chapter, soft constraints).
contact_claims contact_claims_of(bool elliptic) {
  contact_claims c;
  c.friction_cone = elliptic ? "elliptic" : "pyramidal";
  c.newton_restitution = false;
  c.soft = true;
  c.words = std::string("MuJoCo XML reference, option/cone: \"[pyramidal, elliptic], 'pyramidal'. The type of contact "
                        "friction cone. Elliptic cones are a better model of the physical reality, but pyramidal cones "
                        "sometimes make the solver faster and more robust.\"; the contacts are soft constraints (solref, "
                        "solimp); no restitution coefficient (a bounce through solref's damping ratio)") +
            (elliptic ? "; cone=\"elliptic\" set" : "; the default cone");
  c.setup = std::string("MJCF (mjcf_contact): the ground a plane geom turned by the slope about y; each body a body with a "
                        "freejoint, its inertial given and one geom (a box of the half-edges, a sphere, a cylinder turned "
                        "onto the body's y); every geom friction=\"mu 0 0\" and condim 3 (1 where mu = 0): MuJoCo takes a "
                        "pair's larger friction, so every pair has mu; e > 0 as solref=\"0.02 zeta\" with zeta = "
                        "-ln e / sqrt(pi^2 + ln^2 e), else solref's default (0.02, 1); solimp, impratio and the solver "
                        "(Newton, 100 iterations, no noslip pass) at their defaults; cone=\"") +
            (elliptic ? "elliptic" : "pyramidal") + "\"";
  return c;
}
}  // namespace

std::vector<engine_integrator> integrators() {
  struct info {
    int id;
    const char* words;
    int order;
  };
  const info all[] = {
      {mjINT_EULER, "semi-implicit Euler", 1},
      {mjINT_RK4, "4th-order Runge Kutta", 4},
      {mjINT_IMPLICIT, "implicit in velocity", 1},
  };
  std::vector<engine_integrator> out;
  for (const info& i : all) {
    engine_integrator e;
    e.name = std::string("mujoco::") + integrator_xml(i.id);
    e.origin = "MuJoCo " + version() + ", mjtIntegrator " +
               (i.id == mjINT_EULER ? "mjINT_EULER" : i.id == mjINT_RK4 ? "mjINT_RK4" : "mjINT_IMPLICIT") +
               " (mjmodel.h: \"" + i.words + "\"); declared order " + std::to_string(i.order) +
               (i.id == mjINT_RK4 ? " (the name)" : " (a first-order method by its description)") +
               "; the model from an MJCF string, mj_step at fixed timestep";
    e.declared.order = i.order;
    // "semi-implicit Euler" names the symplectic Euler method (Hairer, Lubich & Wanner 2006,
    // section I.1.2) without saying so: no symplecticity is declared.
    const int id = i.id;
    e.start = [id](const scenario& s) -> std::unique_ptr<engine_run> { return std::make_unique<run>(s, id); };
    e.multibody = true;
    e.robots = true;
    if (id == mjINT_EULER) {  // MuJoCo's default integrator and cone
      e.contact = contact_claims_of(false);
      e.contact_model = [](const scenario& s) { return mjcf_contact_case(s, false); };
      e.contact_model_extension = "xml";
    }
    out.push_back(std::move(e));
  }
  {  // The elliptic cone, on the default integrator: contact scenarios only.
    engine_integrator e;
    e.name = "mujoco::Euler/elliptic";
    e.origin = "MuJoCo " + version() + ", mjINT_EULER with <option cone=\"elliptic\"/>: the contact scenarios only";
    e.declared.order = 1;
    e.start = [](const scenario& s) -> std::unique_ptr<engine_run> { return std::make_unique<run>(s, mjINT_EULER, true); };
    e.contact = contact_claims_of(true);
    e.contact_only = true;
    e.contact_model = [](const scenario& s) { return mjcf_contact_case(s, true); };
    e.contact_model_extension = "xml";
    out.push_back(std::move(e));
  }
  // The fix of mujoco::RK4's orientation (docs/findings/upstream/mujoco-rk4.md), as an
  // integrator of its own: the same four mj_forward evaluations a step.
  engine_integrator e;
  e.name = "mujoco::RK4/dexp_corrected";
  e.origin = "MuJoCo " + version() + " mj_forward at each of the four stages of the classical RK4 tableau, with "
             "the orientation integrated as a Runge-Kutta-Munthe-Kaas method (each stage's body-frame angular "
             "velocity through the dexp^-1 series to degree 2): mechcheck's correction of mj_RungeKutta, declared "
             "order 4";
  e.declared.order = 4;
  e.start = [](const scenario& s) -> std::unique_ptr<engine_run> { return std::make_unique<run>(s, integrator_dexp); };
  e.multibody = true;
  e.robots = true;
  out.push_back(std::move(e));
  return out;
}

}  // namespace mechcheck::audit::mujoco
