#pragma once
/// The adaptive drivers and engine integrators of the third-party adapters a binary is
/// built with: each adapter's list where its macro is defined (MECHCHECK_HAVE_GSL,
/// MECHCHECK_HAVE_ARKODE, MECHCHECK_HAVE_MUJOCO, MECHCHECK_HAVE_SIMBODY,
/// MECHCHECK_HAVE_BULLET, MECHCHECK_HAVE_ODE, MECHCHECK_HAVE_DART -- the build defines them for
/// the targets that link mechcheck::audit_gsl, _arkode, _mujoco, _simbody, _bullet, _ode, _dart). Boost.Odeint's
/// drivers are always there.

#include <vector>

#include "mechcheck/audit/drivers/drivers.hpp"
#include "mechcheck/audit/dynamics/dynamics.hpp"
#include "mechcheck/audit/engines/engines.hpp"
#ifdef MECHCHECK_HAVE_GSL
#include "mechcheck/audit/adapters/gsl.hpp"
#endif
#ifdef MECHCHECK_HAVE_ARKODE
#include "mechcheck/audit/adapters/arkode.hpp"
#endif
#ifdef MECHCHECK_HAVE_MUJOCO
#include "mechcheck/audit/adapters/mujoco.hpp"
#endif
#ifdef MECHCHECK_HAVE_SIMBODY
#include "mechcheck/audit/adapters/simbody.hpp"
#endif
#ifdef MECHCHECK_HAVE_BULLET
#include "mechcheck/audit/adapters/bullet.hpp"
#endif
#ifdef MECHCHECK_HAVE_ODE
#include "mechcheck/audit/adapters/ode_engine.hpp"
#endif
#ifdef MECHCHECK_HAVE_KDL
#include "mechcheck/audit/adapters/kdl.hpp"
#endif
#ifdef MECHCHECK_HAVE_DART
#include "mechcheck/audit/adapters/dart_engine.hpp"
#endif

namespace mechcheck::audit {

/// Odeint's controlled steppers, then GSL's and SUNDIALS' drivers where built.
inline std::vector<adaptive_driver> drivers_found() {
  std::vector<adaptive_driver> all = odeint_drivers();
#ifdef MECHCHECK_HAVE_GSL
  for (auto& d : gsl::drivers()) all.push_back(std::move(d));
#endif
#ifdef MECHCHECK_HAVE_ARKODE
  for (auto& d : arkode::drivers()) all.push_back(std::move(d));
#endif
  return all;
}

/// MuJoCo's, Simbody's, Bullet's, ODE's and DART's integrators, each where built.
inline std::vector<engine_integrator> engines_found() {
  std::vector<engine_integrator> all;
#ifdef MECHCHECK_HAVE_MUJOCO
  for (auto& e : mujoco::integrators()) all.push_back(std::move(e));
#endif
#ifdef MECHCHECK_HAVE_SIMBODY
  for (auto& e : simbody::integrators()) all.push_back(std::move(e));
#endif
#ifdef MECHCHECK_HAVE_BULLET
  for (auto& e : bullet::integrators()) all.push_back(std::move(e));
#endif
#ifdef MECHCHECK_HAVE_ODE
  for (auto& e : ode_engine::integrators()) all.push_back(std::move(e));
#endif
#ifdef MECHCHECK_HAVE_DART
  for (auto& e : dart_engine::integrators()) all.push_back(std::move(e));
#endif
  return all;
}

/// How each engine built computes the inertia of its shapes.
inline std::vector<engine_shapes> shapes_found() {
  std::vector<engine_shapes> all;
#ifdef MECHCHECK_HAVE_MUJOCO
  all.push_back(mujoco::shapes());
#endif
#ifdef MECHCHECK_HAVE_SIMBODY
  all.push_back(simbody::shapes());
#endif
#ifdef MECHCHECK_HAVE_BULLET
  all.push_back(bullet::shapes());
#endif
#ifdef MECHCHECK_HAVE_ODE
  all.push_back(ode_engine::shapes());
#endif
#ifdef MECHCHECK_HAVE_DART
  all.push_back(dart_engine::shapes());
#endif
  return all;
}

/// The dynamics libraries built: their equations of motion against the exact Lagrangian.
inline std::vector<dynamics_library> dynamics_found() {
  std::vector<dynamics_library> all;
#ifdef MECHCHECK_HAVE_KDL
  all.push_back(kdl_dynamics());
#endif
#ifdef MECHCHECK_HAVE_MUJOCO
  all.push_back(mujoco::dynamics());
  all.push_back(mujoco::urdf_dynamics());
#endif
#ifdef MECHCHECK_HAVE_DART
  all.push_back(dart_engine::dynamics());
#endif
#ifdef MECHCHECK_HAVE_SIMBODY
  all.push_back(simbody::dynamics());
#endif
#ifdef MECHCHECK_HAVE_BULLET
  all.push_back(bullet::dynamics());
#endif
  return all;
}

}  // namespace mechcheck::audit
