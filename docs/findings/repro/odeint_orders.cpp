// Boost.Odeint: velocity_verlet declares order_value = 1 and is of order 2; the SB3A
// Runge-Kutta-Nystrom method symplectic_rkn_sb3a_mclachlan has two coefficients written as
// double literals, so in a 50-digit type its one-step error falls as h^3 instead of h^5
// at small steps (symplectic_rkn_sb3a_m4_mclachlan, with exact coefficients, is at the
// type's rounding there). Uses Boost only
// (Odeint and Boost.Multiprecision's cpp_bin_float_50).
//
// Problems: q'' = -q on two degrees of freedom from q = (1, 0), p = (1/4, 3/4): the exact
// flow is q(t) = q0 cos t + p0 sin t. velocity_verlet: global error at t = 2 pi from 256 to
// 512 steps. SB3A: the error of one step of h = 2^-32 and 2^-33 in cpp_bin_float_50: the
// rounded coefficients leave an error ~ 1e-17 h^3, which passes the method's C h^5 below
// h ~ 1e-8 and stays far above the type's rounding (1e-50) there.
//
// Build: c++ -std=c++17 odeint_orders.cpp
// Prints: lines "name value" (see ci/findings).
#include <array>
#include <cmath>
#include <cstdio>
#include <utility>

#include <boost/multiprecision/cpp_bin_float.hpp>
#include <boost/numeric/odeint.hpp>
#include <boost/numeric/odeint/stepper/symplectic_rkn_sb3a_m4_mclachlan.hpp>
#include <boost/version.hpp>

namespace ode = boost::numeric::odeint;

template <class T>
using vec = std::array<T, 2>;

// The acceleration of the oscillator: velocity_verlet's system (q, p, a, t).
struct oscillator_acceleration {
  template <class V, class T>
  void operator()(const V& q, const V&, V& a, T) const {
    a[0] = -q[0];
    a[1] = -q[1];
  }
};
// The force of the oscillator for the RKN steppers: coor -> momentum derivative.
struct oscillator_force {
  template <class V>
  void operator()(const V& q, V& dp) const {
    dp[0] = -q[0];
    dp[1] = -q[1];
  }
};

template <class T>
T error_of(const vec<T>& q, const vec<T>& p, const T& t) {
  using std::cos;
  using std::sin;
  using std::sqrt;
  const vec<T> q0{T(1), T(0)}, p0{T(1) / 4, T(3) / 4};
  T e2 = 0, n2 = 0;
  for (int i = 0; i < 2; ++i) {
    const T qe = q0[i] * cos(t) + p0[i] * sin(t), pe = p0[i] * cos(t) - q0[i] * sin(t);
    e2 += (q[i] - qe) * (q[i] - qe) + (p[i] - pe) * (p[i] - pe);
    n2 += q0[i] * q0[i] + p0[i] * p0[i];
  }
  return sqrt(e2 / n2);
}

double verlet_error(int n) {
  const double pi = std::acos(-1.0), h = 2 * pi / n;
  vec<double> q{1, 0}, p{0.25, 0.75};
  ode::velocity_verlet<vec<double>> stepper;
  for (int i = 0; i < n; ++i) stepper.do_step(oscillator_acceleration(), std::make_pair(std::ref(q), std::ref(p)), i * h, h);
  return error_of<double>(q, p, 2 * pi);
}

template <class Stepper, class T>
T one_step_error(const T& h) {
  vec<T> q{T(1), T(0)}, p{T(1) / 4, T(3) / 4};
  Stepper stepper;
  stepper.do_step(oscillator_force(), std::make_pair(std::ref(q), std::ref(p)), T(0), h);
  return error_of<T>(q, p, h);
}

int main() {
  std::printf("boost_version %d\n", BOOST_VERSION);
  std::printf("velocity_verlet_order_value %d\n", int(ode::velocity_verlet<vec<double>>::order_value));
  std::printf("velocity_verlet_global_order %.3f\n", std::log2(verlet_error(256) / verlet_error(512)));
  using mp = boost::multiprecision::cpp_bin_float_50;
  using sb3a = ode::symplectic_rkn_sb3a_mclachlan<vec<mp>, vec<mp>, mp>;
  using sb3a_m4 = ode::symplectic_rkn_sb3a_m4_mclachlan<vec<mp>, vec<mp>, mp>;
  std::printf("sb3a_order_value %d\n", int(sb3a::order_value));
  const mp h1 = ldexp(mp(1), -32), h2 = ldexp(mp(1), -33);
  std::printf("sb3a_local_order_cpp_bin_float_50 %.3f\n",
              static_cast<double>(log2(one_step_error<sb3a>(h1) / one_step_error<sb3a>(h2))));
  // The same step of the analytic-coefficient variant: at the type's rounding there.
  std::printf("sb3a_one_step_error_at_2^-33 %.3e\n", static_cast<double>(one_step_error<sb3a>(h2)));
  std::printf("sb3a_m4_one_step_error_at_2^-33 %.3e\n", static_cast<double>(one_step_error<sb3a_m4>(h2)));
  // The two coefficients as written, and what the type holds of them.
  const mp written("0.40518861839525227722"), held = static_cast<mp>(0.40518861839525227722);
  std::printf("sb3a_a1_held_minus_written %.3e\n", static_cast<double>(held - written));
  return 0;
}
