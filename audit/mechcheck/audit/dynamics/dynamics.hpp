#pragma once
/// The equations of motion under audit: what a dynamics library computes for a robot --
/// the mass matrix M(q), the bias forces h(q, qdot), inverse dynamics tau(q, qdot, qddot)
/// and forward dynamics qddot(q, qdot, tau) -- against the exact Lagrangian of the same
/// robot (robots/dynamics.hpp) in mpfr50, rounded once to double: its M and h evaluated by
/// composite rigid bodies and Newton-Euler (robots/recursive.hpp, which the law
/// robots.recursive_dynamics holds to the nested AD of L in every tier).
///
/// The residual of a quantity is max |library - reference| / (eps * scale), eps = 2^-52,
/// with the scale of the terms the computation sums, before they cancel (robots::term_scales:
/// I = sum m r^2 + |I_link| over the links' lever bounds r, G = sum m |g| r):
///   M        max(|M|, I);
///   h        max(|g|, G, |h - g|, max(|M|, I) |qdot|^2);
///   tau      max(scale of h, max(|M|, I) |qddot|);
///   qddot    |M^-1| (max(|M|, I) |qddot| + max(scale of h, |tau|))  (M's error, relative
///            to its terms, and the solve's backward error, amplified by M^-1 as cond(M) does
///            where no moment cancels; and the error of tau - h through M^-1);
/// all norms the largest component. The budget is 16 n eps scale for a robot of n moving
/// links: a recursive algorithm passes through n levels, each a handful of 3x3 rotations
/// and 3-term dot products (about 16 roundings of the scale). A residual above the budget is
/// a disagreement; its robot is printed as URDF with its state.

#include <algorithm>
#include <cstdint>
#include <functional>
#include <ostream>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "mechcheck/audit/result.hpp"
#include "mechcheck/core.hpp"
#include "mechcheck/harness/generators.hpp"
#include "mechcheck/robots/robot.hpp"

namespace mechcheck::robots {
template <class T>
struct base_pose;
}  // namespace mechcheck::robots

namespace mechcheck::audit {

/// A library that cannot express a robot (a joint type, a tree where it takes chains).
class robot_refused : public error {
 public:
  using error::error;
};

/// A robot beyond the audit's size (dynamics_max_joints), refused before any library runs.
class robot_too_large : public domain_error {
 public:
  using domain_error::domain_error;
};

/// The most moving joints (a floating base's six motions besides) the dynamics audit takes
/// on a robot: its mpfr50 reference costs n^3 / 3 operations a state for the Cholesky of M
/// (and M's n^2 entries); measured in docs/audit.md ("Robots of any size").
constexpr int dynamics_max_joints = 512;

/// Throws robot_too_large for a robot of more moving joints than dynamics_max_joints (and
/// robots::robot_error for one that is not a robot).
void require_dynamics_size(const robots::robot& robot);

/// A library's failure on a robot it accepted: an error code returned, a value of the wrong
/// size. The message names the library, the quantity and the status.
class library_failure : public error {
 public:
  using error::error;
};

/// The quantities of the equations of motion, and the kinematics every controller asks
/// before them:
///   frame_poses      12 x L: column l the frame of the robot's link l (its order) in the
///                    world, its origin over its rotation's three columns;
///   frame_jacobians  6 L x v: rows 6 l .. 6 l + 5 link l's geometric Jacobian (v_o; omega),
///                    the velocity of its frame's origin and its angular velocity in the world,
///                    against the state's velocities (qdot; u on a floating base, whose
///                    columns a library's base convention maps as its forces: J = J_lib T);
///   frame_bias_accelerations  6 L x 1: rows 6 l .. 6 l + 5 link l's Jdot qdot (a_o; alpha),
///                    the classical acceleration of its frame's origin and its angular
///                    acceleration in the world at zero accelerations (qddot = 0; udot = 0 on a
///                    floating base, the body twist's rate, whose linear part a library that
///                    takes the base's velocity in the world sees as R (w_b x v_b)).
///   link_com_jacobians  6 L x v: as frame_jacobians, of the point of each link at its centre
///                    of mass (its frame's origin for a link without a body): (v_c; omega);
///   centre_of_mass   3 x 1: the robot's centre of mass in the world, over every link of the
///                    description that carries a body (a fixed root's too, which never moves);
///   com_jacobian     3 x v: its Jacobian, cdot = J_c (qdot; u);
///   centroidal_momentum_matrix  6 x v: A_G, h_G = A_G (qdot; u), rows (P; L_G) the links'
///                    total momentum and their angular momentum about the centre of mass
///                    (robots/kinematics.hpp; Orin, Goswami and Lee stack them (L_G; P)).
/// Their reference is the forward kinematics of robots/dynamics.hpp (link_states) in mpfr50,
/// a Jacobian's column k the links' twists at velocity e_k, exactly, and Jdot qdot the links'
/// accelerations of robots/recursive.hpp (link_accelerations) at qddot = 0; scale max(1, the
/// longest path from the world's origin to a link's frame or centre of mass), which bounds
/// every position and every column of a revolute joint (a rotation's entries and a slide's
/// columns are within 1), times w^2 for Jdot qdot, w the largest of 1, a link's |omega| and
/// a rate (its terms are omega x (omega x d), 2 omega x a qdot, alpha x d, w_b x v_b). The
/// centre of mass and J_c take the same scale (the links' centres of mass are within the
/// lever); A_G max(sum m_i r_i^2 + |I_i|, sum m_i lever) (robots::term_scales' inertia: the
/// angular rows' terms m (x - c) x v and R I R^T omega; the linear rows' m v).
enum class dynamics_quantity {
  mass_matrix,
  bias,
  inverse,
  forward,
  frame_poses,
  frame_jacobians,
  frame_bias_accelerations,
  link_com_jacobians,
  centre_of_mass,
  com_jacobian,
  centroidal_momentum_matrix
};
const char* dynamics_quantity_name(dynamics_quantity q);
/// Whether q is one of the kinematics (the frames' and the centre of mass's quantities).
inline bool kinematic_quantity(dynamics_quantity q) {
  return q == dynamics_quantity::frame_poses || q == dynamics_quantity::frame_jacobians ||
         q == dynamics_quantity::frame_bias_accelerations || q == dynamics_quantity::link_com_jacobians ||
         q == dynamics_quantity::centre_of_mass ||
         q == dynamics_quantity::com_jacobian || q == dynamics_quantity::centroidal_momentum_matrix;
}
/// Every quantity, in the reports' order.
inline constexpr dynamics_quantity all_dynamics_quantities[] = {
    dynamics_quantity::mass_matrix,     dynamics_quantity::bias,           dynamics_quantity::inverse,
    dynamics_quantity::forward,         dynamics_quantity::frame_poses,    dynamics_quantity::frame_jacobians,
    dynamics_quantity::frame_bias_accelerations, dynamics_quantity::link_com_jacobians,
    dynamics_quantity::centre_of_mass,  dynamics_quantity::com_jacobian,
    dynamics_quantity::centroidal_momentum_matrix};

/// One library's model of one robot: each quantity it offers (nothing where it offers none).
/// Coordinates in the description's order of its moving joints (robots::tree).
class dynamics_model {
 public:
  virtual ~dynamics_model() = default;
  /// The robot as the library holds it, where its model builder changes the robot it was
  /// given (MuJoCo 2.2.2's compiler turns each inertia tensor into principal moments and a
  /// frame by an iteration that stops short of double precision; its URDF import fuses links joined
  /// by fixed joints): the quantities are then held to this robot's Lagrangian, and the
  /// distance between the two robots is reported apart (dynamics_check::model_difference).
  /// Its moving joints in the order of the robot's coordinates. None: the robot as given.
  virtual std::optional<robots::robot> held_robot() const { return std::nullopt; }
  virtual std::optional<Eigen::MatrixXd> mass_matrix(const Eigen::VectorXd& q) = 0;
  virtual std::optional<Eigen::VectorXd> bias(const Eigen::VectorXd& q, const Eigen::VectorXd& qdot) = 0;
  virtual std::optional<Eigen::VectorXd> inverse(const Eigen::VectorXd& q, const Eigen::VectorXd& qdot,
                                                 const Eigen::VectorXd& qddot) = 0;
  virtual std::optional<Eigen::VectorXd> forward(const Eigen::VectorXd& q, const Eigen::VectorXd& qdot,
                                                 const Eigen::VectorXd& tau) = 0;
  /// The kinematics (dynamics_quantity's frame_poses and frame_jacobians, the links in the
  /// order of the robot the model was built from); none by default.
  virtual std::optional<Eigen::MatrixXd> frame_poses(const Eigen::VectorXd& /*q*/) { return std::nullopt; }
  virtual std::optional<Eigen::MatrixXd> frame_jacobians(const Eigen::VectorXd& /*q*/) { return std::nullopt; }
  virtual std::optional<Eigen::VectorXd> frame_bias_accelerations(const Eigen::VectorXd& /*q*/,
                                                                  const Eigen::VectorXd& /*qdot*/) {
    return std::nullopt;
  }
  virtual std::optional<Eigen::MatrixXd> link_com_jacobians(const Eigen::VectorXd& /*q*/) { return std::nullopt; }
  /// The centre of mass's quantities (dynamics_quantity's centre_of_mass, com_jacobian,
  /// centroidal_momentum_matrix); none by default.
  virtual std::optional<Eigen::VectorXd> centre_of_mass(const Eigen::VectorXd& /*q*/) { return std::nullopt; }
  virtual std::optional<Eigen::MatrixXd> com_jacobian(const Eigen::VectorXd& /*q*/) { return std::nullopt; }
  virtual std::optional<Eigen::MatrixXd> centroidal_momentum_matrix(const Eigen::VectorXd& /*q*/) {
    return std::nullopt;
  }
};

/// A dynamics library: how it builds its model of a robot (throws robot_refused).
struct dynamics_library {
  std::string name;    ///< e.g. "kdl"
  std::string origin;  ///< its functions and version, and what the adapter does for it
  std::function<std::unique_ptr<dynamics_model>(const robots::robot&)> load;
  /// The command's arguments that audit it again, for a disagreement's message ("--dynamics
  /// NAME" when empty; a child's: "--exec-dynamics -- COMMAND").
  std::string selector;
  /// The joints' own terms its adapter sets in the library (robots::joint): a robot with a
  /// nonzero armature or damping where the adapter sets none is refused by name, never held
  /// to a reference the library was not given.
  bool sets_armature = false, sets_damping = false;
  /// Why a term it does not set is not set (the library has no such term, or ignores it),
  /// said in the refusal.
  std::string no_joint_terms;
  /// Why the library, or its adapter, takes no robot on a floating base; empty where it takes
  /// them (through its own convention for the base's coordinates, which its origin names).
  std::string no_floating_base = "its adapter builds robots fixed to the world only";
};

/// A library's order of the robot's coordinates, for its adapter: order[i] is the robot's
/// coordinate at the library's index i.
struct coordinate_order {
  std::vector<int> order;
  /// x in the library's order: out(i) = x(order[i]).
  Eigen::VectorXd to_library(const Eigen::VectorXd& x) const {
    Eigen::VectorXd out(static_cast<Eigen::Index>(order.size()));
    for (std::size_t i = 0; i < order.size(); ++i) out(Eigen::Index(i)) = x(order[i]);
    return out;
  }
  /// y in the robot's order: out(order[i]) = y(i).
  Eigen::VectorXd from_library(const Eigen::VectorXd& y) const {
    Eigen::VectorXd out(static_cast<Eigen::Index>(order.size()));
    for (std::size_t i = 0; i < order.size(); ++i) out(order[i]) = y(Eigen::Index(i));
    return out;
  }
  /// A matrix's rows and columns in the robot's order.
  Eigen::MatrixXd from_library(const Eigen::MatrixXd& m) const {
    const auto n = static_cast<Eigen::Index>(order.size());
    Eigen::MatrixXd out(n, n);
    for (std::size_t i = 0; i < order.size(); ++i)
      for (std::size_t j = 0; j < order.size(); ++j) out(order[i], order[j]) = m(Eigen::Index(i), Eigen::Index(j));
    return out;
  }
};

/// A library's convention for a floating base's velocity: which part of the base's twist
/// comes first, and whether each is in the world's frame or the base's.
struct base_convention {
  bool angular_first = false;
  bool linear_in_world = false, angular_in_world = false;
};

/// The state's u = (v_b; w_b; qdot) against a library's base convention at the base's
/// rotation R: u_lib = T u, with T orthogonal (a rotation of each part and their order), so
/// that forces map alike (Q_lib = T Q keeps the power) and M = T^T M_lib T. The rates differ
/// by the turn of a linear velocity taken in the world: d/dt (R v_b) = R (vdot_b + w_b x v_b),
/// so udot_lib = T (udot + turn) with turn = (w_b x v_b; 0) (zero otherwise; R w_b's rate is
/// R wdot_b), and h = T^T h_lib + M turn. A fixed base: T the identity.
class base_map {
 public:
  base_map() = default;  ///< a fixed base
  base_map(const base_convention& c, const Eigen::Matrix3d& rotation, const Eigen::VectorXd& u);
  Eigen::VectorXd to_library(const Eigen::VectorXd& x) const;    ///< T x (a velocity, a force)
  Eigen::VectorXd from_library(const Eigen::VectorXd& y) const;  ///< T^T y
  Eigen::MatrixXd from_library(const Eigen::MatrixXd& m) const;  ///< T^T m T (M)
  /// h = T^T h_lib + M turn, with M in the state's layout.
  Eigen::VectorXd bias_from_library(const Eigen::VectorXd& h, const Eigen::MatrixXd& m) const;
  Eigen::VectorXd acceleration_to_library(const Eigen::VectorXd& udot) const;  ///< T (udot + turn)
  Eigen::VectorXd acceleration_from_library(const Eigen::VectorXd& a) const;   ///< T^T a - turn

 private:
  bool floating_ = false;
  base_convention c_;
  Eigen::Matrix3d r_ = Eigen::Matrix3d::Identity();
  Eigen::VectorXd turn_;
};

/// The base's rotation of a floating robot's q (dynamics_state's layout), the quaternion
/// normalized in double, as a library given q is.
Eigen::Matrix3d base_rotation(const Eigen::VectorXd& q);

/// A floating robot's base pose from q's head (dynamics_state's layout), the quaternion
/// normalized in T, double or mpfr50 (dimension_error for q without the base's 7,
/// non_finite_error, and domain_error for a zero quaternion).
template <class T>
robots::base_pose<T> floating_base_pose(const Eigen::VectorXd& q);

/// A robot's state for every quantity. On a fixed base: q, qdot, qddot and tau of its moving
/// joints. On a floating base (robots::robot::floating; robots/floating.hpp), MuJoCo's
/// freejoint layout for the pose and the body twist for the velocity:
///   q     = (p; quaternion w x y z; the joints' q): the base's origin in the world and its
///           orientation (normalized where used), 7 + n;
///   qdot  = u = (v_b; w_b; the joints' qdot): the base's twist in its own frame, 6 + n;
///   qddot = udot, the rate of u's components;
///   tau   = Q = (f_b; n_b; the joints' tau): the wrench on the base in its frame, the moment
///           about its origin,
/// so that M udot + h = Q and Q . u is the forces' power. A library whose convention differs
/// (the base's linear velocity in the world, the angular part first) is read through it by
/// its adapter, which says how in the library's origin.
struct dynamics_state {
  Eigen::VectorXd q, qdot, qddot, tau;
};

/// One quantity of one library on one robot at one state.
struct dynamics_residual {
  dynamics_quantity quantity;
  Eigen::MatrixXd library, reference;  ///< a vector is one column
  double scale = 0;      ///< the terms' magnitude (see above)
  double residual = 0;   ///< max |library - reference| / (eps scale)
  double budget = 0;     ///< 16 n
  bool within() const { return residual <= budget; }
};

/// Every quantity the library offers for the robot at the state; empty when it refuses
/// the robot (the reason in `refused`). Where the library holds another robot than the one
/// given (dynamics_model::held_robot), the residuals are against the held robot's Lagrangian
/// and `model_difference` is max |M_held - M_given| / (eps scale of M_given), both mass
/// matrices exact: how far the robot the library computes with is from the robot it was
/// given, in the units of the residuals.
struct dynamics_check {
  std::vector<dynamics_residual> residuals;
  std::string refused;
  std::optional<double> model_difference;
  double model_scale = 0;  ///< the scale of M_given, for model_difference
};

/// Why a library whose adapter sets the joints' armature or damping only as the flags say
/// refuses the robot ("joint J has damping 0.5, which the adapter of L does not set in
/// it: WHY", why from the library's no_joint_terms); empty when it takes it.
std::string unset_joint_terms(const robots::robot& robot, const std::string& library, bool sets_armature,
                              bool sets_damping, const std::string& why = {});

/// The library against the exact Lagrangian on one robot and state. A library's failure
/// (its error code, a non-finite value) is an error naming it.
dynamics_check check_dynamics(const dynamics_library& library, const robots::robot& robot, const dynamics_state& state);

/// The reference quantities in double (rounded once from mpfr50).
dynamics_residual reference_only(dynamics_quantity quantity, const robots::robot& robot, const dynamics_state& state);

/// The exact quantities at a state in mpfr50, unrounded, with the scales of the residual
/// (above): what a library computing in another tier is held to (user_dynamics.hpp).
struct reference_terms {
  dynamic_matrix<mpfr50> mass;
  dynamic_vector<mpfr50> bias, tau, qddot;
  double scale_m = 0, scale_h = 0, scale_tau = 0, scale_forward = 0;
  int moving_links = 0;
};
reference_terms reference_terms_at(const robots::robot& robot, const dynamics_state& state);

/// The kinematics of `robot` at `state` in mpfr50 (dynamics_quantity's frame_poses,
/// frame_jacobians and, with_bias, frame_bias_accelerations), its links in its order, and
/// their scales. Always the robot given, where a library holds another (MuJoCo's compiler
/// changes the inertias, not the bodies' frames, which it holds as written; the held robot's
/// frames come back through roll, pitch and yaw, which lose digits near a pitch of +-pi/2:
/// 179 eps on a random robot).
struct kinematic_reference {
  dynamic_matrix<mpfr50> poses, jacobians, com_jacobians;  ///< com_jacobians: link_com_jacobians'
  dynamic_vector<mpfr50> bias_accelerations;  ///< with_bias only
  /// The centre of mass, J_c and A_G; empty for a robot that carries no mass.
  dynamic_vector<mpfr50> com;
  dynamic_matrix<mpfr50> com_jacobian, momentum_matrix;
  double scale = 0, scale_bias = 0;  ///< poses, Jacobians, the centre of mass and J_c; Jdot qdot
  double scale_momentum = 0;         ///< A_G
  int moving_links = 0;
};
kinematic_reference kinematic_reference_at(const robots::robot& robot, const dynamics_state& state,
                                           bool with_bias = false);

/// A generated robot's state (generators::robot_case) as a dynamics_state.
dynamics_state state_of(const generators::robot_case& c);

/// The campaigns' random robots: fixed and floating bases alike, a draw that shrinks towards
/// the fixed one; a floating robot is floating_robot_cases' (its root given a body; the base's
/// pose, twist, twist rate and wrench) with its state in dynamics_state's layout, the
/// quaternion of the base's roll, pitch and yaw rounded to double; the joints draw an armature
/// and a damping where asked, drawn after the rest (generators::draw_joint_terms): the same
/// robots with them or without.
rc::Gen<generators::robot_case> dynamics_robot_cases(int max_links, bool armature = false, bool damping = false);

/// How a campaign checks one robot at one state (check_dynamics for a dynamics_library).
using dynamics_checker = std::function<dynamics_check(const robots::robot&, const dynamics_state&)>;

/// A library over random robots (generators.hpp: robot_cases): the largest residual of each
/// quantity in eps of its scale, the robots run and refused, and the first disagreement --
/// RapidCheck's shrunk counterexample: the minimal robot as URDF, its state, both values,
/// the residual, and the seed that reproduces it.
struct dynamics_campaign {
  std::string library, origin;
  int asked = 0;  ///< the robots (or a user's robot's states) the campaign was asked to run
  std::string unit = "robots";  ///< what it counts: "robots", or "states" of a user's robot
  int robots = 0, refused = 0;
  std::string first_refusal;  ///< the library's reason for the first robot it refused
  std::uint64_t seed = 0;
  int max_links = 8;
  /// What the random robots' joints carry beside their inertia (dynamics_options' armature
  /// and damping): "an armature and a damping", "an armature", "a damping"; "" none.
  std::string joint_terms;
  struct quantity_figure {
    dynamics_quantity quantity;
    int checked = 0;
    double largest = 0;   ///< residual, eps of the scale
    double budget = 0;    ///< the budget at the largest
    /// The largest residual among the robots of n moving joints, at index n - 1 (0 where
    /// none was checked): how the error grows with the tree, for the report's plot.
    std::vector<double> largest_by_joints;
    /// Of those, the robots on a floating base and their largest residual (each within its
    /// own budget, 16 (n + 1)).
    int floating_checked = 0;
    double floating_largest = 0;
  };
  std::vector<quantity_figure> figures;
  /// Where the library holds another robot than the one given: the largest
  /// model_difference (eps of the mass matrix's scale) and the robot where it was largest,
  /// as URDF. A measurement of the model builder, not a verdict on the quantities.
  int model_checked = 0;
  double model_largest = 0, model_largest_scale = 0;
  std::string model_largest_urdf;
  std::string disagreement;  ///< "" when every quantity stayed within its budget
  std::string counterexample_urdf;
  std::string note;          ///< a library's failure (an error, a non-finite value), if any
  std::vector<std::string> readings;  ///< a user's robot: what its file left unsaid (robots::robot::readings)
  /// Whether any quantity was checked on any robot (false: refused, or nothing offered).
  bool checked_any() const {
    return std::any_of(figures.begin(), figures.end(), [](const quantity_figure& f) { return f.checked > 0; });
  }
  bool agrees() const { return disagreement.empty() && note.empty(); }
  /// The campaign stopped before the robots asked for: at its first disagreement or failure.
  bool stopped() const { return !agrees(); }
};

struct dynamics_options {
  int robots = 100;
  std::uint64_t seed = 1;
  int max_links = 8;
  std::function<void(const std::string&)> progress;
  std::string urdf_file;  ///< a user's robot: its file, for the reproduction command
  /// The random robots' joints draw an armature, a damping (dynamics_robot_cases): the terms
  /// the library sets (run_dynamics_campaign sets them from its flags).
  bool armature = false, damping = false;
};

dynamics_campaign run_dynamics_campaign(const dynamics_library& library, const dynamics_options& options);

/// The verdict of one quantity of a campaign, in words: "DISAGREES" (its residual above the
/// budget, or the quantity of the shrunk disagreement); "failed" (the library failed);
/// "not offered" (the library has no such function); "refused" (it took none of the
/// robots); "within" only when it was checked on every robot the campaign ran to its end;
/// a campaign that stopped at a disagreement or failure says of every other quantity on
/// how many robots it was within before the stop, never "within" alone ("not cleared:
/// within on 3 of 100 robots, the campaign stopped"); likewise a quantity checked on fewer
/// robots than asked (the others refused) says how many.
std::string dynamics_verdict(const dynamics_campaign& c, const dynamics_campaign::quantity_figure& f);

/// A user's robot (a URDF file's) at `states` random states.
dynamics_campaign run_dynamics_on(const dynamics_library& library, const robots::robot& robot,
                                  const dynamics_options& options);

/// The same two, for a target named `name` checked by `check` (a library in another tier:
/// user_dynamics.hpp). `robot` null: random robots. `selector` as dynamics_library's.
dynamics_campaign run_dynamics_checker(const std::string& name, const std::string& origin, const dynamics_checker& check,
                                       const dynamics_options& options, const robots::robot* robot = nullptr,
                                       const std::string& selector = "");

/// The campaigns as a console table, JSON and Markdown (written into `directory`, with each
/// counterexample as a URDF file, and per quantity an SVG of each library's largest residual
/// against the robots' moving joints beside the budget); the files written.
void print_dynamics(std::ostream& out, const std::vector<dynamics_campaign>& campaigns);
std::vector<std::string> write_dynamics_report(const std::string& directory, const std::vector<dynamics_campaign>& campaigns);

}  // namespace mechcheck::audit
