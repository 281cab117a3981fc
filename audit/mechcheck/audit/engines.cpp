#include "mechcheck/audit/engines.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <mutex>
#include <ostream>
#include <sstream>

#include <Eigen/Cholesky>
#include <Eigen/Geometry>
#include <nlohmann/json.hpp>

#include "mechcheck/audit/audit.hpp"
#include "mechcheck/audit/model.hpp"
#include "mechcheck/audit/problems/chains.hpp"
#include "mechcheck/central/kepler.hpp"
#include "mechcheck/rigid_body/heavy_top.hpp"
#include "mechcheck/audit/finite_differences.hpp"
#include "mechcheck/audit/report.hpp"
#include "mechcheck/audit/studies.hpp"
#include "mechcheck/reference/pendulum.hpp"
#include "mechcheck/reference/solids.hpp"
#include "mechcheck/reference/tops.hpp"

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
double wrap(double a) { return std::remainder(a, 2 * std::acos(-1.0)); }

std::string exact_text(double x) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", x);
  return buf;
}

/// The observables at t of a Hamiltonian model's certified reference (model.hpp, in double:
/// the reference of the double-rounded start the engines are given), made when first asked
/// for; a reference certified to fewer than 20 digits is an error, not a yardstick.
template <class H>
std::function<Eigen::VectorXd(double)> certified(hamiltonian_model<H> model,
                                                 std::function<Eigen::VectorXd(const state<double>&)> observables) {
  struct lazy {
    std::mutex mutex;
    std::optional<problem<double>> solved;
  };
  auto l = std::make_shared<lazy>();
  return [model = std::move(model), observables = std::move(observables), l](double t) -> Eigen::VectorXd {
    std::lock_guard<std::mutex> lock(l->mutex);
    if (!l->solved) {
      // 25 digits: nine above the engines' double rounding, a third of the cost of 35.
      reference_settings settings;
      settings.options.target_digits = 25;
      l->solved = model_problem<double>(model, settings);
    }
    if (t == 0) return observables(l->solved->initial);
    const state<double> x = l->solved->exact(t);
    const double u = l->solved->exact_uncertainty(t);
    if (!(u <= 1e-20))
      throw convergence_error("the reference of " + model.setup.name + " at t = " + to_text(t) +
                              " is certified to relative " + to_text(u) + " only");
    return observables(x);
  };
}

model_setup setup_of(const std::string& name, const std::string& parameters, const Eigen::VectorXd& q0,
                     const Eigen::VectorXd& p0, double t_end) {
  model_setup m;
  m.name = "engine scenario " + name;
  m.description = m.name;
  m.source = "engines.cpp";
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
  std::string parameters = "g=" + exact_text(s.gravity);
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
  s.exact = certified(hm, [model, n](const state<double>& x) {
    // phidot = M(phi)^-1 p; relative angles and rates.
    const Eigen::VectorXd rate = model.mass_matrix<double>(x.q).llt().solve(Eigen::VectorXd(x.p));
    Eigen::VectorXd out(2 * n);
    for (Eigen::Index k = 0; k < n; ++k) {
      out(k) = wrap(x.q(k) - (k > 0 ? x.q(k - 1) : 0.0));
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
  std::string parameters = "g=" + exact_text(s.gravity) + "|d=" + exact_text(model.ground);
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
  s.exact = certified(hm, [model](const state<double>& x) {
    const auto c = model.at(mpfr50(x.q(0)));
    mpfr50 m = 0;
    for (int k = 0; k < 3; ++k)
      m += model.mass[k] * (c.vx[k] * c.vx[k] + c.vz[k] * c.vz[k]) + model.moment[k] * c.rate[k] * c.rate[k];
    const mpfr50 phidot1 = mpfr50(x.p(0)) / m;
    Eigen::VectorXd out(6);
    for (int k = 0; k < 3; ++k) {
      out(k) = wrap(static_cast<double>(k == 0 ? c.phi[0] : mpfr50(c.phi[k] - c.phi[k - 1])));
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
  s.exact = certified(hm, [model](const state<double>& y) {
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

double hinge_inertia(const scenario& s) { return s.mass * s.com.squaredNorm() + s.inertia(1); }

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

namespace {
/// A multibody scenario's observation: the energy of every link (and their mutual
/// gravitation), the angular momentum about the origin; a chain's joint angles and rates
/// (the engine's joint coordinates where it has them, else the link frames') and its
/// constraint violation; free bodies' positions and velocities.
engine_observation observe_multibody(const scenario& s, const body_reading& r) {
  const std::size_t n = s.links.size();
  if (r.links.size() != n)
    throw dimension_error("observe: " + s.name + " has " + std::to_string(n) + " bodies, the engine read " +
                          std::to_string(r.links.size()));
  engine_observation o;
  for (std::size_t k = 0; k < n; ++k) {
    const link& l = s.links[k];
    const body_frame& f = r.links[k];
    const Eigen::Vector3d wb = f.rotation.transpose() * f.omega, mb = l.inertia.cwiseProduct(wb);
    o.energy += l.mass * f.velocity.squaredNorm() / 2 + wb.dot(mb) / 2 + l.mass * s.gravity * f.position(2);
    o.momentum += l.mass * f.position.cross(f.velocity) + f.rotation * mb;
    for (std::size_t j = k + 1; j < n && s.gravitation != 0; ++j)
      o.energy -= s.gravitation * l.mass * s.links[j].mass / (r.links[j].position - f.position).norm();
  }
  if (s.structure == body_structure::free_bodies) {
    o.observables.resize(Eigen::Index(6 * n));
    for (std::size_t k = 0; k < n; ++k) {
      o.observables.segment<3>(Eigen::Index(3 * k)) = r.links[k].position;
      o.observables.segment<3>(Eigen::Index(3 * (n + k))) = r.links[k].velocity;
    }
    return o;
  }
  const Eigen::Index m = static_cast<Eigen::Index>(n);
  o.observables.resize(2 * m);
  if (r.joint_q.size() == m && r.joint_v.size() == m) {
    for (Eigen::Index k = 0; k < m; ++k) o.observables(k) = wrap(r.joint_q(k)), o.observables(m + k) = r.joint_v(k);
    o.readout = "the engine's joint coordinates";
  } else {
    double phi_before = 0, rate_before = 0;
    for (Eigen::Index k = 0; k < m; ++k) {
      const body_frame& f = r.links[std::size_t(k)];
      const double phi = std::atan2(f.rotation(0, 2), f.rotation(0, 0));
      o.observables(k) = wrap(phi - phi_before);
      o.observables(m + k) = f.omega(1) - rate_before;
      phi_before = phi;
      rate_before = f.omega(1);
    }
    o.readout = "the link frames (rotation about y and angular velocity)";
  }
  // Each hinge: the link's origin from its point on the parent (the world for link 0),
  // their velocities, the tilt of the link's y axis from the parent's; the loop likewise.
  constraint_violation c;
  const auto worst = [&c](const Eigen::Vector3d& dx, const Eigen::Vector3d& dv, const Eigen::Vector3d& da) {
    c.position = std::max(c.position, dx.norm());
    c.velocity = std::max(c.velocity, dv.norm());
    c.axis = std::max(c.axis, da.norm());
  };
  for (std::size_t k = 0; k < n; ++k) {
    const body_frame& f = r.links[k];
    const Eigen::Vector3d arm = f.rotation * s.links[k].com;
    const Eigen::Vector3d origin = f.position - arm, origin_velocity = f.velocity - f.omega.cross(arm);
    if (k == 0) {
      worst(origin - s.links[0].hinge, origin_velocity, f.rotation.col(1) - Eigen::Vector3d::UnitY());
    } else {
      const body_frame& p = r.links[k - 1];
      const Eigen::Vector3d to_hinge = p.rotation * (s.links[k].hinge - s.links[k - 1].com);
      worst(origin - (p.position + to_hinge), origin_velocity - (p.velocity + p.omega.cross(to_hinge)),
            f.rotation.col(1) - p.rotation.col(1));
    }
  }
  if (s.loop) {
    const body_frame& f = r.links.back();
    const Eigen::Vector3d arm = f.rotation * (s.loop->point - s.links.back().com);
    const Eigen::Vector3d dx = f.position + arm - s.loop->anchor, dv = f.velocity + f.omega.cross(arm);
    c.loop = dx.norm();
    worst(dx, dv, f.rotation.col(1) - Eigen::Vector3d::UnitY());
  }
  o.constraint = c;
  return o;
}
}  // namespace

engine_observation observe(const scenario& s, const body_reading& r) {
  if (s.structure != body_structure::one_body) return observe_multibody(s, r);
  engine_observation o;
  const Eigen::Vector3d wb = r.rotation.transpose() * r.omega, mb = s.inertia.cwiseProduct(wb);
  o.energy = s.mass * r.velocity.squaredNorm() / 2 + wb.dot(mb) / 2 + s.mass * s.gravity * r.position(2);
  if (s.central != 0) o.energy -= s.mass * s.central / r.position.norm();
  o.momentum = s.mass * r.position.cross(r.velocity) + r.rotation * mb;
  if (s.momentum == scenario::momentum_law::vertical) o.momentum.head<2>().setZero();
  if (s.joint != joint_kind::free) {
    const Eigen::Vector3d arm = r.rotation * s.com;  // pivot to centre of mass, world frame
    constraint_violation c;
    c.position = (r.position - arm).norm();
    c.velocity = (r.velocity - r.omega.cross(arm)).norm();
    if (s.joint == joint_kind::hinge_y)
      c.axis = (r.rotation.col(1) - Eigen::Vector3d::UnitY()).norm();
    o.constraint = c;
  }
  switch (s.kind) {
    case scenario_kind::free_top:
    case scenario_kind::free_top_near_axis:
    case scenario_kind::boxes:
      o.observables = wb;
      break;
    case scenario_kind::free_symmetric_top:
      o.observables.resize(6);
      o.observables << wb, r.rotation.col(2);
      break;
    case scenario_kind::heavy_top:
      o.observables.resize(6);
      o.observables << r.rotation.col(2), r.omega / s.omega0.norm();
      break;
    case scenario_kind::heavy_top_nutation:
      o.observables.resize(2);
      o.observables << r.rotation(2, 2), r.omega.cross(Eigen::Vector3d(r.rotation.col(2)))(2) / s.omega0.norm();
      break;
    case scenario_kind::pendulum_small:
    case scenario_kind::pendulum_large:
      // One consistent set of coordinates: the engine's own where it has them, else the
      // body frame's rotation about y and its angular velocity (never the angle of the
      // centre of mass with the rate of the frame: with an unconverged constraint the two
      // disagree, and a Jacobian of the mix is not the map's).
      o.observables.resize(2);
      if (r.joint_q.size() == 1 && r.joint_v.size() == 1) {
        o.observables << r.joint_q(0), r.joint_v(0);
        o.readout = "the engine's joint coordinates";
      } else {
        o.observables << std::atan2(r.rotation(0, 2), r.rotation(0, 0)), r.omega(1);
        o.readout = "the body frame (rotation about y and angular velocity)";
      }
      break;
    case scenario_kind::projectile:
    case scenario_kind::kepler:
      o.observables.resize(6);
      o.observables << r.position, r.velocity;
      break;
    default:
      throw domain_error("observe: " + s.name + " is a multibody scenario without its bodies");
  }
  return o;
}

double engine_run::trajectory(double h, long n, const std::function<void(long, const body_reading&)>& each, bool timed) {
  using clock = std::chrono::steady_clock;
  double seconds = 0;
  for (long k = 1; k <= n; ++k) {
    if (timed) {
      const auto t0 = clock::now();
      step(h);
      seconds += std::chrono::duration<double>(clock::now() - t0).count();
    } else {
      step(h);
    }
    each(k, read());
  }
  return seconds;
}

namespace {
/// The halving studies of a scenario: every observable together, then each class. The
/// runs (n steps to t_end) are cached by n, so that the classes share them: the longest
/// study decides the cost. A run that throws is a failed point of every study.
void order_of(const engine_integrator& in, const scenario& s, const engine_options& opt, engine_scenario_audit& a) {
  struct outcome {
    bool ok = false;
    Eigen::VectorXd obs;
    std::string note;
  };
  std::map<long, outcome> runs;
  const auto run_n = [&](long n) -> const outcome& {
    auto it = runs.find(n);
    if (it != runs.end()) return it->second;
    outcome o;
    try {
      auto e = in.start(s);
      e->advance(s.t_end / static_cast<double>(n), n);
      o.obs = observe(s, e->read()).observables;
      o.ok = true;
    } catch (const scenario_refused&) {
      throw;
    } catch (const std::exception& ex) {
      o.note = "n = " + std::to_string(n) + " steps: " + ex.what();
    }
    return runs.emplace(n, std::move(o)).first->second;
  };
  const Eigen::VectorXd exact = s.exact(s.t_end);
  const auto study = [&](int first, int count) {
    const auto run = [&](long n) -> study_run {
      study_run r;
      const outcome& o = run_n(n);
      if (!o.ok) {
        r.ok = false;
        r.note = o.note;
        return r;
      }
      r.error = (o.obs.segment(first, count) - exact.segment(first, count)).norm() / s.scale;
      r.evaluations = static_cast<double>(n);  // one engine step: one rounding per step
      const auto previous = runs.find(n / 2);
      if (n % 2 == 0 && previous != runs.end() && previous->second.ok)
        r.change = (o.obs.segment(first, count) - previous->second.obs.segment(first, count)).norm() / s.scale;
      return r;
    };
    return halving_study(run, s.steps0, opt.max_study_steps, eps,
                         [&s](long n) { return s.t_end / static_cast<double>(n); });
  };
  a.global = study(0, static_cast<int>(exact.size()));
  for (const auto& c : s.classes) a.classes.emplace_back(c.name, study(c.first, c.count));
}

/// The rounding budget of an engine's relative invariant after n steps of unknown
/// arithmetic: 64 eps a step as a random walk.
double engine_rounding_budget(double n) { return 64 * eps * std::sqrt(std::max(n, 1.0)); }

/// The growth class of a long run's relative error (classify_growth) with the scenario's
/// time scale and the engine's rounding budget as the floor of each window.
growth_class growth_of(const growth_recorder& g, const scenario& s, long long steps) {
  const std::vector<double> steps_w = g.window_steps();
  std::vector<double> time(steps_w.size()), floor(steps_w.size());
  for (std::size_t w = 0; w < steps_w.size(); ++w) {
    time[w] = steps_w[w] * s.h_long;
    floor[w] = engine_rounding_budget(steps_w[w]);
  }
  return classify_growth(time, g.window_rms(), floor, s.time_scale, static_cast<double>(steps) * s.h_long);
}

std::vector<std::pair<double, double>> history(const growth_recorder& g, double h) {
  std::vector<std::pair<double, double>> out;
  const std::vector<double> rms = g.window_rms(), steps = g.window_steps();
  for (std::size_t w = 0; w < rms.size(); ++w)
    if (rms[w] > 0) out.emplace_back(steps[w] * h, rms[w]);
  return out;
}

void run_long(const engine_integrator& in, const scenario& s, const engine_options& opt,
              engine_scenario_audit& a) {
  if (opt.long_run_steps <= 0) return;
  growth_recorder energy, momentum, anchor;
  auto e = in.start(s);
  const engine_observation o0 = observe(s, e->read());
  constraint_violation worst;
  const double e_scale = std::abs(o0.energy) > 0 ? std::abs(o0.energy) : 1.0;
  const double l_scale = o0.momentum.norm() > 0 ? o0.momentum.norm() : 1.0;
  const bool momentum_kept = s.momentum != scenario::momentum_law::none;
  // The run in three thirds, each timed apart (the cost is the median third's).
  double third[3] = {0, 0, 0};
  long long done = 0, base = 0;  // steps observed; the first step of the current third - 1
  const auto each = [&](long k, const body_reading& r) {
    const long long n = base + k;
    const engine_observation o = observe(s, r);
    const double de = std::abs(o.energy - o0.energy) / e_scale;
    if (!std::isfinite(de)) throw non_finite_error("the energy is not finite");
    energy.add(n, de);
    if (momentum_kept) momentum.add(n, (o.momentum - o0.momentum).norm() / l_scale);
    if (o.constraint) {
      if (n == 1) a.constraint_first = *o.constraint;
      worst.position = std::max(worst.position, o.constraint->position);
      worst.velocity = std::max(worst.velocity, o.constraint->velocity);
      worst.axis = std::max(worst.axis, o.constraint->axis);
      worst.loop = std::max(worst.loop, o.constraint->loop);
      anchor.add(n, o.constraint->position);
    }
    done = n;
  };
  try {
    for (int j = 0; j < 3; ++j) {
      base = opt.long_run_steps * j / 3;
      const long long length = opt.long_run_steps * (j + 1) / 3 - base;
      if (length > 0) third[j] = e->trajectory(s.h_long, static_cast<long>(length), each, opt.timing) / static_cast<double>(length);
    }
  } catch (const std::exception& ex) {
    a.long_run_failure = "step " + std::to_string(done + 1) + ": " + ex.what();
  }
  a.long_run_steps = done;
  if (o0.constraint && a.long_run_steps > 0) {
    a.constraint_max = worst;
    a.constraint_growth = anchor.exponent();
  }
  if (opt.timing && a.long_run_failure.empty()) {
    std::sort(std::begin(third), std::end(third));
    a.seconds_per_step = third[1];
  }
  if (s.conserves_energy) {
    const growth_class c = growth_of(energy, s, a.long_run_steps);
    a.energy_growth = c.exponent;
    a.energy_class = c.kind;
    a.energy_max = energy.max_error();
    a.energy_history = history(energy, s.h_long);
  }
  if (momentum_kept) {
    const growth_class c = growth_of(momentum, s, a.long_run_steps);
    a.momentum_growth = c.exponent;
    a.momentum_class = c.kind;
    a.momentum_max = momentum.max_error();
    a.momentum_history = history(momentum, s.h_long);
  }
}

/// det of one step's Jacobian in (theta, p = I thetadot) at the scenario's initial state.
/// p is I thetadot with a constant I: the determinant in (theta, thetadot) is the same.
/// Each map value is an engine step of unknown arithmetic: rho = 64 eps |Z| (the rounding
/// of the state read back through the engine's frames; the resolution is stated with it).
void jacobian_of(const engine_integrator& in, const scenario& s, engine_scenario_audit& a) {
  if (s.joint != joint_kind::hinge_y) return;
  const auto map = [&](const dynamic_vector<double>& z) {
    auto e = in.start(with_hinge_state(s, z(0), z(1)));
    e->step(s.h_long);
    const Eigen::VectorXd x = observe(s, e->read()).observables;
    dynamic_vector<double> out(2);
    out << x(0), x(1);
    return out;
  };
  dynamic_vector<double> z(2);
  z << std::atan2(s.rotation0(0, 2), s.rotation0(0, 0)), s.omega0(1);
  try {
    const fd_jacobian<double> j = finite_difference_jacobian<double>(map, z, 64);
    const Eigen::Matrix2d m = j.value, err = j.error;
    a.det_minus_one = m.determinant() - 1;
    a.det_resolution = determinant_resolution(m, err);
  } catch (const scenario_refused&) {
    throw;
  } catch (const std::exception& ex) {
    a.long_run_failure += (a.long_run_failure.empty() ? "" : "; ") + std::string("Jacobian: ") + ex.what();
  }
}

/// One step forward and one back from the scenario's start, against the start.
void reversal_of(const engine_integrator& in, const scenario& s, engine_scenario_audit& a) {
  const Eigen::VectorXd x0 = s.exact(0);
  const auto defect = [&](double h) {
    auto e = in.start(s);
    e->step(h);
    e->step(-h);
    return (observe(s, e->read()).observables - x0).norm() / s.scale;
  };
  try {
    a.reversal_defect = defect(s.h_long);
    a.reversal_defect_half = defect(s.h_long / 2);
  } catch (const scenario_refused&) {
    throw;
  } catch (const std::exception& ex) {
    a.reversal_defect.reset();
    a.reversal_defect_half.reset();
    a.reversal_refused = ex.what();
  }
}

constexpr double det_resolution_needed = 1e-6;

verdict judge_symplectic(const engine_integrator& in, const std::vector<engine_scenario_audit>& all) {
  verdict v;
  v.claim = "symplectic";
  const std::optional<bool>& declared = in.declared.symplectic;
  v.declared = declared ? (*declared ? "yes" : "no") : "-";
  bool measured = false, defect = false;
  std::string evidence;
  for (const auto& a : all) {
    // A determinant resolved to 1e-6 or better: 100 times below the h^2 = 1e-4 defect of a
    // first-order non-symplectic step at h = 0.01. Coarser, the difference quotients did
    // not settle (the map is not smooth at the difference steps) and say nothing.
    if (!a.det_minus_one || !(a.det_resolution <= det_resolution_needed)) continue;
    measured = true;
    const bool here = std::abs(*a.det_minus_one) > a.det_resolution;
    defect = defect || here;
    char buf[160];
    std::snprintf(buf, sizeof buf, "%s%s: det - 1 = %.2e (resolution %.1e)", evidence.empty() ? "" : "; ",
                  a.scenario.c_str(), *a.det_minus_one, a.det_resolution);
    evidence += buf;
  }
  v.evidence = evidence;
  if (!measured) {
    v.measured = "not measured";
    v.result = verdict::outcome::not_measured;
    return v;
  }
  v.measured = defect ? "no (a defect above the resolution)" : "no defect above the resolution";
  // A defect above the resolution settles the question; its absence confirms a declared
  // symplectic map but cannot contradict "not symplectic": the defect of a high-order
  // method at h_long (RK4's ~1e-11 on the pendulum) may lie below the resolution.
  if (!declared) {
    v.result = verdict::outcome::not_declared;
  } else if (*declared) {
    v.result = defect ? verdict::outcome::contradicted : verdict::outcome::confirmed;
  } else if (defect) {
    v.result = verdict::outcome::confirmed;
  } else {
    v.result = verdict::outcome::not_resolvable;
    v.needs = "a defect above the resolution: a larger step, or a method of low order";
  }
  return v;
}
}  // namespace

namespace {
/// The long run's energy error as a drift of the stepper audit (verdicts.hpp judges it):
/// preserved within the rounding of an engine step of unknown arithmetic, 64 eps a step as
/// a random walk (64 eps sqrt(N)); lost at an error of order one; else its growth class.
std::optional<long_run> energy_run(const scenario& s, const engine_scenario_audit& a) {
  if (!s.conserves_energy || (a.long_run_steps == 0 && a.long_run_failure.empty())) return std::nullopt;
  long_run run;
  run.steps = a.long_run_steps;
  run.h = s.h_long;
  run.failure = a.long_run_failure;
  drift d;
  d.name = "energy";
  d.max_relative = a.energy_max;
  d.budget_relative = engine_rounding_budget(static_cast<double>(a.long_run_steps));
  d.preserved = a.long_run_failure.empty() && d.max_relative <= d.budget_relative;
  d.exponent = a.energy_growth;
  d.kind = d.preserved ? "preserved to rounding"
           : d.max_relative >= 0.25 || !std::isfinite(d.max_relative) ? "lost (error of order one)"
           : a.energy_class.empty() ? "not resolved"
                                    : a.energy_class;
  run.invariants.push_back(d);
  return run;
}
}  // namespace

engine_audit audit_engine(const engine_integrator& in, const engine_options& opt) {
  if (in.name.empty() || !in.start) throw domain_error("audit_engine: the integrator needs a name and a start function");
  // A name that matches no scenario would audit nothing: refuse it with the valid names.
  const std::vector<scenario> all = scenarios();
  for (const auto& name : opt.scenarios)
    if (std::none_of(all.begin(), all.end(), [&](const scenario& s) { return s.name == name; })) {
      std::string known;
      for (const auto& s : all) known += " " + s.name;
      throw domain_error("audit_engine: no scenario named '" + name + "' (known:" + known + ")");
    }
  engine_audit out;
  out.integrator = in.name;
  out.origin = in.origin;
  out.declared = in.declared;
  std::vector<problem_audit> problems, energy_problems;
  std::vector<std::string> class_names;
  for (const scenario& s : all) {
    if (!opt.scenarios.empty() &&
        std::find(opt.scenarios.begin(), opt.scenarios.end(), s.name) == opt.scenarios.end())
      continue;
    if (opt.progress) opt.progress(in.name + " on " + s.name);
    engine_scenario_audit a;
    a.scenario = s.name;
    try {
      if (s.structure != body_structure::one_body && !in.multibody)
        throw scenario_refused(in.name + ": the adapter builds one-body scenarios only");
      order_of(in, s, opt, a);
      run_long(in, s, opt, a);
      jacobian_of(in, s, a);
      reversal_of(in, s, a);
      auto e = in.start(s);
      a.readout = observe(s, e->read()).readout;
      a.model_differs = e->model_differs();
    } catch (const scenario_refused& e) {
      a.refused = e.what();
    } catch (const std::exception& e) {
      // A start that throws (an engine's own error, a bad model): a recorded failure of
      // this scenario; the audit goes on with the next.
      a.failure = e.what();
    }
    for (const auto& [name, study] : a.classes) {
      problem_audit pa;
      pa.problem = s.name + " (" + name + ")";
      pa.skipped = a.refused.empty() && !a.model_differs.empty() ? "not judged: " + a.model_differs : a.refused;
      pa.global = study;
      problems.push_back(pa);
      if (std::find(class_names.begin(), class_names.end(), name) == class_names.end()) class_names.push_back(name);
    }
    if (!a.refused.empty() && a.classes.empty()) {
      problem_audit pa;
      pa.problem = s.name;
      pa.skipped = a.refused;
      problems.push_back(pa);
    }
    problem_audit pe;
    pe.problem = s.name;
    pe.skipped = a.refused;
    pe.run = a.refused.empty() ? energy_run(s, a) : std::nullopt;
    energy_problems.push_back(pe);
    out.scenarios.push_back(std::move(a));
  }
  // The order: per class, and over every class's studies together (the worst case, as the
  // stepper audit's over problems); the measured value names each class.
  std::string measured;
  for (const auto& name : class_names) {
    std::vector<problem_audit> of_class;
    const std::string tag = " (" + name + ")";
    for (const auto& p : problems)
      if (p.problem.size() > tag.size() && p.problem.compare(p.problem.size() - tag.size(), tag.size(), tag) == 0)
        of_class.push_back(p);
    verdict v = judge_order(in.declared, of_class, eps);
    v.claim = "order in the " + name;
    if (v.measured != "-") measured += (measured.empty() ? "" : ", ") + v.measured + " in the " + name;
    out.order_by_class.push_back(std::move(v));
  }
  out.order = judge_order(in.declared, problems, eps);
  if (!measured.empty()) out.order.measured = measured;
  out.symplectic = judge_symplectic(in, out.scenarios);
  out.energy = judge_energy(in.declared, energy_problems);
  return out;
}

std::vector<shape> shapes() {
  return {
      {"box", 2, {0.3, 0.5, 0.7}},     {"sphere", 2, {0.4, 0, 0}},        {"cylinder", 2, {0.2, 0.9, 0}},
      {"capsule", 2, {0.2, 0.6, 0}},   {"cone", 2, {0.3, 0.8, 0}},        {"ellipsoid", 2, {0.2, 0.3, 0.5}},
      {"two_spheres", 2, {0.1, 0.4, 0}},
  };
}

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
  } else {
    throw domain_error("exact_principal_moments: no shape " + s.name);
  }
  Eigen::Vector3d out(static_cast<double>(inertia(0, 0)), static_cast<double>(inertia(1, 1)),
                      static_cast<double>(inertia(2, 2)));
  std::sort(out.data(), out.data() + 3);
  return out;
}

std::vector<shape_audit> audit_shapes(const engine_shapes& engine) {
  std::vector<shape_audit> out;
  for (const shape& s : shapes()) {
    shape_audit a;
    a.engine = engine.engine;
    a.shape = s.name;
    a.exact = exact_principal_moments(s);
    try {
      a.measured = engine.moments(s);
      std::sort(a.measured.data(), a.measured.data() + 3);
      if (!a.measured.allFinite()) throw non_finite_error(engine.engine + ": the inertia of " + s.name + " is not finite");
      a.relative_error = ((a.measured - a.exact).cwiseAbs().cwiseQuotient(a.exact)).maxCoeff();
    } catch (const scenario_refused& e) {
      a.refused = e.what();
    } catch (const std::exception& e) {
      a.failure = e.what();  // an engine's error, a non-finite moment, a child that broke the protocol
    }
    out.push_back(std::move(a));
  }
  return out;
}

namespace {
using json = nlohmann::ordered_json;
std::string sci(double x) {
  if (!std::isfinite(x)) return std::isnan(x) ? "nan" : "inf";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.1e", x);
  return buf;
}
/// "bounded (t^0.01, max 2.5e-07)", "not resolvable: ... (max ...)", or "-" (not run).
std::string growth(const std::string& kind, const std::optional<double>& g, double max) {
  if (kind.empty()) return "-";
  char buf[64];
  if (g && std::isfinite(*g)) std::snprintf(buf, sizeof buf, " (t^%.2f, max %s)", *g, sci(max).c_str());
  else std::snprintf(buf, sizeof buf, " (max %s)", sci(max).c_str());
  return kind + buf;
}
/// "orientation 2.00, angular velocity 4.00" (each class's fit), or "refused", "failed".
std::string fit_text(const engine_scenario_audit& a) {
  if (!a.refused.empty()) return "refused";
  if (!a.failure.empty()) return "failed";
  std::string t;
  for (const auto& [name, study] : a.classes) {
    t += (t.empty() ? "" : ", ") + name + " " +
         (study.fit.used ? detail::fixed(study.fit.value) + (decisive(study.fit) ? "" : settled(study.fit) ? "*" : "?")
                         : "-");
    if (study.stalled) t += " (stalls at " + sci(study.stalled->error) + ")";
  }
  return t.empty() ? "-" : t;
}

std::string constraint_text(const engine_scenario_audit& a) {
  if (!a.constraint_max) return "-";
  const constraint_violation& m = *a.constraint_max;
  std::string t = "anchor " + sci(a.constraint_first ? a.constraint_first->position : 0) + " m after one step, " +
                  sci(m.position) + " m at most; its velocity " + sci(m.velocity) + " m/s";
  if (m.axis > 0) t += "; axis " + sci(m.axis) + " rad";
  if (m.loop > 0) t += "; loop closure " + sci(m.loop) + " m";
  if (a.constraint_growth) t += " (t^" + detail::fixed(*a.constraint_growth) + ")";
  return t;
}

std::string verdict_line(const verdict& v) {
  std::string t = v.claim + ": declared " + v.declared + ", measured " + v.measured + ": " + outcome_name(v.result);
  if (!v.evidence.empty()) t += " (" + v.evidence + ")";
  if (!v.needs.empty()) t += " Needs: " + v.needs + ".";
  for (const auto& r : v.readings)
    t += " Reading \"" + r.reading + "\": measured " + r.measured + (r.holds ? ", holds." : ", does not hold.");
  return t;
}
}  // namespace

void print_engines(std::ostream& out, const std::vector<engine_audit>& audits, const std::vector<shape_audit>& shapes) {
  char line[640];
  std::snprintf(line, sizeof line, "%-28s %-20s %-46s %-34s %-34s\n", "integrator", "scenario", "order by class",
                "energy", "angular momentum");
  out << line;
  for (const auto& a : audits) {
    for (const auto& s : a.scenarios) {
      std::snprintf(line, sizeof line, "%-28s %-20s %-46s %-34s %-34s\n", a.integrator.c_str(), s.scenario.c_str(),
                    fit_text(s).c_str(), growth(s.energy_class, s.energy_growth, s.energy_max).c_str(),
                    growth(s.momentum_class, s.momentum_growth, s.momentum_max).c_str());
      out << line;
      if (!s.failure.empty()) out << "    failed: " << s.failure << "\n";
      if (s.constraint_max) out << "    constraint: " << constraint_text(s) << "\n";
      if (!s.model_differs.empty()) out << "    order not judged: " << s.model_differs << "\n";
    }
    out << "  order: declared " << a.order.declared << ", measured " << a.order.measured << ": "
        << outcome_name(a.order.result) << (a.order.needs.empty() ? "" : " (needs " + a.order.needs + ")") << "\n";
    for (const verdict* v : {&a.symplectic, &a.energy})
      if (v->result != verdict::outcome::not_measured && v->result != verdict::outcome::not_declared)
        out << "  " << v->claim << ": declared " << v->declared << ", measured " << v->measured << ": "
            << outcome_name(v->result) << " (" << v->evidence << ")\n";
  }
  for (const auto& a : shapes) {
    std::snprintf(line, sizeof line, "inertia %-10s %-12s %s\n", a.engine.c_str(), a.shape.c_str(),
                  !a.failure.empty()   ? ("failed: " + a.failure).c_str()
                  : a.refused.empty() ? ("largest relative error " + sci(a.relative_error)).c_str()
                                      : "not offered");
    out << line;
  }
}

std::string engines_to_json(const std::vector<engine_audit>& audits, const std::vector<shape_audit>& shapes) {
  const auto study_json = [](const order_study& st) {
    json j;
    for (const auto& p : st.points)
      j["points"].push_back({{"h", p.h}, {"error", std::isfinite(p.error) ? json(p.error) : json(sci(p.error))}});
    j["fit"] = {{"value", st.fit.value}, {"spread", st.fit.spread}, {"used", st.fit.used}};
    if (st.stalled) j["stall"] = {{"error", st.stalled->error}, {"h", st.stalled->h}};
    if (!st.note.empty()) j["note"] = st.note;
    return j;
  };
  const auto violation = [](const constraint_violation& c) {
    json j{{"position", c.position}, {"velocity", c.velocity}, {"axis", c.axis}};
    if (c.loop > 0) j["loop"] = c.loop;
    return j;
  };
  json all = json::array();
  for (const auto& a : audits) {
    json j{{"integrator", a.integrator}, {"origin", a.origin}, {"order", json::parse(verdict_json_text(a.order))}};
    for (const auto& v : a.order_by_class) j["order_by_class"].push_back(json::parse(verdict_json_text(v)));
    j["symplectic"] = json::parse(verdict_json_text(a.symplectic));
    j["energy"] = json::parse(verdict_json_text(a.energy));
    for (const auto& s : a.scenarios) {
      json js{{"scenario", s.scenario}};
      if (!s.refused.empty()) js["refused"] = s.refused;
      if (!s.failure.empty()) js["failure"] = s.failure;
      if (!s.readout.empty()) js["readout"] = s.readout;
      if (!s.model_differs.empty()) js["model_differs"] = s.model_differs;
      for (const auto& p : s.global.points)
        js["global"].push_back({{"h", p.h}, {"error", std::isfinite(p.error) ? json(p.error) : json(sci(p.error))}});
      js["global_fit"] = {{"value", s.global.fit.value}, {"spread", s.global.fit.spread}, {"used", s.global.fit.used}};
      if (s.global.stalled) js["stall"] = {{"error", s.global.stalled->error}, {"h", s.global.stalled->h}};
      for (const auto& [name, study] : s.classes) js["classes"][name] = study_json(study);
      if (s.energy_growth) js["energy_growth"] = *s.energy_growth;
      if (!s.energy_class.empty()) js["energy_class"] = s.energy_class;
      if (s.momentum_growth) js["momentum_growth"] = *s.momentum_growth;
      if (!s.momentum_class.empty()) js["momentum_class"] = s.momentum_class;
      js["energy_max"] = s.energy_max;
      js["momentum_max"] = s.momentum_max;
      js["long_run_steps"] = s.long_run_steps;
      js["seconds_per_step"] = s.seconds_per_step;
      if (s.constraint_first) js["constraint_first_step"] = violation(*s.constraint_first);
      if (s.constraint_max) js["constraint_max"] = violation(*s.constraint_max);
      if (s.constraint_growth) js["constraint_growth"] = *s.constraint_growth;
      if (s.det_minus_one) js["jacobian"] = {{"det_minus_one", *s.det_minus_one}, {"resolution", s.det_resolution}};
      if (s.reversal_defect)
        js["reversal"] = {{"defect", *s.reversal_defect}, {"defect_half_step", *s.reversal_defect_half}};
      else if (!s.reversal_refused.empty())
        js["reversal"] = {{"refused", s.reversal_refused}};
      for (const auto& [t, e] : s.energy_history) js["energy_history"].push_back({t, e});
      for (const auto& [t, e] : s.momentum_history) js["momentum_history"].push_back({t, e});
      if (!s.long_run_failure.empty()) js["long_run_failure"] = s.long_run_failure;
      j["scenarios"].push_back(js);
    }
    all.push_back(j);
  }
  json shape_rows = json::array();
  for (const auto& a : shapes) {
    json j{{"engine", a.engine}, {"shape", a.shape}};
    if (!a.failure.empty()) {
      j["failure"] = a.failure;
    } else if (!a.refused.empty()) {
      j["refused"] = a.refused;
    } else {
      j["measured"] = {a.measured(0), a.measured(1), a.measured(2)};
      j["exact"] = {a.exact(0), a.exact(1), a.exact(2)};
      j["relative_error"] = a.relative_error;
    }
    shape_rows.push_back(j);
  }
  return json{{"integrators", all}, {"shapes", shape_rows}}.dump(1) + "\n";
}

std::string engines_to_markdown(const std::vector<engine_audit>& audits, const std::vector<shape_audit>& shapes) {
  std::ostringstream md;
  md << "# Physics engines against exact solutions\n\n";
  for (const auto& s : scenarios()) md << "- `" << s.name << "`: " << s.description << "\n";
  md << "\nThe order of each class of observables (a fit marked * is settled but not decisive, ? not settled; "
        "only decisive fits, three exponents within 0.1, decide a contradiction). The hinge scenarios are read "
        "from one set of coordinates, named in the last column.\n\n"
        "| integrator | scenario | order by class | energy, long run | angular momentum, long run | "
        "constraint | det M - 1 (resolution) | h then -h: defect at h, h/2 | us/step | readout |\n"
        "|---|---|---|---|---|---|---|---|---|---|\n";
  for (const auto& a : audits)
    for (const auto& s : a.scenarios)
      md << "| " << a.integrator << " | " << s.scenario << " | " << fit_text(s) << " | "
         << growth(s.energy_class, s.energy_growth, s.energy_max)
         << (s.long_run_failure.empty() ? "" : " (failed at " + s.long_run_failure + ")") << " | "
         << growth(s.momentum_class, s.momentum_growth, s.momentum_max) << " | " << constraint_text(s) << " | "
         << (s.det_minus_one ? sci(*s.det_minus_one) + " (" + sci(s.det_resolution) + ")" : std::string("-")) << " | "
         << (s.reversal_defect ? sci(*s.reversal_defect) + ", " + sci(*s.reversal_defect_half)
                               : s.reversal_refused.empty() ? std::string("-") : std::string("no negative step"))
         << " | "
         << (s.seconds_per_step > 0 ? detail::fixed(s.seconds_per_step * 1e6) : std::string("-")) << " | "
         << (s.readout.empty() ? "-" : s.readout)
         << (s.model_differs.empty() ? "" : "; order not judged: " + s.model_differs) << " |\n";
  md << "\n";
  if (!shapes.empty()) {
    md << "## Inertia of primitive shapes\n\nPrincipal moments the engine computes from mass and dimensions "
          "against reference/solids.hpp in mpfr50 (the compound by the parallel-axis theorem, eq 160); the "
          "largest relative error over the three moments (double's eps = 2.2e-16).\n\n";
    for (const auto& s : audit::shapes())
      md << "- `" << s.name << "`: mass " << detail::fixed(s.mass) << ", size (" << s.size(0) << ", " << s.size(1)
         << ", " << s.size(2) << ")\n";
    md << "\n| engine | shape | exact moments | engine's moments | largest relative error |\n|---|---|---|---|---|\n";
    for (const auto& a : shapes) {
      md << "| " << a.engine << " | " << a.shape << " | ";
      if (!a.failure.empty()) {
        md << "- | failed: " << a.failure << " | - |\n";
        continue;
      }
      if (!a.refused.empty()) {
        md << "- | not offered | - |\n";
        continue;
      }
      char buf[256];
      std::snprintf(buf, sizeof buf, "%.6g, %.6g, %.6g | %.6g, %.6g, %.6g | %s |\n", a.exact(0), a.exact(1),
                    a.exact(2), a.measured(0), a.measured(1), a.measured(2), sci(a.relative_error).c_str());
      md << buf;
    }
    md << "\n";
  }
  for (const auto& a : audits) {
    md << "## " << a.integrator << "\n\n" << a.origin << "\n\n- " << verdict_line(a.order) << "\n";
    for (const auto& v : a.order_by_class) md << "- " << verdict_line(v) << "\n";
    md << "- " << verdict_line(a.symplectic) << "\n- " << verdict_line(a.energy) << "\n\n";
  }
  return md.str();
}

std::vector<std::string> write_engine_report(const std::string& directory,
                                             const std::vector<engine_audit>& audits,
                                             const std::vector<shape_audit>& shapes) {
  namespace fs = std::filesystem;
  fs::create_directories(directory);
  std::vector<std::string> written;
  const auto put = [&](const std::string& name, const std::string& text) {
    const fs::path path = fs::path(directory) / name, tmp = fs::path(directory) / (name + ".tmp");
    {
      std::ofstream o(tmp);
      o << text;
      if (!o) throw error("write_engine_report: cannot write " + tmp.string());
    }
    fs::rename(tmp, path);
    written.push_back(path.string());
  };
  put("engines.json", engines_to_json(audits, shapes));
  put("engines.md", engines_to_markdown(audits, shapes));
  const auto series = [&](const std::string& scenario, const auto& points_of, bool with_fit = false) {
    std::vector<plot_series> out;
    for (const auto& a : audits)
      for (const auto& s : a.scenarios)
        if (s.scenario == scenario && s.refused.empty()) {
          // The convergence plot names each series with its fitted slope.
          const std::string fit = with_fit && s.global.fit.used ? " (" + detail::fixed(s.global.fit.value) + ")" : "";
          plot_series c{a.integrator + fit, points_of(s)};
          if (!c.points.empty()) out.push_back(std::move(c));
        }
    return out;
  };
  using points = std::vector<std::pair<double, double>>;
  const auto errors = [](const engine_scenario_audit& s) {
    points p;
    for (const auto& q : s.global.points)
      if (q.error > 0 && std::isfinite(q.error)) p.emplace_back(q.h, q.error);
    return p;
  };
  // Work: steps to t_end times the median wall time of one step in the long run.
  const auto work = [](const engine_scenario_audit& s) {
    points p;
    if (s.seconds_per_step > 0)
      for (const auto& q : s.global.points)
        if (q.error > 0 && std::isfinite(q.error)) p.emplace_back(s.seconds_per_step * q.evaluations, q.error);
    return p;
  };
  put("engines-convergence.svg", svg_loglog("Global error at t_end, free_top", "step h",
                                            "|omega - omega_exact| / |omega0|", series("free_top", errors, true)));
  if (std::any_of(audits.begin(), audits.end(), [](const engine_audit& a) {
        return std::any_of(a.scenarios.begin(), a.scenarios.end(),
                           [](const engine_scenario_audit& s) { return s.seconds_per_step > 0; });
      }))
    put("engines-work.svg", svg_loglog("Work and precision, free_top", "seconds to t_end",
                                     "|omega - omega_exact| / |omega0|", series("free_top", work)));
  put("engines-energy.svg", svg_loglog("Relative energy error over the long run, free_top", "t",
                                       "RMS |E - E0| / |E0| per window",
                                       series("free_top", [](const engine_scenario_audit& s) { return s.energy_history; })));
  put("engines-momentum.svg", svg_loglog("Angular-momentum error over the long run, free_top", "t",
                                         "RMS |L - L0| / |L0| per window",
                                         series("free_top", [](const engine_scenario_audit& s) { return s.momentum_history; })));
  return written;
}

}  // namespace mechcheck::audit
