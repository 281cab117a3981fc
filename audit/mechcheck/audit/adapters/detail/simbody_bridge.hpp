#pragma once
// The part of the Simbody adapter that includes Simbody: Simbody 3.7's headers do not
// compile as C++20 (ambiguous rewritten operator== on its index types), so this bridge is
// compiled as C++17 and speaks only standard types. Not a public header.

#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace SimTK {
class MobilizedBody;
class SimbodyMatterSubsystem;
}  // namespace SimTK

namespace mechcheck::audit::simbody_bridge {

/// An integrator this build cannot run (see CPodes in the adapter's notes).
class refused : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// A robot for its equations of motion (dynamics.hpp), in the bridge's standard types:
/// bodies parents first, each on a mobilizer from its parent (Ground for the first).
struct robot_setup {
  struct body {
    int parent = -1;  ///< index into bodies; -1: Ground
    int joint = 2;    ///< 0 a Pin (revolute), 1 a Slider (prismatic), 2 a Weld (fixed), 3 Free (a floating root)
    double rotation[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};  ///< the joint's origin in the parent, row-major
    double position[3] = {0, 0, 0};
    double axis[3] = {0, 0, 1};                        ///< unit, in the body's frame
    double mass = 0;
    double com[3] = {0, 0, 0};                         ///< centre of mass in the body's frame
    double inertia[9] = {0, 0, 0, 0, 0, 0, 0, 0, 0};   ///< about the centre of mass, row-major
    double damping = 0;  ///< a Pin's or Slider's viscous damping (Force::MobilityLinearDamper)
    int link = -1;       ///< the robot's link it is (its caller's numbering)
  };
  double gravity[3] = {0, 0, 0};
  std::vector<body> bodies;
};

/// The scenario in the bridge's standard types (engines.hpp's scenario, see there).
struct setup {
  int joint = 0;  ///< 0 free, 1 a pin about world y at the origin, 2 a ball at the origin
  double mass = 1;
  double inertia[3] = {1, 1, 1};  ///< principal moments about the centre of mass
  double com[3] = {0, 0, 0};      ///< centre of mass in the body frame
  double gravity = 0;             ///< along -z
  double central = 0;             ///< k of the central force -m k x / |x|^3
  double rotation0[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};  ///< body to world, row-major
  double position0[3] = {0, 0, 0}, velocity0[3] = {0, 0, 0};  ///< centre of mass
  double omega0[3] = {0, 0, 0};                                ///< world frame
  int integrator = 0;             ///< index into the list below
  /// Multibody scenarios (engines.hpp's links, loop and gravitation): structure 1 a chain
  /// of pins about y, 2 free bodies under their mutual gravitation, 3 a robot (below); 0
  /// the one body above.
  struct link {
    double mass = 1, inertia[3] = {1, 1, 1}, com[3] = {0, 0, 0}, hinge[3] = {0, 0, 0};
    double angle0 = 0, rate0 = 0, position0[3] = {0, 0, 0}, velocity0[3] = {0, 0, 0};
  };
  int structure = 0;
  std::vector<link> links;
  bool loop = false;
  double loop_point[3] = {0, 0, 0}, loop_anchor[3] = {0, 0, 0};
  double gravitation = 0;
  /// structure 3: a robot (its gravity its own), started at q0 and u0 (qdot) in the order of
  /// its moving bodies; read back as joint_q and joint_u in that order. A Free root (robot's
  /// first body, joint 3) takes seven q, its origin and quaternion w x y z (setQToFitTransform),
  /// and six u, its angular velocity and its origin's velocity in the ground (Simbody's own
  /// u of a Free mobilizer from the ground; setUToFitVelocity), and is read back alike.
  robot_setup robot;
  std::vector<double> q0, u0;
  /// structure 4: bodies on a half-space ground and against each other under Simbody's
  /// compliant contact (a ContactTrackerSubsystem and a CompliantContactSubsystem), every
  /// surface of one ContactMaterial; each body on a Free mobilizer, read back as `links`.
  struct contact_body {
    int shape = 0;  ///< 0 a ContactGeometry::Brick (half-lengths size), 1 a Sphere (radius size[0])
    double size[3] = {0, 0, 0};
    double mass = 1, inertia[3] = {1, 1, 1};  ///< principal moments about the centre, body axes
    double rotation0[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};  ///< body to world, row-major
    double position0[3] = {0, 0, 0}, velocity0[3] = {0, 0, 0}, omega0[3] = {0, 0, 0};
  };
  struct contact_model {
    bool ground = true;
    double normal[3] = {0, 0, 1};  ///< the ground's outward unit normal; the plane through the origin
    double stiffness = 0, dissipation = 0, mu = 0;  ///< ContactMaterial(stiffness, dissipation, mu, mu, 0)
    double transition_velocity = 0.01;               ///< CompliantContactSubsystem's
    std::vector<contact_body> bodies;
  } contact;
  /// > 0: the integrator error-controlled at this accuracy (Integrator::setAccuracy), h the
  /// interval at which it reports (stepTo); 0: a fixed step h (setFixedStepSize).
  double accuracy = 0;
};

/// One body's frame.
struct frame {
  double rotation[9];     ///< body to world, row-major
  double omega_world[3];  ///< angular velocity in the world frame
  double position[3], velocity[3];  ///< of the centre of mass
};

struct reading {
  double rotation[9];     ///< body to world, row-major
  double omega_world[3];  ///< angular velocity in the world frame
  double position[3], velocity[3];  ///< of the centre of mass
  bool pin = false;       ///< a pin: q and u below are its angle and rate
  double q = 0, u = 0;
  std::vector<frame> links;  ///< multibody scenarios: every body's frame
  std::vector<double> joint_q, joint_u;  ///< a chain, a robot: its mobilizers' q and u
};

/// Principal moments of a shape by Simbody's UnitInertia helpers (sphere, brick,
/// cylinderAlongZ, ellipsoid; the compound by Inertia::shiftFromMassCenter): false for a
/// shape Simbody has no helper for.
bool shape_moments(const std::string& name, double mass, const double size[3], double out[3]);

int integrator_count();
const char* integrator_name(int i);
std::string version();

class model {
 public:
  explicit model(const setup& s);  ///< throws std::exception (Simbody's)
  ~model();
  void step(double h);  ///< one fixed step; throws std::exception (Simbody's)
  reading read() const;
  int nq() const;
  const double* q() const;

 private:
  struct impl;
  std::unique_ptr<impl> p_;
};

/// Inside the bridge (its sources include Simbody): the robot's bodies on their mobilizers
/// (a Pin or Slider whose frames turn z or x onto the joint's axis, a Weld for a fixed
/// joint, in robot_setup's order); returns the moving bodies in order. Gravity is the
/// caller's. `all`, where given, gets every body, robot_setup's order.
std::vector<SimTK::MobilizedBody> build_robot(const robot_setup& r, SimTK::SimbodyMatterSubsystem& matter,
                                              std::vector<SimTK::MobilizedBody>* all = nullptr);

/// Simbody's equations of motion of a robot_setup: q, u, udot, tau and the rows and columns
/// of M in the order of the moving bodies in `bodies` (u = qdot for a Pin and a Slider). A
/// Free root comes first: its q are the pose (position, quaternion w x y z, which
/// setQToFitTransform takes), its six u Simbody's (w_FM, v_FM, both in the ground's frame).
class robot_dynamics {
 public:
  explicit robot_dynamics(const robot_setup& r);  ///< throws std::exception (Simbody's)
  ~robot_dynamics();
  int size() const;
  void mass_matrix(const double* q, double* m) const;  ///< row-major
  void bias(const double* q, const double* u, double* h) const;
  void inverse(const double* q, const double* u, const double* udot, double* tau) const;
  void forward(const double* q, const double* u, const double* tau, double* udot) const;
  /// Every body's frame in the ground at q (MobilizedBody::getBodyTransform, X_GB): 12
  /// numbers a body, robot_setup's order: the position, then the rotation's columns.
  void frames(const double* q, double* out) const;
  /// Every body's frame Jacobian at its origin (calcFrameJacobian): 6 rows a body, (angular;
  /// linear) in the ground, row-major, its columns the mobilities in this class's order; at
  /// its mass centre (robot_setup's com, a station on the body) where at_com.
  void frame_jacobians(const double* q, double* out, bool at_com = false) const;
  /// Every body's JFDot u at its origin (calcBiasForFrameJacobian): 6 numbers a body,
  /// (angular; linear) in the ground.
  void frame_biases(const double* q, const double* u, double* out) const;
  /// The system's mass centre in the ground at q (calcSystemMassCenterLocationInGround).
  void centre_of_mass(const double* q, double* out) const;
  /// At q and u = e_k for each mobility k (this class's order), column k of a 9 x size
  /// row-major matrix: the mass centre's velocity (calcSystemMassCenterVelocityInGround), the
  /// linear momentum and the angular momentum about the mass centre (calcSystemCentralMomentum's
  /// [1] and [0]), in the ground.
  void central_momenta(const double* q, double* out) const;

 private:
  struct impl;
  std::unique_ptr<impl> p_;
};

}  // namespace mechcheck::audit::simbody_bridge
