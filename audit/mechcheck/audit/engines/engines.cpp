#include "mechcheck/audit/engines/engines.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <map>
#include <mutex>

#include <Eigen/Geometry>

#include "mechcheck/audit/audit.hpp"
#include "mechcheck/audit/dynamics/dynamics.hpp"
#include "mechcheck/audit/finite_differences.hpp"
#include "mechcheck/audit/studies.hpp"
#include "mechcheck/robots/dynamics.hpp"
#include "mechcheck/robots/floating.hpp"

namespace mechcheck::audit {
namespace {
constexpr double eps = std::numeric_limits<double>::epsilon();
}  // namespace


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
    for (Eigen::Index k = 0; k < m; ++k) o.observables(k) = wrap_angle(r.joint_q(k)), o.observables(m + k) = r.joint_v(k);
    o.readout = "the engine's joint coordinates";
  } else {
    double phi_before = 0, rate_before = 0;
    for (Eigen::Index k = 0; k < m; ++k) {
      const body_frame& f = r.links[std::size_t(k)];
      const double phi = std::atan2(f.rotation(0, 2), f.rotation(0, 0));
      o.observables(k) = wrap_angle(phi - phi_before);
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

/// A robot's observation: its joint coordinates (angles reduced to [-pi, pi]) and rates as
/// the engine reports them, and its energy there; no momentum law, no constraint to
/// measure (the engine integrates in the joint coordinates). On a floating base: its centre
/// of mass and momenta at the engine's state (robot_start::momenta), the angular momentum
/// about the centre of mass the long run's.
engine_observation observe_robot(const scenario& s, const body_reading& r) {
  const robot_start& start = *s.robot;
  const Eigen::Index n = start.q0.size(), nv = start.qdot0.size();
  if (r.joint_q.size() != n || r.joint_v.size() != nv)
    throw dimension_error("observe: " + s.name + " has " + std::to_string(n) + " coordinates and " + std::to_string(nv) +
                          " velocities, the engine read " + std::to_string(r.joint_q.size()) + " and " +
                          std::to_string(r.joint_v.size()));
  engine_observation o;
  if (start.momenta) {
    if (!r.joint_q.allFinite() || !r.joint_v.allFinite()) throw non_finite_error("observe: " + s.name + ": the engine's state is not finite");
    o.observables = start.momenta(r.joint_q, r.joint_v);
    o.momentum = o.observables.tail(3);
    o.energy = start.energy(r.joint_q, r.joint_v);
    o.readout = "the engine's base pose and twist and joint coordinates";
    return o;
  }
  o.observables.resize(2 * n);
  for (Eigen::Index i = 0; i < n; ++i) {
    o.observables(i) = start.angular[std::size_t(i)] ? wrap_angle(r.joint_q(i)) : r.joint_q(i);
    o.observables(n + i) = r.joint_v(i);
  }
  o.energy = start.energy(r.joint_q, r.joint_v);
  o.readout = "the engine's joint coordinates";
  return o;
}
}  // namespace

engine_observation observe(const scenario& s, const body_reading& r) {
  if (s.structure == body_structure::robot) return observe_robot(s, r);
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
    case scenario_kind::free_body: {
      // The fixed angular momentum's direction in the world, from the start the engine was given.
      const Eigen::Vector3d m0 = s.rotation0 * s.inertia.cwiseProduct(s.rotation0.transpose() * s.omega0);
      o.observables.resize(12);
      o.observables << wb, r.rotation.transpose() * m0.normalized(), r.position, r.velocity;
      break;
    }
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
    order_study st = halving_study(run, s.steps0, opt.max_study_steps, in.epsilon,
                                   [&s](long n) { return s.t_end / static_cast<double>(n); });
    end_fit_at_rounding_rise(st, in.epsilon);
    return st;
  };
  a.global = study(0, static_cast<int>(exact.size()));
  for (const auto& c : s.classes) a.classes.emplace_back(c.name, study(c.first, c.count));
}

/// The rounding budget of an engine's relative invariant after n steps of unknown
/// arithmetic in a precision of machine epsilon u: 64 u a step as a random walk.
double engine_rounding_budget(double u, double n) { return 64 * u * std::sqrt(std::max(n, 1.0)); }

/// "4.8e-01" or, magnified, "4.8e-01 (the energy's terms 2.0e+02 times the energy exchanged)".
std::string rounding_budget_words(double budget, double magnification) {
  std::string w = detail::sci(budget);
  if (magnification > 1) w += " (the energy's terms " + detail::sci(magnification) + " times the energy exchanged)";
  return w;
}

/// The growth class of a long run's relative error (classify_growth) with the scenario's
/// time scale and the engine's rounding budget as the floor of each window.
/// `magnification` is the rounding's scale over the invariant's (the energy's terms against
/// the energy a pendulum exchanges: 1 where the invariant is its own scale).
growth_class growth_of(const growth_recorder& g, const scenario& s, long long steps, double u,
                       double magnification = 1) {
  const std::vector<double> steps_w = g.window_steps();
  std::vector<double> time(steps_w.size()), floor(steps_w.size());
  for (std::size_t w = 0; w < steps_w.size(); ++w) {
    time[w] = steps_w[w] * s.h_long;
    floor[w] = magnification * engine_rounding_budget(u, steps_w[w]);
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
  // The energy error relative to the energy the motion exchanges (E0 above the potential's
  // floor) where the scenario has one, else to |E0|; its rounding, of the energy's terms
  // (|E0| and the exchange at most), magnified by their ratio to it.
  const std::optional<double> v_floor = potential_floor(s);
  const double exchanged = v_floor ? o0.energy - *v_floor : 0;
  const double e_scale = exchanged > 0 ? exchanged : std::abs(o0.energy) > 0 ? std::abs(o0.energy) : 1.0;
  const double e_magnification = exchanged > 0 ? (std::abs(o0.energy) + exchanged) / exchanged : 1.0;
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
  // The classes of every audit's invariants (invariant_class): preserved within the
  // rounding budget of the run, lost at an error of order one, else the growth class.
  // A budget of order one resolves nothing: neither "preserved to rounding" nor a growth
  // class is claimed under it (a float pendulum's energy, its terms 200 times the energy it
  // exchanges, over 10^5 steps), only an error of order one.
  const double budget = engine_rounding_budget(in.epsilon, static_cast<double>(a.long_run_steps));
  const bool whole = a.long_run_failure.empty();
  const auto classify = [&](double max, double b, const growth_class& c, double magnification) {
    if (!(b < invariant_lost_at) && max < invariant_lost_at)
      return "not resolvable: the rounding budget " + rounding_budget_words(b, magnification) + " is of order one";
    return invariant_class(max, whole && max <= b, c.kind);
  };
  if (s.conserves_energy) {
    const growth_class c = growth_of(energy, s, a.long_run_steps, in.epsilon, e_magnification);
    a.energy_max = energy.max_error();
    a.energy_budget = e_magnification * budget;
    a.energy_class = classify(a.energy_max, a.energy_budget, c, e_magnification);
    if (a.energy_class == c.kind) a.energy_growth = c.exponent;
    a.energy_history = history(energy, s.h_long);
  }
  if (momentum_kept) {
    const growth_class c = growth_of(momentum, s, a.long_run_steps, in.epsilon);
    a.momentum_max = momentum.max_error();
    a.momentum_budget = budget;
    a.momentum_class = classify(a.momentum_max, a.momentum_budget, c, 1.0);
    if (a.momentum_class == c.kind) a.momentum_growth = c.exponent;
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
    const fd_jacobian<double> j = finite_difference_jacobian<double>(map, z, 64 * (in.epsilon / eps));
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

/// A robot scenario as the integrator's engine holds it (engine_run::held_robot): the
/// reference and the energy of the robot the engine computes with; the start, and the robot
/// the engine is built from, unchanged. `held` says how far the two robots' mass matrices
/// are apart at the start (Frobenius norms, relative).
scenario as_held(const engine_integrator& in, const scenario& s, std::string& held) {
  if (s.structure != body_structure::robot) return s;
  const std::optional<robots::robot> r = in.start(s)->held_robot();
  if (!r) return s;
  const robot_start& given = *s.robot;
  scenario h = robot_scenario(s.name, *r, given.q0, given.qdot0, s.t_end);
  auto start = std::make_shared<robot_start>(*h.robot);
  start->robot = given.robot;
  h.robot = start;
  const robots::robot_model<double> m_given(given.robot), m_held(*r);
  const auto mass_at_start = [&given](const robots::robot_model<double>& m) -> Eigen::MatrixXd {
    if (!given.robot.floating) return robots::robot_hamiltonian<double>{&m}.mass_matrix<double>(given.q0);
    return robots::floating_recursive_mass_matrix(m, floating_base_pose<double>(given.q0),
                                                  Eigen::VectorXd(given.q0.tail(given.q0.size() - 7)));
  };
  const Eigen::MatrixXd a = mass_at_start(m_given), b = mass_at_start(m_held);
  char buf[200];
  std::snprintf(buf, sizeof buf,
                "measured against the robot the engine holds (its mass matrix at the start %.2g of the given "
                "robot's away, relative)",
                (b - a).norm() / a.norm());
  held = buf;
  return h;
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
    // Nothing declared: not declared. Declared, and a Jacobian ran on some scenario but none
    // resolved to the resolution needed: not resolvable; no Jacobian at all: not measured.
    const bool ran = std::any_of(all.begin(), all.end(), [](const engine_scenario_audit& a) { return a.det_minus_one.has_value(); });
    v.measured = ran ? "not resolved" : "-";
    v.result = !declared ? verdict::outcome::not_declared
               : ran     ? verdict::outcome::not_resolvable
                         : verdict::outcome::not_measured;
    if (declared && ran) {
      char buf[200];
      std::snprintf(buf, sizeof buf, "a Jacobian resolved to %.0e or better (its difference quotients settled)",
                    det_resolution_needed);
      v.needs = buf;
    }
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
/// preserved within the rounding of an engine step in a precision of machine epsilon u, 64 u
/// a step as a random walk (64 u sqrt(N)); lost at an error of order one; else its growth class.
std::optional<long_run> energy_run(const scenario& s, const engine_scenario_audit& a, double u) {
  if (!s.conserves_energy || (a.long_run_steps == 0 && a.long_run_failure.empty())) return std::nullopt;
  long_run run;
  run.steps = a.long_run_steps;
  run.h = s.h_long;
  run.failure = a.long_run_failure;
  drift d;
  d.name = "energy";
  d.max_relative = a.energy_max;
  d.budget_relative = a.energy_budget > 0 ? a.energy_budget : engine_rounding_budget(u, static_cast<double>(a.long_run_steps));
  d.preserved = a.energy_class == "preserved to rounding";
  d.exponent = a.energy_growth;
  d.kind = a.energy_class.empty() ? invariant_class(d.max_relative, d.preserved, "not resolved") : a.energy_class;
  run.invariants.push_back(d);
  return run;
}
}  // namespace

engine_audit audit_engine(const engine_integrator& in, const engine_options& opt) {
  if (in.name.empty() || !in.start) throw domain_error("audit_engine: the integrator needs a name and a start function");
  // A name that matches no scenario would audit nothing: refuse it with the valid names.
  std::vector<scenario> all = scenarios();
  all.insert(all.end(), opt.drawn.begin(), opt.drawn.end());
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
  for (const scenario& given : all) {
    if (!opt.scenarios.empty() &&
        std::find(opt.scenarios.begin(), opt.scenarios.end(), given.name) == opt.scenarios.end())
      continue;
    scenario s = given;
    if (opt.progress) opt.progress(in.name + " on " + s.name);
    engine_scenario_audit a;
    a.scenario = s.name;
    a.description = s.description;
    try {
      if (s.structure == body_structure::robot && !in.robots)
        throw scenario_refused(in.name + ": the adapter builds no robot (a tree of revolute and prismatic joints)");
      if (s.structure != body_structure::one_body && !in.multibody)
        throw scenario_refused(in.name + ": the adapter builds one-body scenarios only");
      s = as_held(in, given, a.held);
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
    pe.run = a.refused.empty() ? energy_run(s, a, in.epsilon) : std::nullopt;
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
    verdict v = judge_order(in.declared, of_class, in.epsilon);
    v.claim = "order in the " + name;
    if (v.measured != "-") measured += (measured.empty() ? "" : ", ") + v.measured + " in the " + name;
    out.order_by_class.push_back(std::move(v));
  }
  out.order = judge_order(in.declared, problems, in.epsilon);
  if (!measured.empty()) out.order.measured = measured;
  out.symplectic = judge_symplectic(in, out.scenarios);
  out.energy = judge_energy(in.declared, energy_problems);
  return out;
}

std::vector<shape_audit> audit_shapes(const engine_shapes& engine) {
  std::vector<shape_audit> out;
  // One row: `measure` fills measured (and, without a mass, mass and said); exact follows
  // from the mass the moments are for.
  const auto row = [&](const shape& s, bool mass_given, const auto& measure) {
    shape_audit a;
    a.engine = engine.engine;
    a.shape = s.name;
    a.mass_given = mass_given;
    a.mass = s.mass;
    try {
      measure(a);
      std::sort(a.measured.data(), a.measured.data() + 3);
      const std::string what = engine.engine + ": the inertia of " + s.name + (mass_given ? "" : " without a mass");
      if (!a.measured.allFinite() || !std::isfinite(a.mass)) throw non_finite_error(what + " is not finite");
      if (a.mass < 0) throw error(what + ": a negative mass " + detail::sci(a.mass));
      shape at_mass = s;
      at_mass.mass = a.mass;
      a.density = a.mass / shape_volume(s);
      if (a.mass > 0) {
        a.exact = exact_principal_moments(at_mass);
        a.relative_error = ((a.measured - a.exact).cwiseAbs().cwiseQuotient(a.exact)).maxCoeff();
      }
    } catch (const scenario_refused& e) {
      a.refused = e.what();
    } catch (const std::exception& e) {
      a.failure = e.what();  // an engine's error, a non-finite moment, a child that broke the protocol
    }
    out.push_back(std::move(a));
  };
  for (const shape& s : shapes()) {
    row(s, true, [&](shape_audit& a) { a.measured = engine.moments(s); });
    if (engine.without_mass)
      row(s, false, [&](shape_audit& a) {
        const engine_default_mass d = engine.without_mass(s);
        a.mass = d.mass;
        a.measured = d.moments;
        a.said = d.said;
      });
  }
  return out;
}

}  // namespace mechcheck::audit
