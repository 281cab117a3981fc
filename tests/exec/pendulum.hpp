#pragma once
// A hinge pendulum about world y in its joint coordinates (theta, rate), for the exec
// protocol's engine child (child.cpp) and the benchmark of its cost (bench/exec_bench.cpp):
// the scenario's body (mass m, centre of mass c in its frame, moment I_yy) under gravity g
// along -z; theta'' = m g (c_x cos theta + c_z sin theta) / (m |c|^2 + I_yy). A step may be
// given a cost in wall time (a busy wait), to stand for an engine's work.
#include <chrono>
#include <cmath>
#include <string>
#include <vector>

namespace exec_test {

struct pendulum {
  double m = 1, g = 0, cx = 0, cz = 0, j = 1;
  double theta = 0, rate = 0;
  std::string integrator;  ///< "rk4", else symplectic Euler
  long steps = 0, requests = 0;
  std::chrono::nanoseconds cost{0};

  double acc(double th) const { return m * g * (cx * std::cos(th) + cz * std::sin(th)) / j; }
  void step(double h) {
    ++steps;
    if (cost.count() > 0) {
      const auto until = std::chrono::steady_clock::now() + cost;
      while (std::chrono::steady_clock::now() < until) {
      }
    }
    if (integrator == "rk4") {
      const double k1 = rate, l1 = acc(theta), k2 = rate + h / 2 * l1, l2 = acc(theta + h / 2 * k1),
                   k3 = rate + h / 2 * l2, l3 = acc(theta + h / 2 * k2), k4 = rate + h * l3, l4 = acc(theta + h * k3);
      theta += h / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
      rate += h / 6 * (l1 + 2 * l2 + 2 * l3 + l4);
    } else {  // symplectic Euler: the rate first
      rate += h * acc(theta);
      theta += h * rate;
    }
  }
  /// The frame: R = R_y(theta) (row-major), the centre of mass R c, its velocity w x R c with
  /// w = (0, rate, 0), and w.
  std::vector<double> frame() const {
    const double c = std::cos(theta), s = std::sin(theta);
    const double x = cx * c + cz * s, z = -cx * s + cz * c;
    return {c, 0, s, 0, 1, 0, -s, 0, c, x, 0, z, rate * z, 0, -rate * x, 0, rate, 0};
  }
};

}  // namespace exec_test
