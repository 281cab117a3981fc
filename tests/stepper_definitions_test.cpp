// Every library stepper by its definition: one step from a fixed state equals the method's
// defining formula, written out here independently, in mpfr50 to a few eps. Order,
// symplecticity and symmetry do not pin a method (a stepper replaced by its adjoint keeps
// all three); the formula does.

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <vector>

#include <boost/math/special_functions/legendre.hpp>

#include "mechcheck/integrators.hpp"
#include "tiers.hpp"

namespace stepper_definitions {
using namespace mechcheck;
using T = mpfr50;
using vec = dynamic_vector<T>;
using state = phase_state<vec>;

/// The planar Kepler problem H = |p|^2/2 - 1/|q| (mass 1, k = 1): separable, nonlinear.
const kepler_system<T> kepler(T(1), T(1));

vec force(const vec& q) {
  using std::sqrt;
  const T r = sqrt(q.squaredNorm());
  return vec(-q / (r * r * r));
}
vec velocity(const vec& p) { return p; }

state start() {
  vec q(2), p(2);
  q << T(1), T(1) / 4;
  p << T(1) / 10, T(9) / 10;
  return {q, p};
}

const T h = T(1) / 8;

/// |a - b| in eps of mpfr50 on the state's scale (~1).
double eps_distance(const state& a, const state& b) {
  using std::sqrt;
  const T d = sqrt(T((a.q - b.q).squaredNorm() + (a.p - b.p).squaredNorm()));
  return static_cast<double>(T(d / tier_epsilon<T>()));
}

template <template <class, class> class Method>
state library_step(const state& x0, const T& step = h) {
  Method<kepler_system<T>, vec> method{kepler};
  state x = x0;
  method(x, step);
  return x;
}

state kick(state x, const T& dt) {
  x.p += dt * force(x.q);
  return x;
}
state drift(state x, const T& dt) {
  x.q += dt * velocity(x.p);
  return x;
}
state verlet(const state& x, const T& dt) { return kick(drift(kick(x, dt / 2), dt), dt / 2); }

// A few eps (measured: at most 1.9 eps, composition8): each formula rounds a few times per
// evaluation; the library's compensated or
// in-place arithmetic rounds differently. The distance between the library and the formula
// for a different method (the adjoint, a wrong coefficient) is ~h^2 or more: 1e47 eps.
constexpr double budget = 16;

TEST(stepper_definitions, explicit_euler) {
  const state x0 = start();
  const state expected{vec(x0.q + h * velocity(x0.p)), vec(x0.p + h * force(x0.q))};
  EXPECT_LE(eps_distance(library_step<explicit_euler>(x0), expected), budget);
}

TEST(stepper_definitions, symplectic_euler_kicks_then_drifts) {
  const state x0 = start();
  EXPECT_LE(eps_distance(library_step<symplectic_euler>(x0), drift(kick(x0, h), h)), budget);
  // Its adjoint (drift then kick) is a different map.
  EXPECT_GT(eps_distance(library_step<symplectic_euler>(x0), kick(drift(x0, h), h)), 1e40);
}

TEST(stepper_definitions, stormer_verlet_is_kick_drift_kick) {
  const state x0 = start();
  EXPECT_LE(eps_distance(library_step<stormer_verlet>(x0), verlet(x0, h)), budget);
  const state dkd = drift(kick(drift(x0, h / 2), h), h / 2);  // position Verlet
  EXPECT_GT(eps_distance(library_step<stormer_verlet>(x0), dkd), 1e40);
  // Later steps reuse the last force (first same as last): still the same map.
  stormer_verlet<kepler_system<T>, vec> method{kepler};
  state x = x0, y = x0;
  for (int k = 0; k < 3; ++k) {
    method(x, h);
    y = verlet(y, h);
  }
  EXPECT_LE(eps_distance(x, y), 3 * budget);
}

TEST(stepper_definitions, rk4_is_the_classical_tableau) {
  const state x0 = start();
  const auto f = [](const state& x) { return state{velocity(x.p), force(x.q)}; };
  const auto plus = [](const state& x, const T& a, const state& k) {
    return state{vec(x.q + a * k.q), vec(x.p + a * k.p)};
  };
  const state k1 = f(x0), k2 = f(plus(x0, h / 2, k1)), k3 = f(plus(x0, h / 2, k2)),
              k4 = f(plus(x0, h, k3));
  const state expected{vec(x0.q + h / 6 * (k1.q + 2 * k2.q + 2 * k3.q + k4.q)),
                       vec(x0.p + h / 6 * (k1.p + 2 * k2.p + 2 * k3.p + k4.p))};
  EXPECT_LE(eps_distance(library_step<rk4>(x0), expected), budget);
}

/// The triple jump S_{2k+2}(h) = S_{2k}(g1 h) S_{2k}(g0 h) S_{2k}(g1 h) in closed form:
/// g1 = 1/(2 - 2^(1/(2k+1))), g0 = -2^(1/(2k+1)) g1 (Yoshida 1990, eq 5.18).
state triple_jump(const state& x, const T& dt, int order) {
  if (order == 2) return verlet(x, dt);
  using std::cbrt;
  using std::pow;
  const int k = order / 2 - 1;
  const T root = pow(T(2), T(1) / T(2 * k + 1));
  const T g1 = 1 / (2 - root), g0 = -root * g1;
  return triple_jump(triple_jump(triple_jump(x, g1 * dt, order - 2), g0 * dt, order - 2),
                     g1 * dt, order - 2);
}

template <class S, class V>
using composition4 = composition<S, V, 4>;
template <class S, class V>
using composition6 = composition<S, V, 6>;
template <class S, class V>
using composition8 = composition<S, V, 8>;

TEST(stepper_definitions, compositions_are_yoshidas_triple_jumps) {
  const state x0 = start();
  EXPECT_LE(eps_distance(library_step<composition4>(x0), triple_jump(x0, h, 4)), budget);
  EXPECT_LE(eps_distance(library_step<composition6>(x0), triple_jump(x0, h, 6)), 4 * budget);
  EXPECT_LE(eps_distance(library_step<composition8>(x0), triple_jump(x0, h, 8)), 16 * budget);
}

/// McLachlan's SB3A: b1 = -3/73, b2 = 17/59, b3 = 1 - 2(b1 + b2) and a1, a2 solving
///   sum_i a_i d_i^2 = 1/3 (linear in a1, a2; d_i the kicks before drift i) and
///   sum_i b_i c_i^2 = 1/3 (quadratic; c_i the drifts before kick i),
/// a3 = 1/2 - a1 - a2: the linear condition gives a2(a1), the quadratic one is fitted
/// exactly through three points and solved in closed form (the library uses Newton).
std::array<T, 3> sb3a_drifts() {
  const T b1 = T(-3) / 73, b2 = T(17) / 59, b3 = 1 - 2 * (b1 + b2);
  const std::array<T, 5> b{b1, b2, b3, b2, b1};
  const auto drifts = [](const T& a1, const T& a2) {
    const T a3 = T(1) / 2 - a1 - a2;
    return std::array<T, 6>{a1, a2, a3, a3, a2, a1};
  };
  const auto linear = [&](const T& a1, const T& a2) {
    const auto a = drifts(a1, a2);
    T d = 0, sum = 0;
    for (int i = 0; i < 6; ++i) {
      sum += a[i] * d * d;
      if (i < 5) d += b[i];
    }
    return T(sum - T(1) / 3);
  };
  // linear(a1, a2) = l0 + la a1 + lb a2.
  const T l0 = linear(0, 0), la = linear(1, 0) - l0, lb = linear(0, 1) - l0;
  const auto a2_of = [&](const T& a1) { return T(-(l0 + la * a1) / lb); };
  const auto quadratic = [&](const T& a1) {
    const auto a = drifts(a1, a2_of(a1));
    T c = 0, sum = 0;
    for (int i = 0; i < 5; ++i) {
      c += a[i];
      sum += b[i] * c * c;
    }
    return T(sum - T(1) / 3);
  };
  // Through a1 = 0, 1/2, 1: q(a1) = A a1^2 + B a1 + C.
  const T q0 = quadratic(0), q1 = quadratic(T(1) / 2), q2 = quadratic(1);
  const T cc = q0, aa = 2 * (q2 - 2 * q1 + q0), bb = q2 - q0 - aa;
  using std::abs;
  using std::sqrt;
  const T disc = sqrt(T(bb * bb - 4 * aa * cc));
  const T r1 = (-bb + disc) / (2 * aa), r2 = (-bb - disc) / (2 * aa);
  // McLachlan's published a1 = 0.40518861839525227722 (1995, table of SB3A).
  const T a1 = abs(T(r1 - T(0.4))) < abs(T(r2 - T(0.4))) ? r1 : r2;
  const T a2 = a2_of(a1);
  return {a1, a2, T(T(1) / 2 - a1 - a2)};
}

TEST(stepper_definitions, mclachlan4_is_sb3a) {
  const auto a = sb3a_drifts();
  // The published digits (McLachlan 1995): a1 = 0.40518861839525227722,
  // a2 = -0.28714404081652408900.
  EXPECT_LT(static_cast<double>(abs(T(a[0] - T("0.40518861839525227722")))), 1e-20);
  EXPECT_LT(static_cast<double>(abs(T(a[1] - T("-0.28714404081652408900")))), 1e-20);
  const T b1 = T(-3) / 73, b2 = T(17) / 59, b3 = 1 - 2 * (b1 + b2);
  state x = start();
  const std::array<T, 6> drifts{a[0], a[1], a[2], a[2], a[1], a[0]};
  const std::array<T, 5> kicks{b1, b2, b3, b2, b1};
  for (int i = 0; i < 6; ++i) {
    x = drift(x, drifts[i] * h);
    if (i < 5) x = kick(x, kicks[i] * h);
  }
  EXPECT_LE(eps_distance(library_step<mclachlan4>(start()), x), budget);
}

/// The s-stage Gauss-Legendre method from its definition: nodes c_i = (1 + x_i)/2 at the
/// roots of P_s (Boost.Math's legendre_p_zeros), and a_ij, b_j from the simplifying
/// assumptions C(s), B(s): sum_j a_ij c_j^(k-1) = c_i^k / k, sum_j b_j c_j^(k-1) = 1/k,
/// k = 1..s (Vandermonde systems, solved by Eigen). The stages by fixed-point iteration
/// to convergence in the tier.
template <int S>
state gauss_step(const state& x0, const T& dt) {
  const auto zeros = boost::math::legendre_p_zeros<T>(S);  // non-negative zeros
  std::vector<T> x;
  for (const T& z : zeros) {
    x.push_back(-z);
    if (z != 0) x.push_back(z);
  }
  std::sort(x.begin(), x.end());
  dynamic_vector<T> c(S);
  for (int i = 0; i < S; ++i) c(i) = (1 + x[i]) / 2;
  dynamic_matrix<T> v(S, S);  // v(k, j) = c_j^k
  for (int k = 0; k < S; ++k)
    for (int j = 0; j < S; ++j) v(k, j) = pow(c(j), k);
  dynamic_vector<T> rhs_b(S);
  for (int k = 0; k < S; ++k) rhs_b(k) = T(1) / T(k + 1);
  const dynamic_vector<T> b = v.fullPivLu().solve(rhs_b);
  dynamic_matrix<T> a(S, S);
  for (int i = 0; i < S; ++i) {
    dynamic_vector<T> rhs(S);
    for (int k = 0; k < S; ++k) rhs(k) = pow(c(i), k + 1) / T(k + 1);
    a.row(i) = v.fullPivLu().solve(rhs).transpose();
  }
  std::vector<state> k(S, state{velocity(x0.p), force(x0.q)});
  for (int iteration = 0; iteration < 400; ++iteration) {
    std::vector<state> next;
    for (int i = 0; i < S; ++i) {
      state y = x0;
      for (int j = 0; j < S; ++j) {
        y.q += dt * a(i, j) * k[j].q;
        y.p += dt * a(i, j) * k[j].p;
      }
      next.push_back({velocity(y.p), force(y.q)});
    }
    k = next;
  }
  state out = x0;
  for (int i = 0; i < S; ++i) {
    out.q += dt * b(i) * k[i].q;
    out.p += dt * b(i) * k[i].p;
  }
  return out;
}

template <int S>
void expect_gauss_legendre() {
  const state x0 = start();
  gauss_legendre<kepler_system<T>, vec, S> method{kepler};
  state x = x0;
  method(x, h);
  EXPECT_LE(eps_distance(x, gauss_step<S>(x0, h)), budget) << S << " stages";
}

TEST(stepper_definitions, gauss_legendre_is_collocation_at_the_gauss_nodes) {
  expect_gauss_legendre<1>();
  expect_gauss_legendre<2>();
  expect_gauss_legendre<3>();
  expect_gauss_legendre<4>();
}

}  // namespace stepper_definitions
