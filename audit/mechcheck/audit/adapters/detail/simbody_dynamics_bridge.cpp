// Compiled as C++17 (see simbody_bridge.hpp): Simbody's equations of motion of a robot.
#include <Simbody.h>

#include <memory>
#include <vector>

#include "mechcheck/audit/adapters/detail/simbody_bridge.hpp"

namespace mechcheck::audit::simbody_bridge {

namespace {
using namespace SimTK;

Mat33 mat33(const double* m) { return Mat33(m[0], m[1], m[2], m[3], m[4], m[5], m[6], m[7], m[8]); }
Vec3 vec3(const double* v) { return Vec3(v[0], v[1], v[2]); }

/// The body's mass properties as MassProperties wants them: the inertia about the body's
/// origin, shifted from the centre of mass (Inertia::shiftFromMassCenter), symmetrized first
/// (the tensor turned into the body frame carries asymmetry at rounding).
MassProperties mass_properties(const robot_setup::body& b) {
  const Mat33 i = mat33(b.inertia);
  const Mat33 symmetric = (i + ~i) / 2;
  const Inertia central(symmetric);
  return MassProperties(b.mass, vec3(b.com), central.shiftFromMassCenter(-vec3(b.com), b.mass));
}
}  // namespace

std::vector<MobilizedBody> build_robot(const robot_setup& r, SimbodyMatterSubsystem& matter,
                                       std::vector<MobilizedBody>* all) {
  std::vector<MobilizedBody> mobods, moving;
  for (const auto& b : r.bodies) {
    MobilizedBody& parent = b.parent < 0 ? matter.updGround() : mobods[std::size_t(b.parent)];
    const Transform origin(Rotation(mat33(b.rotation)), vec3(b.position));
    const Body::Rigid info(mass_properties(b));
    if (b.joint == 3) {
      mobods.push_back(MobilizedBody::Free(parent, Transform(), info, Transform()));
      moving.push_back(mobods.back());
    } else if (b.joint == 0 || b.joint == 1) {
      // The mobilizer's frames F (on the parent, at the joint's origin) and M (on the
      // body, at its origin) turned so that their z axis (Pin) or x axis (Slider) is the
      // joint's axis: X_PB = origin * R_a * motion(q) * R_a^T.
      const Rotation ra(UnitVec3(vec3(b.axis)), b.joint == 0 ? CoordinateAxis(ZAxis) : CoordinateAxis(XAxis));
      if (b.joint == 0)
        mobods.push_back(MobilizedBody::Pin(parent, origin * Transform(ra), info, Transform(ra)));
      else
        mobods.push_back(MobilizedBody::Slider(parent, origin * Transform(ra), info, Transform(ra)));
      moving.push_back(mobods.back());
    } else {
      mobods.push_back(MobilizedBody::Weld(parent, origin, info, Transform()));
    }
  }
  if (all) *all = mobods;
  return moving;
}

struct robot_dynamics::impl {
  MultibodySystem system;
  SimbodyMatterSubsystem matter{system};
  GeneralForceSubsystem forces{system};
  std::vector<MobilizedBody> all;     ///< every body, robot_setup's order
  std::vector<MobilizedBody> moving;  ///< in order
  Force::Gravity gravity;
  std::vector<UIndex> u;              ///< per mobility, in the moving bodies' order
  std::vector<Vec3> com;              ///< each body's mass centre in its frame, robot_setup's order
  bool free = false;                  ///< the first moving body is a Free root
  mutable State state;

  explicit impl(const robot_setup& r)
      : moving(build_robot(r, matter, &all)), gravity(forces, matter, vec3(r.gravity)),
        free(!r.bodies.empty() && r.bodies.front().joint == 3) {
    for (const auto& b : r.bodies) com.push_back(vec3(b.com));
    std::size_t k = 0;
    for (const auto& b : r.bodies)
      if (b.joint == 0 || b.joint == 1 || b.joint == 3) {
        if (b.damping > 0) Force::MobilityLinearDamper(forces, moving[k], MobilizerUIndex(0), b.damping);
        ++k;
      }
    state = system.realizeTopology();
    for (const MobilizedBody& m : moving)
      for (int i = 0; i < m.getNumU(state); ++i) u.push_back(UIndex(m.getFirstUIndex(state) + i));
  }
  void set(const double* qs, const double* us, Stage stage) const {
    std::size_t at = 0, rate = 0;
    for (std::size_t k = 0; k < moving.size(); ++k) {
      if (free && k == 0) {
        const Rotation r(Quaternion(qs[3], qs[4], qs[5], qs[6]));
        moving[k].setQToFitTransform(state, Transform(r, Vec3(qs[0], qs[1], qs[2])));
        for (int i = 0; i < 6; ++i) moving[k].setOneU(state, i, us ? us[rate + std::size_t(i)] : 0.0);
        at += 7, rate += 6;
        continue;
      }
      moving[k].setOneQ(state, 0, qs[at++]);
      moving[k].setOneU(state, 0, us ? us[rate] : 0.0);
      ++rate;
    }
    system.realize(state, stage);
  }
  Vector mobility(const double* x) const {
    Vector out(state.getNU(), 0.0);
    for (std::size_t k = 0; k < u.size(); ++k) out[u[k]] = x[k];
    return out;
  }
  /// The force elements' applied forces (gravity's body forces, the dampers' mobility
  /// forces -c u), summed by the system at Stage::Dynamics.
  const Vector_<SpatialVec>& body_forces() const { return system.getRigidBodyForces(state, Stage::Dynamics); }
  const Vector& mobility_forces() const { return system.getMobilityForces(state, Stage::Dynamics); }
  void out(const Vector& v, double* x) const {
    for (std::size_t k = 0; k < u.size(); ++k) x[k] = v[u[k]];
  }
};

robot_dynamics::robot_dynamics(const robot_setup& r) : p_(std::make_unique<impl>(r)) {}
robot_dynamics::~robot_dynamics() = default;

int robot_dynamics::size() const { return static_cast<int>(p_->u.size()); }

void robot_dynamics::mass_matrix(const double* q, double* m) const {
  p_->set(q, nullptr, Stage::Position);
  Matrix full;
  p_->matter.calcM(p_->state, full);
  const std::size_t n = p_->u.size();
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = 0; j < n; ++j) m[i * n + j] = full(p_->u[i], p_->u[j]);
}

// f_residual = M udot + f_inertial - f_applied (SimbodyMatterSubsystem.h), the applied
// forces the force elements' (gravity, the dampers): at udot = 0 the bias h, at udot the
// inverse dynamics.
void robot_dynamics::bias(const double* q, const double* u, double* h) const {
  p_->set(q, u, Stage::Dynamics);
  Vector residual;
  p_->matter.calcResidualForceIgnoringConstraints(p_->state, p_->mobility_forces(), p_->body_forces(), Vector(),
                                                  residual);
  p_->out(residual, h);
}

void robot_dynamics::inverse(const double* q, const double* u, const double* udot, double* tau) const {
  p_->set(q, u, Stage::Dynamics);
  Vector residual;
  p_->matter.calcResidualForceIgnoringConstraints(p_->state, p_->mobility_forces(), p_->body_forces(),
                                                  p_->mobility(udot), residual);
  p_->out(residual, tau);
}

// M udot + f_inertial = f_applied (calcAccelerationIgnoringConstraints), f_applied = tau and
// the force elements'.
void robot_dynamics::forward(const double* q, const double* u, const double* tau, double* udot) const {
  p_->set(q, u, Stage::Dynamics);
  Vector accelerations;
  Vector_<SpatialVec> a_gb;
  p_->matter.calcAccelerationIgnoringConstraints(p_->state, p_->mobility(tau) + p_->mobility_forces(),
                                                 p_->body_forces(), accelerations, a_gb);
  p_->out(accelerations, udot);
}

void robot_dynamics::frames(const double* q, double* out) const {
  p_->set(q, nullptr, Stage::Position);
  for (std::size_t b = 0; b < p_->all.size(); ++b) {
    const Transform& x = p_->all[b].getBodyTransform(p_->state);
    for (int i = 0; i < 3; ++i) out[12 * b + std::size_t(i)] = x.p()[i];
    for (int c = 0; c < 3; ++c)
      for (int i = 0; i < 3; ++i) out[12 * b + 3 + 3 * std::size_t(c) + std::size_t(i)] = x.R().asMat33()(i, c);
  }
}

namespace {
Array_<MobilizedBodyIndex> indices(const std::vector<MobilizedBody>& bodies) {
  Array_<MobilizedBodyIndex> out;
  for (const MobilizedBody& b : bodies) out.push_back(b.getMobilizedBodyIndex());
  return out;
}
}  // namespace

void robot_dynamics::frame_jacobians(const double* q, double* out, bool at_com) const {
  p_->set(q, nullptr, Stage::Position);
  Array_<Vec3> origins(p_->all.size(), Vec3(0));
  if (at_com)
    for (std::size_t b = 0; b < p_->all.size(); ++b) origins[unsigned(b)] = p_->com[b];
  Matrix jf;
  p_->matter.calcFrameJacobian(p_->state, indices(p_->all), origins, jf);
  const std::size_t nu = p_->u.size();
  for (std::size_t r = 0; r < 6 * p_->all.size(); ++r)
    for (std::size_t k = 0; k < nu; ++k) out[r * nu + k] = jf(int(r), p_->u[k]);
}

void robot_dynamics::frame_biases(const double* q, const double* u, double* out) const {
  p_->set(q, u, Stage::Velocity);
  const Array_<Vec3> origins(p_->all.size(), Vec3(0));
  Vector bias;
  p_->matter.calcBiasForFrameJacobian(p_->state, indices(p_->all), origins, bias);
  for (std::size_t r = 0; r < 6 * p_->all.size(); ++r) out[r] = bias[int(r)];
}

void robot_dynamics::centre_of_mass(const double* q, double* out) const {
  p_->set(q, nullptr, Stage::Position);
  const Vec3 c = p_->matter.calcSystemMassCenterLocationInGround(p_->state);
  for (int i = 0; i < 3; ++i) out[i] = c[i];
}

void robot_dynamics::central_momenta(const double* q, double* out) const {
  const std::size_t nu = p_->u.size();
  std::vector<double> e(nu, 0.0);
  for (std::size_t k = 0; k < nu; ++k) {
    e[k] = 1;
    p_->set(q, e.data(), Stage::Velocity);
    e[k] = 0;
    const Vec3 v = p_->matter.calcSystemMassCenterVelocityInGround(p_->state);
    const SpatialVec h = p_->matter.calcSystemCentralMomentum(p_->state);
    for (int i = 0; i < 3; ++i) {
      out[std::size_t(i) * nu + k] = v[i];
      out[std::size_t(3 + i) * nu + k] = h[1][i];
      out[std::size_t(6 + i) * nu + k] = h[0][i];
    }
  }
}

}  // namespace mechcheck::audit::simbody_bridge
