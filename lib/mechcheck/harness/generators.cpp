/// The generators of generators.hpp, compiled once.
#include "mechcheck/harness/generators.hpp"

#include <algorithm>

namespace mechcheck::generators {

rc::Gen<int> uniform_int(int lo, int hi) {
  return rc::gen::resize(rc::kNominalSize, rc::gen::inRange(lo, hi + 1));
}

rc::Gen<int> int_with_ends(int lo, int hi) {
  return rc::gen::weightedOneOf<int>(
      {{14, uniform_int(lo, hi)}, {1, rc::gen::just(lo)}, {1, rc::gen::just(hi)}});
}

rc::Gen<double> dyadic(double lo, double hi) {
  const int a = static_cast<int>(std::ceil(lo * 256)), b = static_cast<int>(std::floor(hi * 256));
  return rc::gen::map(int_with_ends(a, b), [](int k) { return k / 256.0; });
}

rc::Gen<double> dyadic_towards_zero(double bound) {
  const int top = static_cast<int>(std::floor(bound * 256));
  return rc::gen::map(rc::gen::pair(int_with_ends(0, top), rc::gen::arbitrary<bool>()),
                      [](const std::pair<int, bool>& v) {
                        return v.second ? -v.first / 256.0 : v.first / 256.0;
                      });
}

rc::Gen<double> coordinate() { return dyadic_towards_zero(2); }

rc::Gen<double> positive() { return dyadic(0.25, 4); }

rc::Gen<double> coefficient() {
  return rc::gen::map(rc::gen::pair(int_with_ends(0, 256), rc::gen::arbitrary<bool>()),
                      [](const std::pair<int, bool>& v) {
                        const double c = 1 + v.first / 256.0;
                        return v.second ? -c : c;
                      });
}

rc::Gen<int> degrees_of_freedom() { return uniform_int(1, 3); }

void showValue(const phase_sample& x, std::ostream& os) {
  const auto vec = [&](const std::vector<double>& v) {
    os << "(";
    for (std::size_t i = 0; i < v.size(); ++i) os << (i ? ", " : "") << v[i];
    os << ")";
  };
  os << "q = ";
  vec(x.q);
  os << ", p = ";
  vec(x.p);
}

rc::Gen<phase_sample> phase_points(int n) {
  return rc::gen::build<phase_sample>(
      rc::gen::set(&phase_sample::q, rc::gen::container<std::vector<double>>(n, coordinate())),
      rc::gen::set(&phase_sample::p, rc::gen::container<std::vector<double>>(n, coordinate())));
}

void showValue(const smooth_function& f, std::ostream& os) {
  const auto name = [&](int i) {
    return (i < f.dof ? "q" : "p") + std::to_string(i < f.dof ? i : i - f.dof);
  };
  if (f.terms.empty()) os << "0";
  for (std::size_t k = 0; k < f.terms.size(); ++k) {
    const auto& t = f.terms[k];
    os << (k ? " + " : "") << t.coefficient;
    for (int i = 0; i < 2 * f.dof; ++i)
      if (t.exponents[i]) os << "*" << name(i) << (t.exponents[i] > 1 ? "^2" : "");
    if (t.kind != smooth_function::wave::none) {
      os << "*" << (t.kind == smooth_function::wave::sine ? "sin(" : "cos(") << t.phase;
      for (int i = 0; i < 2 * f.dof; ++i)
        if (t.frequencies[i]) os << " + " << t.frequencies[i] << "*" << name(i);
      os << ")";
    }
  }
}

namespace detail {
rc::Gen<smooth_function::term> smooth_term(int dof) {
  return rc::gen::exec([dof] {
    smooth_function::term t;
    t.coefficient = *coefficient();
    t.exponents.assign(2 * dof, 0);
    const int degree = *uniform_int(0, 3);
    for (int d = 0; d < degree; ++d) {
      const int i = *uniform_int(0, 2 * dof - 1);
      if (t.exponents[i] < 2) ++t.exponents[i];
    }
    t.kind = *rc::gen::element(smooth_function::wave::none, smooth_function::wave::none,
                               smooth_function::wave::sine, smooth_function::wave::cosine);
    t.frequencies.assign(2 * dof, 0);
    if (t.kind != smooth_function::wave::none) {
      for (auto& a : t.frequencies) a = *uniform_int(-2, 2);
      t.phase = *dyadic_towards_zero(3);
    }
    return t;
  });
}
}  // namespace detail


rc::Gen<smooth_function> smooth_functions(int dof) {
  return rc::gen::exec([dof] {
    smooth_function f;
    f.dof = dof;
    const int count = *uniform_int(1, 4);
    for (int k = 0; k < count; ++k) f.terms.push_back(*detail::smooth_term(dof));
    return f;
  });
}

rc::Gen<smooth_function> smooth_functions_without_q(int dof, int k) {
  return rc::gen::map(smooth_functions(dof), [k](smooth_function f) {
    for (auto& t : f.terms) {
      t.exponents[k] = 0;
      t.frequencies[k] = 0;
    }
    return f;
  });
}

void showValue(const radial_potential& u, std::ostream& os) {
  os << "U(r) =";
  for (const auto& [power, c] : u.terms) os << " + " << c << "*r^" << power;
}

rc::Gen<radial_potential> radial_potentials() {
  return rc::gen::exec([] {
    radial_potential u;
    const int count = *uniform_int(1, 3);
    for (int k = 0; k < count; ++k)
      u.terms.emplace_back(*rc::gen::element(-2, -1, 1, 2, 3), *coefficient());
    return u;
  });
}

rc::Gen<phase_sample> points_away_from_origin() {
  return rc::gen::suchThat(phase_points(3), [](const phase_sample& x) {
    return x.q[0] * x.q[0] + x.q[1] * x.q[1] + x.q[2] * x.q[2] >= 1.0 / 16;
  });
}

void showValue(const pair_potential& u, std::ostream& os) {
  switch (u.kind) {
    case pair_potential::shape::power_law:
      os << "U(r) = " << u.a << "*r^" << u.k;
      break;
    case pair_potential::shape::lennard_jones:
      os << "U(r) = " << u.a << "*((" << u.b << "/r)^12 - 2*(" << u.b << "/r)^6)";
      break;
    default:
      os << "U(r) = " << u.a << "*(1 - exp(-" << u.b << "*(r - " << u.c << ")))^2 - " << u.a;
  }
}

rc::Gen<pair_potential> pair_potentials() {
  return rc::gen::exec([] {
    pair_potential u;
    u.kind = *rc::gen::element(pair_potential::shape::power_law,
                               pair_potential::shape::lennard_jones, pair_potential::shape::morse);
    switch (u.kind) {
      case pair_potential::shape::power_law:
        u.a = *coefficient();
        u.k = *rc::gen::element(-1, 2, -2, 1, 3);
        break;
      case pair_potential::shape::lennard_jones:
        u.a = *dyadic(0.25, 1);
        u.b = *dyadic(0.5, 1);
        break;
      default:
        u.a = *dyadic(0.25, 2);
        u.b = *dyadic(0.5, 2);
        u.c = *dyadic(0.5, 1.5);
    }
    return u;
  });
}

rc::Gen<pair_potential> homogeneous_pair_potentials() {
  return rc::gen::exec([] {
    pair_potential u;
    u.a = *coefficient();
    u.k = *rc::gen::element(-1, 2, -2, 1, 3);
    return u;
  });
}

void showValue(const particle_sample& s, std::ostream& os) {
  for (std::size_t i = 0; i < s.masses.size(); ++i)
    os << (i ? "; " : "") << "m=" << s.masses[i] << " r=(" << s.q[3 * i] << ", "
       << s.q[3 * i + 1] << ", " << s.q[3 * i + 2] << ") v=(" << s.qdot[3 * i] << ", "
       << s.qdot[3 * i + 1] << ", " << s.qdot[3 * i + 2] << ")";
}

rc::Gen<particle_sample> particle_samples(int min_particles, int max_particles) {
  return rc::gen::exec([=] {
    particle_sample s;
    const int n = *uniform_int(min_particles, max_particles);
    for (int i = 0; i < n; ++i) {
      s.masses.push_back(*positive());
      // Particle i sits within 1/2 of the corner i of the cube [-1, 1]^3: every pair is
      // at least 1 apart, and the shrunk case is the corners themselves.
      std::vector<double> r(3);
      for (int c = 0; c < 3; ++c) r[c] = (((i >> c) & 1) ? 1.0 : -1.0) + *dyadic_towards_zero(0.5);
      s.q.insert(s.q.end(), r.begin(), r.end());
      for (int c = 0; c < 3; ++c) s.qdot.push_back(*coordinate());
    }
    return s;
  });
}

rc::Gen<std::vector<double>> directions() {
  return rc::gen::suchThat(rc::gen::container<std::vector<double>>(3, coordinate()),
                           [](const std::vector<double>& v) {
                             return v[0] != 0 || v[1] != 0 || v[2] != 0;
                           });
}

rc::Gen<std::vector<double>> coordinates(int n) {
  return rc::gen::container<std::vector<double>>(n, coordinate());
}

void showValue(const model_case& c, std::ostream& os) {
  static const char* names[] = {"spring pendulum", "spherical pendulum", "rotating pivot",
                                "particles", "relativistic coupled particles",
                                "quartic coupled particles"};
  os << names[c.which] << " params (";
  for (double p : c.params) os << p << " ";
  os << ") q (";
  for (double x : c.q) os << x << " ";
  os << ") qdot (";
  for (double x : c.qdot) os << x << " ";
  os << ") t " << c.t;
  if (c.which >= 3) {
    os << " ";
    showValue(c.pair, os);
    os << " ";
    showValue(c.particles, os);
  }
}

namespace {
/// The particles of a model case with which >= 3.
void draw_particles(model_case& c) {
  c.pair = *pair_potentials();
  c.particles = *particle_samples(2, 3);
  c.q = c.particles.q;
  c.qdot = c.particles.qdot;
  if (c.which >= 4) {
    // beta, kappa: |kappa| <= min mass / 4 with pairs at least 1 apart keeps the kinetic
    // matrix positive definite for up to 3 particles.
    const double m = *std::min_element(c.particles.masses.begin(), c.particles.masses.end());
    c.params = {c.which == 5 ? *dyadic(0, 1) : 0.0, *dyadic(-0.25, 0.25) * m};
    if (c.which == 4)  // relativistic: every component below 0.45, |v| < 0.78
      for (auto& v : c.qdot) v = *dyadic_towards_zero(0.45);
    c.particles.qdot = c.qdot;
  }
}
}  // namespace

rc::Gen<model_case> model_cases() {
  return rc::gen::exec([] {
    model_case c;
    c.which = *uniform_int(0, 5);
    switch (c.which) {
      case 0:  // m, k, l, g; x in [-1/2, 1/2] with l >= 1
        c.params = {*positive(), *positive(), *dyadic(1, 3), *positive()};
        c.q = {*dyadic_towards_zero(0.5), *coordinate()};
        c.qdot = *coordinates(2);
        break;
      case 1:  // m, l, g; theta in [1/2, 3/2] keeps sin^2(theta) >= 0.23
        c.params = {*positive(), *positive(), *positive()};
        c.q = {*dyadic(0.5, 1.5), *coordinate()};
        c.qdot = *coordinates(2);
        break;
      case 2:  // m, l, g, R in [0, 4] (0: a fixed pivot), w
        c.params = {*positive(), *positive(), *positive(), *dyadic(0, 4), *coefficient()};
        c.q = {*coordinate()};
        c.qdot = {*coordinate()};
        c.t = *coordinate();
        break;
      default:
        draw_particles(c);
    }
    return c;
  });
}

rc::Gen<model_case> closed_particle_cases() {
  return rc::gen::exec([] {
    model_case c;
    c.which = *uniform_int(3, 5);
    draw_particles(c);
    return c;
  });
}


namespace {
/// 2^k for k drawn in [lo, hi], shrinking towards 2^0.
rc::Gen<double> power_of_two(int lo, int hi) {
  return rc::gen::exec([lo, hi] {
    const bool down = *rc::gen::arbitrary<bool>();
    return std::ldexp(1.0, down ? -*int_with_ends(0, -lo) : *int_with_ends(0, hi));
  });
}
Eigen::Vector3d draw_triple(const rc::Gen<double>& g) { return {*g, *g, *g}; }

/// A link's mass, centre of mass and inertia (random_robots' header), drawn inside the
/// caller's rc::gen::exec: the same draws, in the same order, as when they were written out
/// in random_robots, so that a seed gives the robots it gave before.
robots::inertial draw_inertial() {
  robots::inertial b;
  b.mass = *power_of_two(-6, 7) * *dyadic(1, 2);
  b.origin.xyz = draw_triple(dyadic_towards_zero(0.5));
  b.origin.rpy = draw_triple(dyadic_towards_zero(3.14));
  // Principal moments s (x, 1, z): x down to 2^-10, z anywhere between |x - 1| and
  // x + 1 (u = 0 and 1 are the triangle's bounds), all turned by a further rpy.
  const double s = *power_of_two(-5, 5), x = std::ldexp(1.0, -*int_with_ends(0, 10));
  const double u = 0.5 + *dyadic_towards_zero(0.5);
  const double z = std::abs(x - 1) + u * (x + 1 - std::abs(x - 1));
  const Eigen::Vector3d turn = draw_triple(dyadic_towards_zero(3.14));
  const Eigen::Matrix3d rot = robots::rpy_rotation<double>(turn);
  const Eigen::Matrix3d full = rot * Eigen::Vector3d(s * x, s, s * z).asDiagonal() * rot.transpose();
  b.inertia = (full + full.transpose()) / 2;
  return b;
}
}  // namespace

rc::Gen<robots::robot> random_robots(int max_links) {
  return rc::gen::exec([max_links] {
    robots::robot r;
    r.name = "random";
    r.links.push_back({"base", std::nullopt});
    const int n = *rc::gen::inRange(1, max_links + 1);
    for (int i = 1; i <= n; ++i) {
      robots::joint j;
      j.name = "joint" + std::to_string(i);
      // A chain unless a tree is drawn: parent i - 1 - back, back shrinking to 0.
      const int back = *rc::gen::weightedOneOf<int>({{3, rc::gen::just(0)}, {1, rc::gen::inRange(0, i)}});
      j.parent = r.links[std::size_t(i - 1 - back)].name;
      j.child = "link" + std::to_string(i);
      j.type = *rc::gen::weightedElement<robots::joint_type>({{6, robots::joint_type::revolute},
                                                               {1, robots::joint_type::continuous},
                                                               {2, robots::joint_type::prismatic},
                                                               {1, robots::joint_type::fixed}});
      const int along = *rc::gen::weightedElement<int>({{1, 2}, {1, 0}, {1, 1}, {3, 3}});
      if (along < 3) {
        j.axis = Eigen::Vector3d::Unit(along);
      } else {
        const std::vector<double> d = *directions();
        j.axis = Eigen::Vector3d(d[0], d[1], d[2]).normalized();
      }
      j.origin.xyz = draw_triple(dyadic_towards_zero(1));
      j.origin.rpy = draw_triple(dyadic_towards_zero(3.14));
      const robots::inertial b = draw_inertial();
      r.links.push_back({j.child, b});
      r.joints.push_back(j);
    }
    return r;
  });
}

namespace {
/// ", name = (v0, v1, ...)"
void show_numbers(std::ostream& os, const char* name, const std::vector<double>& v) {
  os << ", " << name << " = (";
  for (std::size_t i = 0; i < v.size(); ++i) os << (i ? ", " : "") << v[i];
  os << ")";
}
}  // namespace

void showValue(const robot_case& c, std::ostream& os) {
  const robots::robot& r = c.robot;
  os << r.links.size() - 1 << " links:";
  for (const robots::joint& j : r.joints)
    os << " " << j.name << " " << robots::joint_type_name(j.type) << " " << j.parent << "->" << j.child << " axis ("
       << j.axis.transpose() << ")" << (j.armature != 0 ? " armature " + to_text(j.armature) : std::string())
       << (j.damping != 0 ? " damping " + to_text(j.damping) : std::string());
  show_numbers(os, "q", c.q);
  show_numbers(os, "qdot", c.qdot);
  show_numbers(os, "qddot", c.qddot);
  show_numbers(os, "tau", c.tau);
}

rc::Gen<robot_case> robot_cases(int max_links) {
  return rc::gen::exec([max_links] {
    robot_case c;
    c.robot = *random_robots(max_links);
    // A robot that moves: the first joint is not fixed where every joint is.
    if (std::all_of(c.robot.joints.begin(), c.robot.joints.end(),
                    [](const robots::joint& j) { return j.type == robots::joint_type::fixed; }))
      c.robot.joints.front().type = robots::joint_type::revolute;
    const robots::tree t = robots::validate(c.robot);
    const rc::Gen<double> rate = rc::gen::map(rc::gen::pair(dyadic_towards_zero(2), power_of_two(0, 3)),
                                              [](const std::pair<double, double>& v) { return v.first * v.second; });
    for (std::size_t j = 0; j < c.robot.joints.size(); ++j) {
      if (t.coordinate[j] < 0) continue;
      const bool slide = c.robot.joints[j].type == robots::joint_type::prismatic;
      c.q.push_back(*dyadic_towards_zero(slide ? 1 : 3.14));
      c.qdot.push_back(*rate);
      c.qddot.push_back(*rate);
      c.tau.push_back(*rate);
    }
    return c;
  });
}

void draw_joint_terms(robots::robot& r, bool armature, bool damping) {
  for (robots::joint& j : r.joints) {
    if (j.type == robots::joint_type::fixed) continue;
    if (armature) j.armature = std::max(0, *rc::gen::inRange(-8, 17)) / 64.0;
    if (damping) j.damping = std::max(0, *rc::gen::inRange(-16, 33)) / 16.0;
  }
}

void showValue(const floating_robot_case& c, std::ostream& os) {
  os << "on a floating base";
  if (const auto& b = c.joints.robot.links.front().body)
    os << " of mass " << b->mass << " (centre (" << b->origin.xyz.transpose() << "), rpy (" << b->origin.rpy.transpose()
       << "), inertia (" << b->inertia.row(0) << "; " << b->inertia.row(1) << "; " << b->inertia.row(2) << "))";
  os << " at xyz (" << c.base.xyz.transpose() << ") rpy (" << c.base.rpy.transpose() << ")";
  show_numbers(os, "twist", c.twist);
  show_numbers(os, "twist rate", c.twist_rate);
  show_numbers(os, "wrench", c.wrench);
  os << "; ";
  showValue(c.joints, os);
}

rc::Gen<floating_robot_case> floating_robot_cases(rc::Gen<robot_case> joints) {
  return rc::gen::exec([joints] {
    floating_robot_case c;
    c.joints = *joints;
    c.joints.robot.links.front().body = draw_inertial();
    c.base.xyz = draw_triple(dyadic_towards_zero(1));
    c.base.rpy = draw_triple(dyadic_towards_zero(3.14));
    for (auto* v : {&c.twist, &c.twist_rate, &c.wrench})
      for (int i = 0; i < 6; ++i) v->push_back(*dyadic_towards_zero(4));
    return c;
  });
}

}  // namespace mechcheck::generators

namespace mechcheck::generators {

void showValue(const contact_case& c, std::ostream& os) {
  os << "contact case: theta = " << c.theta << ", psi = " << c.psi << ", mu = " << c.mu << ", mass = " << c.mass
     << ", size = " << c.size << ", aspects = (" << c.aspect_b << ", " << c.aspect_c << "), e = " << c.e
     << ", speed = " << c.speed << ", slope = " << c.slope << ", height = " << c.height;
}

rc::Gen<contact_case> contact_cases() {
  return rc::gen::exec([] {
    contact_case c;
    c.theta = *dyadic_towards_zero(3.15);
    c.psi = *dyadic_towards_zero(3.15);
    c.mu = *dyadic(0.05, 1.5);
    c.mass = std::ldexp(*dyadic(1, 1.99609375), *uniform_int(-6, 7));
    c.size = std::ldexp(*dyadic(1, 1.99609375), *uniform_int(-3, 2));
    c.aspect_b = *dyadic(0.5, 2);
    c.aspect_c = *dyadic(0.5, 2);
    c.e = *dyadic(0, 1);
    c.speed = *dyadic(0.25, 4);
    // The slope around the friction angle: below, within 1/64 rad, or above it.
    const double friction_angle = std::atan(c.mu);
    const int side = *uniform_int(0, 2);
    const double offset = side == 1 ? *dyadic_towards_zero(1.0 / 64) : *dyadic(1.0 / 64, 0.5);
    double slope = side == 0 ? friction_angle - offset : friction_angle + offset;
    slope = std::floor(std::clamp(slope, 0.0, 1.3) * 256) / 256;  // dyadic
    c.slope = slope;
    c.height = *dyadic(0.125, 2);
    return c;
  });
}

}  // namespace mechcheck::generators
