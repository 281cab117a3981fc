// mechcheck-audit: audits one-step integrators (the library's, Boost.Odeint's, third-party
// libraries', tableau files', a child process's), adaptive drivers and physics engines
// against what they declare, and dynamics libraries' equations of motion against the exact
// Lagrangian; prints a table and writes JSON, Markdown and SVG plots into the directory -o
// names.
//
// Exit status: 0 when everything asked for was audited; 1 when an input was refused (a bad
// option, a tableau file that cannot be read, a child that cannot be started: the others are
// still audited and written); 2 when a claim --require names is contradicted; 3 when a child
// failed during the audit (its runs are failed runs of the report). The largest applies.

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <string>
#include <vector>

#include <unistd.h>

#include <CLI/CLI.hpp>
#include <rapidcheck/detail/Configuration.h>

#include "families.hpp"
#include "mechcheck/audit/adapters/exec.hpp"
#include "mechcheck/audit/adapters/found.hpp"
#include "mechcheck/audit/problems/classic.hpp"
#include "mechcheck/audit/problems/urdf.hpp"
#include "mechcheck/audit/report.hpp"
#include "mechcheck/audit/tableaus/tableau_file.hpp"
#include "patterns.hpp"
#include "run_family.hpp"

namespace {
using namespace mechcheck;
using clock_type = std::chrono::steady_clock;

/// The problems with exact solutions (the default), the classic ones with certified
/// references (problems/classic.hpp; by name only), and henon_heiles for both its orbits.
std::vector<std::string> known_problems() {
  std::vector<std::string> names = {"oscillator", "kepler_e0.5", "kepler_e0.9", "pendulum", "free_top", "twist"};
  for (const auto& n : audit::classic_problem_names()) names.push_back(n);
  names.push_back("henon_heiles");
  return names;
}

/// henon_heiles names both its orbits.
std::vector<std::string> expanded(const std::vector<std::string>& names) {
  std::vector<std::string> out;
  for (const auto& n : names)
    if (n == "henon_heiles") {
      out.push_back("henon_heiles_regular");
      out.push_back("henon_heiles_chaotic");
    } else {
      out.push_back(n);
    }
  return out;
}

/// Where the classical tableaus are: the installed share/mechcheck/tableaus next to this
/// program's bin/, else the source tree's tableaus/ (a build tree's program).
std::string tableau_directory() {
  std::error_code ec;
  const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", ec);
  if (!ec) {
    const auto installed = self.parent_path().parent_path() / "share" / "mechcheck" / "tableaus";
    if (std::filesystem::is_directory(installed, ec)) return installed.lexically_normal().string();
  }
#ifdef MECHCHECK_SOURCE_TABLEAUS
  if (std::filesystem::is_directory(MECHCHECK_SOURCE_TABLEAUS, ec)) return MECHCHECK_SOURCE_TABLEAUS;
#endif
  return "share/mechcheck/tableaus under the installation prefix";
}

/// The stepper families of a tier, as the request asks (list_only: their names alone).
std::vector<audit_tool::family_result> families_in(const std::string& tier, const audit_tool::request& r) {
  std::vector<audit_tool::family_result> families;
  if (tier == "double") {
    families = {audit_tool::tableau_double(r), audit_tool::exec_double(r), audit_tool::builtin_double(r),
                audit_tool::odeint_double(r)};
#ifdef MECHCHECK_HAVE_GSL
    families.push_back(audit_tool::gsl_double(r));
#endif
#ifdef MECHCHECK_HAVE_ARKODE
    families.push_back(audit_tool::arkode_double(r));
#endif
  } else {
    families = {audit_tool::tableau_mpfr50(r), audit_tool::builtin_mpfr50(r), audit_tool::odeint_mpfr50(r)};
#ifdef MECHCHECK_HAVE_ARKODE
    families.push_back(audit_tool::arkode_mpfr50(r));
#endif
  }
  return families;
}

/// The families ("mechcheck::", "odeint::", ...) of a list of names, for messages.
std::string families_of(const std::vector<std::string>& names) {
  std::vector<std::string> families;
  for (const auto& n : names) {
    const auto at = n.find("::");
    const std::string f = at == std::string::npos ? n : n.substr(0, at + 2) + "*";
    if (std::find(families.begin(), families.end(), f) == families.end()) families.push_back(f);
  }
  std::string out;
  for (const auto& f : families) out += (out.empty() ? "" : ", ") + f;
  return out;
}

/// Every pattern names something: a pattern that matches no name is a misspelling, refused
/// with the names there are.
bool every_pattern_matches(const char* option, const char* what, const std::vector<std::string>& patterns,
                           const std::vector<std::string>& names) {
  bool ok = true;
  for (const auto& p : patterns)
    if (std::none_of(names.begin(), names.end(), [&](const std::string& n) { return audit_tool::matches({p}, n); })) {
      std::cerr << "mechcheck-audit: " << option << " '" << p << "' matches no " << what << "; this build has "
                << names.size() << " of them, named " << families_of(names) << " (--list names each)\n";
      ok = false;
    }
  return ok;
}
}  // namespace

namespace {
/// RapidCheck loads its configuration at the first check: from RC_PARAMS (a malformed one
/// exits the process; a "reproduce" one would replay its own case in every campaign), and
/// it prints "Using configuration: seed=<random>" that no campaign uses. The command's
/// campaigns take their seeds from --seed alone: loaded here, from nothing, silently.
void load_rapidcheck_quietly() {
  struct null_buffer : std::streambuf {
    int overflow(int c) override { return c; }
  } none;
  ::unsetenv("RC_PARAMS");
  std::streambuf* const saved = std::cerr.rdbuf(&none);
  rc::detail::configuration();
  std::cerr.rdbuf(saved);
}
}  // namespace

int main(int argc, char** argv) {
  load_rapidcheck_quietly();
  // Everything after "--" is a child's command (--exec-*), passed as given.
  std::vector<std::string> child_command;
  for (int i = 1; i < argc; ++i)
    if (std::string(argv[i]) == "--") {
      for (int j = i + 1; j < argc; ++j) child_command.emplace_back(argv[j]);
      argc = i;
      break;
    }
  CLI::App app{"mechcheck-audit: order, symplecticity, time symmetry, long-time energy "
               "behaviour, first integrals and cost of one-step integrators, adaptive drivers and "
               "physics engines, against what they declare"};
  // The claims a tableau file may declare, by their verdicts' names: the same table the
  // analysis judges them from.
  std::string tableau_claim_names;
  for (const auto& [field, claim] : audit::tableau_claims)
    tableau_claim_names += (tableau_claim_names.empty() ? "" : ", ") + std::string(claim) + " (" + std::string(field) + ")";
  app.footer("Exit status: 0 all audited; 1 an input refused (the others are still audited and written); "
             "2 a claim --require names is contradicted (a stepper's or engine integrator's measured claim, or "
             "a tableau file's algebraic one: " + tableau_claim_names + "; a declared \"no\" states that the "
             "property is absent, and is contradicted where it holds), or a "
             "dynamics library's quantity disagrees with the Lagrangian or the library checked nothing; "
             "2 also when a target --require-measured names measured nothing of a problem or scenario it was "
             "audited on (refused, skipped, or every run failed); "
             "3 a child failed during the audit.\n"
             "The classical tableaus (--tableau): " + tableau_directory());
  std::vector<std::string> steppers, problems, tiers = {"double", "mpfr50"};
  std::vector<std::string> long_run_problems = {"kepler_e0.5"};
  long long long_run_steps = 100000, long_run_steps_mpfr50 = 10000;
  std::string output;
  std::vector<std::string> require, require_measured;
  bool timing = false, list = false, quiet = false;
  app.add_option("-s,--stepper", steppers,
                 "steppers to audit, as shell patterns on their names "
                 "(e.g. 'mechcheck::*', 'odeint::runge_kutta4'); default all");
  app.add_option("-p,--problem", problems,
                 "problems; default the six with exact solutions. The classic ones without (pleiades, "
                 "arenstorf, outer_solar_system, henon_heiles_regular, henon_heiles_chaotic or henon_heiles for "
                 "both, double_pendulum) by name: their references are certified in mpfr50 and cached "
                 "(MECHCHECK_CACHE_DIR, else ~/.cache/mechcheck)")
      ->check(CLI::IsMember(known_problems()));
  app.add_option("-t,--tier", tiers, "tiers: double, mpfr50")
      ->check(CLI::IsMember({"double", "mpfr50"}));
  app.add_option("--long-run-problem", long_run_problems, "problems of the long run")
      ->check(CLI::IsMember(known_problems()));
  app.add_option("--long-run-steps", long_run_steps, "steps of the long run in double (0: none)")
      ->check(CLI::Range(0LL, 100000000LL));
  app.add_option("--long-run-steps-mpfr50", long_run_steps_mpfr50,
                 "steps of the long run in mpfr50 (0: none); its rounding is 1e-50, so the "
                 "run shows truncation behaviour only, and an implicit step costs ~1 ms")
      ->check(CLI::Range(0LL, 100000000LL));
  app.add_option("-o,--output", output,
                 "the directory the report goes to (created): audit.json and audit.md for steppers, "
                 "drivers.*, tableaus.*, engines.*, and the SVG plots; required unless --list");
  app.add_flag("--timing", timing, "put wall times into the files (not reproducible; off by default)");
  app.add_flag("--list", list,
               "list what this build can audit -- steppers (with their tiers), adaptive drivers, engine "
               "integrators, engine scenarios, problems -- filtered by the patterns given, and exit");
  app.add_option("--require", require,
                 "exit with status 2 when a claim of a stepper or engine integrator matching this pattern is "
                 "contradicted, a tableau file's algebraic claims included (tableau::<name>: " + tableau_claim_names +
                     "; e.g. 'mechcheck::*'; '*' for all), or when a dynamics library matching it disagrees with the "
                     "Lagrangian or checks nothing (every robot refused)");
  app.add_option("--require-measured", require_measured,
                 "exit with status 2 when a stepper, adaptive driver or engine integrator matching this pattern "
                 "measured nothing of a problem or scenario it was audited on (it refused or skipped it, or every "
                 "run failed): a gate that cannot pass on a target that measured nothing (name the problems or "
                 "scenarios it must measure with -p or --scenario)");
  app.add_flag("-q,--quiet", quiet, "no progress on stderr");
  double newton_tolerance = 0;
  app.add_option("--newton-tolerance", newton_tolerance,
                 "Newton tolerance of third-party implicit steppers (GSL's driver control, "
                 "ARKODE's SStolerances); default each adapter's own (1e-14)")
      ->check(CLI::PositiveNumber);
  std::vector<std::string> tableau_files;
  app.add_option("--tableau", tableau_files,
                 "a Butcher tableau in JSON (docs/tableau-format.md; the classical ones are in " + tableau_directory() +
                     "): its order conditions up to order " + std::to_string(audit::default_tableau_orders) +
                     " (or one past its declared orders) in mpfr100 at the precision its coefficients are "
                     "given to, then its stepper audited as tableau::<name>; with no --stepper only the tableaus "
                     "are audited. A file that cannot be read is a row of the report; the others go on");
  std::vector<std::string> driver_patterns;
  app.add_option("--driver", driver_patterns,
                 "adaptive drivers to audit against their tolerances (1e-3 .. 1e-12), as shell "
                 "patterns (e.g. 'gsl::*', '*'; --list names them); with no --stepper and no "
                 "--tableau only the drivers are audited");
  std::vector<std::string> engine_patterns;
  app.add_option("--engine", engine_patterns,
                 "physics-engine integrators to audit on the scenarios with exact references, "
                 "as shell patterns (e.g. 'mujoco::*'); with no --stepper, --tableau or --driver "
                 "only the engines are audited");
  std::vector<std::string> dynamics_patterns, urdf_files;
  int dynamics_robots = 100;
  std::uint64_t dynamics_seed = 1;
  app.add_option("--dynamics", dynamics_patterns,
                 "dynamics libraries whose equations of motion (mass matrix, bias forces, inverse and forward "
                 "dynamics) are held to the exact Lagrangian on random robots, as shell patterns (e.g. 'kdl', '*'); "
                 "alone, only they are audited");
  app.add_option("--urdf", urdf_files, "with --dynamics: a robot of your own (URDF), at --robots random states")
      ->check(CLI::ExistingFile);
  app.add_option("--robots", dynamics_robots, "with --dynamics: random robots (or states of --urdf robots; default 100)")
      ->check(CLI::Range(1, 1000000));
  app.add_option("--seed", dynamics_seed, "the seed of the random robots, bodies and contact cases (--dynamics, --engine-robots, --engine-floating-robots, --engine-bodies, --contact-cases; default 1)");
  std::vector<std::string> engine_scenarios, scenario_names;
  for (const auto& s : audit::scenarios()) scenario_names.push_back(s.name);
  for (const auto& s : audit::contact_scenarios()) scenario_names.push_back(s.name);
  int engine_robots = 0, engine_robot_links = 3;
  app.add_option("--engine-robots", engine_robots,
                 "with --engine: N random robots (chains and trees, revolute, prismatic and fixed joints, skew "
                 "axes, rotated inertias; --seed) as scenarios beside the hand-built ones, named robot_<seed>_<k>; "
                 "each one's URDF is written to the report's robots/ folder")
      ->check(CLI::Range(0, 1000));
  app.add_option("--engine-robot-links", engine_robot_links,
                 "with --engine-robots: at most this many links a robot (1 to 8, default 3; the reference's cost "
                 "grows with the square of the moving joints)")
      ->check(CLI::Range(1, 8));
  int engine_floating_robots = 0;
  app.add_option("--engine-floating-robots", engine_floating_robots,
                 "with --engine: N random robots on a floating base (at most --engine-robot-links links, --seed) as "
                 "scenarios named floating_<seed>_<k>, held to their centre of mass and momenta (Newton and Euler for "
                 "the whole robot); each one's URDF is written to the report's robots/ folder")
      ->check(CLI::Range(0, 1000));
  int engine_bodies = 0;
  app.add_option("--engine-bodies", engine_bodies,
                 "with --engine: N random free bodies (principal axes turned anywhere, spun about none of them; "
                 "--seed) as scenarios beside the hand-built ones, named body_<seed>_<k>")
      ->check(CLI::Range(0, 1000));
  int contact_cases = 0;
  app.add_option("--contact-cases", contact_cases,
                 "with a contact scenario named: N random sliding and resting boxes per engine (direction, yaw, mu, "
                 "mass, size, speed, slope; --seed) held to isotropy, independence of mass and size and no creep, the "
                 "first one broken shrunk and written to the report as the engine's file (MJCF) or JSON")
      ->check(CLI::Range(0, 100000));
  app.add_option("--scenario", engine_scenarios,
                 "engine scenarios, as shell patterns (default all; 'robot_*' the --engine-robots alone, "
                 "'floating_*' the --engine-floating-robots, 'body_*' the --engine-bodies)");
  long long engine_long_run_steps = 100000;
  app.add_option("--engine-long-run-steps", engine_long_run_steps, "steps of the engines' long run (0: none)")
      ->check(CLI::Range(0LL, 100000000LL));
  bool exec_stepper = false, exec_driver = false, exec_engine = false, exec_dynamics = false;
  double exec_timeout = 30;
  app.add_flag("--exec-driver", exec_driver,
               "audit the adaptive driver a child program serves (docs/protocol.md): the command follows \"--\"");
  app.add_flag("--exec-stepper", exec_stepper,
               "audit the stepper a child program serves (docs/protocol.md): the command follows \"--\", "
               "run from its argument vector (no shell); in double");
  app.add_flag("--exec-engine", exec_engine,
               "audit the physics engine's integrators a child program serves (docs/protocol.md) on the "
               "scenarios: the command follows \"--\"");
  app.add_flag("--exec-dynamics", exec_dynamics,
               "audit the equations of motion a child program computes (docs/protocol.md) on random robots "
               "(--robots, --seed) or --urdf robots: the command follows \"--\"");
  app.add_option("--exec-timeout", exec_timeout, "seconds a child may take to reply (default 30)")
      ->check(CLI::Range(1e-3, 1e6));
  CLI11_PARSE(app, argc, argv);
  try {
    for (const auto& [option, patterns] : {std::pair{"--stepper", &steppers}, std::pair{"--driver", &driver_patterns},
                                           std::pair{"--engine", &engine_patterns}, std::pair{"--dynamics", &dynamics_patterns},
                                           std::pair{"--scenario", &engine_scenarios},
                                           std::pair{"--require", &require},
                                           std::pair{"--require-measured", &require_measured}})
      for (const auto& p : *patterns) audit_tool::check_pattern(option, p);
  } catch (const error& e) {
    std::cerr << "mechcheck-audit: " << e.what() << "\n";
    return 1;
  }
  if (int(exec_stepper) + int(exec_driver) + int(exec_engine) + int(exec_dynamics) > 1) {
    std::cerr << "mechcheck-audit: --exec-stepper, --exec-driver, --exec-engine and --exec-dynamics: one child a command\n";
    return 1;
  }
  if ((exec_stepper || exec_driver || exec_engine || exec_dynamics) != !child_command.empty()) {
    std::cerr << "mechcheck-audit: "
              << (child_command.empty()
                      ? "--exec-stepper, --exec-driver, --exec-engine and --exec-dynamics need the child's command after \"--\""
                      : "a command after \"--\" needs --exec-stepper, --exec-driver, --exec-engine or --exec-dynamics")
              << "\n";
    return 1;
  }
  if (!list && output.empty()) {
    std::cerr << "mechcheck-audit: say where the report goes: -o DIR (it is created; the JSON, Markdown and SVG "
                 "files are written there)\n";
    return 1;
  }
  problems = expanded(problems);
  long_run_problems = expanded(long_run_problems);

  const auto start = clock_type::now();
  const auto elapsed = [&] { return std::chrono::duration<double>(clock_type::now() - start).count(); };
  const auto progress = [&](const std::string& what) { std::fprintf(stderr, "[%7.1f s] %s\n", elapsed(), what.c_str()); };
  int status = 0;  // the largest of 1 (an input refused), 2 (a required claim contradicted), 3 (a child failed)
  const auto raise = [&status](int s) { status = std::max(status, s); };
  // --require-measured: a target it names that measured nothing of what it was audited on.
  const auto require_measured_of = [&](const std::string& name, const std::vector<std::string>& missing) {
    if (missing.empty() || !audit_tool::matches_any(require_measured, name)) return;
    std::cerr << "mechcheck-audit: " << name << ": not measured:";
    for (std::size_t k = 0; k < missing.size(); ++k) std::cerr << (k ? "; " : " ") << missing[k];
    std::cerr << "\n";
    raise(2);
  };
  // Writes a report by `write` and names its files; false (with the reason) on failure.
  const auto report_files = [&](const auto& write) {
    try {
      const std::vector<std::string> written = write();
      std::cout << "\nwrote";
      for (const auto& w : written) std::cout << " " << w;
      std::cout << "\n";
      return true;
    } catch (const std::exception& e) {
      std::cerr << "mechcheck-audit: " << e.what() << "\n";
      return false;
    }
  };

  // The inputs: tableau files (a file that cannot be read is a row of the report), a child.
  audit_tool::request request;
  request.patterns = steppers;
  std::vector<audit::tableau_analysis> analyses;
  for (const auto& file : tableau_files) {
    try {
      request.tableaus.push_back(audit::read_tableau(file));
      analyses.push_back(audit::analyse(request.tableaus.back()));
    } catch (const error& e) {
      std::cerr << "mechcheck-audit: " << e.what() << "\n";
      analyses.push_back(audit::failed_tableau(file, e.what()));
      raise(1);
    }
    if (!list) std::cout << audit::describe(analyses.back()) << "\n";
  }
  if (!tableau_files.empty()) request.patterns.push_back("tableau::*");  // alone: only them
  std::vector<audit::exec_target> exec_targets;
  std::vector<audit::exec_driver_target> exec_drivers;
  std::vector<audit::exec_engine_target> exec_engines;
  std::vector<audit::exec_dynamics_target> exec_libraries;
  audit::exec_options eo;
  eo.timeout = exec_timeout;
  bool child_refused = false;
  if (!child_command.empty()) {
    try {
      if (exec_driver) exec_drivers.push_back(audit::exec_driver(child_command, eo));
      if (exec_stepper) exec_targets.push_back(audit::exec_stepper(child_command, eo));
      if (exec_engine) exec_engines.push_back(audit::exec_engine(child_command, eo));
      if (exec_dynamics) exec_libraries.push_back(audit::exec_dynamics(child_command, eo));
    } catch (const error& e) {
      std::cerr << "mechcheck-audit: " << e.what() << "\n";
      child_refused = true;
      raise(1);
    }
    // Alone, only the child's.
    if (exec_driver) driver_patterns.push_back("exec::*");
    if (exec_stepper) request.patterns.push_back("exec::*");
    if (exec_engine && engine_patterns.empty()) engine_patterns.push_back("exec::*");
    if (exec_dynamics && dynamics_patterns.empty()) dynamics_patterns.push_back("exec::*");
    if (exec_stepper && std::find(tiers.begin(), tiers.end(), "double") == tiers.end()) {
      std::cerr << "mechcheck-audit: --exec-stepper runs in double; -t mpfr50 alone has nothing to run\n";
      return 1;
    }
  }
  for (const auto& t : exec_targets) request.exec_steppers.push_back(t.box);

  // What this build can audit.
  std::vector<audit::engine_integrator> all_engines = audit::engines_found();
  for (const auto& t : exec_engines) all_engines.insert(all_engines.end(), t.integrators.begin(), t.integrators.end());
  std::vector<audit::adaptive_driver> all_drivers = audit::drivers_found();
  for (const auto& t : exec_drivers) all_drivers.push_back(t.driver);
  const auto names_of = [](const auto& items) {
    std::vector<std::string> out;
    for (const auto& i : items) out.push_back(i.name);
    return out;
  };
  request.newton_tolerance = newton_tolerance;
  // The steppers' names in each tier (the families list them without auditing).
  const auto stepper_names = [&](const std::vector<std::string>& patterns) {
    audit_tool::request r = request;
    r.patterns = patterns;
    r.list_only = true;
    std::map<std::string, std::vector<std::string>> tiers_of;  // name -> tiers
    std::vector<std::string> order;
    for (const auto& tier : tiers) {
      for (const auto& f : families_in(tier, r))
        for (const auto& n : f.names) {
          if (!tiers_of.count(n)) order.push_back(n);
          tiers_of[n].push_back(tier);
        }
    }
    std::vector<std::pair<std::string, std::vector<std::string>>> out;
    for (const auto& n : order) out.emplace_back(n, tiers_of[n]);
    return out;
  };

  if (list) {
    // Every kind, each filtered by its own patterns (none: all of it).
    const auto steppers_listed = stepper_names(request.patterns);
    std::cout << "steppers (" << steppers_listed.size() << "; -s, --tableau, --exec-stepper):\n";
    for (const auto& [n, ts] : steppers_listed) {
      std::string t;
      for (const auto& x : ts) t += (t.empty() ? "" : ", ") + x;
      std::cout << "  " << n << " [" << t << "]\n";
    }
    std::vector<std::string> d = names_of(all_drivers), e = names_of(all_engines);
    std::erase_if(d, [&](const std::string& n) { return !audit_tool::matches(driver_patterns, n); });
    std::erase_if(e, [&](const std::string& n) { return !audit_tool::matches(engine_patterns, n); });
    std::cout << "adaptive drivers (" << d.size() << "; --driver, --exec-driver; double):\n";
    for (const auto& n : d) std::cout << "  " << n << "\n";
    std::cout << "engine integrators (" << e.size() << "; --engine, --exec-engine; double):\n";
    for (const auto& n : e) std::cout << "  " << n << "\n";
    std::cout << "engine scenarios (" << scenario_names.size() << "; --scenario):\n";
    for (const auto& n : scenario_names) std::cout << "  " << n << "\n";
    const auto p = known_problems();
    std::cout << "problems (" << p.size() - 1 << "; -p, --long-run-problem):\n";
    for (const auto& n : p)
      std::cout << "  " << n << (n == "henon_heiles" ? " (both orbits: henon_heiles_regular and _chaotic)" : "") << "\n";
    const auto dl = audit::dynamics_found();
    std::cout << "dynamics libraries (" << dl.size() << "; --dynamics, --urdf):\n";
    for (const auto& l : dl) std::cout << "  " << l.name << ": " << l.origin << "\n";
    return status;
  }

  // Every pattern names something (a misspelt name is an error listing what there is).
  {
    std::vector<std::string> all_steppers;
    for (const auto& [n, ts] : stepper_names({})) all_steppers.push_back(n);
    bool ok = every_pattern_matches("--stepper", "stepper", steppers, all_steppers);
    if (!child_refused) {
      ok = every_pattern_matches("--driver", "adaptive driver", driver_patterns, names_of(all_drivers)) && ok;
      ok = every_pattern_matches("--engine", "engine integrator", engine_patterns, names_of(all_engines)) && ok;
    }
    std::vector<std::string> everything = all_steppers;
    for (const auto& n : names_of(all_engines)) everything.push_back(n);
    std::vector<std::string> required = everything;  // --require: the dynamics libraries too
    for (const auto& n : names_of(audit::dynamics_found())) required.push_back(n);
    for (const auto& t : exec_libraries) required.push_back(t.library.name);
    if (!child_refused)
      ok = every_pattern_matches("--require", "stepper, engine integrator or dynamics library", require, required) && ok;
    for (const auto& n : names_of(all_drivers)) everything.push_back(n);
    if (!child_refused)
      ok = every_pattern_matches("--require-measured", "stepper, adaptive driver or engine integrator", require_measured,
                                 everything) && ok;
    if (!ok) return 1;
  }
  if (child_refused && steppers.empty() && tableau_files.empty() &&
      std::all_of(driver_patterns.begin(), driver_patterns.end(), [](const std::string& p) { return p == "exec::*"; }) &&
      std::all_of(engine_patterns.begin(), engine_patterns.end(), [](const std::string& p) { return p == "exec::*"; }) &&
      std::all_of(dynamics_patterns.begin(), dynamics_patterns.end(), [](const std::string& p) { return p == "exec::*"; }))
    return status;  // the child was all there was to audit

  // The equations of motion.
  if (!dynamics_patterns.empty()) {
    std::vector<audit::dynamics_library> libraries = audit::dynamics_found();
    for (const auto& t : exec_libraries) libraries.push_back(t.library);
    std::erase_if(libraries, [&](const audit::dynamics_library& l) { return !audit_tool::matches(dynamics_patterns, l.name); });
    if (libraries.empty()) {
      std::cerr << "mechcheck-audit: --dynamics matches no dynamics library of this build\n";
      return 1;
    }
    std::vector<robots::robot> own;
    try {
      for (const auto& f : urdf_files) {
        own.push_back(audit::read_urdf(f));
        audit::require_dynamics_size(own.back());
      }
    } catch (const error& e) {
      std::cerr << "mechcheck-audit: " << e.what() << "\n";
      return 1;
    }
    audit::dynamics_options dopt;
    dopt.robots = dynamics_robots;
    dopt.seed = dynamics_seed;
    if (!quiet) dopt.progress = progress;
    std::vector<audit::dynamics_campaign> campaigns;
    for (const auto& l : libraries) {
      if (own.empty()) campaigns.push_back(audit::run_dynamics_campaign(l, dopt));
      for (std::size_t k = 0; k < own.size(); ++k) {
        const robots::robot& r = own[k];
        dopt.urdf_file = urdf_files[k];
        campaigns.push_back(audit::run_dynamics_on(l, r, dopt));
        campaigns.back().library = l.name + " on " + r.name;
      }
    }
    audit::print_dynamics(std::cout, campaigns);
    if (!report_files([&] { return audit::write_dynamics_report(output, campaigns); })) return 1;
    for (const auto& c : campaigns)
      if (!c.agrees() && audit_tool::matches_any(require, c.library)) {
        std::cerr << "mechcheck-audit: " << c.library << ": a quantity disagrees with the Lagrangian (see the table)\n";
        raise(2);
      }
    // A gate that cannot pass on nothing: a required library that checked no quantity.
    for (const auto& c : campaigns)
      if (c.agrees() && !c.checked_any() && audit_tool::matches_any(require, c.library)) {
        std::cerr << "mechcheck-audit: " << c.library << ": checked nothing ("
                  << (c.refused ? "it refused " + std::to_string(c.refused) + " of " + std::to_string(c.robots) +
                                      " " + c.unit + "; the first: " + c.first_refusal
                                : std::string("it offers none of the quantities"))
                  << ")\n";
        raise(2);
      }
    for (const auto& t : exec_libraries)
      if (t.failures() > 0) {
        std::cerr << "mechcheck-audit: " << t.library.name << ": " << t.failures() << " children failed; the last: "
                  << t.last_failure() << "\n";
        raise(3);
      }
    if (steppers.empty() && tableau_files.empty() && driver_patterns.empty() && engine_patterns.empty() &&
        exec_targets.empty())
      return status;
  }

  // The engines.
  if (!engine_patterns.empty()) {
    std::vector<audit::engine_integrator> engines = all_engines;
    std::erase_if(engines, [&](const audit::engine_integrator& e) { return !audit_tool::matches(engine_patterns, e.name); });
    std::vector<audit::engine_audit> engine_audits;
    // The random robots drawn once: every integrator shares their certified references.
    std::vector<audit::scenario> robots = audit::random_robot_scenarios(engine_robots, dynamics_seed, engine_robot_links);
    for (auto& r : audit::random_floating_robot_scenarios(engine_floating_robots, dynamics_seed, engine_robot_links))
      robots.push_back(std::move(r));
    std::vector<audit::scenario> drawn = robots;
    for (auto& b : audit::random_body_scenarios(engine_bodies, dynamics_seed)) drawn.push_back(std::move(b));
    // The scenarios' patterns as names: each must name one at least.
    std::vector<std::string> scenarios_named;
    for (const auto& pattern : engine_scenarios) {
      std::vector<std::string> all = scenario_names;
      for (const auto& r : drawn) all.push_back(r.name);
      std::string known;
      bool any = false;
      for (const auto& n : all) {
        known += " " + n;
        if (audit_tool::matches({pattern}, n)) any = true, scenarios_named.push_back(n);
      }
      if (!any) {
        std::cerr << "mechcheck-audit: --scenario " << pattern << " names no scenario (known:" << known << ")\n";
        return 1;
      }
    }
    // The contact scenarios (contact.hpp) are their own audit: named (--scenario 'contact_*'),
    // never part of the default set.
    std::vector<std::string> contact_named;
    for (const auto& n : scenarios_named)
      if (n.rfind("contact_", 0) == 0) contact_named.push_back(n);
    std::erase_if(scenarios_named, [](const std::string& n) { return n.rfind("contact_", 0) == 0; });
    std::vector<audit::contact_audit> contact_audits;
    if (!contact_named.empty()) {
      // The integrators whose adapters build no contact scenario are named once, not
      // refused scenario by scenario (unless one alone was asked for).
      std::string without;
      for (const auto& e : engines)
        if (!e.contact && engines.size() > 1) without += (without.empty() ? "" : ", ") + e.name;
      if (!without.empty()) std::cout << "no contact scenario in the adapters of: " << without << "\n";
      for (const auto& e : engines) {
        if (!e.contact && engines.size() > 1) continue;
        audit::contact_options copt;
        copt.scenarios = contact_named;
        copt.cases = contact_cases;
        copt.seed = dynamics_seed;
        if (!quiet) copt.progress = progress;
        contact_audits.push_back(audit::audit_contact(e, copt));
      }
      audit::print_contact(std::cout, contact_audits);
      if (!report_files([&] { return audit::write_contact_report(output, contact_audits); })) return 1;
      for (const auto& a : contact_audits)
        if (!a.claims_hold() && audit_tool::matches_any(require, a.integrator)) {
          std::cerr << "mechcheck-audit: " << a.integrator << ": a declared contact claim is contradicted (see the table)\n";
          raise(2);
        }
      if (scenarios_named.empty()) {
        std::cout << "audited the contact of " << contact_audits.size() << " engine integrators in "
                  << static_cast<long>(elapsed() + 0.5) << " s\n";
        for (const auto& t : exec_engines)
          if (t.failures() > 0) {
            std::cerr << "mechcheck-audit: " << audit::command_text(child_command) << ": " << t.failures()
                      << " children failed; the last: " << t.last_failure() << "\n";
            raise(3);
          }
        if (steppers.empty() && tableau_files.empty() && driver_patterns.empty() && exec_targets.empty()) return status;
      }
    }
    // The other scenarios, unless contact scenarios alone were named.
    if (contact_named.empty() || !scenarios_named.empty()) {
      for (const auto& e : engines) {
        if (e.contact_only) continue;  // a contact setting: nothing to study without contact
        audit::engine_options eopt;
        eopt.scenarios = scenarios_named;
        eopt.drawn = drawn;
        eopt.long_run_steps = engine_long_run_steps;
        eopt.timing = timing;
        if (!quiet) eopt.progress = progress;
        engine_audits.push_back(audit::audit_engine(e, eopt));
      }
      // The inertia of the shapes of every engine one of whose integrators was asked for.
      std::vector<audit::shape_audit> shape_audits;
      std::vector<audit::engine_shapes> shape_engines = audit::shapes_found();
      for (const auto& t : exec_engines)
        if (t.shapes) shape_engines.push_back(*t.shapes);
      for (const auto& engine : shape_engines)
        if (std::any_of(engines.begin(), engines.end(),
                        [&](const audit::engine_integrator& e) { return e.name.rfind(engine.engine + "::", 0) == 0; }))
          for (auto& a : audit::audit_shapes(engine)) shape_audits.push_back(std::move(a));
      audit::print_engines(std::cout, engine_audits, shape_audits);
      if (!report_files([&] {
            std::vector<std::string> written = audit::write_engine_report(output, engine_audits, shape_audits);
            // Each robot as URDF, for the engines' own loaders.
            for (const auto& s : robots) {
              const std::filesystem::path path = std::filesystem::path(output) / "robots" / (s.name + ".urdf");
              std::filesystem::create_directories(path.parent_path());
              std::ofstream file(path);
              file << audit::to_urdf(s.robot->robot);
              if (!file) throw error("cannot write " + path.string());
              written.push_back(path.string());
            }
            return written;
          }))
        return 1;
      std::cout << "audited " << engine_audits.size() << " engine integrators in " << static_cast<long>(elapsed() + 0.5)
                << " s\n";
      for (const auto& a : engine_audits) {
        if (!a.claims_hold() && audit_tool::matches_any(require, a.integrator)) {
          std::cerr << "mechcheck-audit: " << a.integrator << ": a declared claim is contradicted (see the table)\n";
          raise(2);
        }
        require_measured_of(a.integrator, a.unmeasured());
      }
    }
    if (steppers.empty() && tableau_files.empty() && driver_patterns.empty() && exec_targets.empty()) {
      for (const auto& t : exec_engines)
        if (t.failures() > 0) {
          std::cerr << "mechcheck-audit: " << audit::command_text(child_command) << ": " << t.failures()
                    << " children failed; the last: " << t.last_failure() << "\n";
          raise(3);
        }
      return status;
    }
  }

  // The adaptive drivers (double).
  const bool drivers_only = !driver_patterns.empty() && steppers.empty() && tableau_files.empty() && exec_targets.empty();
  std::vector<audit::driver_audit> driver_audits;
  if (!driver_patterns.empty()) {
    std::vector<audit::adaptive_driver> drivers = all_drivers;
    std::erase_if(drivers, [&](const audit::adaptive_driver& d) { return !audit_tool::matches(driver_patterns, d.name); });
    const double t0 = elapsed();
    audit::driver_options dopt;
    dopt.problems = problems;
    dopt.timing = timing;
    if (!quiet) dopt.progress = progress;
    for (const auto& d : drivers) driver_audits.push_back(audit::audit_driver(d, dopt));
    audit::print_drivers(std::cout, driver_audits);
    for (const auto& a : driver_audits) require_measured_of(a.driver, a.unmeasured());
    if (!quiet) std::fprintf(stderr, "[%7.1f s] drivers done in %.1f s\n", elapsed(), elapsed() - t0);
  }
  const auto child_failures = [&] {
    for (const auto& t : exec_drivers)
      if (t.failures() > 0) {
        std::cerr << "mechcheck-audit: " << t.driver.name << ": " << t.failures() << " children failed; the last: "
                  << t.last_failure() << "\n";
        raise(3);
      }
    for (const auto& t : exec_targets)
      if (t.failures() > 0) {
        std::cerr << "mechcheck-audit: " << t.box.name << ": " << t.failures() << " children failed; the last: "
                  << t.last_failure() << "\n";
        raise(3);
      }
    for (const auto& t : exec_engines)
      if (t.failures() > 0) {
        std::cerr << "mechcheck-audit: " << audit::command_text(child_command) << ": " << t.failures()
                  << " children failed; the last: " << t.last_failure() << "\n";
        raise(3);
      }
  };
  if (drivers_only) {
    const std::string plot_problem = long_run_problems.empty() ? "kepler_e0.5" : long_run_problems.front();
    if (!report_files([&] { return audit::write_driver_report(output, driver_audits, plot_problem, timing); }))
      return 1;
    std::cout << "audited " << driver_audits.size() << " drivers in " << static_cast<long>(elapsed() + 0.5) << " s\n";
    child_failures();
    return status;
  }

  // The steppers, tier by tier.
  request.options.problems = problems;
  request.options.long_run_problems = long_run_problems;
  request.options.timing = timing;
  if (!quiet) request.options.progress = progress;
  std::vector<audit::stepper_audit> audits;
  for (const auto& tier : tiers) {
    const double t0 = elapsed();
    request.options.long_run_steps = tier == "double" ? long_run_steps : long_run_steps_mpfr50;
    for (const auto& f : families_in(tier, request)) audits.insert(audits.end(), f.audits.begin(), f.audits.end());
    if (!quiet) std::fprintf(stderr, "[%7.1f s] %s done in %.1f s\n", elapsed(), tier.c_str(), elapsed() - t0);
  }
  audit::report_options report;
  report.timing = timing;
  if (!long_run_problems.empty()) report.long_run_problem = long_run_problems.front();
  if (!audits.empty()) audit::print_table(std::cout, audits, report);
  const bool wrote = report_files([&] {
    std::vector<std::string> written;
    if (!audits.empty()) written = audit::write_report(output, audits, report);
    if (!driver_audits.empty())
      for (const auto& w : audit::write_driver_report(output, driver_audits, report.long_run_problem, timing))
        written.push_back(w);
    if (!analyses.empty())
      for (const auto& w : audit::write_tableau_report(output, analyses)) written.push_back(w);
    return written;
  });
  if (!wrote) return 1;
  std::cout << "audited " << audits.size() << " stepper-tier pairs in " << static_cast<long>(elapsed() + 0.5) << " s\n";
  for (const auto& a : audits) {
    if (!a.claims_hold() && audit_tool::matches_any(require, a.stepper)) {
      std::cerr << "mechcheck-audit: " << a.stepper << " [" << a.tier << "]: a declared claim is contradicted (see the table)\n";
      raise(2);
    }
    require_measured_of(a.stepper, a.unmeasured());
  }
  // A tableau file's algebraic claims (the stage order is one no stepper carries).
  for (const auto& a : analyses) {
    if (!audit_tool::matches_any(require, "tableau::" + a.name)) continue;
    for (const auto& v : a.verdicts)
      if (v.result == audit::verdict::outcome::contradicted) {
        std::cerr << "mechcheck-audit: tableau::" << a.name << " (" << a.path << "): " << v.claim << " declared "
                  << v.declared << " is contradicted by its order conditions (see the analysis)\n";
        raise(2);
      }
  }
  // A child that failed (crashed, hung, broke the protocol): its runs are failed runs of the
  // report, and the command says so by its status.
  child_failures();
  return status;
}
