/// Tops: Euler's equations and the free rigid body, the intermediate-axis theorem, the
/// heavy symmetric top (notes lectures 17-20, eqs 169-243).
///
/// Exact identities are checked to k eps of their natural scale. Integrated motion is
/// checked against exact solutions by a convergence study (Gauss-Legendre 4, order 8:
/// the error against the reference must fall as h^8, so a reference wrong by d would
/// stall the study at d), and the quadratic invariants that Gauss-Legendre keeps exactly
/// (|M|^2, T, R^T M, R^T R) to the rounding of the steps.

#include <array>
#include <cmath>

#include "convergence.hpp"
#include "generators.hpp"
#include "mechcheck/harness/law.hpp"
#include "mechcheck/reference.hpp"

namespace {

namespace mc = mechcheck;
namespace gen = mechcheck::generators;
using mc::dynamic_vector;
using mc::lift;
using mc::matrix3;
using mc::vector3;
using mc::harness::check_close;
using mc::harness::check_zero;
using mc::harness::law_info;
using mc::properties::check_exponent;
using mc::properties::converged_exponent;
using mc::properties::steps_for;

template <class T>
using body_stepper = mc::gauss_legendre<mc::free_rigid_body<T>, dynamic_vector<T>, 4>;

/// Principal moments (a + b, b + c, c + a) with a, b, c in [1/4, 2]: the triangle
/// inequality holds with room (I_i + I_j - I_k = 2 * one of a, b, c).
template <class T>
vector3<T> random_moments() {
  const double a = *gen::dyadic(0.25, 2), b = *gen::dyadic(0.25, 2), c = *gen::dyadic(0.25, 2);
  return vector3<T>(T(a + b), T(b + c), T(c + a));
}

template <class T>
matrix3<T> random_attitude() {
  const double phi = *gen::dyadic(-3, 3), theta = *gen::dyadic(-3, 3), psi = *gen::dyadic(-3, 3);
  return mc::euler_rotation(T(phi), T(theta), T(psi));
}

template <class T>
mc::phase_state<dynamic_vector<T>> body_state(const vector3<T>& m, const matrix3<T>& r) {
  return {dynamic_vector<T>(m), mc::attitude_state(r)};
}

/// M alone, without the attitude.
template <class T>
mc::phase_state<dynamic_vector<T>> body_only(const vector3<T>& m) {
  return {dynamic_vector<T>(m), dynamic_vector<T>(0)};
}

template <class T>
vector3<T> momentum_of(const mc::phase_state<dynamic_vector<T>>& x) {
  return vector3<T>(x.q(0), x.q(1), x.q(2));
}

/// Integrate the free body to time t_end in `steps` Gauss-Legendre steps.
template <class T>
mc::phase_state<dynamic_vector<T>> free_motion(const mc::free_rigid_body<T>& body,
                                               mc::phase_state<dynamic_vector<T>> x,
                                               const T& t_end, long steps) {
  body_stepper<T> step{body};
  mc::integrate(step, x, T(t_end / steps), steps);
  return x;
}

struct euler_equations {
  static law_info info() {
    return {"rigid.euler_equations",
            "Euler's equations I1 dOmega1/dt + Omega2 Omega3 (I3 - I2) = 0 (cyclic) are "
            "dM/dt = M x Omega; with dR/dt they keep R^T M, |M|^2 and T constant",
            {"169", "170", "171", "172", "173", "174", "175"}};
  }
  // Products of three factors and 2-3 term sums: k = 16 on |M|^2 max(1/I) (the size of
  // M x Omega); R^T M sums 3 products of R entries (<= 1) with M: k = 16 on the same.
  template <class T>
  static void property() {
    const mc::free_rigid_body<T> body(random_moments<T>());
    const vector3<T> m = gen::draw_vector3<T>();
    const matrix3<T> r = random_attitude<T>();
    const vector3<T> w = body.angular_velocity(m);
    const vector3<T>& in = body.moments;
    const T scale = m.squaredNorm() / in.minCoeff() + 1;
    dynamic_vector<T> dq(3), dp(9);
    const auto x = body_state(m, r);
    body.vector_field(x.q, x.p, dq, dp);
    // Eqs 173-175 as printed: I_i dOmega_i/dt = -Omega_j Omega_k (I_k - I_j).
    const vector3<T> printed(-w(1) * w(2) * (in(2) - in(1)), -w(2) * w(0) * (in(0) - in(2)),
                             -w(0) * w(1) * (in(1) - in(0)));
    for (int i = 0; i < 3; ++i)
      check_close("I" + std::to_string(i + 1) + " dOmega/dt vs eqs 173-175", dq(i), printed(i),
                  scale, 16);
    const vector3<T> dm(dq(0), dq(1), dq(2));
    const vector3<T> lab_rate = mc::attitude_matrix(dp).transpose() * m + r.transpose() * dm;
    for (int i = 0; i < 3; ++i)
      check_zero("d/dt (R^T M)_" + std::to_string(i + 1) + " (eq 170)", lab_rate(i), scale, 16);
    check_zero("d|M|^2/dt", T(2 * m.dot(dm)), T(scale * m.norm() + 1), 16);
    check_zero("dT/dt", T(w.dot(dm)), T(scale * w.norm() + 1), 16);
  }
};
MECHCHECK_LAW(euler_equations);

struct free_body_invariants {
  static law_info info() {
    return {"rigid.free_body_invariants",
            "Along the free motion |M|^2 and T are conserved, M is constant in the lab frame "
            "and R stays orthogonal (Gauss-Legendre keeps these quadratic invariants exactly)",
            {"170", "172", "173", "174", "175"}};
  }
  // Rounding only: each of n steps adds a few eps (Kahan-compensated update, stages
  // converged to the floor) to quantities of size |M|^2 max(1/I): k = 8 n.
  template <class T>
  static void property() {
    const mc::free_rigid_body<T> body(random_moments<T>());
    const vector3<T> m0 = gen::draw_vector3<T>();
    const matrix3<T> r0 = random_attitude<T>();
    const long steps = 16;
    const auto x = free_motion(body, body_state(m0, r0), T(1), steps);
    const vector3<T> m = momentum_of(x);
    const matrix3<T> r = mc::attitude_matrix(x.p);
    const T scale = m0.squaredNorm() / body.moments.minCoeff() + 1;
    const double k = 8.0 * steps;
    check_close("|M|^2", m.squaredNorm(), m0.squaredNorm(), scale, k);
    check_close("T", body.kinetic_energy(m), body.kinetic_energy(m0), scale, k);
    const vector3<T> lab = mc::lab_angular_momentum(m, r), lab0 = mc::lab_angular_momentum(m0, r0);
    for (int i = 0; i < 3; ++i)
      check_close("lab M_" + std::to_string(i + 1), lab(i), lab0(i), scale, k);
    const matrix3<T> gram = r * r.transpose() - matrix3<T>::Identity();
    check_zero("max |R R^T - 1|", gram.cwiseAbs().maxCoeff(), lift<T>(1), k);
  }
};
MECHCHECK_LAW(free_body_invariants);

/// A free symmetric top with I1 = I2 in [1/2, 2], I3 / I1 in [1/8, 2] (the triangle
/// inequality allows up to 2), |M| in [1/2, 2] and any attitude.
template <class T>
mc::reference::free_symmetric_top<T> random_symmetric_top() {
  const T i1 = T(*gen::dyadic(0.5, 2));
  const T i3 = i1 * T(*gen::dyadic(0.125, 2));
  const T m = T(*gen::dyadic(0.5, 2));
  return {i1, i3, m, T(*gen::dyadic(-3, 3)), T(*gen::dyadic(0.125, 3)), T(*gen::dyadic(-3, 3))};
}

struct symmetric_free_top {
  static law_info info() {
    return {"rigid.symmetric_free_top",
            "Free symmetric top: Omega_1, Omega_2 turn at omega = Omega_3 (I3 - I1)/I1 in the "
            "body, the axis precesses about M at M/I1 in the lab; the integrated motion "
            "converges to R(phi0 + M t/I1, theta0, psi0 - omega t) with order 8",
            {"176", "177", "178", "179", "181", "182", "183", "184", "185", "186", "187",
             "188", "222", "223", "224", "225", "226"}};
  }
  // Exact part: Omega from the Euler-angle rates (phidot = M/I1, thetadot = 0,
  // psidot = -omega, eq 226) equals I^-1 M (eqs 222-226), and Omega + omega x3 = M/I1
  // (eqs 185-188): few-term sums, k = 16 on M/I_min. Integrated part: truncation model
  // e(h) = C h^8 for Gauss-Legendre 4 against the closed form at t = 1.
  template <class T>
  static void property() {
    const auto top = random_symmetric_top<T>();
    const mc::free_rigid_body<T> body(vector3<T>(top.i1, top.i1, top.i3));
    const vector3<T> m0 = top.body_momentum();
    const vector3<T> w = body.angular_velocity(m0);
    const T scale = top.momentum / (top.i1 < top.i3 ? top.i1 : top.i3);
    const vector3<T> from_rates = mc::body_angular_velocity(
        top.phi0, top.theta0, top.psi0, top.precession_rate(), lift<T>(0), top.spin_rate());
    const vector3<T> sum = w + top.body_frequency() * vector3<T>::UnitZ();
    for (int i = 0; i < 3; ++i) {
      check_close("Omega_" + std::to_string(i + 1) + " from the rates vs I^-1 M", from_rates(i),
                  w(i), scale, 16);
      check_close("(Omega + omega x3)_" + std::to_string(i + 1) + " vs M/I1", sum(i),
                  T(m0(i) / top.i1), scale, 16);
    }
    const auto x0 = body_state(m0, top.attitude(T(0)));
    const matrix3<T> r_ref = top.attitude(T(1));
    const vector3<T> m_ref = r_ref * vector3<T>(T(0), T(0), top.momentum);
    const auto error = [&](const T& h) {
      const auto x = free_motion(body, x0, T(1), steps_for(h));
      const T er = (mc::attitude_matrix(x.p) - r_ref).cwiseAbs().maxCoeff();
      const T em = (momentum_of(x) - m_ref).cwiseAbs().maxCoeff() / top.momentum;
      return er > em ? er : em;
    };
    check_exponent("attitude and M against the closed form: fitted order",
                   converged_exponent(error, T(0.25), 8, lift<T>(1)), 8);
  }
};
MECHCHECK_LAW(symmetric_free_top);

struct erratum_180 {
  static law_info info() {
    return {"rigid.erratum_180",
            "Printed eq 180 has the wrong sign: dOmega_2/dt = +omega Omega_1 (from eq 177)",
            {"180"},
            mc::harness::expectation::falsified,
            "printed: dOmega_2/dt = -omega Omega_1 (with eq 179 that is hyperbolic, not the "
            "oscillation of eqs 182-184); correct: dOmega_2/dt = omega Omega_1"};
  }
  template <class T>
  static void property() {
    const auto top = random_symmetric_top<T>();
    const mc::free_rigid_body<T> body(vector3<T>(top.i1, top.i1, top.i3));
    const vector3<T> m = top.body_momentum();
    const vector3<T> w = body.angular_velocity(m);
    const vector3<T> dw = body.angular_velocity(body.momentum_rate(m));
    const T omega = w(2) * (top.i3 - top.i1) / top.i1;
    check_close("dOmega_2/dt vs printed -omega Omega_1", dw(1), T(-omega * w(0)),
                T(m.squaredNorm() / (top.i1 * top.i3) + 1), 16);
  }
};
MECHCHECK_LAW(erratum_180);

struct erratum_227 {
  static law_info info() {
    return {"rigid.erratum_227",
            "Printed eq 227 has the wrong sign: psidot = M3/I3 - M3/I1 (eq 226) is -omega",
            {"227"},
            mc::harness::expectation::falsified,
            "printed: psidot = Omega_3 (I3 - I1)/I1 = omega; correct: psidot = Omega_3 "
            "(I1 - I3)/I1 = -omega (the body turns at -omega relative to the plane of M, "
            "Omega and x_3, which is why Omega turns at +omega in the body)"};
  }
  template <class T>
  static void property() {
    const auto top = random_symmetric_top<T>();
    const mc::free_rigid_body<T> body(vector3<T>(top.i1, top.i1, top.i3));
    const vector3<T> w = body.angular_velocity(top.body_momentum());
    const vector3<T> from_rates = mc::body_angular_velocity(
        top.phi0, top.theta0, top.psi0, top.precession_rate(), lift<T>(0), top.body_frequency());
    check_close("Omega_3 from the rates with printed psidot vs M3/I3", from_rates(2), w(2),
                T(top.momentum / (top.i1 < top.i3 ? top.i1 : top.i3)), 16);
  }
};
MECHCHECK_LAW(erratum_227);

/// Moments I1 < I2 < I3 = (a + b, a + c, b + c) with a < b < c, spaced by >= 1/8.
template <class T>
vector3<T> ordered_moments() {
  const double a = *gen::dyadic(0.25, 1);
  const double b = a + *gen::dyadic(0.125, 1);
  const double c = b + *gen::dyadic(0.125, 1);
  return vector3<T>(T(a + b), T(a + c), T(b + c));
}

struct asymmetric_free_top {
  static law_info info() {
    return {"rigid.asymmetric_free_top",
            "Free asymmetric top: the Jacobi-elliptic solution (reference) keeps |M|^2 and T, "
            "starts at Omega(0), and the integrated Euler equations converge to it with "
            "order 8",
            {"172", "173", "174", "175"}};
  }
  // The reference at t: sn, cn, dn to a few eps each, products of square roots: k = 64
  // on |M|^2 / I1. The study: e(h) = C h^8 for Gauss-Legendre 4, t in [0, 1].
  template <class T>
  static void property() {
    const vector3<T> in = ordered_moments<T>();
    const mc::free_rigid_body<T> body(in);
    const vector3<T> m0 = gen::draw_vector3<T>();
    const vector3<T> w0 = body.angular_velocity(m0);
    const T m2 = m0.squaredNorm(), two_e = m0.dot(w0);
    using std::abs;
    // Away from the separatrix M^2 = 2 E I2, where the period diverges (k -> 1).
    RC_PRE(abs(T(m2 - two_e * in(1))) > m2 / 64);
    const T scale = m2 / in(0) + 1;
    const auto reference = [&](const T& t) {
      return mc::reference::asymmetric_top_angular_velocity(in, w0, t);
    };
    const vector3<T> start = reference(T(0));
    for (int i = 0; i < 3; ++i)
      check_close("reference Omega_" + std::to_string(i + 1) + "(0)", start(i), w0(i),
                  T(w0.norm() + 1), 64);
    const vector3<T> w1 = reference(T(1));
    const vector3<T> m1 = in.cwiseProduct(w1);
    check_close("reference |M|^2 at t = 1", m1.squaredNorm(), m2, scale, 64);
    check_close("reference 2T at t = 1", m1.dot(w1), two_e, scale, 64);
    const auto x0 = body_state(m0, matrix3<T>(matrix3<T>::Identity()));
    const auto error = [&](const T& h) {
      const auto x = free_motion(body, x0, T(1), steps_for(h));
      return T((body.angular_velocity(momentum_of(x)) - w1).cwiseAbs().maxCoeff());
    };
    check_exponent("Omega(1) against the Jacobi solution: fitted order",
                   converged_exponent(error, T(0.25), 8, T(w0.norm() + 1)), 8);
  }
};
MECHCHECK_LAW(asymmetric_free_top);

/// d(dOmega/dt)/dOmega at Omega by AD.
template <class T>
mc::dynamic_matrix<T> euler_jacobian(const mc::free_rigid_body<T>& body, const vector3<T>& w) {
  const auto rate = [&body]<class S>(const dynamic_vector<S>& v) -> dynamic_vector<S> {
    const mc::free_rigid_body<T>& b = body;
    vector3<S> m;
    for (int i = 0; i < 3; ++i) m(i) = v(i) * lift<S>(b.moments(i));
    return dynamic_vector<S>(b.angular_velocity(b.momentum_rate(m)));
  };
  return mc::jacobian(rate, dynamic_vector<T>(w));
}

struct intermediate_axis {
  static law_info info() {
    return {"rigid.intermediate_axis",
            "Intermediate-axis theorem: about principal axis i the linearised Euler equations "
            "have eigenvalues 0, +-mu with mu^2 = Omega^2 (I_i - I_j)(I_k - I_i)/(I_j I_k), "
            "positive exactly for the middle axis; the perturbation grows at mu there and "
            "stays on its ellipse about the others",
            {"189", "190", "191", "192", "193", "194", "195", "197", "198", "199", "200",
             "201"}};
  }
  // Exact: (1/2) tr J^2 = mu^2 from AD, products of 4 factors: k = 32 on Omega^2 I3/I1.
  // Integrated (Gauss-Legendre 4, h mu = 1/16, to t = 4/mu): from the growing
  // eigenvector with |eta| = d = Omega/2^20, the nonlinear terms change the rate by
  // O((d e^{mu t}/Omega)^2) < 1e-8 and the truncation by O((h mu)^8) < 1e-9; the
  // measured rate must be within 1e-6 of mu. Stable axes: the quadratic form
  // Q = |I_i - I_j| I_j eta_j^2 + |I_k - I_i| I_k eta_k^2 is conserved by the linear flow;
  // nonlinear terms change it by a relative O(d / Omega) < 1e-5, the truncation
  // (h nu = 1/8, 32 steps) by O((h nu)^8) < 1e-7.
  template <class T>
  static void property() {
    const vector3<T> in = ordered_moments<T>();
    const mc::free_rigid_body<T> body(in);
    const T omega = T(*gen::dyadic(0.5, 2)) * (*rc::gen::arbitrary<bool>() ? 1 : -1);
    const T d = omega / T(1 << 20);
    using std::abs;
    using std::exp;
    using std::log;
    using std::sqrt;
    for (int i = 0; i < 3; ++i) {
      const int j = (i + 1) % 3, k = (i + 2) % 3;
      vector3<T> w = vector3<T>::Zero();
      w(i) = omega;
      const auto jac = euler_jacobian(body, w);
      const T mu2 = omega * omega * (in(i) - in(j)) * (in(k) - in(i)) / (in(j) * in(k));
      const std::string axis = "axis " + std::to_string(i + 1);
      const T scale = omega * omega * in(2) / in(0);
      check_close(axis + ": (1/2) tr J^2 vs mu^2", T((jac * jac).trace() / 2), mu2, scale, 32);
      RC_ASSERT((mu2 > 0) == (i == 1));  // eqs 200-201: unstable exactly about the middle
      vector3<T> w0 = w;
      if (mu2 > 0) {
        const T mu = sqrt(mu2);
        // Growing eigenvector: J(j,k) eta_k = mu eta_j.
        w0(j) += d;
        w0(k) += d * mu / jac(j, k);
        const T t_end = 4 / mu;
        const auto x = free_motion(body, body_only(vector3<T>(in.cwiseProduct(w0))), t_end, 64);
        const vector3<T> w1 = body.angular_velocity(momentum_of(x));
        const T grown = sqrt(T(w1(j) * w1(j) + w1(k) * w1(k))),
                start = sqrt(T(w0(j) * w0(j) + w0(k) * w0(k)));
        const T rate = log(grown / start) / t_end;
        check_close(axis + ": measured growth rate vs mu", rate, mu, mu,
                    static_cast<double>(T(1e-6) / mc::tier_epsilon<T>()));
      } else {
        w0(j) += d;
        w0(k) += d;
        const T t_end = 4 / sqrt(-mu2);
        const auto x = free_motion(body, body_only(vector3<T>(in.cwiseProduct(w0))), t_end, 32);
        const vector3<T> w1 = body.angular_velocity(momentum_of(x));
        const auto q = [&](const vector3<T>& v) {
          return T(abs(T(in(i) - in(j))) * in(j) * v(j) * v(j) +
                   abs(T(in(k) - in(i))) * in(k) * v(k) * v(k));
        };
        check_close(axis + ": ellipse Q(t)/Q(0)", T(q(w1) / q(w0)), lift<T>(1), lift<T>(1),
                    static_cast<double>(T(1e-5) / mc::tier_epsilon<T>()));
      }
    }
  }
};
MECHCHECK_LAW(intermediate_axis);

struct erratum_196 {
  static law_info info() {
    return {"rigid.erratum_196",
            "Printed eq 196 has (I3 - I2) where eq 174 gives (I3 - I1)",
            {"196"},
            mc::harness::expectation::falsified,
            "printed: I2 deta2/dt = Omega eta3 (I3 - I2); correct: I2 deta2/dt = Omega eta3 "
            "(I3 - I1), which with eq 197 gives eq 198 as printed"};
  }
  template <class T>
  static void property() {
    const vector3<T> in = ordered_moments<T>();
    const mc::free_rigid_body<T> body(in);
    const T omega = T(*gen::dyadic(0.5, 2));
    const auto jac = euler_jacobian(body, vector3<T>(omega, T(0), T(0)));
    check_close("I2 d(deta2/dt)/deta3 vs printed Omega (I3 - I2)", T(in(1) * jac(1, 2)),
                T(omega * (in(2) - in(1))), T(omega * in(2)), 16);
  }
};
MECHCHECK_LAW(erratum_196);

// ---------------------------------------------------------------- heavy symmetric top

/// I1 in [1/2, 2], I3 in [1/4, 2], mgl in [1/4, 2].
template <class T>
mc::heavy_top<T> random_heavy_top() {
  return {T(*gen::dyadic(0.5, 2)), T(*gen::dyadic(0.25, 2)), T(*gen::dyadic(0.25, 2))};
}

/// q = (phi, theta, psi) with theta in [1/8, 3], qdot in [-2, 2]^3.
template <class T>
std::array<dynamic_vector<T>, 2> random_top_state() {
  dynamic_vector<T> q(3), v(3);
  q << T(*gen::dyadic(-3, 3)), T(*gen::dyadic(0.125, 3)), T(*gen::dyadic(-3, 3));
  v << T(*gen::dyadic(-2, 2)), T(*gen::dyadic(-2, 2)), T(*gen::dyadic(-2, 2));
  return {q, v};
}

template <class T>
T top_scale(const mc::heavy_top<T>& top, const dynamic_vector<T>& v) {
  return (top.i1 + top.i3) * (v.squaredNorm() + 1) + top.mgl;
}

struct heavy_top_lagrangian {
  static law_info info() {
    return {"rigid.heavy_top_lagrangian",
            "Heavy symmetric top: eq 229 is eq 228 with Omega from eqs 213-215; its momenta "
            "(by AD) are p_phi, p_theta = I1 thetadot, p_psi of eqs 235-236, its energy "
            "function is E of eq 237, its Legendre transform is H, and the closed-form "
            "Hamilton equations are H's vector field",
            {"215", "228", "229", "235", "236", "237"}};
  }
  // Sums of a few products of rates, moments and trigonometric values: k = 32 on
  // (I1 + I3)(|qdot|^2 + 1) + mgl; the Legendre transform's Newton solve adds a few eps.
  template <class T>
  static void property() {
    const auto top = random_heavy_top<T>();
    const auto [q, v] = random_top_state<T>();
    const T t = lift<T>(0), scale = top_scale(top, v);
    const vector3<T> w = mc::body_angular_velocity(q(0), q(1), q(2), v(0), v(1), v(2));
    using std::cos;
    const T eq228 = top.i1 * (w(0) * w(0) + w(1) * w(1)) / 2 + top.i3 * w(2) * w(2) / 2 -
                    top.mgl * cos(q(1));
    check_close("eq 229 vs eq 228", top(q, v, t), eq228, scale, 32);
    const dynamic_vector<T> p = mc::generalized_momenta(top, q, v, t);
    check_close("dL/dphidot vs p_phi (eq 236)", p(0), top.p_phi(q, v, t), scale, 32);
    check_close("dL/dthetadot vs I1 thetadot", p(1), T(top.i1 * v(1)), scale, 32);
    check_close("dL/dpsidot vs p_psi (eq 235)", p(2), top.p_psi(q, v, t), scale, 32);
    const T e = top.energy(q, v, t);
    check_close("energy function vs E (eq 237)", mc::energy_function(top, q, v, t), e, scale, 32);
    check_close("H(q, p) vs E", top.hamiltonian(q, p), e, scale, 32);
    // The steppers' closed-form Hamilton equations against the AD vector field of H.
    const auto h = [&top]<class S>(const dynamic_vector<S>& x, const dynamic_vector<S>& y) {
      return top.hamiltonian(x, y);
    };
    const dynamic_vector<T> field = mc::hamiltonian_vector_field(h, mc::phase_point<T>(q, p));
    dynamic_vector<T> dq(3), dp(3);
    top.vector_field(q, p, dq, dp);
    using std::sin;
    const T field_scale = scale * (p.norm() + 1) / (sin(q(1)) * sin(q(1)));
    for (int i = 0; i < 3; ++i) {
      check_close("dq_" + std::to_string(i) + " vs dH/dp by AD", dq(i), field(i), field_scale, 32);
      check_close("dp_" + std::to_string(i) + " vs -dH/dq by AD", dp(i), field(3 + i),
                  field_scale, 32);
    }
  }
};
MECHCHECK_LAW(heavy_top_lagrangian);

struct heavy_top_conservation {
  static law_info info() {
    return {"rigid.heavy_top_conservation",
            "Along the Euler-Lagrange motion of eq 229, p_psi, p_phi and E (eqs 235-237) have "
            "zero time derivative",
            {"229", "230", "235", "236", "237"}};
  }
  // d/dt phi = phi_q qdot + phi_qdot qddot with qddot from a 3x3 solve of the AD
  // Hessian (cond(W) <= I_max / (I1 sin^2 theta) <= 2^7): k = 64 on the scale times
  // (|qdot| + 1)(1 + |qddot|).
  template <class T>
  static void property() {
    const auto top = random_heavy_top<T>();
    const auto [q, v] = random_top_state<T>();
    const T t = lift<T>(0);
    const dynamic_vector<T> a = mc::accelerations(top, q, v, t);
    const T scale = top_scale(top, v) * (v.norm() + 1) * (a.norm() + 1);
    const auto check = [&](const std::string& name, const auto& phi) {
      check_zero("d/dt " + name, mc::total_time_derivative(phi, q, v, a, t), scale, 64);
    };
    check("p_psi", [&top]<class S>(const dynamic_vector<S>& x, const dynamic_vector<S>& xd,
                                   const S& s) { return top.p_psi(x, xd, s); });
    check("p_phi", [&top]<class S>(const dynamic_vector<S>& x, const dynamic_vector<S>& xd,
                                   const S& s) { return top.p_phi(x, xd, s); });
    check("E", [&top]<class S>(const dynamic_vector<S>& x, const dynamic_vector<S>& xd,
                               const S& s) { return top.energy(x, xd, s); });
  }
};
MECHCHECK_LAW(heavy_top_conservation);

struct heavy_top_steady_precession {
  static law_info info() {
    return {"rigid.heavy_top_steady_precession",
            "Steady precession: both rates of eq 232 give thetaddot = 0 through the "
            "Euler-Lagrange equations of eq 229; slow/fast approach mgl/(I3 Omega3) and "
            "I3 Omega3/(I1 cos theta) (eqs 233-234) to first order in "
            "eps = I1 mgl cos theta/(I3 Omega3)^2; below the minimum spin "
            "(2/I3) sqrt(I1 mgl cos theta) none exists and the top falls",
            {"229", "231", "232", "233", "234"}};
  }
  // thetaddot from the AD jet: k = 64 on the scale times (|qdot| + 1). Limits, exactly:
  // slow/(mgl/(I3 Omega3)) - 1 = x/(1 + s)^2 in [eps, 4 eps], fast/(I3 Omega3/(I1 cos)) - 1
  // = -x/(2(1 + s)) in [-2 eps, -eps], x = 4 eps, s = sqrt(1 - x).
  template <class T>
  static void property() {
    const auto top = random_heavy_top<T>();
    const T theta = T(*gen::dyadic(0.125, 1.5));
    const T factor = T(*gen::dyadic(1.0625, 8));
    const T spin = factor * top.minimum_spin(theta);
    const auto [slow, fast] = top.steady_precession_rates(theta, spin);
    using std::cos;
    const T ct = cos(theta), t = lift<T>(0);
    for (const T& rate : {slow, fast}) {
      dynamic_vector<T> q(3), v(3);
      q << T(0), theta, T(0);
      v << rate, T(0), T(spin - rate * ct);
      const dynamic_vector<T> a = mc::accelerations(top, q, v, t);
      check_zero("thetaddot at phidot = " + mc::to_text(rate), a(1),
                 T(top_scale(top, v) * (v.norm() + 1) / top.i1), 64);
    }
    const T eps = top.i1 * top.mgl * ct / (top.i3 * top.i3 * spin * spin);
    const T slow_ratio = slow / (top.mgl / (top.i3 * spin)) - 1;
    const T fast_ratio = fast / (top.i3 * spin / (top.i1 * ct)) - 1;
    const T slack = T(64) * mc::tier_epsilon<T>();
    RC_ASSERT(slow_ratio >= eps - slack && slow_ratio <= 4 * eps + slack);
    RC_ASSERT(fast_ratio <= -eps + slack && fast_ratio >= -2 * eps - slack);
    // Below the minimum spin: no root, and thetaddot > 0 at every phidot (smallest at the
    // vertex phidot = I3 Omega3 / (2 I1 cos theta)).
    const T weak = T(*gen::dyadic(0, 0.9375)) * top.minimum_spin(theta);
    RC_ASSERT_THROWS_AS(top.steady_precession_rates(theta, weak), mc::domain_error);
    const T vertex = top.i3 * weak / (2 * top.i1 * ct);
    dynamic_vector<T> q(3), v(3);
    q << T(0), theta, T(0);
    v << vertex, T(0), T(weak - vertex * ct);
    RC_ASSERT(mc::accelerations(top, q, v, t)(1) > 0);
  }
};
MECHCHECK_LAW(heavy_top_steady_precession);

struct erratum_minimum_spin {
  static law_info info() {
    return {"rigid.erratum_minimum_spin",
            "The minimum spin printed after eq 232 has cos theta outside the square root",
            {"232"},
            mc::harness::expectation::falsified,
            "printed: Omega_3 = (2/I3) sqrt(I1 mu g l) cos theta; correct: Omega_3 = (2/I3) "
            "sqrt(I1 mu g l cos theta), where the discriminant of eq 232 vanishes"};
  }
  template <class T>
  static void property() {
    const auto top = random_heavy_top<T>();
    const T theta = T(*gen::dyadic(0.125, 1.5));
    using std::cos;
    using std::sqrt;
    const T printed = 2 / top.i3 * sqrt(top.i1 * top.mgl) * cos(theta);
    const T disc = 1 - 4 * top.mgl * top.i1 * cos(theta) / (top.i3 * top.i3 * printed * printed);
    check_zero("discriminant of eq 232 at the printed minimum spin", disc, lift<T>(1), 16);
  }
};
MECHCHECK_LAW(erratum_minimum_spin);

struct heavy_top_nutation {
  static law_info info() {
    return {"rigid.heavy_top_nutation",
            "Nutation: from a turning point, cos theta stays between the roots of "
            "E' = V_eff (eqs 238-242) and returns after the period of eq 243 "
            "(4 K(k)/sqrt(beta (u3 - u_low))); the integrated motion converges to both with "
            "order 8",
            {"238", "239", "240", "241", "242", "243"}};
  }
  // Gauss-Legendre 4 on Hamilton's equations of H. Truncation model: |(theta, p_theta)(T) - start| =
  // C h^8; the band holds up to the same error (taken from the finest run, times 4) plus
  // 64 eps.
  template <class T>
  static void property() {
    const auto top = random_heavy_top<T>();
    const T theta0 = T(*gen::dyadic(0.25, 1.25));
    const T phidot0 = T(*gen::dyadic(-1, 1)), spin = T(*gen::dyadic(1, 4));
    const auto band = top.nutation_from_turning_point(theta0, phidot0, spin);
    RC_PRE(band.u_high < T(0.96875) && band.u_low > T(-0.96875));  // away from the vertical
    RC_PRE(band.u_high - band.u_low > T(1) / 1024);  // a nutation, not a steady precession
    using std::cos;
    dynamic_vector<T> q0(3), v0(3);
    q0 << T(0), theta0, T(0);
    v0 << phidot0, T(0), T(spin - phidot0 * cos(theta0));
    const dynamic_vector<T> p0 = mc::generalized_momenta(top, q0, v0, lift<T>(0));
    struct run {
      T error, u_min, u_max, u_half;
    };
    const auto integrate = [&](long n) {
      mc::gauss_legendre<mc::heavy_top<T>, dynamic_vector<T>, 4> step{top};
      mc::phase_state<dynamic_vector<T>> x{q0, p0};
      const T dt = band.period / T(n);
      run r{0, 2, -2, 0};
      for (long i = 1; i <= n; ++i) {
        step(x, dt);
        const T u = cos(x.q(1));
        r.u_min = u < r.u_min ? u : r.u_min;
        r.u_max = u > r.u_max ? u : r.u_max;
        if (2 * i == n) r.u_half = u;
      }
      using std::abs;
      const T dtheta = abs(T(x.q(1) - theta0)), dp = abs(T(x.p(1) - p0(1))) / top.i1;
      r.error = dtheta > dp ? dtheta : dp;
      return r;
    };
    run finest{};
    const auto error = [&](const T& hh) {
      finest = integrate(steps_for(hh));  // hh: step as a fraction of the period
      return finest.error;
    };
    check_exponent("return after the eq 243 period: fitted order",
                   converged_exponent(error, T(1) / 16, 8, lift<T>(1)), 8);
    const T slack = 4 * finest.error + 64 * mc::tier_epsilon<T>();
    RC_ASSERT(finest.u_min >= band.u_low - slack);
    RC_ASSERT(finest.u_max <= band.u_high + slack);
    using std::abs;
    const T other = abs(T(band.u_low - cos(theta0))) < abs(T(band.u_high - cos(theta0)))
                        ? band.u_high
                        : band.u_low;
    check_close("cos theta at half period vs the other turning point", finest.u_half, other,
                lift<T>(1), static_cast<double>(slack / mc::tier_epsilon<T>()));
  }
};
MECHCHECK_LAW(heavy_top_nutation);

}  // namespace
