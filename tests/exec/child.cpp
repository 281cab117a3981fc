// A child serving a stepper by the protocol of docs/protocol.md, for the tests of
// audit/exec.hpp: well-behaved (velocity Verlet, classical RK4, and explicit Euler that
// claims order 2), or misbehaving on its first step in one way each.
//
// Usage: mechcheck_exec_child MODE
//   verlet       velocity Verlet on y = (q, p), q and p of equal length (canonical,
//                separable); claims order 2, symplectic, symmetric
//   rk4          classical RK4 on any y; claims order 4
//   euler_says_2 explicit Euler; claims order 2 (the audit must contradict it)
//   crash        abort() at the first step          hang       sleeps at the first step
//   exit         exit(3) at the first step          malformed  replies "not json"
//   oversized    replies a 2 MiB line               nan        replies a NaN state
//   version_2    its handshake says protocol version 2
//   grandchild   starts a grandchild that sleeps, then hangs (both must be killed)
//   driver       an adaptive driver (kind "driver"): RK4 at h = tol^(1/4) (t1 - t0)
//   driver_fails a driver that reports a failure for every integration
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

using json = nlohmann::json;
using vec = std::vector<double>;

namespace {
std::string mode;

std::string hex(double x) {
  char b[40];
  std::snprintf(b, sizeof b, "%a", x);
  return b;
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

vec axpy(const vec& y, double a, const vec& x) {
  vec out = y;
  for (std::size_t i = 0; i < y.size(); ++i) out[i] += a * x[i];
  return out;
}

vec step(double t, double h, vec y) {
  const std::size_t n = y.size();
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
  const vec k1 = rhs(t, y), k2 = rhs(t + h / 2, axpy(y, h / 2, k1)), k3 = rhs(t + h / 2, axpy(y, h / 2, k2)),
            k4 = rhs(t + h, axpy(y, h, k3));
  for (std::size_t i = 0; i < n; ++i) y[i] += h / 6 * (k1[i] + 2 * k2[i] + 2 * k3[i] + k4[i]);
  return y;
}
}  // namespace

int main(int argc, char** argv) {
  mode = argc > 1 ? argv[1] : "rk4";
  const bool driver = mode == "driver" || mode == "driver_fails";
  json hello = {{"protocol", "mechcheck"}, {"version", mode == "version_2" ? 2 : 1}, {"kind", driver ? "driver" : "stepper"},
                {"name", "test_child/" + mode}, {"origin", "tests/exec/child.cpp"}};
  if (mode == "verlet")
    hello["claims"] = {{"order", 2}, {"symplectic", true}, {"symmetric", true}},
    hello["structure"] = {{"canonical", true}, {"separable", true}};
  else
    hello["claims"] = {{"order", mode == "rk4" ? 4 : 2}};
  send(hello);
  for (;;) {
    const json r = receive();
    const std::string op = r.value("op", "");
    if (op == "start" || op == "end") {
      send({{"ok", true}});
      continue;
    }
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
