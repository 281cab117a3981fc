// DART applies a joint's damping implicitly, with the Skeleton's time step h, in its inverse
// and forward dynamics alike: its equations of motion are M qddot + C + N + d (qdot + h qddot)
// = tau, not the Lagrangian's M qddot + C + N + d qdot = tau. DART's words (Joint.hpp, on
// the damping force): "We apply the damping force in implicit manner. The damping force is
// F = -(dampingCoefficient * dq(k+1)), where dq(k+1) is approximated as dq(k) + h * ddq(k)";
// GenericJoint::updateForceID: "Implicit damping force: tau_d = -Kd * dq - Kd * h * ddq".
// Uses DART only.
//
// Setup: a Skeleton of one body on a RevoluteJoint about z (no gravity), mass 1 at 0.5 m
// along x with moments 0.25 about its centre (M = 0.25 + 0.5^2 = 0.5), damping d = 0.5; the
// state qdot = 1.1, qddot = 2 for the inverse dynamics, tau = 3 for the forward; at DART's
// default time step (0.001 s) and at 2^-80 s.
//
// Build: c++ dart_implicit_damping.cpp -isystem /opt/mechcheck/dart/usr/include -isystem /usr/include/eigen3 \
//   /usr/lib/x86_64-linux-gnu/libdart.so.6.12 /usr/lib/x86_64-linux-gnu/libfcl.so.0.7 /usr/lib/x86_64-linux-gnu/libccd.so.2
// Prints: lines "name value".
#include <dart/dynamics/BodyNode.hpp>
#include <dart/dynamics/RevoluteJoint.hpp>
#include <dart/dynamics/Skeleton.hpp>

#include <cstdio>

using namespace dart::dynamics;

int main() {
  const double mass = 1, offset = 0.5, moment = 0.25, d = 0.5, qdot = 1.1, qddot = 2, tau = 3;
  const SkeletonPtr skeleton = Skeleton::create("arm");
  skeleton->setGravity(Eigen::Vector3d::Zero());
  RevoluteJoint::Properties joint;
  joint.mName = "hinge";
  joint.mAxis = Eigen::Vector3d::UnitZ();
  BodyNode* body = skeleton->createJointAndBodyNodePair<RevoluteJoint>(nullptr, joint).second;
  body->setInertia(Inertia(mass, Eigen::Vector3d(offset, 0, 0), Eigen::Vector3d::Constant(moment).asDiagonal()));
  body->getParentJoint()->setDampingCoefficient(0, d);
  std::printf("default_time_step %.17g\n", skeleton->getTimeStep());
  std::printf("mass_matrix %.17g\n", skeleton->getMassMatrix()(0, 0));
  for (const double h : {skeleton->getTimeStep(), 0x1p-80}) {
    const char* name = h == 0x1p-80 ? "h_2^-80" : "h_default";
    skeleton->setTimeStep(h);
    skeleton->setPositions(Eigen::VectorXd::Zero(1));
    skeleton->setVelocities(Eigen::VectorXd::Constant(1, qdot));
    skeleton->setAccelerations(Eigen::VectorXd::Constant(1, qddot));
    skeleton->computeInverseDynamics(false, true, false);
    const double inverse = skeleton->getForces()(0);
    skeleton->setForces(Eigen::VectorXd::Constant(1, tau));
    skeleton->computeForwardDynamics();
    const double forward = skeleton->getAccelerations()(0);
    const double m = moment + mass * offset * offset;
    std::printf("%s inverse %.17g (M qddot + d qdot = %.17g; + h d qddot = %.17g)\n", name, inverse,
                m * qddot + d * qdot, m * qddot + d * (qdot + h * qddot));
    std::printf("%s forward %.17g ((tau - d qdot) / M = %.17g; / (M + h d) = %.17g)\n", name, forward,
                (tau - d * qdot) / m, (tau - d * qdot) / (m + h * d));
  }
  return 0;
}
