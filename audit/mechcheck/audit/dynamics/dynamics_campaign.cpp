// The dynamics audit over random robots, shrunk by RapidCheck, and its report (dynamics.hpp).
#include <algorithm>
#include <cctype>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <Eigen/Geometry>
#include <nlohmann/json.hpp>
#include <rapidcheck.h>

#include "mechcheck/audit/dynamics/dynamics.hpp"
#include "mechcheck/audit/problems/urdf.hpp"
#include "mechcheck/audit/report.hpp"
#include "mechcheck/harness/generators.hpp"
#include "mechcheck/robots/dynamics.hpp"

namespace mechcheck::audit {

dynamics_state state_of(const generators::robot_case& c) {
  dynamics_state x;
  x.q = generators::to_tier<double>(c.q);
  x.qdot = generators::to_tier<double>(c.qdot);
  x.qddot = generators::to_tier<double>(c.qddot);
  x.tau = generators::to_tier<double>(c.tau);
  return x;
}

namespace {

/// The robot of `c` on a floating base, in dynamics_state's layout: q = (p; quaternion w x y z
/// of the base's rpy, rounded to double; the joints'), and the base's twist, its rate and
/// wrench ahead of the joints' rates, accelerations and torques.
generators::robot_case floated(const generators::floating_robot_case& f) {
  generators::robot_case c = f.joints;
  c.robot.floating = true;
  const Eigen::Quaterniond r(robots::rpy_rotation<double>(f.base.rpy));
  std::vector<double> q{f.base.xyz(0), f.base.xyz(1), f.base.xyz(2), r.w(), r.x(), r.y(), r.z()};
  q.insert(q.end(), c.q.begin(), c.q.end());
  c.q = q;
  for (const auto& [head, v] : {std::pair{&f.twist, &c.qdot}, std::pair{&f.twist_rate, &c.qddot}, std::pair{&f.wrench, &c.tau}})
    v->insert(v->begin(), head->begin(), head->end());
  return c;
}

std::string vector_text(const Eigen::MatrixXd& m) {
  std::ostringstream s;
  s.precision(17);
  s << "[";
  for (Eigen::Index i = 0; i < m.rows(); ++i) {
    if (m.cols() > 1) s << (i ? "; " : "");
    for (Eigen::Index j = 0; j < m.cols(); ++j) s << (i + j && m.cols() == 1 ? ", " : j ? ", " : "") << m(i, j);
  }
  return s.str() + "]";
}

/// The campaign's property over cases drawn by `draw`: figures recorded until the first
/// disagreement (then RapidCheck shrinks it, and the last failing case is the minimal one).
dynamics_campaign campaign(const std::string& name, const std::string& origin, const dynamics_checker& checker,
                           const dynamics_options& opt, const std::function<generators::robot_case()>& draw,
                           const std::string& selector, const robots::robot* user = nullptr) {
  dynamics_campaign c;
  c.library = name;
  c.origin = origin;
  c.asked = opt.robots;
  if (user) c.unit = "states";
  c.seed = opt.seed;
  c.max_links = opt.max_links;
  if (!user)
    c.joint_terms = opt.armature && opt.damping ? "an armature and a damping"
                    : opt.armature              ? "an armature"
                    : opt.damping               ? "a damping"
                                                : "";
  for (const auto q : all_dynamics_quantities)
    c.figures.push_back({q, 0, 0, 0});
  bool failed = false;
  auto last_progress = std::chrono::steady_clock::now();
  const auto property = [&] {
    const generators::robot_case rc = draw();
    dynamics_check check;
    try {
      check = checker(rc.robot, state_of(rc));
    } catch (const std::exception& e) {
      failed = true;
      c.note = e.what();
      c.counterexample_urdf = to_urdf(rc.robot);
      RC_FAIL(std::string("the library failed: ") + e.what());
    }
    if (!failed) {
      ++c.robots;
      const auto joints = static_cast<std::size_t>(robots::validate(rc.robot).dofs);
      if (!check.refused.empty() && !c.refused++) c.first_refusal = check.refused;
      if (check.model_difference) {
        ++c.model_checked;
        if (*check.model_difference >= c.model_largest) {
          c.model_largest = *check.model_difference;
          c.model_largest_scale = check.model_scale;
          c.model_largest_urdf = to_urdf(rc.robot);
        }
      }
      for (const auto& r : check.residuals)
        for (auto& f : c.figures)
          if (f.quantity == r.quantity) {
            ++f.checked;
            if (r.residual >= f.largest) f.largest = r.residual, f.budget = r.budget;
            if (rc.robot.floating) ++f.floating_checked, f.floating_largest = std::max(f.floating_largest, r.residual);
            if (joints == 0) continue;  // a robot without a moving joint: nothing to plot
            if (f.largest_by_joints.size() < joints) f.largest_by_joints.resize(joints, 0.0);
            double& by = f.largest_by_joints[joints - 1];
            by = std::max(by, r.residual);
          }
      // Every 25 robots, and at least every 2 s (a large robot's states take seconds each).
      const auto now = std::chrono::steady_clock::now();
      if (opt.progress && (c.robots % 25 == 0 || now - last_progress >= std::chrono::seconds(2))) {
        last_progress = now;
        opt.progress(name + ": " + std::to_string(c.robots) + " of " + std::to_string(opt.robots) + " " + c.unit);
      }
    }
    for (const auto& r : check.residuals)
      if (!r.within()) {
        failed = true;
        std::ostringstream s;
        s.precision(3);
        s << dynamics_quantity_name(r.quantity) << ": residual " << r.residual << " eps of its scale " << r.scale
          << " (budget " << r.budget << ")\n  q = " << vector_text(state_of(rc).q) << "\n  qdot = " << vector_text(state_of(rc).qdot)
          << "\n  qddot = " << vector_text(state_of(rc).qddot) << "\n  tau = " << vector_text(state_of(rc).tau)
          << "\n  " << name << ": " << vector_text(r.library) << "\n  reference: " << vector_text(r.reference)
          << "\n  seed " << opt.seed << ", "
          << (user ? std::to_string(opt.robots) + " states of robot " + user->name
                   : std::to_string(opt.robots) + " robots of at most " + std::to_string(opt.max_links) + " links")
          << " (mechcheck-audit -o dynamics-case "
          << (!user ? std::string() : "--urdf " + (opt.urdf_file.empty() ? std::string("<its URDF>") : shell_word(opt.urdf_file)) + " ") << "--robots " << opt.robots << " --seed "
          << opt.seed << " " << (selector.empty() ? "--dynamics " + name : selector) << " finds and shrinks it again)";
        c.disagreement = s.str();
        c.counterexample_urdf = to_urdf(rc.robot);
        RC_FAIL(c.disagreement);
      }
  };
  rc::detail::TestParams params;
  params.seed = opt.seed;
  params.maxSuccess = opt.robots;
  params.maxSize = 100;
  rc::detail::checkTestable(property, rc::detail::TestMetadata{}, params);
  return c;
}
}  // namespace

dynamics_campaign run_dynamics_checker(const std::string& name, const std::string& origin, const dynamics_checker& check,
                                       const dynamics_options& opt, const robots::robot* robot,
                                       const std::string& selector) {
  if (opt.robots < 1)
    throw domain_error("run_dynamics: " + std::string(robot ? "states" : "robots") + " must be >= 1, got " +
                       std::to_string(opt.robots));
  if (!robot) {
    if (opt.max_links < 1 || opt.max_links > 32)
      throw domain_error("run_dynamics: max_links must be in 1..32, got " + std::to_string(opt.max_links));
    const int links = opt.max_links;
    // Fixed and floating bases alike (a draw that shrinks towards the fixed one).
    const rc::Gen<generators::robot_case> cases = dynamics_robot_cases(links, opt.armature, opt.damping);
    return campaign(name, origin, check, opt, [cases] { return *cases; }, selector);
  }
  require_dynamics_size(*robot);
  const robots::tree t = robots::validate(*robot);
  dynamics_campaign c = campaign(name, origin, check, opt, [&] {
    generators::robot_case rc;
    rc.robot = *robot;
    for (std::size_t j = 0; j < robot->joints.size(); ++j) {
      if (t.coordinate[j] < 0) continue;
      rc.q.push_back(*generators::dyadic_towards_zero(3.14));
      rc.qdot.push_back(*generators::dyadic_towards_zero(4));
      rc.qddot.push_back(*generators::dyadic_towards_zero(4));
      rc.tau.push_back(*generators::dyadic_towards_zero(4));
    }
    if (!robot->floating) return rc;
    // The base's pose, twist, twist rate and wrench as floating_robot_cases draws them.
    generators::floating_robot_case f;
    f.joints = rc;
    f.base.xyz = Eigen::Vector3d(*generators::dyadic_towards_zero(1), *generators::dyadic_towards_zero(1),
                                 *generators::dyadic_towards_zero(1));
    f.base.rpy = Eigen::Vector3d(*generators::dyadic_towards_zero(3.14), *generators::dyadic_towards_zero(3.14),
                                 *generators::dyadic_towards_zero(3.14));
    for (auto* v : {&f.twist, &f.twist_rate, &f.wrench})
      for (int i = 0; i < 6; ++i) v->push_back(*generators::dyadic_towards_zero(4));
    return floated(f);
  }, selector, robot);
  c.max_links = t.dofs;
  c.readings = robot->readings;
  return c;
}

void require_dynamics_size(const robots::robot& robot) {
  const int n = robots::validate(robot).dofs;
  if (n > dynamics_max_joints)
    throw robot_too_large("robot " + robot.name + " has " + std::to_string(n) + " moving joints, more than the " +
                          std::to_string(dynamics_max_joints) +
                          " the dynamics audit takes: its mpfr50 reference solves M by Cholesky, n^3 / 3 operations "
                          "a state (docs/audit.md, \"Robots of any size\")");
}

rc::Gen<generators::robot_case> dynamics_robot_cases(int max_links, bool armature, bool damping) {
  return rc::gen::exec([max_links, armature, damping] {
    // The joints' terms drawn last: a library's robots are the same with them or without.
    if (!*rc::gen::element(false, true)) {
      generators::robot_case c = *generators::robot_cases(max_links);
      generators::draw_joint_terms(c.robot, armature, damping);
      return c;
    }
    generators::floating_robot_case f = *generators::floating_robot_cases(generators::robot_cases(max_links));
    generators::draw_joint_terms(f.joints.robot, armature, damping);
    return floated(f);
  });
}

namespace {
dynamics_checker checker_of(const dynamics_library& library) {
  return [&library](const robots::robot& r, const dynamics_state& x) { return check_dynamics(library, r, x); };
}
}  // namespace

dynamics_campaign run_dynamics_campaign(const dynamics_library& library, const dynamics_options& opt) {
  dynamics_options dressed = opt;
  dressed.armature = library.sets_armature;
  dressed.damping = library.sets_damping;
  return run_dynamics_checker(library.name, library.origin, checker_of(library), dressed, nullptr, library.selector);
}

dynamics_campaign run_dynamics_on(const dynamics_library& library, const robots::robot& robot, const dynamics_options& opt) {
  return run_dynamics_checker(library.name, library.origin, checker_of(library), opt, &robot, library.selector);
}

namespace {
std::string sci(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.2g", x);
  return buf;
}
}  // namespace

std::string dynamics_verdict(const dynamics_campaign& c, const dynamics_campaign::quantity_figure& f) {
  const std::string unit = " " + c.unit;
  if (!c.disagreement.empty() && c.disagreement.rfind(dynamics_quantity_name(f.quantity), 0) == 0) return "DISAGREES";
  if (f.checked > 0 && f.largest > f.budget) return "DISAGREES";
  if (!c.note.empty()) return "failed";
  if (f.checked == 0) {
    if (c.stopped()) return "not reached: the campaign stopped at its first disagreement";
    return c.robots > 0 && c.refused == c.robots ? "refused" : "not offered";
  }
  const std::string count = std::to_string(f.checked) + " of " + std::to_string(c.asked);
  if (c.stopped()) return "not cleared: within on " + count + unit + ", the campaign stopped at its first disagreement";
  if (f.checked < c.asked) return "within on " + count + unit + " (" + std::to_string(c.refused) + " refused)";
  return "within";
}

namespace {
std::string verdict_of(const dynamics_campaign& c, const dynamics_campaign::quantity_figure& f) {
  return dynamics_verdict(c, f);
}
}  // namespace

namespace {
/// The readings of the campaigns' robots, each once (every library runs the same files).
std::vector<std::string> readings_of(const std::vector<dynamics_campaign>& campaigns) {
  std::vector<std::string> all;
  for (const auto& c : campaigns)
    for (const auto& r : c.readings)
      if (std::find(all.begin(), all.end(), r) == all.end()) all.push_back(r);
  return all;
}
}  // namespace

namespace {
/// "on floating bases: 404 robots; largest residual 24 (mass matrix), ..." where any robot
/// of the campaign floated; "" otherwise.
std::string floating_line(const dynamics_campaign& c) {
  std::string out;
  for (const auto& f : c.figures) {
    if (f.floating_checked == 0) continue;
    out += (out.empty() ? "on floating bases: " : "; ") + std::to_string(f.floating_checked) + " robots, largest " +
           sci(f.floating_largest) + " (" + dynamics_quantity_name(f.quantity) + ")";
  }
  return out;
}
}  // namespace

void print_dynamics(std::ostream& out, const std::vector<dynamics_campaign>& campaigns) {
  char line[512];
  int width = 7;  // the library column: its longest name
  for (const auto& c : campaigns) width = std::max(width, static_cast<int>(c.library.size()));
  std::snprintf(line, sizeof line, "%-*s %-18s %7s %12s %8s  %s\n", width, "library", "quantity", "robots", "largest",
                "budget", "verdict");
  out << "\nequations of motion against the exact Lagrangian (residual in eps of the terms' scale)\n" << line;
  for (const auto& c : campaigns) {
    for (const auto& f : c.figures) {
      std::snprintf(line, sizeof line, "%-*s %-18s %7d %12s %8s  %s\n", width, c.library.c_str(),
                    dynamics_quantity_name(f.quantity), f.checked, f.checked ? sci(f.largest).c_str() : "-",
                    f.checked ? sci(f.budget).c_str() : "-", verdict_of(c, f).c_str());
      out << line;
    }
    if (c.model_checked) {
      std::snprintf(line, sizeof line, "%-*s %-18s %7d %12s %8s  %s\n", width, c.library.c_str(), "held robot",
                    c.model_checked, sci(c.model_largest).c_str(), "-", "(its M against the given robot's)");
      out << line;
    }
    if (const std::string f = floating_line(c); !f.empty()) out << "  " << c.library << " " << f << "\n";
    if (!c.joint_terms.empty()) out << "  " << c.library << "'s robots: each moving joint draws " << c.joint_terms << "\n";
    if (c.refused) {
      std::string first = c.first_refusal;  // a library's message may run over lines: one here
      std::replace(first.begin(), first.end(), '\n', ' ');
      out << "  " << c.library << " refused " << c.refused << " of " << c.robots << " robots (the first: " << first
          << ")\n";
    }
    if (!c.note.empty()) out << "  " << c.library << " failed: " << c.note << "\n";
    if (!c.disagreement.empty()) out << "  " << c.library << ", shrunk: " << c.disagreement << "\n";
  }
  for (const auto& r : readings_of(campaigns)) out << "  reading: " << r << "\n";
}

std::vector<std::string> write_dynamics_report(const std::string& directory, const std::vector<dynamics_campaign>& campaigns) {
  namespace fs = std::filesystem;
  fs::create_directories(directory);
  std::vector<std::string> written;
  nlohmann::ordered_json j = nlohmann::ordered_json::array();
  std::ostringstream md, after;
  md << "# Equations of motion against the exact Lagrangian\n\n"
     << "Residual: max |library - reference| / (eps scale), eps = 2^-52, the reference in mpfr50 rounded once "
        "(docs/audit.md, \"Equations of motion\").\n\n"
     << "| library | quantity | robots | largest residual | budget | verdict |\n|---|---|---:|---:|---:|---|\n";
  for (const auto& c : campaigns) {
    // "kdl on arm", "exec::sympy_lagrange": a file name of letters, digits, '-', '_' and '.'.
    std::string stem;
    for (const char ch : c.library) {
      const bool plain = std::isalnum(static_cast<unsigned char>(ch)) || ch == '_' || ch == '.' || ch == '-';
      if (plain) stem += ch;
      else if (stem.empty() || stem.back() != '-') stem += '-';
    }
    nlohmann::ordered_json e = {{"library", c.library}, {"origin", c.origin}, {"seed", c.seed}, {"robots", c.robots},
                                {"refused", c.refused}, {"max_links", c.max_links}};
    if (c.refused) e["first_refusal"] = c.first_refusal;
    if (!c.joint_terms.empty()) e["joint_terms"] = c.joint_terms;
    nlohmann::ordered_json fig = nlohmann::ordered_json::array();
    for (const auto& f : c.figures) {
      fig.push_back({{"quantity", dynamics_quantity_name(f.quantity)}, {"checked", f.checked}, {"largest", f.largest},
                     {"budget", f.budget}, {"largest_by_joints", f.largest_by_joints},
                     {"floating_checked", f.floating_checked}, {"floating_largest", f.floating_largest},
                     {"verdict", verdict_of(c, f)}});
      md << "| " << c.library << " | " << dynamics_quantity_name(f.quantity) << " | " << f.checked << " | "
         << (f.checked ? sci(f.largest) : "-") << " | " << (f.checked ? sci(f.budget) : "-") << " | " << verdict_of(c, f) << " |\n";
    }
    e["quantities"] = fig;
    if (c.model_checked) {
      const std::string file = (fs::path(directory) / (stem + "-held-robot-largest.urdf")).string();
      std::ofstream(file) << c.model_largest_urdf;
      written.push_back(file);
      e["held_robot"] = {{"checked", c.model_checked}, {"largest_difference", c.model_largest},
                         {"scale", c.model_largest_scale},
                         {"robot", fs::path(file).filename().string()}};
      md << "| " << c.library << " | held robot (its M against the given robot's) | " << c.model_checked << " | "
         << sci(c.model_largest) << " | - | measured |\n";
    }
    if (!c.readings.empty()) e["readings"] = c.readings;
    if (!c.note.empty()) e["failure"] = c.note;
    if (!c.disagreement.empty()) e["disagreement"] = c.disagreement;
    if (!c.counterexample_urdf.empty()) {
      const std::string file = (fs::path(directory) / (stem + "-counterexample.urdf")).string();
      std::ofstream(file) << c.counterexample_urdf;
      written.push_back(file);
      e["counterexample"] = fs::path(file).filename().string();
      after << "\n" << c.library << ", shrunk counterexample (" << fs::path(file).filename().string() << "):\n\n```\n"
            << (c.note.empty() ? c.disagreement : c.note) << "\n```\n";
    }
    j.push_back(e);
  }
  // The held robots and the counterexamples after the table, which they would break.
  for (const auto& c : campaigns)
    if (c.model_checked)
      md << "\n" << c.library << " computes with the robot as it holds it (the residuals are against that robot's "
         << "Lagrangian); its exact mass matrix differs from the given robot's by up to " << sci(c.model_largest)
         << " eps of the scale (the robot where it is largest: the file held_robot.robot of dynamics.json).\n";
  for (const auto& c : campaigns)
    if (const std::string f = floating_line(c); !f.empty()) md << "\n" << c.library << " " << f << ".\n";
  // The joints' terms: each library's random robots carry those its adapter sets (a robot
  // with one it does not set would be refused); the same robots otherwise.
  std::string terms;
  for (const auto& c : campaigns)
    if (!c.joint_terms.empty()) terms += (terms.empty() ? "" : "; ") + c.library + "'s " + c.joint_terms;
  if (!terms.empty())
    md << "\nThe random robots' moving joints draw the terms each library's adapter sets (an armature in [0, 1/4], a "
          "damping in [0, 2], each zero a third of the time, drawn after the rest of the robot): "
       << terms << "; the others' none.\n";
  for (const auto& r : readings_of(campaigns)) md << "\nReading: " << r << ".\n";
  md << after.str();
  // Per quantity, each library's largest residual against the robots' moving joints, and
  // the budget 16 n.
  for (const auto q : all_dynamics_quantities) {
    std::vector<plot_series> series;
    std::size_t most = 0;
    for (const auto& c : campaigns)
      for (const auto& f : c.figures) {
        if (f.quantity != q || f.checked == 0) continue;
        plot_series s{c.library, {}};
        for (std::size_t n = 1; n <= f.largest_by_joints.size(); ++n)
          s.points.emplace_back(static_cast<double>(n), f.largest_by_joints[n - 1]);
        most = std::max(most, f.largest_by_joints.size());
        series.push_back(std::move(s));
      }
    if (series.empty()) continue;
    plot_series budget{"budget 16 n (16 (n + 1) on a floating base)", {}};
    for (std::size_t n = 1; n <= most; ++n) budget.points.emplace_back(static_cast<double>(n), 16.0 * static_cast<double>(n));
    series.push_back(std::move(budget));
    std::string name = dynamics_quantity_name(q);
    std::replace(name.begin(), name.end(), ' ', '-');
    const std::string file = (fs::path(directory) / ("dynamics-" + name + ".svg")).string();
    std::ofstream(file) << svg_loglog(std::string("Largest residual of the ") + dynamics_quantity_name(q) +
                                          " against the robots' moving joints",
                                      "moving joints n", "largest residual (eps of its scale)", series);
    written.push_back(file);
    md << "\n![" << dynamics_quantity_name(q) << "](" << fs::path(file).filename().string() << ")\n";
  }
  const std::string json_file = (fs::path(directory) / "dynamics.json").string();
  std::ofstream(json_file) << j.dump(2) << "\n";
  const std::string md_file = (fs::path(directory) / "dynamics.md").string();
  std::ofstream(md_file) << md.str();
  written.push_back(json_file);
  written.push_back(md_file);
  return written;
}

}  // namespace mechcheck::audit
