#include "mechcheck/audit/bullet.hpp"

#include <btBulletDynamicsCommon.h>

#include <cmath>
#include <memory>
#include <string>

#include <Eigen/Core>

static_assert(sizeof(btScalar) == sizeof(double), "mechcheck's Bullet adapter needs bullet-float64");

namespace mechcheck::audit::bullet {

namespace {
struct gyroscopic_mode {
  const char* name;
  int flags;
};
const gyroscopic_mode modes[] = {
    {"none", 0},
    {"explicit", BT_ENABLE_GYROSCOPIC_FORCE_EXPLICIT},
    {"implicit_world", BT_ENABLE_GYROSCOPIC_FORCE_IMPLICIT_WORLD},
    {"implicit_body", BT_ENABLE_GYROSCOPIC_FORCE_IMPLICIT_BODY},
};

Eigen::Vector3d vec(const btVector3& v) { return {v.x(), v.y(), v.z()}; }
Eigen::Matrix3d mat(const btMatrix3x3& m) {
  Eigen::Matrix3d r;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) r(i, j) = m[i][j];
  return r;
}

class run final : public engine_run {
 public:
  run(const scenario& s, const gyroscopic_mode& g)
      : s_(s), name_(std::string("bullet::gyroscopic_") + g.name) {
    config_ = std::make_unique<btDefaultCollisionConfiguration>();
    dispatcher_ = std::make_unique<btCollisionDispatcher>(config_.get());
    broadphase_ = std::make_unique<btDbvtBroadphase>();
    solver_ = std::make_unique<btSequentialImpulseConstraintSolver>();
    world_ = std::make_unique<btDiscreteDynamicsWorld>(dispatcher_.get(), broadphase_.get(), solver_.get(),
                                                        config_.get());
    world_->setGravity(btVector3(0, 0, -s.gravity));
    shape_ = std::make_unique<btSphereShape>(0.1);
    btVector3 inertia(1, 1, 1);
    btTransform start;
    start.setIdentity();
    switch (s.kind) {
      case scenario_kind::free_top:
      case scenario_kind::free_top_near_axis:
        inertia = btVector3(s.inertia(0), s.inertia(1), s.inertia(2));
        break;
      case scenario_kind::pendulum_small:
      case scenario_kind::pendulum_large:
        inertia = btVector3(1e-3, 1e-3, 1e-3);
        start.setOrigin(btVector3(-s.length * std::sin(s.theta0), 0, -s.length * std::cos(s.theta0)));
        start.setBasis(btMatrix3x3(btQuaternion(btVector3(0, 1, 0), s.theta0)));
        break;
      case scenario_kind::projectile:
        break;
    }
    btRigidBody::btRigidBodyConstructionInfo info(s.mass, nullptr, shape_.get(), inertia);
    info.m_startWorldTransform = start;
    info.m_linearDamping = 0;
    info.m_angularDamping = 0;
    body_ = std::make_unique<btRigidBody>(info);
    body_->setActivationState(DISABLE_DEACTIVATION);
    body_->setFlags(g.flags);
    world_->addRigidBody(body_.get());
    switch (s.kind) {
      case scenario_kind::free_top:
      case scenario_kind::free_top_near_axis:
        body_->setAngularVelocity(btVector3(s.omega0(0), s.omega0(1), s.omega0(2)));  // R = 1
        break;
      case scenario_kind::pendulum_small:
      case scenario_kind::pendulum_large: {
        // Pivot at the origin: in the bob's frame at l along its own +z.
        hinge_ = std::make_unique<btHingeConstraint>(*body_, btVector3(0, 0, s.length), btVector3(0, 1, 0));
        world_->addConstraint(hinge_.get());
        break;
      }
      case scenario_kind::projectile:
        body_->setLinearVelocity(btVector3(s.velocity0(0), s.velocity0(1), s.velocity0(2)));
        break;
    }
  }
  ~run() override {
    if (hinge_) world_->removeConstraint(hinge_.get());
    if (body_) world_->removeRigidBody(body_.get());
  }
  run(const run&) = delete;
  run& operator=(const run&) = delete;

  void step(double h) override {
    if (!(h > 0 && std::isfinite(h))) throw domain_error(name_ + ": the step must be positive, got " + to_text(h));
    ++steps_;
    world_->stepSimulation(h, 0);
    const Eigen::Vector3d x = vec(body_->getCenterOfMassPosition()), w = vec(body_->getAngularVelocity());
    if (!x.allFinite() || !w.allFinite())
      throw non_finite_error(name_ + ": step " + std::to_string(steps_) + ": the body's state is not finite");
  }

  engine_observation observe() const override {
    engine_observation o;
    const Eigen::Matrix3d r = mat(body_->getWorldTransform().getBasis());
    const Eigen::Vector3d w_world = vec(body_->getAngularVelocity());
    const Eigen::Vector3d x = vec(body_->getCenterOfMassPosition()), v = vec(body_->getLinearVelocity());
    switch (s_.kind) {
      case scenario_kind::free_top:
      case scenario_kind::free_top_near_axis: {
        const Eigen::Vector3d w = r.transpose() * w_world, m = s_.inertia.cwiseProduct(w);
        o.observables = w;
        o.energy = w.dot(m) / 2;
        o.momentum = r * m;
        break;
      }
      case scenario_kind::pendulum_small:
      case scenario_kind::pendulum_large:
        o.observables.resize(2);
        o.observables << std::atan2(-x(0), -x(2)), w_world(1);
        o.energy = s_.mass * v.squaredNorm() / 2 + 1e-3 * w_world.squaredNorm() / 2 + s_.mass * s_.gravity * x(2);
        break;
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
  std::unique_ptr<btDefaultCollisionConfiguration> config_;
  std::unique_ptr<btCollisionDispatcher> dispatcher_;
  std::unique_ptr<btBroadphaseInterface> broadphase_;
  std::unique_ptr<btSequentialImpulseConstraintSolver> solver_;
  std::unique_ptr<btDiscreteDynamicsWorld> world_;
  std::unique_ptr<btCollisionShape> shape_;
  std::unique_ptr<btRigidBody> body_;
  std::unique_ptr<btHingeConstraint> hinge_;
  long long steps_ = 0;
};
}  // namespace

std::string version() {
  const int v = btGetVersion();
  return std::to_string(v / 100) + "." + std::to_string(v % 100);
}

std::vector<engine_integrator> integrators() {
  std::vector<engine_integrator> out;
  for (const gyroscopic_mode& g : modes) {
    engine_integrator e;
    e.name = std::string("bullet::gyroscopic_") + g.name;
    e.origin = "Bullet " + version() + " (bullet-float64), btDiscreteDynamicsWorld::stepSimulation(h, 0), " +
               "btRigidBody gyroscopic flags " + (g.flags == 0 ? "0 (no gyroscopic force)" : g.name) +
               (g.flags == BT_ENABLE_GYROSCOPIC_FORCE_IMPLICIT_BODY
                    ? " (btRigidBody.h: \"enabled by default in Bullet 2.83 and onwards\")"
                    : "") +
               "; Bullet states no order";
    const gyroscopic_mode* mode = &g;
    e.start = [mode](const scenario& s) -> std::unique_ptr<engine_run> { return std::make_unique<run>(s, *mode); };
    out.push_back(std::move(e));
  }
  return out;
}

}  // namespace mechcheck::audit::bullet
