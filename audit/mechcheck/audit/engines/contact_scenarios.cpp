// The contact scenarios (contact.hpp): their bodies, ground and coefficients, in engine-
// neutral terms. Their exact answers are computed where they are measured (contact_audit.cpp)
// from reference/contact.hpp.
#include <cmath>

#include <Eigen/Geometry>

#include "mechcheck/audit/engines/contact.hpp"
#include "mechcheck/audit/engines/scenarios.hpp"
#include "mechcheck/reference/solids.hpp"

namespace mechcheck::audit {

const char* contact_shape_name(contact_shape s) {
  switch (s) {
    case contact_shape::box: return "box";
    case contact_shape::sphere: return "sphere";
    case contact_shape::cylinder: return "cylinder";
  }
  return "?";
}

Eigen::Vector3d contact_setup::normal() const { return {std::sin(slope), 0, std::cos(slope)}; }
Eigen::Vector3d contact_setup::fall_line() const { return {std::cos(slope), 0, -std::sin(slope)}; }

namespace {
constexpr double g = 9.81;

Eigen::Vector3d box_moments(double m, const Eigen::Vector3d& half) {
  const Eigen::Vector3d e = 2 * half;  // edges
  return {m * (e(1) * e(1) + e(2) * e(2)) / 12, m * (e(0) * e(0) + e(2) * e(2)) / 12, m * (e(0) * e(0) + e(1) * e(1)) / 12};
}

contact_body box(double m, const Eigen::Vector3d& half) {
  contact_body b;
  b.shape = contact_shape::box;
  b.size = half;
  b.mass = m;
  b.inertia = box_moments(m, half);
  return b;
}

contact_body ball(double m, double r) {
  contact_body b;
  b.shape = contact_shape::sphere;
  b.size = {r, 0, 0};
  b.mass = m;
  b.inertia = Eigen::Vector3d::Constant(0.4 * m * r * r);
  return b;
}

/// A scenario of kind contact: the fields the smooth studies use are left at rest (they
/// are not run on contact scenarios); gravity and t_end are the contact study's.
scenario contact_scenario(std::string name, std::string description, contact_setup setup, double t_end,
                          double gravity = g) {
  scenario s;
  s.kind = scenario_kind::contact;
  s.structure = body_structure::contact;
  s.name = std::move(name);
  s.description = std::move(description);
  s.gravity = gravity;
  s.t_end = t_end;
  s.h_long = 1.0 / 60;
  s.time_scale = t_end;
  s.conserves_energy = false;
  s.exact = [](double) { return Eigen::VectorXd(); };
  s.contact = std::make_shared<const contact_setup>(std::move(setup));
  return s;
}

/// A body resting on the ground: its lowest point on the plane, its z axis along the normal.
void place_on_ground(contact_body& b, const contact_setup& c, double along) {
  const Eigen::Matrix3d turn = Eigen::AngleAxisd(c.slope, Eigen::Vector3d::UnitY()).toRotationMatrix();
  const double lift = b.shape == contact_shape::box ? b.size(2) : b.size(0);
  b.rotation0 = turn * b.rotation0;
  b.position0 = along * c.fall_line() + lift * c.normal();
}
}  // namespace

std::vector<scenario> contact_scenarios() {
  std::vector<scenario> out;
  {  // A box sliding on level ground.
    contact_setup c;
    c.mu = 0.5;
    contact_body b = box(1, {0.1, 0.1, 0.05});
    place_on_ground(b, c, 0);
    b.velocity0 = {2, 0, 0};
    c.bodies.push_back(b);
    out.push_back(contact_scenario("contact_slide",
                                   "a box (half-edges 0.1, 0.1, 0.05 m, 1 kg) sliding on level ground at 2 m/s along x, "
                                   "mu = 0.5: decelerates at mu g, stops at v0 / (mu g) = 0.408 s after v0^2 / (2 mu g) = "
                                   "0.408 m, in a straight line, whatever its direction and yaw (the sweep: theta 0 to 90 "
                                   "degrees, psi 0 and 30)",
                                   c, 1.0));
  }
  {  // A box at rest on a slope below its friction angle.
    contact_setup c;
    c.slope = 0.25;
    c.mu = 0.5;
    contact_body b = box(1, {0.1, 0.1, 0.05});
    place_on_ground(b, c, 0);
    c.bodies.push_back(b);
    out.push_back(contact_scenario("contact_slope_stick",
                                   "a box at rest on a slope of 0.25 rad, mu = 0.5 (tan 0.25 = 0.255 <= mu): it stays at "
                                   "rest for ever, no creep",
                                   c, 3.0));
  }
  {  // A box sliding down a slope above its friction angle.
    contact_setup c;
    c.slope = 0.5;
    c.mu = 0.3;
    contact_body b = box(1, {0.1, 0.1, 0.05});
    place_on_ground(b, c, 0);
    c.bodies.push_back(b);
    out.push_back(contact_scenario("contact_slope_slide",
                                   "a box released on a slope of 0.5 rad, mu = 0.3 (tan 0.5 = 0.546 > mu): slides down the "
                                   "fall line at g (sin - mu cos) = 2.120 m/s^2",
                                   c, 1.0));
  }
  {  // A solid sphere rolling down a slope.
    contact_setup c;
    c.slope = 0.3;
    c.mu = 0.5;
    contact_body b = ball(1, 0.1);
    place_on_ground(b, c, 0);
    c.bodies.push_back(b);
    out.push_back(contact_scenario("contact_roll",
                                   "a solid sphere (r = 0.1 m, 1 kg) released on a slope of 0.3 rad, mu = 0.5 (rolling "
                                   "needs 2/7 tan 0.3 = 0.088): rolls without slipping, its centre at 5/7 g sin = 2.071 "
                                   "m/s^2, v = omega r throughout",
                                   c, 1.0));
  }
  {  // A solid cylinder rolling down a slope.
    contact_setup c;
    c.slope = 0.3;
    c.mu = 0.5;
    contact_body b;
    b.shape = contact_shape::cylinder;
    b.size = {0.1, 0.1, 0};
    b.mass = 1;
    const double r = 0.1, l = 0.2;
    b.inertia = {(3 * r * r + l * l) / 12, r * r / 2, (3 * r * r + l * l) / 12};  // axis along y
    place_on_ground(b, c, 0);
    b.position0 = r * c.normal();  // its lowest line on the plane
    c.bodies.push_back(b);
    out.push_back(contact_scenario("contact_roll_cylinder",
                                   "a solid cylinder (r = 0.1 m, length 0.2 m, 1 kg, its axis along y) released on a slope "
                                   "of 0.3 rad, mu = 0.5: rolls at 2/3 g sin = 1.933 m/s^2, v = omega r",
                                   c, 1.0));
  }
  {  // The billiard ball.
    contact_setup c;
    c.mu = 0.2;
    contact_body b = ball(0.17, 0.028575);
    place_on_ground(b, c, 0);
    b.velocity0 = {2, 0, 0};
    c.bodies.push_back(b);
    out.push_back(contact_scenario("contact_billiard",
                                   "a billiard ball (r = 28.575 mm, 0.17 kg) struck at 2 m/s without spin on level cloth, "
                                   "mu = 0.2: slides until t = 2 v0 / (7 mu g) = 0.291 s, then rolls for ever at 5/7 v0 = "
                                   "1.429 m/s (its angular momentum about the contact point kept)",
                                   c, 1.0));
  }
  {  // A ball bouncing.
    contact_setup c;
    c.mu = 0.5;
    c.restitution = 0.5;
    contact_body b = ball(0.1, 0.05);
    b.position0 = {0, 0, 1.05};
    c.bodies.push_back(b);
    out.push_back(contact_scenario("contact_bounce",
                                   "a ball (r = 0.05 m, 0.1 kg) dropped from 1 m (its lowest point) on level ground, e = "
                                   "0.5: rises to e^(2k) m after its k-th bounce (0.25, 0.0625, 0.0156), never higher, and "
                                   "rests from t = sqrt(2 h / g) (1 + e)/(1 - e) = 1.355 s",
                                   c, 2.5));
  }
  for (const bool oblique : {false, true}) {  // Two balls colliding in free space.
    contact_setup c;
    c.ground = false;
    c.mu = 0;
    c.restitution = 0.5;
    contact_body a = ball(1, 0.1), b = ball(2, 0.1);
    const double offset = oblique ? 0.05 : 0;  // impact parameter 0.1 = r: the normal at 30 degrees
    a.position0 = {-0.3, -offset, 0};
    a.velocity0 = {1, 0, 0};
    b.position0 = {0.3, offset, 0};
    b.velocity0 = {-0.5, 0, 0};
    c.bodies = {a, b};
    out.push_back(contact_scenario(
        oblique ? "contact_collision_oblique" : "contact_collision",
        std::string("two balls (r = 0.1 m, 1 and 2 kg) meeting at 1 and -0.5 m/s in free space, no gravity, frictionless, "
                    "e = 0.5, ") +
            (oblique ? "their centres 0.1 m apart across the motion (the contact normal at 30 degrees)"
                     : "head-on") +
            ": the momentum kept, the normal relative velocity reversed times e, (1 - e^2) of its kinetic energy lost",
        c, 1.0, 0.0));
  }
  {  // A box at rest on level ground.
    contact_setup c;
    c.mu = 0.5;
    contact_body b = box(1, {0.1, 0.1, 0.05});
    place_on_ground(b, c, 0);
    c.bodies.push_back(b);
    out.push_back(contact_scenario("contact_rest", "a box at rest on level ground: it stays, no drift, no energy gained", c,
                                   3.0));
  }
  {  // A stack of three boxes.
    contact_setup c;
    c.mu = 0.5;
    for (int k = 0; k < 3; ++k) {
      contact_body b = box(1, {0.1, 0.1, 0.1});
      b.position0 = {0, 0, 0.1 + 0.2 * k};
      c.bodies.push_back(b);
    }
    out.push_back(contact_scenario("contact_stack",
                                   "three boxes (0.2 m cubes, 1 kg) stacked at rest on level ground: they stay, no drift, "
                                   "no energy gained",
                                   c, 3.0));
  }
  return out;
}

scenario contact_slide_case(double mu, double mass, double half, double speed, double theta, double psi) {
  contact_setup c;
  c.mu = mu;
  contact_body b = box(mass, {half, half, half / 2});
  b.rotation0 = Eigen::AngleAxisd(psi, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  place_on_ground(b, c, 0);
  b.velocity0 = speed * Eigen::Vector3d(std::cos(theta), std::sin(theta), 0);
  c.bodies.push_back(b);
  // To rest and 0.25 s beyond: the drift after the stop is part of the distance.
  return contact_scenario("contact_slide", "a drawn sliding box", c, speed / (mu * g) + 0.25);
}

scenario contact_stick_case(double mu, double slope, double mass, double half) {
  contact_setup c;
  c.slope = slope;
  c.mu = mu;
  contact_body b = box(mass, {half, half, half / 2});
  place_on_ground(b, c, 0);
  c.bodies.push_back(b);
  return contact_scenario("contact_slope_stick", "a drawn box on a slope below its friction angle", c, 2.0);
}

scenario with_direction(const scenario& slide, double theta, double psi) {
  if (!slide.contact || slide.name != "contact_slide")
    throw domain_error("with_direction: " + slide.name + " is not contact_slide");
  scenario s = slide;
  contact_setup c = *slide.contact;
  contact_body& b = c.bodies.front();
  const double speed = b.velocity0.norm();
  b.velocity0 = speed * Eigen::Vector3d(std::cos(theta), std::sin(theta), 0);
  b.rotation0 = Eigen::AngleAxisd(psi, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  s.contact = std::make_shared<const contact_setup>(std::move(c));
  return s;
}

}  // namespace mechcheck::audit
