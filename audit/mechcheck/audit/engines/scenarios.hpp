#pragma once
/// The engine scenarios: physical setups in engine-neutral terms (one body held by a joint,
/// a chain of hinged links, free bodies under their gravitation), each with the exact
/// reference of its observables, and the shapes whose inertia engines compute. Every
/// engine adapter maps them to its engine; the engine audit (engines.hpp) measures with them.

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "mechcheck/audit/engines/contact.hpp"
#include "mechcheck/core.hpp"
#include "mechcheck/robots/robot.hpp"

namespace mechcheck::audit {

/// The scenarios (their parameters are fixed: see scenarios()).
enum class scenario_kind {
  free_top,            ///< asymmetric free body, no gravity: body angular velocity
  free_top_near_axis,  ///< the same near the intermediate axis (flips)
  boxes,               ///< gazebo-classic's benchmark box near its intermediate axis
  free_symmetric_top,  ///< symmetric free body: body angular velocity and symmetry axis
  heavy_top,           ///< symmetric top on a fixed point in steady precession
  heavy_top_nutation,  ///< the same top nutating from a turning point
  pendulum_small,      ///< hinge pendulum, amplitude 0.1 rad: angle and rate
  pendulum_large,      ///< hinge pendulum, amplitude 2.5 rad
  projectile,          ///< free body in uniform gravity: position and velocity
  kepler,              ///< point mass under a central inverse-square force
  double_pendulum,     ///< two links hinged about y: joint angles and rates
  chain5,              ///< five links hinged about y
  four_bar,            ///< a chain of three bars closed on the ground (a loop)
  three_body,          ///< three free bodies under their mutual gravitation
  robot,               ///< a robot (robots/robot.hpp), given or drawn: its joint coordinates and rates
  free_body,           ///< a free asymmetric body, given or drawn, its principal axes anywhere
  contact,             ///< bodies on the ground or meeting each other (contact.hpp)
};

/// How a scenario's bodies are put together.
enum class body_structure {
  one_body,     ///< the scenario's own body (its fields below), held by `joint`
  chain,        ///< `links`, each hinged about world y to the one before (link 0 to the world)
  free_bodies,  ///< `links`, free, under their mutual gravitation
  robot,        ///< `robot`: a kinematic tree in its joint coordinates (robot_start)
  contact,      ///< `contact`: bodies on the ground under Coulomb friction and restitution
};

/// One body of a multibody scenario: mass, principal moments about its centre of mass
/// along its frame's axes (the world's at zero angles), centre of mass `com` in its frame.
/// In a chain the frame's origin is the link's hinge, at `hinge` in the parent link's frame
/// (link 0: in the world); its state at t = 0 is the joint's angle `angle0` about y from
/// the parent's frame, and rate `rate0`. A free body's frame origin is its centre of mass,
/// its state at t = 0 position0 and velocity0 (no rotation).
struct link {
  double mass = 1;
  Eigen::Vector3d inertia{1, 1, 1};
  Eigen::Vector3d com{0, 0, 0};
  Eigen::Vector3d hinge{0, 0, 0};
  double angle0 = 0, rate0 = 0;
  Eigen::Vector3d position0{0, 0, 0}, velocity0{0, 0, 0};
};

/// A chain's last link hinged about y to the world as well: its point `point` (its frame)
/// at the world point `anchor`.
struct loop_closure {
  Eigen::Vector3d point{0, 0, 0}, anchor{0, 0, 0};
};

/// A robot scenario's robot and its start in the robot's coordinates (URDF's order of the
/// moving joints: robots::tree::coordinate): angles of revolute and continuous joints,
/// slides of prismatic ones, and their rates. An engine builds the tree from `robot` (its
/// links' inertia tensors in any frame, axes in any direction) and reports its joint
/// coordinates and rates in that order (body_reading::joint_q, joint_v).
///
/// A robot on a floating base (robots::robot::floating) starts, and is reported, in the
/// dynamics audit's layout (dynamics_state): q = (p; quaternion w x y z; the joints' q), the
/// root link's frame in the world, and qdot = u = (v_b; w_b; the joints' qdot), the base's
/// twist in its own frame. An engine maps them to its own base coordinates, as its dynamics
/// adapter does.
struct robot_start {
  robots::robot robot;
  Eigen::VectorXd q0, qdot0;
  std::vector<bool> angular;  ///< per joint coordinate: an angle (compared modulo 2 pi)
  /// T + V at a state, in double (robots/dynamics.hpp): the observation's energy.
  std::function<double(const Eigen::VectorXd& q, const Eigen::VectorXd& qdot)> energy;
  /// A floating base: the observables at a state, in double: the centre of mass c, the
  /// linear momentum P and the angular momentum about the centre of mass L_G (9 numbers).
  std::function<Eigen::VectorXd(const Eigen::VectorXd& q, const Eigen::VectorXd& u)> momenta;
};

/// How the scenario's body is held.
enum class joint_kind {
  free,     ///< six degrees of freedom; the body frame's origin is the centre of mass
  hinge_y,  ///< a hinge about world y through the world origin (the pivot)
  ball,     ///< a ball joint at the world origin (the pivot)
};

/// A scenario: one rigid body in engine-neutral terms every adapter maps to its engine,
/// and the exact reference of its observables.
///
/// The body: mass m, principal moments `inertia` about its centre of mass along the body
/// axes. For a jointed body the body frame's origin is the pivot (the world origin) and the
/// centre of mass is at `com` in the body frame; for a free body com = 0. World z is up;
/// gravity is |g| along -z; `central` k adds the force -m k x / |x|^3 on the centre of
/// mass at x (the Kepler problem's attraction to the origin, evaluated where the engine
/// evaluates forces).
/// The state at t = 0: orientation rotation0 (body to world), centre of mass position0 and
/// velocity0, angular velocity omega0 in the world frame (consistent with the joint).
struct scenario {
  scenario_kind kind;
  std::string name, description;
  body_structure structure = body_structure::one_body;
  std::vector<link> links;          ///< chain and free bodies
  std::optional<loop_closure> loop;  ///< a chain closed on the ground
  double gravitation = 0;           ///< G between free bodies: force G m_i m_j / r^2
  std::shared_ptr<const robot_start> robot;  ///< body_structure::robot
  std::shared_ptr<const contact_setup> contact;  ///< body_structure::contact (contact.hpp)
  joint_kind joint = joint_kind::free;
  double mass = 1;
  Eigen::Vector3d inertia{1, 1, 1};
  Eigen::Vector3d com{0, 0, 0};
  double gravity = 0;
  double central = 0;
  Eigen::Matrix3d rotation0 = Eigen::Matrix3d::Identity();
  Eigen::Vector3d position0{0, 0, 0}, velocity0{0, 0, 0}, omega0{0, 0, 0};
  double t_end = 1;              ///< time of the order study
  long steps0 = 16;              ///< its coarsest run
  double h_long = 0.01;          ///< step of the long run
  /// The scenario's own time scale: the period of its slowest motion where it has one, else
  /// the order study's span (said where it is set). The long run's growth classes are
  /// fitted past one of it and need ten (studies.hpp, classify_growth).
  double time_scale = 1;
  bool conserves_energy = true;
  /// Angular momentum about the world origin conserved: every component, or only its
  /// vertical one (a top on a fixed point under gravity).
  enum class momentum_law { none, vector, vertical } momentum = momentum_law::none;
  /// The observables at time t (exact) and their scale.
  std::function<Eigen::VectorXd(double)> exact;
  double scale = 1;
  /// The classes of the observables: a name ("orientation", "angular velocity", "joint
  /// coordinates", "position", "velocity") and the range [first, first + count) of the
  /// observables it holds. The order is measured and judged per class.
  struct observable_class {
    std::string name;
    int first = 0, count = 0;
  };
  std::vector<observable_class> classes;
};

/// The scenarios every engine is asked for.
std::vector<scenario> scenarios();

/// A robot released at (q0, qdot0) under its own gravity, observed in its joint coordinates
/// and rates at t_end (one class, "joint coordinates", as the chains), against the
/// certified reference of its Hamiltonian H = p^T M^-1 p / 2 + V (robots::robot_hamiltonian,
/// the Legendre transform of L = T - V, notes eqs 245-255; model.hpp solves it in mpfr50
/// to 25 digits when first asked, from p0 = M(q0) qdot0).
/// Energy is conserved (no damping, no limits); momentum is not (the base is fixed). Its
/// scale: max(1, |(q0, qdot0)|). Throws robots::robot_error for a robot that is not one
/// (robots::validate), domain_error for one without a moving joint, dimension_error for a
/// start of another size.
scenario robot_scenario(std::string name, const robots::robot& r, const Eigen::VectorXd& q0,
                        const Eigen::VectorXd& qdot0, double t_end = 1);

/// A robot on a floating base (robot.floating) is observed by what it keeps whatever its
/// joints do: its centre of mass c(t) = c0 + cdot0 t + g t^2 / 2 (class "centre of mass"),
/// its linear momentum P(t) = P0 + m g t ("linear momentum") and its angular momentum about
/// the centre of mass L_G(t) = L_G0 ("angular momentum"): by Newton and Euler for the whole
/// robot, uniform gravity acts at c and the joints' forces are internal (notes eqs 79-83).
/// The reference is exact, computed in mpfr50 from the start (robots/floating.hpp), with no
/// certification; its joint coordinates are not observed (they have no reference here). The
/// long run's energy is T + V, its momentum L_G. The start is q0 = (p; quaternion w x y z;
/// the joints' q) and qdot0 = u = (v_b; w_b; the joints' qdot) (robot_start); the scale is
/// the largest of 1 and the observables' terms over the run (|c0| + |cdot0| t_end + |g|
/// t_end^2 / 2, the links' sum m_i |v_i| + m |g| t_end, and sum m_i |x_i - c| |v_i| + |I_i
/// w_i|).

/// `count` random robots (generators::random_robots: 1 to max_links links, chains and
/// trees, revolute, continuous, prismatic and fixed joints, axes in any direction, rotated
/// inertias) as scenarios named robot_<seed>_<k>, each released at a random start (angles
/// in [-pi, pi], slides in [-1, 1], rates in [-2, 2]); the same seed gives the same robots.
/// A drawn robot without a moving joint gets its first joint revolute.
std::vector<scenario> random_robot_scenarios(int count, std::uint64_t seed, int max_links = 3);

/// `count` random robots on a floating base as scenarios named floating_<seed>_<k>: the
/// dynamics campaign's floating robots (generators::floating_robot_cases over robot_cases of
/// at most max_links links; the base's pose in [-1, 1]^3 and roll, pitch, yaw in [-3.14,
/// 3.14], its twist in [-4, 4] a component; robot_cases' joints: angles in [-3.14, 3.14],
/// slides in [-1, 1], rates up to 16),
/// under their own gravity, the base's quaternion rounded to double. The same seed gives
/// the same robots, robot k the same whatever the count.
std::vector<scenario> random_floating_robot_scenarios(int count, std::uint64_t seed, int max_links = 3);

/// A free body of mass `mass` and principal moments I1 < I2 < I3 < I1 + I2 (`inertia`)
/// along the columns of rotation0 (its principal axes in the world), its centre of mass at
/// position0 moving at velocity0, turning at omega0 (world frame), no gravity. Observed as
/// the body angular velocity R^T omega (against the Jacobi elliptic solution of Euler's
/// equations, reference::asymmetric_top_angular_velocity, in mpfr50 from R0^T omega0), the
/// direction of the fixed angular momentum in the body, R^T M / |M| = I Omega / |M| (the
/// orientation but for the turn about M), and the centre of mass's uniform motion. Energy
/// and angular momentum (about the origin) are conserved; the time scale is the period of
/// Omega. Throws domain_error for moments not strictly rising or breaking the triangle
/// inequality, a rotation0 that is not one (to 16 eps), a body that does not turn or one on
/// the separatrix (M^2 = 2 E I2); non_finite_error for a number that is not finite.
scenario free_body_scenario(std::string name, double mass, const Eigen::Vector3d& inertia,
                            const Eigen::Matrix3d& rotation0, const Eigen::Vector3d& position0,
                            const Eigen::Vector3d& velocity0, const Eigen::Vector3d& omega0, double t_end = 4);

/// `count` random free bodies as scenarios named body_<seed>_<k>: masses in [1/4, 4],
/// moments I1 in [1/4, 2] with both gaps at least I1 / 16 and I3 < I1 + I2, the principal
/// axes turned by roll, pitch and yaw in [-3.14, 3.14], a body angular velocity in [-2, 2]^3
/// about no principal axis (two components at least, |Omega| >= 1/4, |M^2 - 2 E I2| >=
/// M^2 / 8), the centre of mass in [-1, 1]^3 moving at up to 1 a component; every number
/// dyadic. The same seed gives the same bodies, body k the same whatever the count.
std::vector<scenario> random_body_scenarios(int count, std::uint64_t seed);

/// A hinge scenario (pendulum) started at angle theta and rate thetadot instead of its own
/// initial state: the map of one step in (theta, thetadot) for the Jacobian study.
scenario with_hinge_state(scenario s, double theta, double thetadot);

/// An angle reduced to [-pi, pi]: how joint angles are compared with their references.
double wrap_angle(double a);

/// Moment of inertia of a hinge scenario's body about its hinge: m |com|^2 + I_yy.
double hinge_inertia(const scenario& s);

/// A lower bound of the gravitational potential sum m g z over every configuration the
/// joints allow, for a jointed scenario under gravity: a body on a pivot at the origin,
/// -m g |com|; a chain, each link's centre of mass at most the lengths of the links above
/// it and its own arm below the first hinge (hanging straight down: the bound is reached by
/// an open chain of bars, not by a closed loop). None for a free body, the robots or no
/// gravity. E0 minus it is the energy the motion can exchange: the engines' long runs
/// report their energy error relative to that, not to |E0|, whose potential has an
/// arbitrary zero (a pendulum's swing at 0.1 rad is 0.5 % of |E0| = m g l cos 0.1).
std::optional<double> potential_floor(const scenario& s);

/// A body's frame: orientation (body to world), centre of mass position and velocity,
/// angular velocity in the world frame.
struct body_frame {
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
  Eigen::Vector3d position{0, 0, 0}, velocity{0, 0, 0}, omega{0, 0, 0};
};

/// The frames of a chain's links at joint angles and rates (relative, as link::angle0 and
/// rate0): what an engine in body coordinates starts from.
std::vector<body_frame> chain_frames(const scenario& s, const Eigen::VectorXd& angles, const Eigen::VectorXd& rates);

/// A uniform solid, centred at the body origin, its axis (cylinder, capsule, cone) along z;
/// or a compound body: two solid spheres of radius r and mass m/2 centred at (+-d, 0, 0).
struct shape {
  std::string name;  ///< box, sphere, cylinder, capsule, cone, ellipsoid, two_spheres, convex_hull
  double mass = 1;
  /// box: edges; sphere: (r); cylinder, cone: (r, height); capsule: (r, length of its
  /// cylinder); ellipsoid: semi-axes; two_spheres: (r, d); convex_hull: (a, b, c), the hull
  /// of the points (+-a, 0, c) and (0, +-b, -c) (a tetrahedron, centroid at the origin).
  Eigen::Vector3d size{0, 0, 0};
};

/// The shapes every engine is asked for.
std::vector<shape> shapes();

/// A shape's principal moments about its centre of mass, ascending, from reference/solids.hpp
/// (and the parallel-axis theorem, eq 160, for the compound) in mpfr50.
Eigen::Vector3d exact_principal_moments(const shape& s);

/// A shape's volume (the compound's spheres apart), in mpfr50 rounded to double.
double shape_volume(const shape& s);

}  // namespace mechcheck::audit
