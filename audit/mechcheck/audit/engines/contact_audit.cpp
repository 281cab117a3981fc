// The contact audit (contact.hpp): each contact scenario run at h = 1/60 .. 1/960, its
// measures against the exact answers of reference/contact.hpp, the trend of their errors,
// the isotropy sweep, the random cases shrunk, and the verdicts on what the engine declares
// of its contact.
#include <algorithm>
#include <cmath>
#include <limits>

#include <Eigen/Geometry>
#include <nlohmann/json.hpp>
#include <rapidcheck.h>

#include "mechcheck/audit/engines/contact.hpp"
#include "mechcheck/audit/engines/engines.hpp"
#include "mechcheck/reference/contact.hpp"

namespace mechcheck::audit {

namespace {
/// A run's frames: frames[0] at t = 0, frames[k] after step k.
struct trajectory {
  double h = 0;
  std::vector<std::vector<body_frame>> frames;
  std::string failure;
};

std::vector<body_frame> bodies_of(const body_reading& r) {
  if (!r.links.empty()) return r.links;
  return {static_cast<const body_frame&>(r)};
}

trajectory run_scenario(const engine_integrator& in, const scenario& s, double h) {
  trajectory t;
  t.h = h;
  const long n = std::lround(s.t_end / h);
  std::unique_ptr<engine_run> e = in.start(s);
  t.frames.push_back(bodies_of(e->read()));
  try {
    e->trajectory(h, n, [&](long, const body_reading& r) { t.frames.push_back(bodies_of(r)); }, false);
  } catch (const scenario_refused&) {
    throw;
  } catch (const std::exception& ex) {
    t.failure = "step " + std::to_string(t.frames.size()) + ": " + ex.what();
  }
  for (const auto& f : t.frames)
    if (f.size() != s.contact->bodies.size())
      throw error(in.name + " on " + s.name + ": a reading of " + std::to_string(f.size()) + " bodies, the scenario has " +
                  std::to_string(s.contact->bodies.size()));
  return t;
}

/// Mechanical energy of the bodies: translation, rotation (about the centre, body axes) and
/// gravity's potential m g z.
double energy(const scenario& s, const std::vector<body_frame>& f) {
  double e = 0;
  for (std::size_t i = 0; i < f.size(); ++i) {
    const contact_body& b = s.contact->bodies[i];
    const Eigen::Vector3d w = f[i].rotation.transpose() * f[i].omega;
    e += b.mass * f[i].velocity.squaredNorm() / 2 + w.dot(b.inertia.cwiseProduct(w)) / 2 + b.mass * s.gravity * f[i].position(2);
  }
  return e;
}

contact_measure measure(std::string name, std::string unit, double value, std::optional<double> exact, double scale) {
  contact_measure m;
  m.name = std::move(name);
  m.unit = std::move(unit);
  m.value = value;
  m.exact = exact;
  m.scale = scale > 0 ? scale : 1;
  return m;
}

/// The first time (interpolated between steps) at which x(t) falls to `level`, or nothing.
std::optional<double> first_below(const std::vector<double>& x, double h, double level) {
  for (std::size_t k = 1; k < x.size(); ++k)
    if (x[k] <= level) {
      const double a = x[k - 1], b = x[k];
      const double f = a > b ? (a - level) / (a - b) : 1.0;
      return (double(k - 1) + std::clamp(f, 0.0, 1.0)) * h;
    }
  return std::nullopt;
}

/// The measures of one run (see contact.hpp), by scenario.
contact_run measures_of(const scenario& s, const trajectory& t) {
  const contact_setup& c = *s.contact;
  const double g = s.gravity, h = t.h;
  contact_run r;
  r.h = h;
  r.failure = t.failure;
  const std::vector<body_frame>& first = t.frames.front();
  const auto& fr = t.frames;
  const std::size_t last = fr.size() - 1;
  const contact_body& b0 = c.bodies.front();
  // Energy: the largest rise over a step, relative to the energy the scenario exchanges.
  double e_scale = 0;
  for (const contact_body& b : c.bodies)
    e_scale += b.mass * (b.velocity0.squaredNorm() / 2 + g * std::max(0.05, std::abs(b.position0(2))));
  for (std::size_t k = 1; k < fr.size(); ++k)
    r.energy_gain = std::max(r.energy_gain, (energy(s, fr[k]) - energy(s, fr[k - 1])) / e_scale);
  r.energy_end_gain = (energy(s, fr.back()) - energy(s, first)) / e_scale;
  const double t_run = double(last) * h;
  const auto& name = s.name;
  if (name == "contact_slide") {
    const Eigen::Vector3d v0 = b0.velocity0, u = v0.normalized();
    const reference::sliding_on_level<double> exact(v0, c.mu, g);
    const Eigen::Vector3d d = fr[last][0].position - first[0].position;
    std::vector<double> speed;
    double deviation = 0;
    for (const auto& f : fr) {
      speed.push_back(Eigen::Vector3d(f[0].velocity(0), f[0].velocity(1), 0).norm());
      const Eigen::Vector3d x = f[0].position - first[0].position;
      deviation = std::max(deviation, (x - x.dot(u) * u).head<2>().norm());
    }
    const double stop = exact.stop_distance();
    r.measures.push_back(measure("stopping distance", "m", d.head<2>().norm(), stop, stop));
    if (const auto ts = first_below(speed, h, 0.01 * v0.norm()))
      r.measures.push_back(measure("stopping time (speed 1% of v0)", "s", *ts, 0.99 * exact.stop_time(), exact.stop_time()));
    r.measures.push_back(measure("deviation from the line", "m", deviation, 0.0, stop));
    // At rest from t_stop + 0.1 s: the drift to the end.
    double drift = 0;
    for (std::size_t k = 0; k < fr.size(); ++k)
      if (double(k) * h >= exact.stop_time() + 0.1) drift = std::max(drift, (fr[k][0].position - fr[last][0].position).norm());
    r.measures.push_back(measure("drift at rest", "m", drift, 0.0, stop));
    const Eigen::Matrix3d turn = first[0].rotation.transpose() * fr[last][0].rotation;
    r.measures.push_back(measure("yaw turned", "rad", std::atan2(turn(1, 0), turn(0, 0)), 0.0, 1.0));
  } else if (name == "contact_slope_stick") {
    const Eigen::Vector3d dl = c.fall_line();
    const double creep = (fr[last][0].position - first[0].position).dot(dl);
    const double half = (fr[last / 2][0].position - first[0].position).dot(dl);
    r.measures.push_back(measure("creep down the slope", "m", creep, 0.0, b0.size(0)));
    r.measures.push_back(measure("creep rate (second half)", "m/s", (creep - half) / (t_run / 2), 0.0, b0.size(0)));
  } else if (name == "contact_slope_slide") {
    const reference::sliding_on_slope<double> exact(c.slope, c.mu, g);
    const double s_end = (fr[last][0].position - first[0].position).dot(c.fall_line());
    r.measures.push_back(measure("distance down the slope", "m", s_end, exact.position(t_run), exact.position(t_run)));
  } else if (name == "contact_roll" || name == "contact_roll_cylinder") {
    const double radius = b0.size(0), k = b0.inertia(1) / (b0.mass * radius * radius);
    const reference::rolling_on_slope<double> exact(c.slope, c.mu, g, k, radius);
    const Eigen::Vector3d n = c.normal();
    const double s_end = (fr[last][0].position - first[0].position).dot(c.fall_line());
    r.measures.push_back(measure("distance down the slope", "m", s_end, exact.distance(t_run), exact.distance(t_run)));
    double slip = 0;
    for (std::size_t k2 = 1; k2 < fr.size(); ++k2) {
      const body_frame& f = fr[k2][0];
      slip = std::max(slip, (f.velocity + f.omega.cross(-radius * n)).norm());
    }
    r.measures.push_back(measure("slip |v - omega r|, largest", "m/s", slip, 0.0, exact.velocity(t_run)));
  } else if (name == "contact_billiard") {
    const double radius = b0.size(0), k = b0.inertia(0) / (b0.mass * radius * radius);
    const reference::billiard<double> exact(b0.velocity0, b0.omega0, radius, k, c.mu, g);
    std::vector<double> slip;
    for (const auto& f : fr) slip.push_back(exact.slip(f[0].velocity, f[0].omega).head<2>().norm());
    const double v0 = b0.velocity0.norm();
    if (const auto tr = first_below(slip, h, 1e-3 * v0))
      r.measures.push_back(measure("rolling from", "s", *tr, exact.roll_time(), exact.roll_time()));
    else
      r.measures.push_back(measure("rolling from (never: slips to the end)", "s", t_run, exact.roll_time(), exact.roll_time()));
    r.measures.push_back(measure("final speed", "m/s", fr[last][0].velocity.head<2>().norm(), exact.velocity(t_run).norm(), v0));
    r.measures.push_back(measure("distance", "m", (fr[last][0].position - first[0].position).head<2>().norm(),
                                 exact.displacement(t_run).norm(), exact.displacement(t_run).norm()));
  } else if (name == "contact_bounce") {
    const double radius = b0.size(0), h0 = b0.position0(2) - radius;
    const reference::bouncing_ball<double> exact(h0, c.restitution, g);
    // Apexes: local maxima of the lowest point's height after the first contact.
    std::vector<double> z;
    for (const auto& f : fr) z.push_back(f[0].position(2) - radius);
    int k = 0;
    bool touched = false;
    for (std::size_t i = 1; i + 1 < z.size() && k < 3; ++i) {
      if (z[i] < 0.5 * h0 * std::pow(c.restitution, 2 * k) * 0.1 + 1e-9 && !touched && double(i) * h > exact.fall_time() * 0.5)
        touched = true;
      if (touched && z[i] > z[i - 1] && z[i] >= z[i + 1] && z[i] > 1e-4) {
        ++k;
        r.measures.push_back(measure("apex " + std::to_string(k), "m", z[i], exact.apex(k), h0));
        touched = false;
      }
    }
    r.measures.push_back(measure("height at rest (end)", "m", z.back(), 0.0, radius));
  } else if (name == "contact_collision" || name == "contact_collision_oblique") {
    const contact_body& b1 = c.bodies[1];
    const Eigen::Vector3d x1 = b0.position0, x2 = b1.position0, v1 = b0.velocity0, v2 = b1.velocity0;
    // The contact normal where they meet: centres 2r apart along the relative motion.
    const Eigen::Vector3d rel = x2 - x1, w = v1 - v2;
    const double a = w.squaredNorm(), bb = -2 * rel.dot(w), cc = rel.squaredNorm() - std::pow(b0.size(0) + b1.size(0), 2);
    const double tc = (-bb - std::sqrt(bb * bb - 4 * a * cc)) / (2 * a);
    const Eigen::Vector3d n = (rel - tc * w).normalized();
    const auto out = reference::collide(b0.mass, v1, b1.mass, v2, n, c.restitution);
    const Eigen::Vector3d p0 = b0.mass * v1 + b1.mass * v2;
    const Eigen::Vector3d p1 = b0.mass * fr[last][0].velocity + b1.mass * fr[last][1].velocity;
    const double vs = v1.norm() + v2.norm();
    r.measures.push_back(measure("body 1's velocity after, error", "m/s", (fr[last][0].velocity - out.v1).norm(), 0.0, vs));
    r.measures.push_back(measure("body 2's velocity after, error", "m/s", (fr[last][1].velocity - out.v2).norm(), 0.0, vs));
    r.measures.push_back(measure("momentum change", "kg m/s", (p1 - p0).norm(), 0.0, b0.mass * v1.norm() + b1.mass * v2.norm()));
    const double k0 = b0.mass * v1.squaredNorm() / 2 + b1.mass * v2.squaredNorm() / 2;
    const double k1 = b0.mass * fr[last][0].velocity.squaredNorm() / 2 + b1.mass * fr[last][1].velocity.squaredNorm() / 2;
    r.measures.push_back(measure("kinetic energy lost", "J", k0 - k1, out.energy_lost, k0));
  } else if (name == "contact_rest" || name == "contact_stack") {
    double drift = 0, gain = 0;
    const double e0 = energy(s, first);
    for (const auto& f : fr) {
      for (std::size_t i = 0; i < f.size(); ++i) drift = std::max(drift, (f[i].position - first[i].position).norm());
      gain = std::max(gain, energy(s, f) - e0);
    }
    r.measures.push_back(measure("drift, largest", "m", drift, 0.0, b0.size(0)));
    // In the last second: where a contact settles into its penetration first, whether the
    // bodies then rest.
    double late = 0;
    const std::size_t from = fr.size() - std::min(fr.size(), std::size_t(std::llround(1 / h)) + 1);
    for (std::size_t k = from; k < fr.size(); ++k)
      for (std::size_t i = 0; i < fr[k].size(); ++i) late = std::max(late, (fr[k][i].position - fr[from][i].position).norm());
    r.measures.push_back(measure("drift in the last second", "m", late, 0.0, b0.size(0)));
    double weight = 0;
    for (const contact_body& b : c.bodies) weight += b.mass * g * b0.size(2);
    r.measures.push_back(measure("energy gained, largest", "J", gain, 0.0, weight));
  }
  return r;
}

std::string fmt(double x, const char* f = "%.3g") {
  char buf[48];
  std::snprintf(buf, sizeof buf, f, x);
  return buf;
}

/// The trend of each measure's error over the study's h. The rounding floor: an error below
/// max(1e-6, n epsilon) at the finest h, n its steps (each step may round a position of the
/// scale's size by epsilon of the engine's arithmetic), is not resolved as a failure to
/// converge: 1e-6 in double; 1.1e-4 over 960 steps of a single-precision engine.
std::vector<contact_trend> trends_of(const std::vector<contact_run>& runs, double t_end, double epsilon) {
  std::vector<contact_trend> out;
  if (runs.empty()) return out;
  const double floor = std::max(1e-6, std::round(t_end / runs.back().h) * epsilon);
  for (std::size_t m = 0; m < runs.front().measures.size(); ++m) {
    const std::string& name = runs.front().measures[m].name;
    std::vector<double> lh, le, errors;
    for (const contact_run& r : runs) {
      const auto it = std::find_if(r.measures.begin(), r.measures.end(), [&](const contact_measure& x) { return x.name == name; });
      if (it == r.measures.end() || !it->exact || !r.failure.empty()) continue;
      const double e = std::abs(it->error());
      errors.push_back(e);
      if (e > 0) {
        lh.push_back(std::log(r.h));
        le.push_back(std::log(e));
      }
    }
    if (errors.empty()) continue;
    contact_trend t;
    t.measure = name;
    t.at_default = errors.front();
    t.limit = errors.back();
    t.floor = floor;
    if (lh.size() >= 3) {
      double mx = 0, my = 0;
      for (std::size_t i = 0; i < lh.size(); ++i) mx += lh[i], my += le[i];
      mx /= double(lh.size());
      my /= double(lh.size());
      double sxy = 0, sxx = 0;
      for (std::size_t i = 0; i < lh.size(); ++i) sxy += (lh[i] - mx) * (le[i] - my), sxx += (lh[i] - mx) * (lh[i] - mx);
      const double slope = sxy / sxx;
      // Converging: the error falls as h^p, p >= 1/2, by at least half over the study.
      if (slope >= 0.5 && errors.back() <= errors.front() / 2) t.order = slope;
    }
    if (errors.back() == 0 && errors.front() == 0)
      t.words = "exact at every h";
    else if (t.order)
      t.words = "converges, order " + fmt(*t.order, "%.2f") + " (" + fmt(errors.front()) + " at h = 1/60, " +
                fmt(errors.back()) + " at the finest)";
    else if (errors.back() < floor)
      t.words = "within the rounding floor at the finest h: " + fmt(errors.back()) + " under " + fmt(floor) + " (" +
                fmt(errors.front()) + " at 1/60)";
    else
      t.words = "does not converge: " + fmt(errors.back()) + " at the finest h (" + fmt(errors.front()) + " at 1/60)";
    out.push_back(t);
  }
  return out;
}

const contact_measure* find(const contact_run& r, const std::string& prefix) {
  for (const auto& m : r.measures)
    if (m.name.rfind(prefix, 0) == 0) return &m;
  return nullptr;
}

const contact_scenario_audit* scenario_named(const contact_audit& a, const std::string& name) {
  for (const auto& s : a.scenarios)
    if (s.scenario == name && s.refused.empty() && !s.runs.empty()) return &s;
  return nullptr;
}

/// The energy a run may gain by rounding alone: 64 u a step as a random walk (the engines'
/// long runs use the same budget), relative to the scenario's energy scale.
double rounding_gain(double u, double steps) { return 64 * u * std::sqrt(std::max(steps, 1.0)); }
}  // namespace

bool contact_audit::claims_hold() const {
  return std::none_of(verdicts.begin(), verdicts.end(),
                      [](const verdict& v) { return v.result == verdict::outcome::contradicted; });
}

namespace {
using outcome = verdict::outcome;

/// How far a soft contact's pose may move an isotropic cone's stopping distance before the
/// spread is the cone's, not the softness's: 0.05 of v0^2/(2 mu g). A pyramid of n friction
/// directions, each bounded on its own, spreads it by 1 - cos(pi / (2n)): 0.293 for two
/// (ODE's), 0.076 for four (MuJoCo's pyramid, built otherwise, spreads it by 0.412); the largest spread a documented soft, elliptic contact has shown is 7e-3 (MuJoCo's,
/// a 0.03 m box of 0.01 kg among the random cases). A cone of eight or more directions is not
/// resolved from a soft contact's pose.
constexpr double soft_pose_spread = 0.05;

/// The first failed run of a scenario, with its h ("" where every run completed): what
/// a failed run measured stops at its failure, and confirms nothing.
std::string failure_of(const contact_scenario_audit& s) {
  for (const contact_run& r : s.runs)
    if (!r.failure.empty()) return s.scenario + " at h = " + fmt(r.h) + " failed: " + r.failure;
  return {};
}

/// The verdicts (contact.hpp): thresholds derived from what each study resolves.
std::vector<verdict> judge_contact(const contact_audit& a, double u) {
  std::vector<verdict> out;
  const contact_claims& c = a.declared;
  {  // The friction cone: the stopping distance against direction.
    verdict v;
    v.claim = "friction cone";
    v.declared = c.friction_cone.value_or("-");
    const contact_scenario_audit* s = scenario_named(a, "contact_slide");
    // The sweep's runs differ only by the rotation of their inputs: an isotropic friction
    // gives them one distance up to rounding. 1e-3 is a thousand times single precision's
    // rounding of the distance and far below a pyramid's spread (up to 1 - 1/sqrt 2).
    const double resolution = 1e-3;
    if (!s || s->isotropy.size() < 2) {  // a spread needs two directions that ran to the end
      v.measured = s && !s->runs.empty() ? "the sweep's runs failed" : "-";
      v.result = c.friction_cone ? outcome::not_measured : outcome::not_declared;
    } else {
      const bool isotropic = s->anisotropy <= resolution;
      v.measured = isotropic ? "isotropic (spread " + fmt(s->anisotropy) + ")" : "anisotropic (spread " + fmt(s->anisotropy) + ")";
      v.evidence = "the stopping distance over theta 0..90 degrees and psi 0, 30 at h = 1/60 spreads by " + fmt(s->anisotropy) +
                   " of v0^2/(2 mu g) (resolution " + fmt(resolution) + ")";
      if (!c.friction_cone) v.result = outcome::not_declared;
      else if (*c.friction_cone == "elliptic" && !isotropic && c.soft.value_or(false) &&
               s->anisotropy <= soft_pose_spread) {
        // An isotropic cone on a soft contact: the body sinks and pitches by its pose.
        v.evidence += "; under a soft contact up to " + fmt(soft_pose_spread) + " is the pose's, above it the cone's";
        v.result = outcome::reading;
        v.readings.push_back({"a soft contact, by design (its penetration depends on the body's pose)", v.measured, true});
      } else if (*c.friction_cone == "elliptic") v.result = isotropic ? outcome::confirmed : outcome::contradicted;
      else v.result = isotropic ? outcome::exceeds : outcome::reading;
      if (c.friction_cone && *c.friction_cone != "elliptic" && !isotropic)
        v.readings.push_back({"a " + *c.friction_cone + " friction limit, as documented", v.measured, true});
    }
    out.push_back(v);
  }
  {  // Static friction: no creep below the friction angle.
    verdict v;
    v.claim = "static friction";
    v.declared = c.soft.value_or(false) ? "soft contact" : "Coulomb";
    const contact_scenario_audit* s = scenario_named(a, "contact_slope_stick");
    if (!s) {
      v.measured = "-";
      v.result = outcome::not_measured;
    } else if (const std::string f = failure_of(*s); !f.empty()) {
      v.measured = "a run failed";
      v.evidence = f;
      v.result = outcome::not_measured;
    } else {
      // The creep's rate over the second half of the run: a static friction that holds it
      // is zero, whatever slip the contact's first steps allowed (that transient is the
      // total's, judged with the exact motions). 1e-6 m/s: far above rounding (a float's
      // position near 0.1 m is good to 1e-8 m over 1.5 s).
      const contact_measure* creep = find(s->runs.front(), "creep down the slope");
      const contact_measure* rate = find(s->runs.front(), "creep rate");
      const double total = creep ? std::abs(creep->value) : 0, speed = rate ? std::abs(rate->value) : 0;
      const bool creeps = speed > 1e-6;
      v.measured = (creeps ? "creeps at " + fmt(speed) + " m/s" : "holds (" + fmt(speed) + " m/s)") + ", " + fmt(total) +
                   " m in 3 s";
      v.evidence = "a box on a slope of 0.25 rad, mu = 0.5, over 3 s at h = 1/60: the creep's rate over the second half "
                   "(resolution 1e-06 m/s); the creep in all: " +
                   (s->trends.size() > 0 ? s->trends.front().words : std::string());
      if (!creeps) v.result = outcome::confirmed;
      else if (c.soft.value_or(false)) {
        v.result = outcome::reading;
        v.readings.push_back({"a soft contact, by design", v.measured, true});
      } else v.result = outcome::measured;
    }
    out.push_back(v);
  }
  {  // At rest: a box on level ground and a stack of three stay where they were put.
    verdict v;
    v.claim = "at rest";
    v.declared = c.soft ? (*c.soft ? "soft contact" : "rigid contact") : "-";
    double total = 0, late = 0;
    std::string where, failed;
    for (const char* name : {"contact_rest", "contact_stack"})
      if (const contact_scenario_audit* s = scenario_named(a, name); s && !s->runs.empty()) {
        if (failed.empty()) failed = failure_of(*s);
        const contact_measure* m = find(s->runs.front(), "drift, largest");
        const contact_measure* l = find(s->runs.front(), "drift in the last second");
        if (m && std::abs(m->value) >= total) total = std::abs(m->value), where = name;
        if (l) late = std::max(late, std::abs(l->value));
      }
    if (!failed.empty()) {
      v.measured = "a run failed";
      v.evidence = failed;
      v.result = outcome::not_measured;
    } else if (where.empty()) {
      v.measured = "-";
      v.result = outcome::not_measured;
    } else {
      // The static friction's resolution: 1e-6 m.
      const double resolution = 1e-6;
      v.evidence = "the largest displacement of a body of contact_rest and contact_stack over 3 s, and in the last second, "
                   "at h = 1/60 (resolution 1e-06 m)";
      if (total <= resolution) {
        v.measured = "at rest (" + fmt(total) + " m in 3 s)";
        v.result = outcome::confirmed;
      } else if (late <= resolution) {
        // Settled into the contact's penetration, then at rest.
        v.measured = "settles by " + fmt(total) + " m (" + where + "), then rests (" + fmt(late) + " m in the last second)";
        v.result = c.soft.value_or(false) ? outcome::reading : outcome::measured;
        if (c.soft.value_or(false)) v.readings.push_back({"a soft contact, by design (it settles into its penetration)", v.measured, true});
      } else {
        v.measured = "moves " + fmt(total) + " m in 3 s (" + where + "), " + fmt(late) + " m in the last second";
        // A soft contact, documented as such, lets bodies move slowly under static loads.
        v.result = c.soft.value_or(false) ? outcome::reading : outcome::measured;
        if (c.soft.value_or(false)) v.readings.push_back({"a soft contact, by design (slow motion under static loads)", v.measured, true});
      }
    }
    out.push_back(v);
  }
  {  // Restitution: the apexes at e^(2k) h.
    verdict v;
    v.claim = "restitution";
    v.declared = c.newton_restitution ? (*c.newton_restitution ? "Newton's" : "none") : "-";
    const contact_scenario_audit* s = scenario_named(a, "contact_bounce");
    if (!s) {
      v.measured = "-";
      v.result = c.newton_restitution ? outcome::not_measured : outcome::not_declared;
    } else if (const std::string f = failure_of(*s); !f.empty()) {
      v.measured = "a run failed";
      v.evidence = f;
      v.result = c.newton_restitution ? outcome::not_measured : outcome::not_declared;
    } else {
      const contact_run& fine = s->runs.back();
      const contact_measure* apex = find(fine, "apex 1");
      v.measured = apex ? "apex 1 at " + fmt(apex->value) + " m (e^2 h = " + fmt(*apex->exact) + ")" : "no bounce";
      v.evidence = "at the finest h; " + (s->trends.empty() ? std::string() : s->trends.front().measure + ": " + s->trends.front().words);
      const bool holds = apex && std::abs(apex->error()) <= 0.02;  // 2 % of h: a step's worth at 1/960
      if (!c.newton_restitution) v.result = outcome::not_declared;
      else if (!*c.newton_restitution) v.result = c.soft.value_or(false) ? outcome::reading : outcome::not_declared;
      else v.result = holds ? outcome::confirmed : outcome::measured;
    }
    out.push_back(v);
  }
  {  // Energy: none gained at a contact event or at rest.
    verdict v;
    v.claim = "energy";
    v.declared = c.newton_restitution.value_or(false) ? "not gained at an impact (Newton's e <= 1)" : "-";
    const bool soft = c.soft.value_or(false), newton = c.newton_restitution.value_or(false);
    // The largest gain beyond rounding where it contradicts a claim (an impact under a
    // restitution documented as Newton's, whose e <= 1 never returns more than the normal
    // velocity), and where it is measured: at rest (an engine's position correction -- its
    // ERP, its split impulse -- pushes a penetration out and lifts the body: energy gained
    // by a mechanism the engines document, whose size is the measurement), a slide, a roll.
    double contradicting = 0, other = 0;
    std::string where_contradicting, where_other, failed;
    int runs = 0;
    for (const auto& s : a.scenarios) {
      if (!s.refused.empty()) continue;
      if (failed.empty()) failed = failure_of(s);
      const bool at_rest = s.scenario == "contact_rest" || s.scenario == "contact_stack";
      const bool impact = s.scenario == "contact_bounce" || s.scenario.rfind("contact_collision", 0) == 0;
      for (const auto& r : s.runs) {
        ++runs;
        const double steps = 1.0 / r.h * 3;
        double gain = 0;
        if (at_rest) {
          if (const contact_measure* m = find(r, "energy gained")) gain = m->value / m->scale;
        } else if (s.scenario == "contact_bounce") {
          // An apex above the one before it (or the drop) gains energy.
          double previous = 1.0;
          for (int k = 1; k <= 3; ++k)
            if (const contact_measure* m = find(r, "apex " + std::to_string(k))) {
              gain = std::max(gain, (m->value / m->scale - previous));
              previous = m->value / m->scale;
            }
        } else if (impact) {
          if (const contact_measure* m = find(r, "kinetic energy lost")) gain = -m->value / m->scale;
        } else {
          gain = soft ? r.energy_end_gain : r.energy_gain;
        }
        gain -= rounding_gain(u, steps);
        const std::string here = s.scenario + " at h = " + fmt(r.h);
        if (impact && newton && gain > contradicting) contradicting = gain, where_contradicting = here;
        if (!(impact && newton) && gain > other) other = gain, where_other = here;
      }
    }
    v.evidence = "at rest: the largest energy since the start; a bounce: an apex above the one before; a collision: the "
                 "kinetic energy after it against before; a slide or a roll: " +
                 std::string(soft ? "the energy at the end against the start (a soft contact)" : "the largest rise over a step") +
                 "; each relative to the energy the scenario exchanges, beyond 64 u sqrt(steps) of rounding";
    if (runs == 0) {
      v.measured = "-";
      v.result = outcome::not_measured;
    } else if (contradicting > 0) {
      v.measured = "gained " + fmt(contradicting) + " of its scale (" + where_contradicting + ")";
      v.result = outcome::contradicted;
    } else if (other > 0) {
      v.measured = "gained " + fmt(other) + " of its scale (" + where_other + ")";
      v.result = outcome::measured;
    } else if (!failed.empty()) {  // none gained up to the failure: not a run's whole
      v.measured = "none gained up to a failed run's failure";
      v.evidence += "; " + failed;
      v.result = outcome::not_measured;
    } else {
      v.measured = "none gained";
      v.result = outcome::confirmed;
    }
    out.push_back(v);
  }
  {  // Agreement with the exact motions at the finest h.
    verdict v;
    v.claim = "exact motions";
    v.declared = "Coulomb friction";
    std::string converging, not_converging, failed;
    for (const auto& s : a.scenarios) {
      if (const std::string f = failure_of(s); !f.empty()) failed += f + "; ";
      for (const auto& t : s.trends) {
        if (s.scenario == "contact_slope_stick" || s.scenario == "contact_rest" || s.scenario == "contact_stack") continue;
        (t.order || t.limit < t.floor ? converging : not_converging) += s.scenario + " " + t.measure + ": " + t.words + "; ";
      }
    }
    v.measured = !not_converging.empty() ? "some errors do not fall with h"
                 : failed.empty()        ? "every error falls with h"
                                         : "runs failed";
    v.evidence = failed + not_converging + converging;
    v.result = !not_converging.empty()                  ? outcome::measured
               : converging.empty() || !failed.empty() ? outcome::not_measured
                                                        : outcome::confirmed;
    out.push_back(v);
  }
  return out;
}
}  // namespace

namespace {
/// A contact scenario's setup as JSON, for an engine without a file of its own: the ground,
/// mu, e, gravity, the step and the duration, each body's shape, mass, moments and start.
std::string setup_json(const scenario& s, double h) {
  using json = nlohmann::ordered_json;
  const contact_setup& c = *s.contact;
  const auto v3 = [](const Eigen::Vector3d& v) { return json::array({v(0), v(1), v(2)}); };
  json j;
  j["scenario"] = s.name;
  j["ground"] = c.ground;
  j["slope"] = c.slope;
  j["ground_normal"] = v3(c.normal());
  j["mu"] = c.mu;
  j["restitution"] = c.restitution;
  j["gravity"] = json::array({0.0, 0.0, -s.gravity});
  j["h"] = h;
  j["t_end"] = s.t_end;
  json bodies = json::array();
  for (const contact_body& b : c.bodies) {
    json o;
    o["shape"] = contact_shape_name(b.shape);
    o["size"] = v3(b.size);
    o["mass"] = b.mass;
    o["principal_moments"] = v3(b.inertia);
    json r = json::array();
    for (int i = 0; i < 3; ++i) r.push_back(json::array({b.rotation0(i, 0), b.rotation0(i, 1), b.rotation0(i, 2)}));
    o["rotation"] = r;
    o["position"] = v3(b.position0);
    o["velocity"] = v3(b.velocity0);
    o["omega"] = v3(b.omega0);
    bodies.push_back(o);
  }
  j["bodies"] = bodies;
  return j.dump(2) + "\n";
}

/// One drawn case (contact_cases): the angles in whole degrees, the rest as drawn.
struct drawn_case {
  int theta = 0, psi = 0;
  double mu = 0.5, mass = 1, half = 0.1, speed = 1, fraction = 0;
  std::string words() const {
    return "theta " + std::to_string(theta) + " deg, psi " + std::to_string(psi) + " deg, mu " + fmt(mu) + ", mass " +
           fmt(mass) + " kg, half-edge " + fmt(half) + " m, speed " + fmt(speed) + " m/s, slope tan a = " + fmt(fraction) +
           " mu";
  }
};

/// The random cases (contact.hpp, contact_cases): RapidCheck draws, checks and shrinks.
contact_cases run_cases(const engine_integrator& in, const contact_options& opt) {
  contact_cases out;
  out.asked = opt.cases;
  out.seed = opt.seed;
  const contact_claims& c = *in.contact;
  out.isotropy_checked = !c.friction_cone || *c.friction_cone == "elliptic";
  out.creep_checked = !c.soft.value_or(false);
  // The resolutions of the sweep and of the static-friction verdict: a difference of the
  // stopping distances over v0^2 / (2 mu g), a creep rate in m/s.
  const double resolution = 1e-3, creep_limit = 1e-6, h = opt.h0;
  bool failed = false;
  const auto property = [&] {
    drawn_case d;  // each shrinks towards its lower bound
    d.theta = *rc::gen::inRange(0, 360);
    d.psi = *rc::gen::inRange(0, 360);
    d.mu = *rc::gen::inRange(5, 151) / 100.0;
    d.mass = std::pow(10.0, *rc::gen::inRange(-200, 201) / 100.0);
    d.half = std::pow(10.0, *rc::gen::inRange(-150, 51) / 100.0);
    d.speed = *rc::gen::inRange(50, 501) / 100.0;
    d.fraction = *rc::gen::inRange(0, 91) / 100.0;
    std::string failure;
    const auto slide = [&](double theta, double psi, double mass, double half) {
      return contact_slide_case(d.mu, mass, half, d.speed, theta * M_PI / 180, psi * M_PI / 180);
    };
    const auto distance = [&](const scenario& s) {
      const contact_run r = measures_of(s, run_scenario(in, s, h));
      if (!r.failure.empty()) failure = r.failure;
      const contact_measure* m = find(r, "stopping distance");
      return m->value / *m->exact;
    };
    const scenario turned = slide(d.theta, d.psi, d.mass, d.half), plain = slide(0, 0, d.mass, d.half);
    const double d_turned = distance(turned), d_plain = distance(plain), d_reference = distance(slide(0, 0, 1, 0.1));
    const scenario stick = contact_stick_case(d.mu, std::atan(d.fraction * d.mu), d.mass, d.half);
    double creep = 0;
    if (out.creep_checked) {
      const contact_run r = measures_of(stick, run_scenario(in, stick, h));
      if (!r.failure.empty()) failure = r.failure;
      creep = std::abs(find(r, "creep rate")->value);
    }
    const double isotropy = std::abs(d_turned - d_plain), mass_and_size = std::abs(d_plain - d_reference);
    if (!failed) {
      ++out.checked;
      if (out.isotropy_checked) out.isotropy = std::max(out.isotropy, isotropy);
      out.mass_and_size = std::max(out.mass_and_size, mass_and_size);
      out.creep_rate = std::max(out.creep_rate, creep);
      if (opt.progress && out.checked % 25 == 0)
        opt.progress(in.name + ": " + std::to_string(out.checked) + " of " + std::to_string(opt.cases) + " contact cases");
    }
    std::string broken, size;
    const scenario* shown = &turned;
    if (!failure.empty()) {
      broken = "a run failed", size = failure;
    } else if (out.isotropy_checked && isotropy > resolution) {
      broken = "isotropy", size = "the stopping distance " + fmt(d_turned, "%.6g") + " of v0^2/(2 mu g) against " +
                                  fmt(d_plain, "%.6g") + " at theta = psi = 0";
    } else if (mass_and_size > resolution) {
      broken = "independence of mass and size", shown = &plain;
      size = "the stopping distance " + fmt(d_plain, "%.6g") + " of v0^2/(2 mu g) against " + fmt(d_reference, "%.6g") +
             " for 1 kg and half-edge 0.1 m";
    } else if (out.creep_checked && creep > creep_limit) {
      broken = "no creep", shown = &stick, size = "creeps at " + fmt(creep) + " m/s";
    }
    if (broken.empty()) return;
    failed = true;
    out.property = broken;
    out.counterexample = broken + ": " + d.words() + ": " + size + " (h = 1/60; seed " + std::to_string(opt.seed) +
                         ", mechcheck-audit -o contact-case --engine '" + in.name + "' --scenario contact_slide --contact-cases " +
                         std::to_string(opt.cases) + " --seed " + std::to_string(opt.seed) +
                         (in.command_arguments.empty() ? "" : " " + in.command_arguments) + " finds and shrinks it again)";
    out.model = in.contact_model ? in.contact_model(*shown) : setup_json(*shown, h);
    out.model_extension = in.contact_model ? in.contact_model_extension : "json";
    RC_FAIL(out.counterexample);
  };
  rc::detail::TestParams params;
  params.seed = opt.seed;
  params.maxSuccess = opt.cases;
  params.maxSize = 100;
  rc::detail::checkTestable(property, rc::detail::TestMetadata{}, params);
  return out;
}

verdict judge_cases(const contact_cases& k, const contact_claims& c) {
  verdict v;
  v.claim = "random cases";
  v.declared = std::string(k.isotropy_checked ? "isotropic, " : "") + "independent of mass and size" +
               (k.creep_checked ? ", no creep" : "");
  v.evidence = std::to_string(k.checked) + " of " + std::to_string(k.asked) + " drawn cases (seed " + std::to_string(k.seed) +
               ") at h = 1/60, each shrunk on failure: the stopping distance against theta = psi = 0" +
               std::string(k.isotropy_checked ? "" : " (not checked: a documented " + c.friction_cone.value_or("") + " cone)") +
               " and against 1 kg and half-edge 0.1 m, to 1e-3 of v0^2/(2 mu g); the creep rate on a slope below the "
               "friction angle, to 1e-6 m/s" + (k.creep_checked ? "" : " (not checked: a documented soft contact)");
  if (k.property.empty()) {
    v.measured = "none broken: largest " + std::string(k.isotropy_checked ? "isotropy " + fmt(k.isotropy) + ", " : "") +
                 "mass and size " + fmt(k.mass_and_size) + (k.creep_checked ? ", creep " + fmt(k.creep_rate) + " m/s" : "");
    v.result = outcome::confirmed;
  } else {
    v.measured = k.counterexample;
    // Isotropy broken under a cone documented as elliptic contradicts it; on a contact
    // documented as soft the body sinks and pitches by its pose, its size and its mass.
    const bool soft = c.soft.value_or(false);
    if (k.property == "isotropy" && c.friction_cone.value_or("") == "elliptic" && (!soft || k.isotropy > soft_pose_spread))
      v.result = outcome::contradicted;
    else if (soft && k.property != "a run failed") {
      v.result = outcome::reading;
      v.readings.push_back({"a soft contact, by design (its penetration depends on the body's pose, size and mass)",
                            k.property + " broken", true});
    } else {
      v.result = outcome::measured;
    }
  }
  return v;
}
}  // namespace

contact_audit audit_contact(const engine_integrator& in, const contact_options& opt) {
  contact_audit out;
  out.integrator = in.name;
  out.origin = in.origin;
  if (in.contact) out.declared = *in.contact;
  for (const scenario& s : contact_scenarios()) {
    if (!opt.scenarios.empty() && std::find(opt.scenarios.begin(), opt.scenarios.end(), s.name) == opt.scenarios.end())
      continue;
    contact_scenario_audit a;
    a.scenario = s.name;
    a.description = s.description;
    if (!in.contact) {
      a.refused = in.name + ": the adapter builds no contact scenario";
      out.scenarios.push_back(a);
      continue;
    }
    if (opt.progress) opt.progress(in.name + " on " + s.name);
    try {
      double h = opt.h0;
      for (int k = 0; k <= opt.halvings; ++k, h /= 2) a.runs.push_back(measures_of(s, run_scenario(in, s, h)));
      a.trends = trends_of(a.runs, s.t_end, in.epsilon);
      if (s.name == "contact_slide") {
        const double exact = reference::sliding_on_level<double>(s.contact->bodies.front().velocity0, s.contact->mu, s.gravity)
                                 .stop_distance();
        double lo = std::numeric_limits<double>::infinity(), hi = 0;
        for (const double psi : {0.0, 30.0})
          for (double theta = 0; theta <= 90; theta += 15) {
            const scenario turned = with_direction(s, theta * M_PI / 180, psi * M_PI / 180);
            const contact_run r = measures_of(turned, run_scenario(in, turned, opt.h0));
            const contact_measure* d = find(r, "stopping distance");
            if (!d || !r.failure.empty()) continue;
            a.isotropy.push_back({theta, psi, d->value / exact});
            lo = std::min(lo, d->value / exact);
            hi = std::max(hi, d->value / exact);
          }
        if (!a.isotropy.empty()) a.anisotropy = hi - lo;
      }
      if (s.name == "contact_bounce")
        for (const auto& m : a.runs.front().measures)
          if (m.name.rfind("apex ", 0) == 0) a.apexes.push_back({std::stod(m.name.substr(5)), m.value, *m.exact});
    } catch (const scenario_refused& e) {
      a.refused = e.what();
      a.runs.clear();
    } catch (const std::exception& e) {
      a.refused = std::string("failed: ") + e.what();
      a.runs.clear();
    }
    out.scenarios.push_back(a);
  }
  out.verdicts = judge_contact(out, in.epsilon);
  if (opt.cases < 0) throw domain_error("audit_contact: cases must be >= 0, got " + std::to_string(opt.cases));
  if (opt.cases > 0 && in.contact) {
    out.cases = run_cases(in, opt);
    out.verdicts.push_back(judge_cases(*out.cases, *in.contact));
  }
  return out;
}

}  // namespace mechcheck::audit
