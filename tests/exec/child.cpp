// A child serving a stepper by the protocol of docs/protocol.md, for the tests of
// audit/exec.hpp: well-behaved (velocity Verlet, classical RK4, and explicit Euler that
// claims order 2), or misbehaving on its first step in one way each.
//
// Usage: mechcheck_exec_child MODE
//   verlet       velocity Verlet on y = (q, p), q and p of equal length (canonical,
//                separable); claims order 2, symplectic, symmetric; each half from "rhs"
//   verlet_split the same, its force and velocity from "force" and "velocity"
//   rk4          classical RK4 on any y; claims order 4
//   euler_says_2 explicit Euler; claims order 2 (the audit must contradict it)
//   crash        abort() at the first step          hang       sleeps at the first step
//   exit         exit(3) at the first step          malformed  replies "not json"
//   oversized    replies a 2 MiB line               nan        replies a NaN state
//   version_2    its handshake says protocol version 2
//   grandchild   starts a grandchild that sleeps, then hangs (both must be killed)
//   driver       an adaptive driver (kind "driver"): RK4 at h = tol^(1/4) (t1 - t0)
//   driver_fails a driver that reports a failure for every integration
//   engine       an engine (kind "engine") of hinge pendulums in their joint coordinates,
//                integrators "euler" (symplectic Euler, claims order 1), "rk4" (claims 4),
//                "euler_says_4" (symplectic Euler claiming 4); it refuses every other scenario
//   engine_diverges  the same, failing at step 1000 of every run ("diverged")
//   engine_broken    the same, a reading of 17 numbers at the second request of a run
//   engine_decimal   the same, asking for decimal numbers (handshake "numbers")
//   engine_float     the same, its state rounded to float after every step (an engine
//                    that computes in single precision, as WebAssembly physics builds do)
//   engine_float_declared  the same, its handshake saying "precision": "single"
//                The engine modes answer "shape" requests for a box (its moments, or without a
//                mass a density of 1000) and refuse the other shapes; engine_broken's reply
//                to a box without a mass has no "mass".
//   engine COST_NS   the engine, each step taking COST_NS nanoseconds of wall time (a busy
//                    wait: bench/exec_bench.cpp)
#include <unistd.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "pendulum.hpp"

using json = nlohmann::json;
using vec = std::vector<double>;

namespace {
std::string mode;

/// C's hexadecimal form of x (std::to_chars: what printf("%a") writes, faster).
std::string hex(double x) {
  if (!std::isfinite(x)) return std::isnan(x) ? "nan" : x > 0 ? "inf" : "-inf";  // as printf
  char b[40] = "-0x";
  const bool negative = std::signbit(x);
  char* start = b + (negative ? 3 : 2);
  if (!negative) b[0] = '0', b[1] = 'x';
  const auto [end, error] = std::to_chars(start, b + sizeof b, std::fabs(x), std::chars_format::hex);
  static_cast<void>(error);
  return std::string(b, end);
}
double num(const json& v) { return v.is_string() ? std::strtod(v.get<std::string>().c_str(), nullptr) : v.get<double>(); }
vec nums(const json& a) {
  vec out;
  for (const auto& v : a) out.push_back(num(v));
  return out;
}
json hexes(const vec& x) {
  json a = json::array();
  for (double v : x) a.push_back(hex(v));
  return a;
}
void send(const json& m) { std::cout << m.dump() << "\n" << std::flush; }
json receive() {
  std::string line;
  if (!std::getline(std::cin, line)) std::exit(0);  // the parent closed our input: done
  return json::parse(line);
}

/// f(t, y) from the parent.
vec rhs(double t, const vec& y) {
  send({{"op", "rhs"}, {"t", hex(t)}, {"y", hexes(y)}});
  const json r = receive();
  if (r.contains("error")) throw std::runtime_error(r["error"].get<std::string>());
  return nums(r["dydt"]);
}

/// A separable problem's halves from the parent: -dH/dq at q, dH/dp at p.
vec half(const char* op, const char* in, const char* out, double t, const vec& x) {
  send({{"op", op}, {"t", hex(t)}, {in, hexes(x)}});
  const json r = receive();
  if (r.contains("error")) throw std::runtime_error(r["error"].get<std::string>());
  return nums(r[out]);
}

/// The run's split (its start's "nq"), for verlet_split.
std::map<long long, std::size_t> split_of;
long long current_run = 0;

vec axpy(const vec& y, double a, const vec& x) {
  vec out = y;
  for (std::size_t i = 0; i < y.size(); ++i) out[i] += a * x[i];
  return out;
}

vec step(double t, double h, vec y) {
  const std::size_t n = y.size();
  if (mode == "verlet_split") {  // the force and the velocity apart: 2 forces a step
    const std::size_t m = split_of.at(current_run);
    vec q(y.begin(), y.begin() + long(m)), p(y.begin() + long(m), y.end());
    vec f = half("force", "q", "dpdt", t, q);
    for (std::size_t i = 0; i < p.size(); ++i) p[i] += h / 2 * f[i];
    const vec v = half("velocity", "p", "dqdt", t, p);
    for (std::size_t i = 0; i < m; ++i) q[i] += h * v[i];
    f = half("force", "q", "dpdt", t + h, q);
    for (std::size_t i = 0; i < p.size(); ++i) p[i] += h / 2 * f[i];
    q.insert(q.end(), p.begin(), p.end());
    return q;
  }
  if (mode == "verlet") {
    const std::size_t m = n / 2;  // q = y[0, m), p = y[m, n)
    vec f = rhs(t, y);
    for (std::size_t i = m; i < n; ++i) y[i] += h / 2 * f[i];  // kick: p' = -dH/dq
    f = rhs(t, y);
    for (std::size_t i = 0; i < m; ++i) y[i] += h * f[i];  // drift: q' = dH/dp at the new p
    f = rhs(t + h, y);
    for (std::size_t i = m; i < n; ++i) y[i] += h / 2 * f[i];
    return y;
  }
  if (mode == "euler_says_2") return axpy(y, h, rhs(t, y));
  if (mode == "asks_nan") {  // a diverged stage: f asked for at a state that is not finite
    vec bad = y;
    bad[0] = std::nan("");
    return axpy(y, h, rhs(t, bad));
  }
  const vec k1 = rhs(t, y), k2 = rhs(t + h / 2, axpy(y, h / 2, k1)), k3 = rhs(t + h / 2, axpy(y, h / 2, k2)),
            k4 = rhs(t + h, axpy(y, h, k3));
  for (std::size_t i = 0; i < n; ++i) y[i] += h / 6 * (k1[i] + 2 * k2[i] + 2 * k3[i] + k4[i]);
  return y;
}
using exec_test::pendulum;

/// x as a JSON number: the shortest decimal that reads back exactly (std::to_chars).
void append_number(std::string& out, double x) {
  char b[32];
  const auto [end, error] = std::to_chars(b, b + sizeof b, x);
  static_cast<void>(error);
  out.append(b, end);
}

/// A reading's JSON text, written directly with JSON numbers (a thousand readings a reply in
/// the long run: the fewer bytes, the less the parent parses).
std::string reading_text(const pendulum& p, bool broken) {
  vec f = p.frame();
  if (broken) f.pop_back();
  std::string out = "{\"frame\":[";
  for (std::size_t i = 0; i < f.size(); ++i) {
    if (i) out += ',';
    append_number(out, f[i]);
  }
  out += "],\"q\":[";
  append_number(out, p.theta);
  out += "],\"v\":[";
  append_number(out, p.rate);
  return out + "]}";
}
json reading(const pendulum& p, bool broken) { return json::parse(reading_text(p, broken)); }

/// x rounded to float and back, through a volatile float: in this file GCC 12 at -O2 and -O3
/// emitted no conversion for the plain cast (no cvtsd2ss in the object code), and the
/// "single precision" engine kept double's state.
double to_float(double x) {
  volatile float f = static_cast<float>(x);
  return f;
}

/// The engine modes; `cost_ns` the wall time of a step (the benchmark's engine).
void serve_engine(long cost_ns) {
  const bool decimal = mode == "engine_decimal";
  json hello = {{"protocol", "mechcheck"}, {"version", 1}, {"kind", "engine"}, {"name", "test_engine/" + mode},
                {"origin", "tests/exec/child.cpp"},
                {"integrators", {{{"name", "euler"}, {"origin", "symplectic Euler"}, {"claims", {{"order", 1}}}},
                                 {{"name", "rk4"}, {"claims", {{"order", 4}}}},
                                 {{"name", "euler_says_4"}, {"claims", {{"order", 4}}}}}}};
  if (decimal) hello["numbers"] = "decimal";
  const bool single = mode == "engine_float" || mode == "engine_float_declared";
  if (mode == "engine_float_declared") hello["precision"] = "single";
  hello["shapes"] = true;
  hello["shapes_without_mass"] = true;
  send(hello);
  std::map<long long, pendulum> runs;
  for (;;) {
    const json r = receive();
    const std::string op = r.value("op", "");
    const long long id = r.value("run", 0LL);
    if (op == "start") {
      const json& sc = r["scenario"];
      if (sc["joint"] != "hinge_y" || sc["structure"] != "one_body") {
        send({{"refused", "this engine builds hinge pendulums only"}});
        continue;
      }
      if (decimal && num(sc["mass"]) != 1.0) std::exit(7);  // decimals must arrive exact
      pendulum p;
      p.cost = std::chrono::nanoseconds(cost_ns);
      p.integrator = r["integrator"].get<std::string>();
      p.m = num(sc["mass"]);
      p.g = num(sc["gravity"]);
      const vec c = nums(sc["com"]), inertia = nums(sc["inertia"]), rot = nums(sc["rotation0"]), w = nums(sc["omega0"]);
      p.cx = c[0], p.cz = c[2];
      p.j = p.m * (c[0] * c[0] + c[1] * c[1] + c[2] * c[2]) + inertia[1];
      p.theta = std::atan2(rot[2], rot[0]);
      p.rate = w[1];
      runs[id] = p;
      send({{"ok", true}, {"reading", reading(p, false)}});
    } else if (op == "shape") {
      const json& sh = r["shape"];
      if (sh["name"] != "box") {
        send({{"refused", "this engine has boxes only"}});
        continue;
      }
      const vec e = nums(sh["size"]);
      const bool given = sh.contains("mass");
      const double m = given ? num(sh["mass"]) : 1000 * e[0] * e[1] * e[2];
      json reply = {{"moments", {m * (e[1] * e[1] + e[2] * e[2]) / 12, m * (e[0] * e[0] + e[2] * e[2]) / 12,
                                 m * (e[0] * e[0] + e[1] * e[1]) / 12}}};
      if (!given && mode != "engine_broken") reply["mass"] = m;
      if (!given) reply["said"] = "a density of 1000";
      send(reply);
    } else if (op == "end") {
      runs.erase(id);
      send({{"ok", true}});
    } else if (op == "step") {
      pendulum& p = runs.at(id);
      ++p.requests;
      const double h = num(r["h"]);
      const long n = r["n"].get<long>();
      const bool each = r["read"] == "each";
      std::string readings;
      bool failed = false;
      const auto t0 = std::chrono::steady_clock::now();
      for (long k = 1; k <= n && !failed; ++k) {
        if (mode == "engine_diverges" && p.steps + 1 == 1000) {
          std::cout << R"({"error":"diverged","at":)" << k << R"(,"readings":[)" << readings << "]}\n" << std::flush;
          failed = true;
          break;
        }
        p.step(h);
        if (single) {
          p.theta = to_float(p.theta);
          p.rate = to_float(p.rate);
        }
        if (each || k == n) readings += (readings.empty() ? "" : ",") + reading_text(p, mode == "engine_broken" && p.requests == 2);
      }
      if (failed) continue;
      // The steps' time: the clock's (reading included) when a cost is given, else 1e-7 s a
      // step (what the tests expect back).
      const double seconds = p.cost.count() > 0 ? std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count()
                                                : 1e-7 * static_cast<double>(n);
      std::cout << R"({"readings":[)" << readings << "]" << (r.value("timed", false) ? ",\"seconds\":\"" + hex(seconds) + "\"" : std::string())
                << "}\n" << std::flush;
    } else {
      send({{"error", "unknown op " + op}});
    }
  }
}
}  // namespace

int main(int argc, char** argv) {
  mode = argc > 1 ? argv[1] : "rk4";
  if (mode.rfind("engine", 0) == 0) {
    serve_engine(argc > 2 ? std::atol(argv[2]) : 0);
    return 0;
  }
  const bool driver = mode == "driver" || mode == "driver_fails";
  json hello = {{"protocol", "mechcheck"}, {"version", mode == "version_2" ? 2 : 1}, {"kind", driver ? "driver" : "stepper"},
                {"name", "test_child/" + mode}, {"origin", "tests/exec/child.cpp"}};
  if (mode == "verlet" || mode == "verlet_split")
    hello["claims"] = {{"order", 2}, {"symplectic", true}, {"symmetric", true}},
    hello["structure"] = {{"canonical", true}, {"separable", true}};
  else
    hello["claims"] = {{"order", mode == "rk4" ? 4 : 2}};
  send(hello);
  for (;;) {
    const json r = receive();
    const std::string op = r.value("op", "");
    if (op == "start" || op == "end") {
      if (op == "start") split_of[r.value("run", 0LL)] = r.value("nq", std::size_t(0));
      send({{"ok", true}});
      continue;
    }
    current_run = r.value("run", 0LL);
    if (op == "integrate" && driver) {
      // RK4 at h = tol^(1/4) (t1 - t0): a global error of order tol; or a reported failure.
      if (mode == "driver_fails") {
        send({{"error", "library X returned -4"}});
        continue;
      }
      const double t0 = num(r["t0"]), t1 = num(r["t1"]), tol = num(r["tolerance"]);
      const long n = std::max(1L, static_cast<long>(std::ceil(1 / std::pow(tol, 0.25))));
      vec y = nums(r["y"]);
      const double h = (t1 - t0) / static_cast<double>(n);
      try {
        for (long i = 0; i < n; ++i) y = step(t0 + static_cast<double>(i) * h, h, y);
        send({{"y", hexes(y)}, {"accepted", n}, {"rejected", 0}});
      } catch (const std::exception& e) {
        send({{"error", e.what()}});
      }
      continue;
    }
    if (op != "step") {
      send({{"error", "unknown op " + op}});
      continue;
    }
    if (mode == "crash") std::abort();
    if (mode == "hang") {
      std::fprintf(stderr, "hanging at the first step\n");
      for (;;) pause();
    }
    if (mode == "grandchild") {
      const pid_t g = fork();
      if (g == 0) {
        for (;;) pause();
      }
      std::fprintf(stderr, "pids %d %d\n", static_cast<int>(getpid()), static_cast<int>(g));
      for (;;) pause();
    }
    if (mode == "exit") {
      std::fprintf(stderr, "giving up\n");
      std::exit(3);
    }
    if (mode == "malformed") {
      std::cout << "not json\n" << std::flush;
      continue;
    }
    if (mode == "oversized") {
      std::cout << std::string(2 << 20, 'x') << "\n" << std::flush;
      continue;
    }
    vec y = nums(r["y"]);
    if (mode == "extra_field") {  // a field version 1 does not have: a protocol breach
      send({{"y", hexes(y)}, {"yy", hexes(y)}});
      continue;
    }
    if (mode == "nan") {
      y[0] = std::nan("");
      send({{"y", hexes(y)}});
      continue;
    }
    try {
      send({{"y", hexes(step(num(r["t"]), num(r["h"]), y))}});
    } catch (const std::exception& e) {
      send({{"error", e.what()}});
    }
  }
}
