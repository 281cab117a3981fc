#include "mechcheck/audit/simbody.hpp"

#include <cmath>
#include <memory>
#include <string>

#include <Eigen/Core>

#include "mechcheck/audit/detail/simbody_bridge.hpp"

namespace mechcheck::audit::simbody {

namespace {
namespace bridge = simbody_bridge;

struct declared {
  const char* name;
  const char* words;  ///< the header's own words on the order
  std::optional<int> order;
};

/// The headers' words, in the bridge's order of integrators.
const declared claims[] = {
    {"ExplicitEuler", "ExplicitEulerIntegrator.h: \"error controlled, first order explicit integrator\"", 1},
    {"RungeKutta2", "RungeKutta2Integrator.h: \"second order, two stage explicit integrator\"", 2},
    {"RungeKutta3", "RungeKutta3Integrator.h: \"third order, three stage explicit integrator\"", 3},
    {"RungeKuttaMerson", "RungeKuttaMersonIntegrator.h: \"error controlled, fourth order explicit integrator\"", 4},
    {"RungeKuttaFeldberg", "RungeKuttaFeldbergIntegrator.h: \"error controlled, fifth order explicit integrator\"", 5},
    {"SemiExplicitEuler", "SemiExplicitEulerIntegrator.h: \"a first order method\"", 1},
    {"SemiExplicitEuler2", "SemiExplicitEuler2Integrator.h: \"variable-step, first-order semi-explicit\"", 1},
    {"Verlet", "VerletIntegrator.h: \"It is a third order, semi-explicit integrator\"", 3},
    {"CPodes", "CPodesIntegrator.h: variable order (BDF or Adams); no order stated", std::nullopt},
};

class run final : public engine_run {
 public:
  run(const scenario& s, int integrator) : s_(s), name_(std::string("simbody::") + bridge::integrator_name(integrator)) {
    bridge::setup b;
    b.integrator = integrator;
    b.mass = s.mass;
    b.gravity = s.gravity;
    switch (s.kind) {
      case scenario_kind::free_top:
      case scenario_kind::free_top_near_axis:
        for (int i = 0; i < 3; ++i) b.inertia[i] = s.inertia(i), b.omega0[i] = s.omega0(i);
        break;
      case scenario_kind::pendulum_small:
      case scenario_kind::pendulum_large:
        b.pin = true;
        b.length = s.length;
        b.theta0 = s.theta0;
        for (double& i : b.inertia) i = 1e-3;
        break;
      case scenario_kind::projectile:
        for (int i = 0; i < 3; ++i) b.velocity0[i] = s.velocity0(i);
        break;
    }
    try {
      model_ = std::make_unique<bridge::model>(b);
    } catch (const bridge::refused& e) {
      throw scenario_refused(name_ + ": " + e.what());
    } catch (const std::exception& e) {
      throw error(name_ + ": setting up " + s.name + ": Simbody: " + e.what());
    }
  }

  void step(double h) override {
    if (!(h > 0 && std::isfinite(h))) throw domain_error(name_ + ": the step must be positive, got " + to_text(h));
    ++steps_;
    try {
      model_->step(h);
    } catch (const std::exception& e) {
      throw convergence_error(name_ + ": step " + std::to_string(steps_) + ": Simbody: " + e.what());
    }
    for (int i = 0; i < model_->nq(); ++i)
      if (!std::isfinite(model_->q()[i]))
        throw non_finite_error(name_ + ": step " + std::to_string(steps_) + ": q[" + std::to_string(i) + "] is not finite");
  }

  engine_observation observe() const override {
    const bridge::reading r = model_->read();
    engine_observation o;
    const Eigen::Matrix3d rot = Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>(r.rotation);
    const Eigen::Vector3d w_world(r.omega_world[0], r.omega_world[1], r.omega_world[2]);
    const Eigen::Vector3d x(r.position[0], r.position[1], r.position[2]), v(r.velocity[0], r.velocity[1], r.velocity[2]);
    switch (s_.kind) {
      case scenario_kind::free_top:
      case scenario_kind::free_top_near_axis: {
        const Eigen::Vector3d w = rot.transpose() * w_world, m = s_.inertia.cwiseProduct(w);
        o.observables = w;
        o.energy = w.dot(m) / 2;
        o.momentum = rot * m;
        break;
      }
      case scenario_kind::pendulum_small:
      case scenario_kind::pendulum_large: {
        const double i_hinge = s_.mass * s_.length * s_.length + 1e-3;
        o.observables.resize(2);
        o.observables << r.q, r.u;
        o.energy = i_hinge * r.u * r.u / 2 - s_.mass * s_.gravity * s_.length * std::cos(r.q);
        break;
      }
      case scenario_kind::projectile:
        o.observables.resize(6);
        o.observables << x, v;
        o.energy = s_.mass * v.squaredNorm() / 2 + s_.mass * s_.gravity * x(2);
        break;
    }
    return o;
  }

 private:
  scenario s_;
  std::string name_;
  std::unique_ptr<bridge::model> model_;
  long long steps_ = 0;
};
}  // namespace

std::string version() { return bridge::version(); }

std::vector<engine_integrator> integrators() {
  std::vector<engine_integrator> out;
  for (int i = 0; i < bridge::integrator_count(); ++i) {
    const declared& d = claims[i];
    if (std::string(d.name) != bridge::integrator_name(i))
      throw error("simbody adapter: integrator list out of step at " + std::to_string(i));
    engine_integrator e;
    e.name = std::string("simbody::") + d.name;
    e.origin = "Simbody " + version() + " " + d.name + "Integrator at a fixed step (setFixedStepSize, stepTo); " +
               d.words + (d.order ? "; declared order " + std::to_string(*d.order) : std::string());
    e.declared_order = d.order;
    e.start = [i](const scenario& s) -> std::unique_ptr<engine_run> { return std::make_unique<run>(s, i); };
    out.push_back(std::move(e));
  }
  return out;
}

}  // namespace mechcheck::audit::simbody
