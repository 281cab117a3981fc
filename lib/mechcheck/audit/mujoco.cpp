#include "mechcheck/audit/mujoco.hpp"

#include <mujoco/mujoco.h>

#include <cmath>
#include <cstring>
#include <memory>
#include <string>

#include <Eigen/Geometry>

namespace mechcheck::audit::mujoco {

namespace {
/// MuJoCo's error handler exits the process by default: ours throws instead (MuJoCo's own
/// Python bindings do the same), and its warnings are kept for the run to report.
thread_local std::string last_warning;
void on_error(const char* msg) { throw error(std::string("MuJoCo error: ") + msg); }
void on_warning(const char* msg) { last_warning = msg; }
void install_handlers() {
  static const bool done = [] {
    mju_user_error = &on_error;
    mju_user_warning = &on_warning;
    return true;
  }();
  static_cast<void>(done);
}

/// A model from an MJCF string, through MuJoCo's virtual file system (no file written).
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

const char* integrator_xml(int integrator) {
  return integrator == mjINT_EULER ? "Euler" : integrator == mjINT_RK4 ? "RK4" : "implicit";
}

/// The MJCF of a scenario (see the header for the mapping).
std::string mjcf(const scenario& s, int integrator) {
  char opt[256];
  std::snprintf(opt, sizeof opt, "<option timestep=\"0.01\" gravity=\"0 0 %.17g\" integrator=\"%s\"/>",
                -s.gravity, integrator_xml(integrator));
  std::string body;
  char buf[512];
  switch (s.kind) {
    case scenario_kind::free_top:
    case scenario_kind::free_top_near_axis:
      std::snprintf(buf, sizeof buf,
                    "<body><freejoint/><inertial pos=\"0 0 0\" mass=\"%.17g\" diaginertia=\"%.17g %.17g %.17g\"/></body>",
                    s.mass, s.inertia(0), s.inertia(1), s.inertia(2));
      body = buf;
      break;
    case scenario_kind::pendulum_small:
    case scenario_kind::pendulum_large:
      std::snprintf(buf, sizeof buf,
                    "<body><joint type=\"hinge\" axis=\"0 1 0\"/><inertial pos=\"0 0 %.17g\" mass=\"%.17g\" "
                    "diaginertia=\"1e-3 1e-3 1e-3\"/></body>",
                    -s.length, s.mass);
      body = buf;
      break;
    case scenario_kind::projectile:
      std::snprintf(buf, sizeof buf,
                    "<body><freejoint/><inertial pos=\"0 0 0\" mass=\"%.17g\" diaginertia=\"1 1 1\"/></body>", s.mass);
      body = buf;
      break;
  }
  return "<mujoco><compiler angle=\"radian\"/>" + std::string(opt) + "<worldbody>" + body + "</worldbody></mujoco>";
}

class run final : public engine_run {
 public:
  run(const scenario& s, int integrator) : s_(s), name_(std::string("mujoco::") + integrator_xml(integrator)) {
    model_ = load(mjcf(s, integrator));
    data_ = mj_makeData(model_);
    if (!data_) throw error(name_ + ": mj_makeData failed");
    switch (s.kind) {
      case scenario_kind::free_top:
      case scenario_kind::free_top_near_axis:
        data_->qpos[3] = 1;  // identity quaternion (w, x, y, z)
        for (int i = 0; i < 3; ++i) data_->qvel[3 + i] = s.omega0(i);  // body frame
        break;
      case scenario_kind::pendulum_small:
      case scenario_kind::pendulum_large:
        data_->qpos[0] = s.theta0;
        break;
      case scenario_kind::projectile:
        data_->qpos[3] = 1;
        for (int i = 0; i < 3; ++i) data_->qvel[i] = s.velocity0(i);  // world frame
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
    if (!(h > 0 && std::isfinite(h)))
      throw domain_error(name_ + ": MuJoCo steps forward only; h = " + to_text(h));
    ++steps_;
    model_->opt.timestep = h;
    last_warning.clear();
    try {
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

  engine_observation observe() const override {
    engine_observation o;
    switch (s_.kind) {
      case scenario_kind::free_top:
      case scenario_kind::free_top_near_axis: {
        const Eigen::Vector3d w(data_->qvel[3], data_->qvel[4], data_->qvel[5]);
        const Eigen::Vector3d m = s_.inertia.cwiseProduct(w);
        const Eigen::Quaterniond q(data_->qpos[3], data_->qpos[4], data_->qpos[5], data_->qpos[6]);
        o.observables = w;
        o.energy = w.dot(m) / 2;
        o.momentum = q.normalized().toRotationMatrix() * m;
        break;
      }
      case scenario_kind::pendulum_small:
      case scenario_kind::pendulum_large: {
        const double theta = data_->qpos[0], rate = data_->qvel[0];
        const double i_hinge = s_.mass * s_.length * s_.length + 1e-3;
        o.observables.resize(2);
        o.observables << theta, rate;
        o.energy = i_hinge * rate * rate / 2 - s_.mass * s_.gravity * s_.length * std::cos(theta);
        break;
      }
      case scenario_kind::projectile: {
        o.observables.resize(6);
        for (int i = 0; i < 3; ++i) o.observables(i) = data_->qpos[i];
        for (int i = 0; i < 3; ++i) o.observables(3 + i) = data_->qvel[i];
        const Eigen::Vector3d v = o.observables.tail(3);
        o.energy = s_.mass * v.squaredNorm() / 2 + s_.mass * s_.gravity * data_->qpos[2];
        break;
      }
    }
    return o;
  }

 private:
  scenario s_;
  std::string name_;
  mjModel* model_ = nullptr;
  mjData* data_ = nullptr;
  long long steps_ = 0;
};
}  // namespace

std::string version() {
  const int v = mj_version();
  return std::to_string(v / 100) + "." + std::to_string(v / 10 % 10) + "." + std::to_string(v % 10);
}

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
    e.declared_order = i.order;
    const int id = i.id;
    e.start = [id](const scenario& s) -> std::unique_ptr<engine_run> { return std::make_unique<run>(s, id); };
    out.push_back(std::move(e));
  }
  return out;
}

}  // namespace mechcheck::audit::mujoco
