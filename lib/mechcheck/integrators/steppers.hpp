#pragma once
/// One-step integrators for Hamiltonian systems (see systems.hpp), one method family per
/// header: explicit_rk.hpp, splitting.hpp, composition.hpp, gauss_legendre.hpp; guards.hpp
/// and workspace.hpp hold what they share.
///
/// Every stepper is a callable `stepper(state, h)` that advances a phase_state<Vec> by
/// one step h in place; a user's own stepper satisfying the same call is audited the
/// same way (mechcheck::stepper concept). Steppers are templated on the system and on
/// the state vector type Vec, whose scalar may be a tier or an AD type over one (the
/// Jacobian of a step is taken by running the stepper on AD scalars).
///
/// Method               order  symplectic  symmetric  needs
/// explicit_euler        1      no          no         vector_field
/// rk4                   4      no          no         vector_field
/// symplectic_euler      1      yes         no         separable (velocity, force)
/// stormer_verlet        2      yes         yes        separable
/// composition<4|6|8>    4/6/8  yes         yes        separable (triple-jump of Verlet)
/// mclachlan4            4      yes         yes        separable (McLachlan's SB3A splitting)
/// gauss_legendre<1..4>  2s     yes         yes        vector_field (implicit, any H)
/// The static members order, symplectic and symmetric declare these; mechcheck::audit
/// confirms or contradicts them.

#include "mechcheck/integrators/composition.hpp"
#include "mechcheck/integrators/explicit_rk.hpp"
#include "mechcheck/integrators/gauss_legendre.hpp"
#include "mechcheck/integrators/guards.hpp"
#include "mechcheck/integrators/splitting.hpp"
