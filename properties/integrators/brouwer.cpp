#include <numbers>

#include "integrators/integrators.hpp"

namespace {
using namespace mechcheck::laws::integrators;
using mc::harness::check_model;

/// Brouwer's law for Gauss-Legendre in double. The flow conserves H (eqs 263-264) and so
/// does the exact Gauss map up to a bounded truncation term (symplectic, eq 302); what
/// remains in floating point is rounding. With the stages solved to the rounding floor and
/// the update y + h sum b_i k_i compensated, each step's rounding is an independent error
/// of order eps h |f|, and the energy error is a random walk: its increments over L steps
/// grow as L^(1/2). A drift (an error repeated every step: a stage iteration stopped
/// early, coefficients that are not symplectic) grows as L; an uncompensated update rounds
/// y itself, eps |y| a step, some 1/h times more: the walk is the same but its steps are
/// ~250 times longer (measured), and the step-size check fails by 15x.
struct brouwer_gauss_legendre {
  using tiers = std::tuple<double>;
  static constexpr int max_cases = 8;  // each case is 2^17 steps

  static law_info info() {
    return {"integrators.brouwer",
            "Gauss-Legendre (s = 4) in double over 2^17 steps: the energy error is a random "
            "walk of rounding errors (exponent 1/2, Brouwer's law) of eps h-sized steps",
            {"263", "264"}};
  }

  template <class T>
  static void property() {
    static_assert(std::is_same_v<T, double>);
    using V = Eigen::Vector2d;
    using W = Eigen::Matrix<mc::float128, 2, 1>;
    // A bound orbit (k = m = 1): semi-major axis a, eccentricity e <= 1/4, perihelion
    // direction w, starting at true anomaly nu. (At larger e the rounding concentrates
    // at pericentre and the exponent from 2^17 steps spreads more: sd 0.025 at e up to
    // 0.5 against 0.008 here.)
    const double a = *gen::dyadic(0.75, 1.5), ecc = *gen::dyadic(0, 0.25);
    const double w = *gen::dyadic(-3, 3), nu = *gen::dyadic(-3, 3);
    const double semi_latus = a * (1 - ecc * ecc), r = semi_latus / (1 + ecc * std::cos(nu));
    const double vr = ecc * std::sin(nu) / std::sqrt(semi_latus);
    const double vt = (1 + ecc * std::cos(nu)) / std::sqrt(semi_latus);
    const double theta = w + nu, c = std::cos(theta), s = std::sin(theta);
    Eigen::Vector4d z(r * c, r * s, vr * c - vt * s, vr * s + vt * c);
    const mc::kepler_system<double> kepler(1.0, 1.0);
    mc::phase_state<V> x{z.head(2), z.tail(2)};
    gauss4<mc::kepler_system<double>, V> gl(kepler);

    // The energy of the stepper's state x + compensation, evaluated exactly enough
    // (float128) that neither its own rounding nor that of storing x in double hides the
    // walk, relative to |E|.
    const mc::kepler_system<mc::float128> exact(mc::float128(1), mc::float128(1));
    const auto energy = [&] {
      const W q = x.q.cast<mc::float128>() + gl.compensation_q().cast<mc::float128>();
      const W p = x.p.cast<mc::float128>() + gl.compensation_p().cast<mc::float128>();
      return exact.energy(q, p);
    };
    const mc::float128 e0 = energy();
    const double abs_e = static_cast<double>(abs(e0));

    // Period 2 pi a^(3/2); ~2048 steps a period keep the bounded truncation part of the
    // energy error (order 8) far below rounding. Not a whole number of steps a period: a
    // commensurate step brings the state back to the same points every period, and their
    // rounding errors with it (on a circular orbit with exactly 2048 the exponent read
    // 0.42); the fractional part is the golden fraction, the offset farthest from any
    // short period.
    const double steps_per_period = 2048 + *gen::dyadic(0, 64) + (std::numbers::phi - 1);
    const double h = 2 * std::numbers::pi * a * std::sqrt(a) / steps_per_period;
    const long steps = 1L << 17;
    std::vector<double> e;
    e.reserve(steps + 1);
    e.push_back(0);
    for (long n = 0; n < steps; ++n) {
      gl(x, h);
      e.push_back(static_cast<double>((energy() - e0) / abs_e));
    }
    // Exponent of the increments over lags 4 .. 1024, each averaged over every start in
    // the run: 1/2 for a random walk (measured 0.50, standard deviation 0.008 over 40
    // orbits; lags up to 4096 spread 0.013, the last lags having few independent blocks).
    const auto growth = mc::audit::growth_of_increments(e, 0, 10);
    const auto fit = mc::audit::growth_of_increments(e, 2, 10);
    check_model("growth exponent of the energy error's increments (lags 2^2..2^10)",
                fit.exponent, 0.5, 1.0, 0.1);

    // Size of a step of the walk. Rounding the increment h sum b_i k_i of each component
    // (s products and sums, and the two compensation operations: s + 2 roundings of at
    // most eps |h f|) changes H by at most (s + 2) eps h (|dH/dq| |dq/dt| + |dH/dp| |dp/dt|)
    // = (s + 2) eps h 2 |p| |F|, largest at pericentre (r_p = a (1 - e), |p| = L / r_p,
    // |F| = 1 / r_p^2); relative to |E|.
    const double rp = a * (1 - ecc), l = std::sqrt(semi_latus);
    const double scale = h * 2 * (l / rp) * (1 / (rp * rp)) / abs_e;
    // Round to nearest: each rounding is at most u = eps/2, so the budget is (s + 2) / 2.
    mc::harness::check_zero("rms energy change of one step (relative), over eps h 2|p||F|/|E|",
                            growth.rms[0], scale, (4 + 2) / 2.0);
  }
};
MECHCHECK_LAW(brouwer_gauss_legendre);

}  // namespace
