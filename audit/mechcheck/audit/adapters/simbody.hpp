#pragma once
/// Simbody (Debian libsimbody-dev 3.7) under the engine audit (engines.hpp). Built into
/// mechcheck::audit_simbody only where Simbody's CMake config is found.
///
/// Units SI; z up, Force::Gravity along -z. A Body::Rigid of the scenario's mass, centre
/// of mass and central inertia (shifted to the body origin, as MassProperties wants it),
/// on a mobilizer from Ground: free a MobilizedBody::Free (quaternions); hinge_y a
/// MobilizedBody::Pin whose frames put its z axis along world y; ball a
/// MobilizedBody::Ball at the origin. The state set by setQToFitTransform (or the pin's
/// angle) and setUToFitVelocity; read back through getBodyRotation,
/// findMassCenterLocationInGround, findStationVelocityInGround of the centre of mass and
/// getBodyAngularVelocity (ground frame). The central force of the Kepler scenario is a
/// Force::Custom evaluated wherever Simbody evaluates forces (each stage).
/// Integrators: every one Simbody ships -- ExplicitEuler, RungeKutta2, RungeKutta3,
/// RungeKuttaMerson, RungeKuttaFeldberg, SemiExplicitEuler, SemiExplicitEuler2, Verlet
/// and CPodes -- at a fixed step (Integrator::setFixedStepSize, stepTo), each declaring
/// the order its header states in its own words (CPodes none), named simbody::<name>.
/// Simbody's exceptions become typed errors naming the step.
///
/// SimTKmath 3.7 exports 101 SUNDIALS symbols (N_V*, Dense*, Band*, ...) of the CPODES it
/// bundles. In a build that also links SUNDIALS 6.4 (the ARKODE/CVODE adapters), SUNDIALS'
/// libraries come first on the link line and their definitions win, so simbody::CPodes is
/// refused (scenario_refused) there; the other eight integrators do not use them.

#include <string>
#include <vector>

#include "mechcheck/audit/dynamics/dynamics.hpp"
#include "mechcheck/audit/engines/engines.hpp"

namespace mechcheck::audit::simbody {

/// "3.7": SimTK_version_simbody of the library.
std::string version();

std::vector<engine_integrator> integrators();

/// How simbody computes the inertia of its shapes (engines.hpp, shapes()).
engine_shapes shapes();

/// Its equations of motion (simbody_dynamics.cpp): a robot becomes a MultibodySystem of a
/// Body::Rigid per link on Pin, Slider and Weld mobilizers whose frames turn the mobilizer's
/// axis onto the joint's; M by calcM, h and inverse dynamics by
/// calcResidualForceIgnoringConstraints and forward dynamics by
/// calcAccelerationIgnoringConstraints, with Force::Gravity's body forces applied.
dynamics_library dynamics();

}  // namespace mechcheck::audit::simbody
