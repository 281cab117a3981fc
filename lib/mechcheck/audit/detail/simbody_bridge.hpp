#pragma once
// The part of the Simbody adapter that includes Simbody: Simbody 3.7's headers do not
// compile as C++20 (ambiguous rewritten operator== on its index types), so this bridge is
// compiled as C++17 and speaks only standard types. Not a public header.

#include <memory>
#include <stdexcept>
#include <string>

namespace mechcheck::audit::simbody_bridge {

/// An integrator this build cannot run (see CPodes in the adapter's notes).
class refused : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct setup {
  bool pin = false;  ///< a pin about world y (pendulum), else a free body
  double mass = 1;
  double inertia[3] = {1, 1, 1};  ///< principal moments about the centre of mass
  double gravity = 0;             ///< along -z
  double length = 1;              ///< pin: pivot to centre of mass
  double theta0 = 0;              ///< pin: initial angle
  double omega0[3] = {0, 0, 0};   ///< free: initial angular velocity (world = body)
  double velocity0[3] = {0, 0, 0};
  int integrator = 0;             ///< index into the list below
};

struct reading {
  double rotation[9];     ///< body to world, row-major
  double omega_world[3];  ///< angular velocity in the world frame
  double position[3], velocity[3];
  double q = 0, u = 0;  ///< pin angle and rate
};

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

}  // namespace mechcheck::audit::simbody_bridge
