// Steppers served by a child process (audit/exec.hpp, docs/protocol.md): a child that keeps
// the protocol is audited like any stepper (velocity Verlet confirmed, explicit Euler that
// claims order 2 contradicted), and a child that crashes, hangs, exits, breaks the protocol
// or returns a NaN ends its run with a typed error naming the command, the request and what
// came back, with nothing left running.
#include <gtest/gtest.h>

#include <signal.h>

#include <algorithm>
#include <bit>
#include <cstdint>
#include <random>
#include <chrono>
#include <cmath>
#include <fstream>
#include <functional>
#include <limits>
#include <sstream>
#include <string>
#include <thread>
#include <tuple>

#include <nlohmann/json.hpp>

#include "mechcheck/audit/steppers/black_box.hpp"
#include "mechcheck/audit/drivers/drivers.hpp"
#include "mechcheck/audit/adapters/exec.hpp"
#include "mechcheck/audit/engines/engines.hpp"

#ifndef MECHCHECK_EXEC_CHILD
#error "the build defines MECHCHECK_EXEC_CHILD, the path of tests/exec/child.cpp's program"
#endif

namespace exec_test {
using namespace mechcheck;
namespace audit = mechcheck::audit;
using outcome = audit::verdict::outcome;

std::vector<std::string> child(const std::string& mode) { return {MECHCHECK_EXEC_CHILD, mode}; }

/// y' = (y1, -y0): the oscillator as C callbacks.
int oscillator(double, const double* y, double* f, void*) {
  f[0] = y[1];
  f[1] = -y[0];
  return 0;
}
audit::ode_system oscillator_system() {
  audit::ode_system s;
  s.dimension = 2;
  s.rhs = &oscillator;
  return s;
}

/// The oscillator alone, its studies to 2^12 steps (h^2 ~ 1e-7 there: a second-order
/// method's error far above the floor): every step is a round trip to the child, and the
/// default 2^16 made one audit 430 s of the sanitizer run.
audit::audit_options few_problems() {
  audit::audit_options o;
  o.problems = {"oscillator"};
  o.long_run_problems = {};
  o.long_run_steps = 0;
  o.max_study_steps = 1 << 12;
  return o;
}

TEST(exec, a_verlet_child_is_audited_like_a_stepper_and_keeps_its_claims) {
  const auto target = audit::exec_stepper(child("verlet"));
  EXPECT_EQ(target.box.name, "exec::test_child/verlet");
  ASSERT_TRUE(target.box.declared.order);
  EXPECT_EQ(*target.box.declared.order, 2);
  const auto a = audit::audit_stepper(audit::black_box_stepper(target.box), audit::reference_problems<double>(), few_problems());
  ASSERT_TRUE(a.find("order") && a.find("symplectic"));
  EXPECT_EQ(a.find("order")->result, outcome::confirmed) << a.find("order")->evidence;
  EXPECT_NEAR(std::stod(a.find("order")->measured), 2.0, 0.1);
  EXPECT_NE(a.find("symplectic")->result, outcome::contradicted) << a.find("symplectic")->evidence;
  EXPECT_EQ(target.failures(), 0) << target.last_failure();
}

TEST(exec, a_child_that_takes_its_force_apart_is_counted_as_the_library_counts) {
  const audit::audit_options o = few_problems();  // the oscillator: separable
  const auto whole = audit::exec_stepper(child("verlet"));
  const auto split = audit::exec_stepper(child("verlet_split"));
  const auto a = audit::audit_stepper(audit::black_box_stepper(whole.box), audit::reference_problems<double>(), o);
  const auto b = audit::audit_stepper(audit::black_box_stepper(split.box), audit::reference_problems<double>(), o);
  ASSERT_EQ(a.problems.size(), b.problems.size());
  for (std::size_t i = 0; i < a.problems.size(); ++i) {
    EXPECT_EQ(a.problems[i].evaluations_per_step, 3.0) << a.problems[i].problem;  // three rhs calls
    EXPECT_EQ(b.problems[i].evaluations_per_step, 2.0) << b.problems[i].problem;  // two forces
  }
  EXPECT_EQ(b.find("order")->result, outcome::confirmed) << b.find("order")->evidence;
  EXPECT_EQ(split.failures(), 0) << split.last_failure();
}

TEST(exec, a_child_that_claims_too_much_is_contradicted) {
  const auto target = audit::exec_stepper(child("euler_says_2"));
  const auto a = audit::audit_stepper(audit::black_box_stepper(target.box), audit::reference_problems<double>(), few_problems());
  ASSERT_TRUE(a.find("order"));
  EXPECT_EQ(a.find("order")->result, outcome::contradicted) << a.find("order")->evidence;
}

/// One step of a misbehaving child: the exec_error's message.
std::string first_step_error(const std::string& mode, double timeout = 30) {
  audit::exec_options o;
  o.timeout = timeout;
  const auto target = audit::exec_stepper(child(mode), o);
  const audit::ode_system ode = oscillator_system();
  void* ctx = target.box.create(ode);
  double y[2] = {1, 0};
  std::string message;
  try {
    target.box.step(y, 0, 0.1, ctx);
  } catch (const audit::exec_error& e) {
    message = e.what();
  }
  target.box.destroy(ctx);
  EXPECT_EQ(target.failures(), message.empty() ? 0 : 1) << mode;
  return message;
}

TEST(exec, a_crash_an_exit_and_a_broken_reply_are_typed_errors_naming_the_command_and_the_request) {
  const std::string crash = first_step_error("crash");
  EXPECT_NE(crash.find("exec '" MECHCHECK_EXEC_CHILD " crash'"), std::string::npos) << crash;
  EXPECT_NE(crash.find("step of run 1 at t = 0, h = 0.1"), std::string::npos) << crash;
  EXPECT_NE(crash.find("killed by signal 6"), std::string::npos) << crash;
  const std::string exit = first_step_error("exit");
  EXPECT_NE(exit.find("exited with status 3"), std::string::npos) << exit;
  EXPECT_NE(exit.find("its standard error ends: \"giving up\""), std::string::npos) << exit;
  EXPECT_NE(first_step_error("malformed").find("the reply is not JSON: \"not json\""), std::string::npos);
  EXPECT_NE(first_step_error("oversized").find("longer than 1048576 bytes"), std::string::npos);
  const std::string extra = first_step_error("extra_field");
  EXPECT_NE(extra.find("the reply: the field \"yy\" is not one of version 1's (y)"), std::string::npos) << extra;
}

TEST(exec, a_non_finite_state_is_a_diverged_run_and_the_child_goes_on) {
  // A child that returns y[0] = nan, and one that asks for f at such a state (the stage of a
  // diverging explicit method): each step ends its run as diverged, with the state named,
  // and neither is a child failure -- the same child serves the next step.
  for (const auto& [mode, words] : {std::pair{"nan", "returned a non-finite state (y[0] = nan)"},
                                    std::pair{"asks_nan", "asked for f at a non-finite state (y[0] = nan)"}}) {
    SCOPED_TRACE(mode);
    const auto target = audit::exec_stepper(child(mode));
    const audit::ode_system ode = oscillator_system();
    void* ctx = target.box.create(ode);
    for (int step = 0; step < 2; ++step) {
      double y[2] = {1, 0};
      try {
        target.box.step(y, 0, 0.1, ctx);
        ADD_FAILURE() << "no error";
      } catch (const non_finite_error& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find(words), std::string::npos) << what;
        // Its context once.
        EXPECT_EQ(what.find("step of run 1"), what.rfind("step of run 1")) << what;
      }
    }
    target.box.destroy(ctx);
    EXPECT_EQ(target.failures(), 0);
  }
  // Through the black-box run, the step at which it diverged.
  const auto target = audit::exec_stepper(child("asks_nan"));
  const auto s = audit::black_box_stepper(target.box);
  const auto a = audit::audit_stepper(s, audit::reference_problems<double>(), few_problems());
  EXPECT_EQ(target.failures(), 0);
  bool said = false;
  for (const auto& p : a.problems)
    said = said || p.global.note.find("diverged at step 1") != std::string::npos;
  EXPECT_TRUE(said) << (a.problems.empty() ? std::string("no problem") : a.problems.front().global.note);
}

TEST(exec, a_hung_child_is_stopped_at_its_timeout_with_its_group) {
  const auto start = std::chrono::steady_clock::now();
  const std::string hang = first_step_error("hang", 0.5);
  EXPECT_NE(hang.find("no reply within 0.5 s"), std::string::npos) << hang;
  EXPECT_NE(hang.find("hanging at the first step"), std::string::npos) << hang;
  // The grandchild it started is killed with it: its process is gone (or a zombie).
  const std::string g = first_step_error("grandchild", 0.5);
  const auto at = g.find("pids ");
  ASSERT_NE(at, std::string::npos) << g;
  std::istringstream pids(g.substr(at + 5));
  int parent = 0, grandchild = 0;
  pids >> parent >> grandchild;
  ASSERT_GT(grandchild, 0) << g;
  // SIGKILL is delivered asynchronously: each is gone (or a zombie until its new parent
  // reaps it) within a second.
  const auto gone = [](int pid) {
    if (::kill(pid, 0) != 0) return true;
    std::ifstream stat("/proc/" + std::to_string(pid) + "/stat");
    std::string text;
    std::getline(stat, text);
    const auto close = text.rfind(')');
    return close != std::string::npos && text.size() > close + 2 && text[close + 2] == 'Z';
  };
  for (const int pid : {parent, grandchild}) {
    bool dead = gone(pid);
    for (int i = 0; i < 100 && !dead; ++i) {
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
      dead = gone(pid);
    }
    EXPECT_TRUE(dead) << "process " << pid << " is still running";
  }
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 10.0);
}

TEST(exec, a_bad_command_or_handshake_is_refused_before_any_run) {
  EXPECT_THROW(audit::exec_stepper({}), domain_error);
  EXPECT_THROW(audit::exec_stepper({"/nonexistent/mechcheck-child"}), audit::exec_error);
  try {
    audit::exec_stepper(child("version_2"));
    ADD_FAILURE() << "a version-2 handshake was accepted";
  } catch (const audit::exec_error& e) {
    EXPECT_NE(std::string(e.what()).find("protocol version 2; this audit speaks version 1"), std::string::npos) << e.what();
  }
  audit::exec_options o;
  o.timeout = 0;
  EXPECT_THROW(audit::exec_stepper(child("rk4"), o), domain_error);
}

TEST(exec, a_failing_child_is_restarted_then_refused) {
  audit::exec_options o;
  o.restarts = 1;
  const auto target = audit::exec_stepper(child("crash"), o);
  const audit::ode_system ode = oscillator_system();
  double y[2] = {1, 0};
  for (int run = 0; run < 2; ++run) {
    void* ctx = target.box.create(ode);
    EXPECT_THROW(target.box.step(y, 0, 0.1, ctx), audit::exec_error);
    target.box.destroy(ctx);
  }
  try {
    target.box.create(ode);
    ADD_FAILURE() << "a third child was started";
  } catch (const audit::exec_error& e) {
    EXPECT_NE(std::string(e.what()).find("not restarted after 2 failures"), std::string::npos) << e.what();
  }
}

TEST(exec, a_driver_child_is_audited_against_its_tolerances_and_its_failures_are_failed_runs) {
  const auto target = audit::exec_driver(child("driver"));
  EXPECT_EQ(target.driver.name, "exec::test_child/driver");
  audit::driver_options o;
  o.problems = {"oscillator"};
  o.tolerances = {1e-4, 1e-6, 1e-8};
  const auto a = audit::audit_driver(target.driver, o);
  ASSERT_EQ(a.problems.size(), 1u);
  for (const auto& p : a.problems[0].points) {
    EXPECT_TRUE(p.failure.empty()) << p.failure;
    EXPECT_GT(p.accepted, 0);
  }
  EXPECT_EQ(target.failures(), 0) << target.last_failure();
  // A driver that reports failure: each run a failed point naming it; the child lives on.
  const auto failing = audit::exec_driver(child("driver_fails"));
  const auto b = audit::audit_driver(failing.driver, o);
  for (const auto& p : b.problems[0].points)
    EXPECT_NE(p.failure.find("the driver failed: library X returned -4"), std::string::npos) << p.failure;
  EXPECT_EQ(failing.failures(), 0);
  // A stepper is not a driver.
  EXPECT_THROW(audit::exec_driver(child("rk4")), audit::exec_error);
}

/// The pendulum scenarios of an engine child, with a short long run.
audit::engine_options pendulums(std::vector<std::string> scenarios = {"pendulum_small"}) {
  audit::engine_options o;
  o.scenarios = std::move(scenarios);
  o.long_run_steps = 3000;
  o.timing = true;
  return o;
}

const audit::engine_integrator& integrator(const audit::exec_engine_target& t, const std::string& name) {
  for (const auto& e : t.integrators)
    if (e.name.size() >= name.size() && e.name.compare(e.name.size() - name.size(), name.size(), name) == 0) return e;
  throw std::runtime_error("no integrator " + name);
}

TEST(exec, an_engine_child_is_audited_on_the_scenarios_it_builds_and_refuses_the_others_by_its_words) {
  const auto t = audit::exec_engine(child("engine"));
  ASSERT_EQ(t.integrators.size(), 3u);
  EXPECT_EQ(t.integrators[1].name, "exec::test_engine/engine::rk4");
  EXPECT_NE(t.integrators[0].origin.find("symplectic Euler"), std::string::npos) << t.integrators[0].origin;
  for (const char* name : {"::rk4", "::euler"}) {
    const auto a = audit::audit_engine(integrator(t, name), pendulums({"pendulum_small", "free_top"}));
    EXPECT_EQ(a.order.result, outcome::confirmed) << name << ": " << a.order.evidence;
    EXPECT_NEAR(std::stod(a.order.measured), std::string(name) == "::rk4" ? 4.0 : 1.0, 0.1) << a.order.measured;
    ASSERT_EQ(a.scenarios.size(), 2u);  // in the scenarios' order: free_top, pendulum_small
    const auto& p = a.scenarios[1];
    EXPECT_TRUE(p.failure.empty() && p.long_run_failure.empty()) << p.failure << p.long_run_failure;
    EXPECT_EQ(p.long_run_steps, 3000);
    EXPECT_EQ(p.readout, "the engine's joint coordinates");
    // The child's clock: 1e-7 s a step, as it says (its batches' sums, a third's mean: a few
    // roundings of 1e-7).
    EXPECT_NEAR(p.seconds_per_step, 1e-7, 8 * std::numeric_limits<double>::epsilon() * 1e-7);
    EXPECT_NE(a.scenarios[0].refused.find("this engine builds hinge pendulums only"), std::string::npos)
        << a.scenarios[0].refused;
  }
  EXPECT_EQ(t.failures(), 0) << t.last_failure();
}

TEST(exec, a_contact_case_is_written_as_the_lines_the_child_reads) {
  // A shrunk contact case of an engine behind the protocol is its start, its steps at
  // h = 1/60 to the scenario's end and its end: piped into the child alone, they replay it.
  namespace ep = audit::exec_protocol;
  const auto t = audit::exec_engine(child("engine_decimal"));
  const auto& e = t.integrators[0];
  ASSERT_TRUE(e.contact_model);
  EXPECT_EQ(e.contact_model_extension, "jsonl");
  for (const auto& s : audit::contact_scenarios()) {
    std::istringstream lines(e.contact_model(s));
    std::string start, step, end, more;
    ASSERT_TRUE(std::getline(lines, start) && std::getline(lines, step) && std::getline(lines, end)) << s.name;
    EXPECT_FALSE(std::getline(lines, more)) << s.name;
    const auto j = nlohmann::json::parse(start), k = nlohmann::json::parse(step);
    EXPECT_EQ(j.at("op"), "start");
    EXPECT_EQ(j.at("integrator"), "euler");  // the child's name, not the audit's
    EXPECT_EQ(j.at("scenario"), nlohmann::json::parse(ep::scenario_json(s, true))) << s.name;
    EXPECT_EQ(k.at("op"), "step");
    EXPECT_EQ(*ep::number_value(k.at("h").get<std::string>()), 1.0 / 60);
    EXPECT_EQ(k.at("n").get<long>(), std::lround(s.t_end * 60)) << s.name;
    EXPECT_EQ(k.at("read"), "last");
    EXPECT_EQ(nlohmann::json::parse(end), (nlohmann::json{{"op", "end"}, {"run", 1}}));
  }
}

TEST(exec, an_engine_child_that_claims_too_much_is_contradicted) {
  const auto t = audit::exec_engine(child("engine_decimal"));  // and its numbers in decimal
  const auto a = audit::audit_engine(integrator(t, "::euler_says_4"), pendulums());
  EXPECT_EQ(a.order.result, outcome::contradicted) << a.order.evidence;
  EXPECT_EQ(t.failures(), 0) << t.last_failure();
}

TEST(exec, an_engine_in_single_precision_is_neither_accused_nor_credited_falsely) {
  // The pendulum engine with its state rounded to float after every step (the arithmetic
  // of the JavaScript engines in WebAssembly). Symplectic Euler's error (order 1) stays far
  // above float's rounding: its order is measured. RK4's error meets float's rounding within
  // three halvings and then rises with the steps (-0.41 at double's floors): not resolvable,
  // never contradicted; Euler's claim of order 4 is not confirmed.
  const auto t = audit::exec_engine(child("engine_float"));
  const auto euler = audit::audit_engine(integrator(t, "::euler"), pendulums());
  EXPECT_EQ(euler.order.result, outcome::confirmed) << euler.order.evidence;
  EXPECT_NEAR(std::stod(euler.order.measured), 1.0, 0.1) << euler.order.measured;
  const auto rk4 = audit::audit_engine(integrator(t, "::rk4"), pendulums());
  EXPECT_NE(rk4.order.result, outcome::contradicted) << rk4.order.evidence;
  const auto says_4 = audit::audit_engine(integrator(t, "::euler_says_4"), pendulums());
  EXPECT_NE(says_4.order.result, outcome::confirmed) << says_4.order.evidence;
  // Declared ("precision": "single"), the floors are float's (100 u sqrt(n)): on
  // pendulum_small the study stops at n = 256, where two halvings read 1.97 (pre-asymptotic,
  // not decisive); on pendulum_large six runs resolve 0.99, and the same engine's false claim
  // of order 4 is contradicted there. Euler's order 1 is confirmed; RK4, no halving of which
  // is resolvable above float's floors, is neither contradicted nor confirmed.
  const auto both = pendulums({"pendulum_small", "pendulum_large"});
  const auto d = audit::exec_engine(child("engine_float_declared"));
  for (const auto& i : d.integrators) EXPECT_EQ(i.epsilon, 0x1p-23) << i.name;
  const auto euler_d = audit::audit_engine(integrator(d, "::euler"), both);
  EXPECT_EQ(euler_d.order.result, outcome::confirmed) << euler_d.order.evidence;
  const auto rk4_d = audit::audit_engine(integrator(d, "::rk4"), both);
  EXPECT_NE(rk4_d.order.result, outcome::contradicted) << rk4_d.order.evidence;
  EXPECT_NE(rk4_d.order.result, outcome::confirmed) << rk4_d.order.evidence;
  const auto says_4_d = audit::audit_engine(integrator(d, "::euler_says_4"), both);
  EXPECT_EQ(says_4_d.order.result, outcome::contradicted) << says_4_d.order.evidence;
  // Undeclared, the same two pendulums: the false claim is not confirmed, but not
  // contradicted either (the study's fits run into float's rounding at double's floors).
  const auto says_4_both = audit::audit_engine(integrator(t, "::euler_says_4"), both);
  EXPECT_NE(says_4_both.order.result, outcome::confirmed) << says_4_both.order.evidence;
}

TEST(exec, an_engine_that_fails_is_a_failed_run_at_its_step_and_the_child_goes_on) {
  const auto t = audit::exec_engine(child("engine_diverges"));
  const auto a = audit::audit_engine(integrator(t, "::euler"), pendulums());
  ASSERT_EQ(a.scenarios.size(), 1u);
  const auto& p = a.scenarios[0];
  EXPECT_EQ(p.long_run_steps, 999);
  EXPECT_NE(p.long_run_failure.find("step 1000: exec::test_engine/engine_diverges::euler: step 1000: diverged"),
            std::string::npos)
      << p.long_run_failure;
  // The order study's runs of 1024 steps and more fail at step 1000 (t_end = 2: h < 0.002);
  // the shorter ones stand.
  ASSERT_FALSE(p.global.points.empty());
  for (const auto& point : p.global.points) EXPECT_GT(point.h, 2.0 / 1000);
  EXPECT_NE(p.global.note.find("diverged"), std::string::npos) << p.global.note;
  EXPECT_EQ(t.failures(), 0) << t.last_failure();
}

TEST(exec, a_broken_reading_ends_the_child_with_a_typed_error_and_the_audit_goes_on) {
  const auto t = audit::exec_engine(child("engine_broken"));
  const auto a = audit::audit_engine(integrator(t, "::rk4"), pendulums());
  EXPECT_GT(t.failures(), 0);
  EXPECT_NE(t.last_failure().find("\"frame\" has 17 numbers, 18 expected"), std::string::npos) << t.last_failure();
  EXPECT_NE(t.last_failure().find("of run"), std::string::npos) << t.last_failure();
  // The first request of each run is a study's whole run: those runs stand.
  EXPECT_FALSE(a.scenarios.at(0).global.points.empty());
}

TEST(exec, an_engine_child_gives_its_shapes_inertia_with_and_without_a_mass) {
  // The child's box: exact moments from its edges; without a mass, a density of 1000. Each
  // row is the closed form to rounding (the box's moments and its volume: a few roundings).
  constexpr double eps = std::numeric_limits<double>::epsilon();
  for (const char* mode : {"engine", "engine_decimal"}) {
    const auto t = audit::exec_engine(child(mode));
    ASSERT_TRUE(t.shapes && t.shapes->without_mass) << mode;
    const auto rows = audit::audit_shapes(*t.shapes);
    ASSERT_EQ(rows.size(), 2 * audit::shapes().size());
    for (const auto& a : rows) {
      if (a.shape != "box") {
        EXPECT_EQ(a.refused, "exec::test_engine/" + std::string(mode) + ": this engine has boxes only") << a.shape;
        continue;
      }
      EXPECT_TRUE(a.failure.empty()) << a.failure;
      EXPECT_LE(a.relative_error, 8 * eps) << mode << (a.mass_given ? "" : " without a mass");
      if (a.mass_given) continue;
      const Eigen::Vector3d e = audit::shapes().front().size;
      EXPECT_NEAR(a.mass, 1000 * e.prod(), 4 * eps * a.mass);
      EXPECT_NEAR(a.density, 1000, 8 * eps * 1000);
      EXPECT_EQ(a.said, "a density of 1000");
    }
    EXPECT_EQ(t.failures(), 0) << t.last_failure();
  }
  // The handshake's flag needs "shapes" and a boolean.
  namespace ep = audit::exec_protocol;
  const std::string head = R"({"protocol": "mechcheck", "version": 1, "kind": "engine", "name": "e", "integrators": [{"name": "i"}], )";
  EXPECT_TRUE(ep::parse_handshake(head + R"("shapes": true, "shapes_without_mass": true})", "engine").shapes_without_mass);
  EXPECT_THROW(ep::parse_handshake(head + R"("shapes_without_mass": true})", "engine"), audit::exec_error);
  EXPECT_THROW(ep::parse_handshake(head + R"("shapes": true, "shapes_without_mass": 1})", "engine"), audit::exec_error);
  // A reply without its mass is the row's failure, and the next request is answered.
  const auto broken = audit::exec_engine(child("engine_broken"));
  const auto rows = audit::audit_shapes(*broken.shapes);
  EXPECT_NE(rows.at(1).failure.find("the reply has no \"mass\""), std::string::npos) << rows.at(1).failure;
  EXPECT_FALSE(rows.at(1).mass_given);
  EXPECT_TRUE(rows.at(0).failure.empty() && rows.at(0).refused.empty()) << rows.at(0).failure;
  EXPECT_EQ(rows.at(2).refused, "exec::test_engine/engine_broken: this engine has boxes only");
}

TEST(exec, every_double_round_trips_through_the_protocols_text_in_both_forms) {
  // Random bit patterns (every exponent, both signs), subnormals, the extremes and the
  // signed zeros and infinities: written by the parent as hexadecimal or 17 digits, read back
  // to the same bits -- through number_value and through a reply's "y".
  namespace ep = audit::exec_protocol;
  using limits = std::numeric_limits<double>;
  std::vector<double> xs = {0.0, -0.0, limits::min(), -limits::min(), limits::denorm_min(), -limits::denorm_min(),
                            limits::max(), -limits::max(), limits::epsilon(), 1.0, -1.0, 0.1, 1.0 / 3,
                            limits::min() - limits::denorm_min(), limits::infinity(), -limits::infinity()};
  std::mt19937_64 bits(20261126);
  for (int k = 0; k < 200000; ++k) {
    const double x = std::bit_cast<double>(bits());
    if (!std::isnan(x)) xs.push_back(x);
  }
  for (int k = 0; k < 20000; ++k)  // subnormals: exponent field 0
    xs.push_back(std::bit_cast<double>(bits() & 0x800FFFFFFFFFFFFFull));
  std::size_t wrong = 0;
  for (const double x : xs)
    for (const bool decimal : {false, true}) {
      const std::string text = ep::number_text(x, decimal);
      const std::optional<double> back = ep::number_value(text);
      if (!back || std::bit_cast<std::uint64_t>(*back) != std::bit_cast<std::uint64_t>(x)) {
        if (++wrong <= 5) ADD_FAILURE() << text << " read back as " << (back ? ep::number_text(*back) : "nothing");
      }
    }
  EXPECT_EQ(wrong, 0u) << "of " << 2 * xs.size();
  EXPECT_EQ(ep::number_text(1.5), "0x1.8p+0");
  EXPECT_EQ(ep::number_text(0.1, true), "0.10000000000000001");
  EXPECT_TRUE(std::isnan(*ep::number_value("nan")));
  // A reply's numbers, read as the parent reads a state.
  std::string line = "{\"y\": [";
  for (std::size_t k = 0; k < 64; ++k) line += (k ? ", \"" : "\"") + ep::number_text(xs[xs.size() - 1 - k], k % 2) + "\"";
  line += "]}";
  const std::vector<double> y = ep::parse_numbers(line, "y", 64);
  for (std::size_t k = 0; k < 64; ++k)
    EXPECT_EQ(std::bit_cast<std::uint64_t>(y[k]), std::bit_cast<std::uint64_t>(xs[xs.size() - 1 - k])) << k;
}

TEST(exec, a_malformed_number_is_refused_with_a_typed_error) {
  namespace ep = audit::exec_protocol;
  for (const char* bad : {"--1", "+-1", "-+1", "++1", "1e", "1e+", "0x", "0x-1", "-0x-1", "0x1p", "1.0.0", " 1", "1 ",
                          "", "-", "+", "1,5", "0b101", "1_000", "e5", "0x1.8p+1x", "infinity?", "1/3"}) {
    EXPECT_FALSE(ep::number_value(bad)) << '"' << bad << '"';
    const std::string line = std::string("{\"y\": [\"") + bad + "\"]}";
    try {
      ep::parse_numbers(line, "y", 1);
      ADD_FAILURE() << '"' << bad << "\" accepted";
    } catch (const audit::exec_error& e) {
      EXPECT_NE(std::string(e.what()).find("is not a number"), std::string::npos) << e.what();
    }
  }
  // Signs and forms that are numbers.
  EXPECT_EQ(*ep::number_value("+1"), 1.0);
  EXPECT_EQ(*ep::number_value("-0x1p-1"), -0.5);
  EXPECT_EQ(*ep::number_value("1E3"), 1000.0);
  EXPECT_EQ(*ep::number_value("0X1P+1"), 2.0);
}

TEST(exec, the_protocol_refuses_deep_large_and_malformed_lines_with_their_reason) {
  namespace ep = audit::exec_protocol;
  const auto refused = [](const auto& call) {
    try {
      call();
    } catch (const audit::exec_error& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  EXPECT_NE(refused([] { ep::parse_numbers(std::string(100000, '[') + std::string(100000, ']'), "y", 1); })
                .find("nested deeper than 16"),
            std::string::npos);
  EXPECT_NE(refused([] { ep::parse_numbers("{\"y\": [\"" + std::string(1000, '1') + "\"]}", "y", 1); }).find("1000 characters"),
            std::string::npos);
  EXPECT_NE(refused([] { ep::parse_numbers("{\"y\": [1, 2]}", "y", 1); }).find("2 numbers, 1 expected"), std::string::npos);
  EXPECT_NE(refused([] { ep::parse_numbers("{\"y\": [null]}", "y", 1); }).find("null is not a number"), std::string::npos);
  EXPECT_EQ(ep::parse_numbers("{\"y\": [\"0x1.8p+1\", \"0.10000000000000001\", 5e-324]}", "y", 3),
            (std::vector<double>{3.0, 0.1, 5e-324}));
  EXPECT_NE(refused([] { ep::parse_handshake(R"({"protocol": "mechcheck", "version": 1, "kind": "engine", "name": "x"})", "engine"); })
                .find("lists its \"integrators\""),
            std::string::npos);
  // A field version 1 does not have -- a misspelt claim, structure or integrator field, a
  // stepper's "integrators" -- is an error naming it and the fields there are.
  for (const auto& [line, kind, words] :
       {std::tuple{R"({"protocol": "mechcheck", "version": 1, "kind": "stepper", "name": "x", "claims": {"symplectc": true}})",
                   "stepper", "the field \"symplectc\" is not one of version 1's (order, symplectic, symmetric)"},
        std::tuple{R"({"protocol": "mechcheck", "version": 1, "kind": "stepper", "name": "x", "claim": {"order": 2}})",
                   "stepper", "the field \"claim\""},
        std::tuple{R"({"protocol": "mechcheck", "version": 1, "kind": "stepper", "name": "x", "structure": {"separble": true}})",
                   "stepper", "structure: the field \"separble\""},
        std::tuple{R"({"protocol": "mechcheck", "version": 1, "kind": "driver", "name": "x", "integrators": []})", "driver",
                   "the field \"integrators\""},
        std::tuple{R"({"protocol": "mechcheck", "version": 1, "kind": "engine", "name": "x", "integrators": [{"name": "a", "order": 2}]})",
                   "engine", "integrator a: the field \"order\""}}) {
    const std::string text = line, as = kind;  // a lambda captures variables, not bindings (Clang 14)
    const std::string what = refused([&] { ep::parse_handshake(text, as); });
    EXPECT_NE(what.find(words), std::string::npos) << what;
  }
  EXPECT_EQ(ep::parse_handshake(R"({"protocol": "mechcheck", "version": 1, "kind": "stepper", "name": "x", "origin": "o",)"
                                R"( "claims": {"order": 2, "symplectic": true, "symmetric": true}, "numbers": "decimal",)"
                                R"( "structure": {"canonical": true, "separable": true}})",
                                "stepper")
                .declared.order,
            2);
  const auto scenarios = audit::scenarios();
  const audit::scenario& pendulum = *std::find_if(scenarios.begin(), scenarios.end(),
                                                 [](const audit::scenario& s) { return s.name == "pendulum_small"; });
  EXPECT_NE(refused([&] { ep::parse_step_reply(R"({"readings": []})", pendulum, 1, false); }).find("0 readings, 1 expected"),
            std::string::npos);
  EXPECT_NE(refused([&] { ep::parse_step_reply(R"({"error": "x", "at": 5})", pendulum, 3, true); }).find("names the step"),
            std::string::npos);
  // A step reply's and a reading's fields are version 1's: another is an error naming it.
  const std::string frame = "[1,0,0, 0,1,0, 0,0,1, 0,0,-1, 0,0,0, 0,0,0]";
  EXPECT_EQ(ep::parse_step_reply(R"({"readings": [{"frame": )" + frame + "}]}", pendulum, 1, false).readings.size(), 1u);
  EXPECT_NE(refused([&] { ep::parse_step_reply(R"({"readings": [{"frame": )" + frame + R"(, "qq": [0]}]})", pendulum, 1, false); })
                .find("a reading: the field \"qq\" is not one of version 1's (frame, links, q, v)"),
            std::string::npos);
  EXPECT_NE(refused([&] { ep::parse_step_reply(R"({"readings": [{"frame": )" + frame + R"(}], "secnds": 1})", pendulum, 1, false); })
                .find("a step reply: the field \"secnds\" is not one of version 1's (readings, error, at, seconds)"),
            std::string::npos);
  // The scenario as sent reads back exactly.
  const auto j = ep::scenario_json(pendulum);
  EXPECT_NE(j.find("\"joint\":\"hinge_y\""), std::string::npos) << j;
}

TEST(exec, a_scenario_sent_in_decimals_reads_back_to_the_bits_of_the_hexadecimal_one) {
  // Every scenario in both forms: the same tree, and every number of the decimal one the
  // double of the hexadecimal one (which %a writes exactly), bit for bit; the mass, gravity
  // and start of the pendulum are the scenario's own.
  namespace ep = audit::exec_protocol;
  std::size_t numbers = 0;
  const std::function<void(const nlohmann::json&, const nlohmann::json&, const std::string&)> same =
      [&](const nlohmann::json& hex, const nlohmann::json& dec, const std::string& at) {
        ASSERT_EQ(hex.type(), dec.type()) << at;
        if (hex.is_object()) {
          ASSERT_EQ(hex.size(), dec.size()) << at;
          for (auto it = hex.begin(); it != hex.end(); ++it) same(it.value(), dec.at(it.key()), at + "." + it.key());
        } else if (hex.is_array()) {
          ASSERT_EQ(hex.size(), dec.size()) << at;
          for (std::size_t k = 0; k < hex.size(); ++k) same(hex[k], dec[k], at + "[" + std::to_string(k) + "]");
        } else if (hex.is_string() && hex.get<std::string>().rfind("0x", 0) != std::string::npos) {
          const auto a = ep::number_value(hex.get<std::string>()), b = ep::number_value(dec.get<std::string>());
          ASSERT_TRUE(a && b) << at;
          EXPECT_EQ(std::bit_cast<std::uint64_t>(*a), std::bit_cast<std::uint64_t>(*b)) << at << ": " << dec;
          ++numbers;
        } else if (hex.is_string() && ep::number_value(hex.get<std::string>())) {  // "-0x..." and "0"
          EXPECT_EQ(std::bit_cast<std::uint64_t>(*ep::number_value(hex.get<std::string>())),
                    std::bit_cast<std::uint64_t>(*ep::number_value(dec.get<std::string>())))
              << at;
          ++numbers;
        } else {
          EXPECT_EQ(hex, dec) << at;
        }
      };
  std::vector<audit::scenario> all = audit::scenarios();
  for (auto& c : audit::contact_scenarios()) all.push_back(std::move(c));
  for (const auto& s : all) {
    const auto hex = nlohmann::json::parse(ep::scenario_json(s, false)), dec = nlohmann::json::parse(ep::scenario_json(s, true));
    same(hex, dec, s.name);
    if (s.contact) {  // a contact scenario carries its setup: each body's shape, mass and start
      ASSERT_EQ(dec.at("structure"), "contact") << s.name;
      const auto& bodies = dec.at("contact").at("bodies");
      ASSERT_EQ(bodies.size(), s.contact->bodies.size()) << s.name;
      EXPECT_EQ(bodies[0].at("shape"), audit::contact_shape_name(s.contact->bodies[0].shape)) << s.name;
      EXPECT_EQ(*ep::number_value(bodies[0].at("mass").get<std::string>()), s.contact->bodies[0].mass) << s.name;
      EXPECT_EQ(*ep::number_value(bodies[0].at("position0")[2].get<std::string>()), s.contact->bodies[0].position0(2)) << s.name;
      EXPECT_EQ(*ep::number_value(dec.at("contact").at("mu").get<std::string>()), s.contact->mu) << s.name;
      EXPECT_EQ(dec.at("contact").at("ground"), s.contact->ground) << s.name;
    }
    if (s.name == "pendulum_small") {
      EXPECT_EQ(*ep::number_value(dec.at("mass").get<std::string>()), s.mass);
      EXPECT_EQ(*ep::number_value(dec.at("gravity").get<std::string>()), s.gravity);
      EXPECT_EQ(*ep::number_value(dec.at("rotation0")[0].get<std::string>()), s.rotation0(0, 0));
    }
  }
  EXPECT_GT(numbers, 200u);
}

}  // namespace exec_test
