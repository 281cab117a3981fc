#pragma once
/// Simbody (Debian libsimbody-dev 3.7) under the engine audit (engines.hpp). Built into
/// mechcheck::audit_simbody only where Simbody's CMake config is found.
///
/// Units SI; z up, Force::Gravity along -z. The scenarios:
///   - free tops and the projectile: a MobilizedBody::Free (quaternions) from Ground with
///     a Body::Rigid of the scenario's mass and principal moments; its u set by
///     setUToFitAngularVelocity / setUToFitLinearVelocity; read back through
///     getBodyRotation, getBodyAngularVelocity (ground frame: the body angular velocity is
///     R^T w), getBodyOriginLocation and getBodyOriginVelocity;
///   - pendulums: a MobilizedBody::Pin whose frames put its z axis along world y, the bob
///     (inertia 1e-3 about its centre) l below the pivot at q = 0; theta = q, thetadot = u.
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

#include "mechcheck/audit/engines.hpp"

namespace mechcheck::audit::simbody {

/// "3.7": SimTK_version_simbody of the library.
std::string version();

std::vector<engine_integrator> integrators();

}  // namespace mechcheck::audit::simbody
