// The engine scenarios and shapes (engines/scenarios.hpp): their parameters, initial states
// and exact references -- the free tops' elliptic solutions, the heavy top, the pendulums,
// Kepler, the chains' certified references, the figure-eight choreography.
#include "mechcheck/audit/engines/scenarios.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include <Eigen/Cholesky>
#include <Eigen/Geometry>

#include "mechcheck/audit/problems/model.hpp"
#include "mechcheck/audit/problems/certified.hpp"
#include "mechcheck/audit/problems/chains.hpp"
#include "mechcheck/central/kepler.hpp"
#include "mechcheck/reference/pendulum.hpp"
#include "mechcheck/reference/solids.hpp"
#include "mechcheck/reference/tops.hpp"
#include "mechcheck/rigid_body/heavy_top.hpp"

namespace mechcheck::audit {

namespace {
constexpr double eps = std::numeric_limits<double>::epsilon();

vector3<mpfr50> to_mp(const Eigen::Vector3d& v) { return {mpfr50(v(0)), mpfr50(v(1)), mpfr50(v(2))}; }
Eigen::Vector3d to_double(const vector3<mpfr50>& v) {
  return {static_cast<double>(v(0)), static_cast<double>(v(1)), static_cast<double>(v(2))};
}

/// Rotation by angle a about world y: takes +z towards +x.
Eigen::Matrix3d rotation_y(double a) { return Eigen::AngleAxisd(a, Eigen::Vector3d::UnitY()).toRotationMatrix(); }

/// The body's velocity state from its angular velocity about a fixed pivot at the origin.
void hold_at_pivot(scenario& s) {
  s.position0 = s.rotation0 * s.com;
  s.velocity0 = s.omega0.cross(s.position0);
}

scenario free_top(scenario_kind kind, std::string name, Eigen::Vector3d omega0, double t_end,
                  std::string description) {
  scenario s;
  s.kind = kind;
  s.name = std::move(name);
  s.description = std::move(description);
  s.inertia = {1, 2, 3};
  s.omega0 = omega0;  // rotation0 = 1: the world and the body components agree
  s.t_end = t_end;
  s.steps0 = 32;
  s.h_long = 0.01;
  s.momentum = scenario::momentum_law::vector;
  s.scale = omega0.norm();
  s.classes = {{"angular velocity", 0, 3}};
  const Eigen::Vector3d in = s.inertia;
  // The body angular velocity at t by Jacobi's elliptic functions, in mpfr50, rounded.
  s.exact = [in, omega0](double t) -> Eigen::VectorXd {
    return to_double(reference::asymmetric_top_angular_velocity(to_mp(in), to_mp(omega0), mpfr50(t)));
  };
  s.time_scale = static_cast<double>(reference::asymmetric_top_period(to_mp(in), to_mp(omega0)));
  return s;
}

/// The body of gazebo-classic's rigid-body benchmark RigidBodyTest.Boxes ("Spawn a single
/// box and record accuracy for momentum and enery conservation"), nonlinear case: a
/// uniform box 0.1 x 0.4 x 0.9 of 10 kg, angular velocity (1e-3, 1.5, 1.5e-2), 10 s. Its
/// moments fall along x, y, z; the elliptic reference wants them rising, so it runs in the
/// body axes (z, y, -x) -- a proper rotation -- and turns the answer back.
scenario gazebo_boxes() {
  scenario s;
  s.kind = scenario_kind::boxes;
  s.name = "boxes";
  s.mass = 10;
  const matrix3<mpfr50> box = reference::box_inertia(mpfr50(10), mpfr50(0.1), mpfr50(0.4), mpfr50(0.9));
  s.inertia = {static_cast<double>(box(0, 0)), static_cast<double>(box(1, 1)), static_cast<double>(box(2, 2))};
  s.omega0 = {1e-3, 1.5, 1.5e-2};
  s.description = "the box of gazebo-classic's RigidBodyTest.Boxes benchmark (0.1 x 0.4 x 0.9, 10 kg, angular "
                  "velocity (1e-3, 1.5, 1.5e-2) about its intermediate axis), no gravity: body angular velocity "
                  "against the Jacobi elliptic solution; its long run is 10^5 steps of 2.5e-3, twelve periods "
                  "of the flip (the benchmark's 10 s is half of one: too short to tell a bounded energy "
                  "error from a growing one)";
  s.t_end = 10;
  s.steps0 = 64;
  s.h_long = 2.5e-3;
  s.momentum = scenario::momentum_law::vector;
  s.scale = s.omega0.norm();
  s.classes = {{"angular velocity", 0, 3}};
  const Eigen::Vector3d in(s.inertia(2), s.inertia(1), s.inertia(0));
  const Eigen::Vector3d w0(s.omega0(2), s.omega0(1), -s.omega0(0));
  s.exact = [in, w0](double t) -> Eigen::VectorXd {
    const Eigen::Vector3d w = to_double(reference::asymmetric_top_angular_velocity(to_mp(in), to_mp(w0), mpfr50(t)));
    return Eigen::Vector3d(-w(2), w(1), w(0));
  };
  s.time_scale = static_cast<double>(reference::asymmetric_top_period(to_mp(in), to_mp(w0)));  // 20.6
  return s;
}

/// A free symmetric top I1 = I2: Omega turns about the body's x3 at
/// (I3 - I1) Omega_3 / I1 (eqs 179-184) and x3 turns about M at |M| / I1 (eqs 188, 224).
scenario free_symmetric_top() {
  scenario s;
  s.kind = scenario_kind::free_symmetric_top;
  s.name = "free_symmetric_top";
  s.description = "free symmetric body, I = (1, 1, 2), body angular velocity (0.6, 0, 1), no gravity: "
                  "body angular velocity and the symmetry axis in the world against their uniform "
                  "rotations (eqs 179-188)";
  s.inertia = {1, 1, 2};
  s.omega0 = {0.6, 0, 1};
  s.t_end = 5;
  s.steps0 = 32;
  s.h_long = 0.01;
  s.momentum = scenario::momentum_law::vector;
  s.scale = 1;
  s.classes = {{"angular velocity", 0, 3}, {"orientation", 3, 3}};
  const Eigen::Vector3d in = s.inertia, w0 = s.omega0;
  {  // the slower of Omega's turn in the body, 2 pi I1 / ((I3 - I1) Omega_3), and x3's
     // about M, 2 pi I1 / |M|: 2 pi
    const double pi = boost::math::constants::pi<double>();
    s.time_scale = std::max(2 * pi * in(0) / std::abs((in(2) - in(0)) * w0(2)),
                            2 * pi * in(0) / in.cwiseProduct(w0).norm());
  }
  s.exact = [in, w0](double time) -> Eigen::VectorXd {
    using std::cos;
    using std::sin;
    const mpfr50 t(time), i1(in(0)), i3(in(2));
    const vector3<mpfr50> w = to_mp(w0);
    const mpfr50 rate = (i3 - i1) * w(2) / i1, c = cos(rate * t), sn = sin(rate * t);
    const vector3<mpfr50> m(i1 * w(0), i1 * w(1), i3 * w(2));  // rotation0 = 1
    const mpfr50 mm = m.norm();
    const vector3<mpfr50> axis = m / mm, e3(mpfr50(0), mpfr50(0), mpfr50(1));
    const mpfr50 phi = mm / i1 * t, cp = cos(phi), sp = sin(phi);
    // Rodrigues: e3 turned by phi about M.
    const vector3<mpfr50> x3 = e3 * cp + axis.cross(e3) * sp + axis * (axis.dot(e3) * (1 - cp));
    Eigen::VectorXd out(6);
    out << static_cast<double>(w(0) * c - w(1) * sn), static_cast<double>(w(0) * sn + w(1) * c),
        static_cast<double>(w(2)), to_double(x3);
    return out;
  };
  return s;
}

/// The top of both heavy-top scenarios: m = 1, centre of mass 0.5 up the axis, central
/// moments (0.05, 0.05, 0.1), g = 9.81, axis at theta from the vertical in the x-z plane,
/// angular velocity phidot z + psidot x3 with Omega_3 = psidot + phidot cos theta.
scenario top_on_a_point(scenario_kind kind, std::string name, double theta, double phidot, double spin) {
  scenario s;
  s.kind = kind;
  s.name = std::move(name);
  s.joint = joint_kind::ball;
  s.mass = 1;
  s.inertia = {0.05, 0.05, 0.1};
  s.com = {0, 0, 0.5};
  s.gravity = 9.81;
  s.rotation0 = rotation_y(theta);
  s.omega0 = phidot * Eigen::Vector3d::UnitZ() + (spin - phidot * std::cos(theta)) * s.rotation0.col(2);
  hold_at_pivot(s);
  s.t_end = 1;
  s.steps0 = 64;
  s.h_long = 0.002;
  s.momentum = scenario::momentum_law::vertical;
  s.scale = 1;
  s.classes = {{"orientation", 0, 3}, {"angular velocity", 3, 3}};
  return s;
}

/// The library's heavy top (rigid_body/heavy_top.hpp) of that body: I1 about the pivot.
heavy_top<mpfr50> library_top(const scenario& s) {
  const mpfr50 l(s.com(2)), m(s.mass);
  return {mpfr50(s.inertia(0)) + m * l * l, mpfr50(s.inertia(2)), m * mpfr50(s.gravity) * l};
}

/// Steady precession (lecture 20, eqs 231-232): the axis at constant theta turns about the
/// vertical at the slow root phidot of I1 cos theta phidot^2 - I3 Omega_3 phidot + mgl = 0.
scenario heavy_top_precession() {
  const double theta = 0.5, spin = 40;
  scenario probe = top_on_a_point(scenario_kind::heavy_top, "", theta, 0, spin);
  const mpfr50 phidot = library_top(probe).steady_precession_rates(mpfr50(theta), mpfr50(spin)).first;
  scenario s = top_on_a_point(scenario_kind::heavy_top, "heavy_top", theta, static_cast<double>(phidot), spin);
  s.description = "symmetric top on a ball joint at its tip, m = 1, centre of mass 0.5 up its axis, I = (0.05, "
                  "0.05, 0.1) about it, g = 9.81, axis 0.5 rad from the vertical, spin Omega_3 = 40: steady "
                  "precession at phidot = " + to_text(static_cast<double>(phidot)) +
                  " (the slow root of eq 232): the axis and omega / |omega(0)| against it";
  s.time_scale = static_cast<double>(2 * boost::math::constants::pi<mpfr50>() / phidot);  // the precession
  const mpfr50 psidot = mpfr50(spin) - phidot * cos(mpfr50(theta));
  const double w_scale = s.omega0.norm();
  s.exact = [phidot, psidot, theta, w_scale](double time) -> Eigen::VectorXd {
    const mpfr50 t(time), phi = phidot * t, st = sin(mpfr50(theta)), ct = cos(mpfr50(theta));
    const vector3<mpfr50> axis(st * cos(phi), st * sin(phi), ct);
    const vector3<mpfr50> w = vector3<mpfr50>(mpfr50(0), mpfr50(0), phidot) + axis * psidot;
    Eigen::VectorXd out(6);
    out << to_double(axis), to_double(w) / w_scale;
    return out;
  };
  return s;
}

/// Nutation from a turning point (eqs 237-243): released at theta0 with phidot = 0, theta
/// returns to theta0 with thetadot = 0 after the period of eq 243. The observables at
/// t_end = that period: the axis' vertical component cos theta and its rate
/// (omega x x3)_z / |omega(0)| -- cos theta0 and 0.
scenario heavy_top_nutation() {
  const double theta = 0.5, spin = 40;
  scenario s = top_on_a_point(scenario_kind::heavy_top_nutation, "heavy_top_nutation", theta, 0, spin);
  const nutation<mpfr50> n = library_top(s).nutation_from_turning_point(mpfr50(theta), mpfr50(0), mpfr50(spin));
  s.t_end = static_cast<double>(n.period);
  s.time_scale = s.t_end;  // the nutation's period
  s.steps0 = 32;
  s.description = "the same top released at 0.5 rad with phidot = 0 (spin 40): it nutates between cos theta = " +
                  to_text(static_cast<double>(n.u_low)) + " and " + to_text(static_cast<double>(n.u_high)) +
                  "; after the nutation period " + to_text(s.t_end) +
                  " (eq 243, Jacobi's K) the axis is back at cos theta0 with zero rate";
  s.classes = {{"orientation", 0, 1}, {"angular velocity", 1, 1}};
  const double c0 = std::cos(theta);  // the engines start from this double's theta
  s.exact = [c0](double) -> Eigen::VectorXd {
    Eigen::VectorXd out(2);
    out << c0, 0;
    return out;
  };
  return s;
}

scenario pendulum(scenario_kind kind, std::string name, double theta0) {
  scenario s;
  s.kind = kind;
  s.name = std::move(name);
  s.joint = joint_kind::hinge_y;
  s.mass = 1;
  s.com = {0, 0, -1};
  s.inertia = {1e-3, 1e-3, 1e-3};  // a bob of radius 0.05 (2/5 m r^2)
  s.gravity = 9.81;
  s.rotation0 = rotation_y(theta0);
  hold_at_pivot(s);
  // theta'' = -(m g l / I) sin theta with I = m l^2 + I_yy about the hinge: the simple
  // pendulum with w0^2 = m g l / I (pendulum_motion with m = l = 1, g = w0^2; p = thetadot).
  const double w02 = s.mass * s.gravity * -s.com(2) / hinge_inertia(s);
  s.description = "hinge pendulum, bob 1 kg at 1 m (inertia 1e-3 about its centre), g = 9.81, "
                  "theta0 = " + to_text(theta0) + " at rest: (theta, thetadot) against the Jacobi "
                  "elliptic solution (eqs 31-33)";
  const reference::pendulum_motion<mpfr50> motion(mpfr50(1), mpfr50(1), mpfr50(w02), mpfr50(theta0), mpfr50(0));
  s.t_end = 2;
  s.steps0 = 32;
  s.h_long = 0.01;
  s.scale = std::abs(theta0) * std::sqrt(1 + w02);
  s.time_scale = static_cast<double>(motion.period());
  s.classes = {{"joint coordinates", 0, 2}};
  s.exact = [motion](double t) {
    const auto [theta, p] = motion.state_at(mpfr50(t));
    Eigen::VectorXd out(2);
    out << static_cast<double>(theta), static_cast<double>(p);
    return out;
  };
  return s;
}

scenario projectile() {
  scenario p;
  p.kind = scenario_kind::projectile;
  p.name = "projectile";
  p.description = "free body of 1 kg in gravity 9.81 along -z from the origin at velocity "
                  "(1, 0.5, 3): position and velocity against the parabola";
  p.gravity = 9.81;
  p.velocity0 = {1, 0.5, 3};
  p.t_end = 1;
  p.steps0 = 16;
  p.h_long = 1e-4;  // 10 s over the long run (it falls 490 m)
  p.time_scale = p.t_end;  // a uniform field has no period: the order study's span
  p.scale = p.velocity0.norm();
  p.classes = {{"position", 0, 3}, {"velocity", 3, 3}};
  const Eigen::Vector3d v0 = p.velocity0;
  const double g = p.gravity;
  p.exact = [v0, g](double t) {
    Eigen::VectorXd out(6);
    out << v0(0) * t, v0(1) * t, v0(2) * t - g * t * t / 2, v0(0), v0(1), v0(2) - g * t;
    return out;
  };
  return p;
}

/// A point mass on a Kepler ellipse of eccentricity 0.5 (eqs 115-117), the orbit of
/// central/kepler.hpp through the rounded initial state, in mpfr50.
scenario kepler() {
  scenario s;
  s.kind = scenario_kind::kepler;
  s.name = "kepler";
  s.central = 1;
  s.inertia = {1e-3, 1e-3, 1e-3};
  s.position0 = {0.5, 0, 0};           // pericentre of a = 1, e = 0.5
  s.velocity0 = {0, std::sqrt(3.0), 0};  // sqrt(k (1 + e) / (a (1 - e)))
  s.description = "point mass of 1 kg under the force -x / |x|^3 (the engine's own force input, evaluated "
                  "at each step), from (0.5, 0, 0) at (0, sqrt 3, 0): e = 0.5, a = 1, period 2 pi; "
                  "position and velocity against the orbit by Kepler's equation (central/kepler.hpp)";
  s.t_end = 5;
  s.steps0 = 64;
  s.h_long = 0.01;
  s.time_scale = 2 * boost::math::constants::pi<double>();  // the orbit's period, a^(3/2) 2 pi / sqrt(k)
  s.momentum = scenario::momentum_law::vector;
  s.scale = 1;
  s.classes = {{"position", 0, 3}, {"velocity", 3, 3}};
  const kepler_orbit<mpfr50> orbit(kepler_constants<mpfr50>(mpfr50(s.mass), mpfr50(s.mass * s.central)),
                                   to_mp(s.position0), to_mp(s.velocity0));
  s.exact = [orbit](double t) -> Eigen::VectorXd {
    const auto [r, v] = orbit.state_at(mpfr50(t));
    Eigen::VectorXd out(6);
    out << to_double(r), to_double(v);
    return out;
  };
  return s;
}

/// An angle in [-pi, pi]: relative joint angles read from frames and from references alike.

using detail::exact_text;

model_setup setup_of(const std::string& name, const std::string& parameters, const Eigen::VectorXd& q0,
                     const Eigen::VectorXd& p0, double t_end) {
  model_setup m;
  m.name = "engine scenario " + name;
  m.description = m.name;
  m.source = "audit/engines/scenarios.cpp";
  m.parameters = parameters;
  for (double x : q0) m.q0.push_back(exact_text(x));
  for (double x : p0) m.p0.push_back(exact_text(x));
  m.t_end = exact_text(t_end);
  return m;
}

/// A chain of n uniform bars of mass m and length l hanging along -z (each bar's moments
/// m l^2 / 12 about x and y, 1e-3 m about its axis), released from rest at absolute
/// angles phi0; gravity 9.81.
scenario chain(scenario_kind kind, std::string name, double m, double l, const std::vector<double>& phi0,
               double t_end, long steps0, std::string description) {
  scenario s;
  s.kind = kind;
  s.name = std::move(name);
  s.description = std::move(description);
  s.structure = body_structure::chain;
  s.gravity = 9.81;
  s.t_end = t_end;
  s.time_scale = t_end;  // no single period (the chain's motion is not periodic): the order study's span
  s.steps0 = steps0;
  s.h_long = 0.01;
  planar_chain model;
  model.gravity = s.gravity;
  // The reference cache's key from the model's own numbers (what is certified), not the
  // scenario's: a model that drifted from its scenario is then certified afresh, never read
  // from a reference computed for the scenario.
  std::string parameters = "g=" + exact_text(model.gravity);
  double previous = 0;
  for (std::size_t k = 0; k < phi0.size(); ++k) {
    link b;
    b.mass = m;
    b.inertia = {m * l * l / 12, m * l * l / 12, 1e-3 * m};
    b.com = {0, 0, -l / 2};
    b.hinge = k == 0 ? Eigen::Vector3d(0, 0, 0) : Eigen::Vector3d(0, 0, -l);
    b.angle0 = phi0[k] - previous;  // exact: the angles are binary fractions
    previous = phi0[k];
    s.links.push_back(b);
    model.links.push_back({b.mass, b.inertia(1), b.com(0), b.com(2), b.hinge(0), b.hinge(2)});
    parameters += "|m=" + exact_text(b.mass) + ",I=" + exact_text(b.inertia(1)) + ",com=" + exact_text(b.com(2)) +
                  ",hinge=" + exact_text(b.hinge(2));
  }
  const Eigen::Index n = static_cast<Eigen::Index>(phi0.size());
  Eigen::VectorXd angles(n);
  for (Eigen::Index k = 0; k < n; ++k) angles(k) = s.links[std::size_t(k)].angle0;
  s.scale = angles.norm() * std::sqrt(1 + s.gravity / l);
  s.classes = {{"joint coordinates", 0, static_cast<int>(2 * n)}};
  hamiltonian_model<planar_chain> hm{setup_of(s.name, parameters, Eigen::Map<const Eigen::VectorXd>(phi0.data(), n),
                                              Eigen::VectorXd::Zero(n), t_end),
                                     model};
  hm.setup.separable = false;
  s.exact = detail::certified<double>(hm, [model, n](const state<double>& x) {
    // phidot = M(phi)^-1 p; relative angles and rates.
    const Eigen::VectorXd rate = model.mass_matrix<double>(x.q).llt().solve(Eigen::VectorXd(x.p));
    Eigen::VectorXd out(2 * n);
    for (Eigen::Index k = 0; k < n; ++k) {
      out(k) = wrap_angle(x.q(k) - (k > 0 ? x.q(k - 1) : 0.0));
      out(n + k) = rate(k) - (k > 0 ? rate(k - 1) : 0.0);
    }
    return out;
  });
  return s;
}

scenario double_pendulum() {
  return chain(scenario_kind::double_pendulum, "double_pendulum", 1, 1, {0.5, 1}, 2, 32,
               "two uniform bars of 1 kg and 1 m hinged about y, end to end from a fixed pivot, g = 9.81, released "
               "from rest at absolute angles (0.5, 1) rad: the joints' angles and rates against a certified "
               "reference (the chain's Hamiltonian in absolute angles, problems/chains.hpp)");
}

scenario chain5() {
  return chain(scenario_kind::chain5, "chain5", 0.5, 0.5, {0.25, 0.5, 0.75, 1, 1.25}, 1, 32,
               "five uniform bars of 0.5 kg and 0.5 m hinged about y end to end, g = 9.81, released from rest "
               "at absolute angles 0.25 .. 1.25 rad: the five joints' angles and rates against a certified "
               "reference (problems/chains.hpp)");
}

/// The four-bar of problems/chains.hpp as a chain closed on the ground: crank 1 m from the
/// origin, coupler 2 m, rocker 1.5 m to the ground point (2, 0, 0), uniform bars of 1 kg
/// (moments l^2 / 12 about y and z, 1e-3 about the bar), g = 9.81, released from rest at
/// crank angle 1 rad.
scenario four_bar_scenario() {
  scenario s;
  s.kind = scenario_kind::four_bar;
  s.name = "four_bar";
  s.description = "four-bar linkage: a chain of three uniform bars of 1 kg (crank 1 m, coupler 2 m, rocker 1.5 m) "
                  "hinged about y from the origin, the rocker's end hinged to the ground at (2, 0, 0) (a loop), "
                  "g = 9.81, released from rest at crank angle 1 rad: the three joints' angles and rates against "
                  "a certified reference (the linkage's one-degree-of-freedom Hamiltonian, problems/chains.hpp)";
  s.structure = body_structure::chain;
  s.gravity = 9.81;
  s.t_end = 2;
  s.time_scale = s.t_end;  // the order study's span, near the linkage's swing
  s.steps0 = 32;
  s.h_long = 0.01;
  four_bar model;
  model.gravity = s.gravity;
  const double length[3] = {model.crank, model.coupler, model.rocker};
  std::string parameters = "g=" + exact_text(model.gravity) + "|d=" + exact_text(model.ground);  // (as above)
  for (int k = 0; k < 3; ++k) {
    link b;
    b.mass = model.mass[k];
    const double l = length[k];
    b.inertia = {1e-3 * b.mass, b.mass * l * l / 12, b.mass * l * l / 12};
    model.moment[k] = b.inertia(1);
    b.com = {l / 2, 0, 0};
    b.hinge = k == 0 ? Eigen::Vector3d(0, 0, 0) : Eigen::Vector3d(length[k - 1], 0, 0);
    s.links.push_back(b);
    parameters += "|l=" + exact_text(l) + ",m=" + exact_text(b.mass) + ",I=" + exact_text(b.inertia(1));
  }
  s.loop = loop_closure{{model.rocker, 0, 0}, {model.ground, 0, 0}};
  const double phi1 = 1;
  const auto g = model.at(mpfr50(phi1));
  for (int k = 0; k < 3; ++k)
    s.links[std::size_t(k)].angle0 = static_cast<double>(k == 0 ? g.phi[0] : mpfr50(g.phi[k] - g.phi[k - 1]));
  Eigen::VectorXd angles(3);
  for (int k = 0; k < 3; ++k) angles(k) = s.links[std::size_t(k)].angle0;
  s.scale = angles.norm() * std::sqrt(1 + s.gravity);
  s.classes = {{"joint coordinates", 0, 6}};
  hamiltonian_model<four_bar> hm{setup_of(s.name, parameters, Eigen::VectorXd::Constant(1, phi1),
                                          Eigen::VectorXd::Zero(1), s.t_end),
                                 model};
  hm.setup.separable = false;
  s.exact = detail::certified<double>(hm, [model](const state<double>& x) {
    const auto c = model.at(mpfr50(x.q(0)));
    mpfr50 m = 0;
    for (int k = 0; k < 3; ++k)
      m += model.mass[k] * (c.vx[k] * c.vx[k] + c.vz[k] * c.vz[k]) + model.moment[k] * c.rate[k] * c.rate[k];
    const mpfr50 phidot1 = mpfr50(x.p(0)) / m;
    Eigen::VectorXd out(6);
    for (int k = 0; k < 3; ++k) {
      out(k) = wrap_angle(static_cast<double>(k == 0 ? c.phi[0] : mpfr50(c.phi[k] - c.phi[k - 1])));
      out(3 + k) = static_cast<double>(phidot1 * (k == 0 ? c.rate[0] : mpfr50(c.rate[k] - c.rate[k - 1])));
    }
    return out;
  });
  return s;
}

/// Three bodies of 1 kg on the figure-eight choreography (Chenciner & Montgomery 2000,
/// initial conditions to 8 digits as Simo gives them), G = 1, in the plane z = 0.
scenario three_body() {
  scenario s;
  s.kind = scenario_kind::three_body;
  s.name = "three_body";
  s.description = "three free bodies of 1 kg (moments 1e-3) under their mutual gravitation G = 1 (the engine's own "
                  "force input), on the figure-eight choreography from x1 = -x2 = (0.97000436, -0.24308753, 0), "
                  "x3 = 0, v3 = (-0.93240737, -0.86473146, 0), v1 = v2 = -v3 / 2: positions and velocities "
                  "against a certified reference (problems/chains.hpp)";
  s.structure = body_structure::free_bodies;
  s.gravitation = 1;
  s.t_end = 2;
  s.time_scale = 6.3259;  // the choreography's period (these initial conditions return after it)
  s.steps0 = 32;
  s.h_long = 0.01;
  s.momentum = scenario::momentum_law::vector;
  s.scale = 1;
  const Eigen::Vector3d x1(0.97000436, -0.24308753, 0), v3(-0.93240737, -0.86473146, 0);
  const Eigen::Vector3d x[3] = {x1, -x1, {0, 0, 0}}, v[3] = {-v3 / 2, -v3 / 2, v3};
  n_bodies model;
  model.gravitation = s.gravitation;
  Eigen::VectorXd q0(9), p0(9);
  for (int k = 0; k < 3; ++k) {
    link b;
    b.mass = 1;
    b.inertia = {1e-3, 1e-3, 1e-3};
    b.position0 = x[k];
    b.velocity0 = v[k];
    s.links.push_back(b);
    model.masses.push_back(b.mass);
    q0.segment<3>(3 * k) = x[k];
    p0.segment<3>(3 * k) = b.mass * v[k];
  }
  s.classes = {{"position", 0, 9}, {"velocity", 9, 9}};
  hamiltonian_model<n_bodies> hm{setup_of(s.name, "G=1|m=1,1,1", q0, p0, s.t_end), model};
  hm.setup.separable = true;
  s.exact = detail::certified<double>(hm, [model](const state<double>& y) {
    Eigen::VectorXd out(18);
    for (int k = 0; k < 3; ++k) {
      out.segment<3>(3 * k) = y.q.segment<3>(3 * k);
      out.segment<3>(9 + 3 * k) = y.p.segment<3>(3 * k) / model.masses[std::size_t(k)];
    }
    return out;
  });
  return s;
}
}  // namespace

double wrap_angle(double a) { return std::remainder(a, 2 * std::acos(-1.0)); }

double hinge_inertia(const scenario& s) { return s.mass * s.com.squaredNorm() + s.inertia(1); }

std::optional<double> potential_floor(const scenario& s) {
  if (!(s.gravity > 0)) return std::nullopt;
  if (s.structure == body_structure::one_body) {
    if (s.joint == joint_kind::free) return std::nullopt;
    return -s.mass * s.gravity * s.com.norm();  // the pivot at the origin
  }
  if (s.structure != body_structure::chain || s.links.empty()) return std::nullopt;
  // Link k's hinge is at most the sum of the hinge offsets above it below link 0's (fixed)
  // hinge, and its centre of mass at most its arm below that.
  double floor = 0, hinge_z = s.links.front().hinge(2);
  for (std::size_t k = 0; k < s.links.size(); ++k) {
    if (k > 0) hinge_z -= s.links[k].hinge.norm();
    floor += s.links[k].mass * s.gravity * (hinge_z - s.links[k].com.norm());
  }
  return floor;
}

scenario with_hinge_state(scenario s, double theta, double thetadot) {
  if (s.joint != joint_kind::hinge_y) throw domain_error("with_hinge_state: " + s.name + " has no hinge");
  if (!std::isfinite(theta) || !std::isfinite(thetadot))
    throw non_finite_error("with_hinge_state: theta = " + to_text(theta) + ", thetadot = " + to_text(thetadot));
  s.rotation0 = rotation_y(theta);
  s.omega0 = {0, thetadot, 0};
  hold_at_pivot(s);
  return s;
}

std::vector<scenario> scenarios() {
  std::vector<scenario> out;
  out.push_back(free_top(scenario_kind::free_top, "free_top", {1, 0.2, 0.5}, 5,
                         "free asymmetric body, I = (1, 2, 3), body angular velocity (1, 0.2, 0.5), "
                         "no gravity: body angular velocity against the Jacobi elliptic solution "
                         "(Landau & Lifshitz section 37)"));
  out.push_back(free_top(scenario_kind::free_top_near_axis, "free_top_near_axis", {0.01, 1, 0.01}, 10,
                         "the same body spun near its intermediate axis, body angular velocity "
                         "(0.01, 1, 0.01): it flips"));
  out.push_back(gazebo_boxes());
  out.push_back(free_symmetric_top());
  out.push_back(heavy_top_precession());
  out.push_back(heavy_top_nutation());
  out.push_back(pendulum(scenario_kind::pendulum_small, "pendulum_small", 0.1));
  out.push_back(pendulum(scenario_kind::pendulum_large, "pendulum_large", 2.5));
  out.push_back(projectile());
  out.push_back(kepler());
  out.push_back(double_pendulum());
  out.push_back(chain5());
  out.push_back(four_bar_scenario());
  out.push_back(three_body());
  return out;
}

std::vector<body_frame> chain_frames(const scenario& s, const Eigen::VectorXd& angles, const Eigen::VectorXd& rates) {
  const Eigen::Index n = static_cast<Eigen::Index>(s.links.size());
  if (s.structure != body_structure::chain) throw domain_error("chain_frames: " + s.name + " is not a chain");
  if (angles.size() != n || rates.size() != n)
    throw dimension_error("chain_frames: " + s.name + " has " + std::to_string(n) + " joints, given " +
                          std::to_string(angles.size()) + " angles and " + std::to_string(rates.size()) + " rates");
  std::vector<body_frame> out(static_cast<std::size_t>(n));
  double phi = 0, phidot = 0;
  Eigen::Vector3d hinge = s.links[0].hinge, hinge_velocity = Eigen::Vector3d::Zero();
  for (Eigen::Index k = 0; k < n; ++k) {
    const link& l = s.links[std::size_t(k)];
    if (k > 0) {
      const body_frame& parent = out[std::size_t(k - 1)];
      const Eigen::Vector3d arm = parent.rotation * l.hinge;
      hinge += arm;
      hinge_velocity += parent.omega.cross(arm);
    }
    phi += angles(k);
    phidot += rates(k);
    body_frame& f = out[std::size_t(k)];
    f.rotation = rotation_y(phi);
    f.omega = {0, phidot, 0};
    f.position = hinge + f.rotation * l.com;
    f.velocity = hinge_velocity + f.omega.cross(f.rotation * l.com);
  }
  return out;
}

std::vector<shape> shapes() {
  return {
      {"box", 2, {0.3, 0.5, 0.7}},     {"sphere", 2, {0.4, 0, 0}},        {"cylinder", 2, {0.2, 0.9, 0}},
      {"capsule", 2, {0.2, 0.6, 0}},   {"cone", 2, {0.3, 0.8, 0}},        {"ellipsoid", 2, {0.2, 0.3, 0.5}},
      {"two_spheres", 2, {0.1, 0.4, 0}}, {"convex_hull", 2, {0.3, 0.4, 0.25}},
  };
}

namespace {
/// The convex hull's points: (+-a, 0, c) and (0, +-b, -c), a tetrahedron of volume 4abc/3.
std::array<vector3<mpfr50>, 4> hull_vertices(const mpfr50& a, const mpfr50& b, const mpfr50& c) {
  const mpfr50 zero(0);
  return {vector3<mpfr50>(a, zero, c), vector3<mpfr50>(-a, zero, c), vector3<mpfr50>(zero, b, -c),
          vector3<mpfr50>(zero, -b, -c)};
}
}  // namespace

Eigen::Vector3d exact_principal_moments(const shape& s) {
  const mpfr50 m(s.mass), a(s.size(0)), b(s.size(1)), c(s.size(2));
  matrix3<mpfr50> inertia;
  if (s.name == "box") {
    inertia = reference::box_inertia(m, a, b, c);
  } else if (s.name == "sphere") {
    inertia = reference::solid_sphere_inertia(m, a);
  } else if (s.name == "cylinder") {
    inertia = reference::solid_cylinder_inertia(m, a, b);
  } else if (s.name == "capsule") {
    inertia = reference::solid_capsule_inertia(m, a, b);
  } else if (s.name == "cone") {
    inertia = reference::solid_cone_inertia(m, a, b);
  } else if (s.name == "ellipsoid") {
    inertia = reference::solid_ellipsoid_inertia(m, a, b, c);
  } else if (s.name == "two_spheres") {
    // Each sphere about its own centre plus the parallel-axis term of eq 160 for its offset.
    const mpfr50 half = m / 2;
    const vector3<mpfr50> offset(b, mpfr50(0), mpfr50(0));
    inertia = 2 * reference::solid_sphere_inertia(half, a) + 2 * parallel_axis_term(half, offset);
  } else if (s.name == "convex_hull") {
    // The tetrahedron of hull_vertices: its centroid the origin, its products of inertia 0
    // (symmetric under x -> -x and under y -> -y).
    inertia = reference::tetrahedron_inertia(m, hull_vertices(a, b, c));
  } else {
    throw domain_error("exact_principal_moments: no shape " + s.name);
  }
  Eigen::Vector3d out(static_cast<double>(inertia(0, 0)), static_cast<double>(inertia(1, 1)),
                      static_cast<double>(inertia(2, 2)));
  std::sort(out.data(), out.data() + 3);
  return out;
}

double shape_volume(const shape& s) {
  const mpfr50 a(s.size(0)), b(s.size(1)), c(s.size(2)), pi = boost::math::constants::pi<mpfr50>();
  const mpfr50 ball = 4 * pi * a * a * a / 3;
  mpfr50 v;
  if (s.name == "box") v = a * b * c;
  else if (s.name == "sphere") v = ball;
  else if (s.name == "cylinder") v = pi * a * a * b;
  else if (s.name == "capsule") v = pi * a * a * b + ball;
  else if (s.name == "cone") v = pi * a * a * b / 3;
  else if (s.name == "ellipsoid") v = 4 * pi * a * b * c / 3;
  else if (s.name == "two_spheres") v = 2 * ball;  // apart: centres 2 d apart, d > r
  else if (s.name == "convex_hull") v = 4 * a * b * c / 3;
  else throw domain_error("shape_volume: no shape " + s.name);
  return static_cast<double>(v);
}

}  // namespace mechcheck::audit
