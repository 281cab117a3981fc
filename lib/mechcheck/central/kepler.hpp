#pragma once
/// The two-body problem and Kepler orbits (notes lectures 8, 10-12, eqs 77, 94-117).
///
/// A relative orbit has reduced mass mu and potential U(r) = -k / r (k > 0 attracts):
///   H = |p|^2 / (2 mu) - k / |q|,   M = q x p,   A = p x M - mu k q / |q|  (eq 77),
///   1/r = (mu k / M^2)(1 + e cos phi), e = |A| / (mu k) = sqrt(1 + 2 E M^2 / (mu k^2))
///   (eqs 115-117), phi measured from A. The semi-latus rectum is p = M^2 / (mu k) and the
///   gravitational parameter per unit mass is k / mu.

#include <cmath>
#include <string>

#include <Eigen/Geometry>
#include <boost/math/constants/constants.hpp>
#include <boost/math/tools/roots.hpp>

#include "mechcheck/core.hpp"

namespace mechcheck {

/// mu = m1 m2 / (m1 + m2) (eq 97). Throws domain_error unless both masses are positive.
template <class T>
T reduced_mass(const T& m1, const T& m2) {
  require_positive(m1, "reduced_mass", "m1");
  require_positive(m2, "reduced_mass", "m2");
  return m1 * m2 / (m1 + m2);
}

/// Centre of mass and relative coordinates of two bodies (eqs 95-96).
template <class T>
struct two_body_coordinates {
  vector3<T> centre, centre_velocity, r, v;  ///< r = r1 - r2, v = v1 - v2
};

template <class T>
two_body_coordinates<T> to_relative(const T& m1, const T& m2, const vector3<T>& r1,
                                    const vector3<T>& r2, const vector3<T>& v1,
                                    const vector3<T>& v2) {
  require_positive(m1, "to_relative", "m1");
  require_positive(m2, "to_relative", "m2");
  require_finite_vector(r1, "to_relative", "r1");
  require_finite_vector(r2, "to_relative", "r2");
  require_finite_vector(v1, "to_relative", "v1");
  require_finite_vector(v2, "to_relative", "v2");
  const T total = m1 + m2;
  return {(m1 * r1 + m2 * r2) / total, (m1 * v1 + m2 * v2) / total, r1 - r2, v1 - v2};
}

/// The bodies' positions from the centre and r (eq 96 with the centre added):
/// r1 = R + m2 r / (m1 + m2), r2 = R - m1 r / (m1 + m2). Velocities alike.
template <class T>
std::pair<vector3<T>, vector3<T>> from_relative(const T& m1, const T& m2, const vector3<T>& centre,
                                                const vector3<T>& r) {
  require_positive(m1, "from_relative", "m1");
  require_positive(m2, "from_relative", "m2");
  require_finite_vector(centre, "from_relative", "centre");
  require_finite_vector(r, "from_relative", "r");
  const T total = m1 + m2;
  return {centre + (m2 / total) * r, centre - (m1 / total) * r};
}

/// A Kepler orbit's physical constants: reduced mass mu and strength k of U = -k / r.
template <class T>
struct kepler_constants {
  T mu, k;
  kepler_constants(T mu_, T k_) : mu(std::move(mu_)), k(std::move(k_)) {
    require_positive(mu, "kepler_constants", "mu");
    require_positive(k, "kepler_constants", "k");
  }
  /// U_eff(r) = M^2 / (2 mu r^2) - k / r (eqs 101, 112).
  T effective_potential(const T& momentum, const T& r) const {
    return momentum * momentum / (2 * mu * r * r) - k / r;
  }
  /// The circular-orbit radius M^2 / (mu k), where U_eff' = 0 (eq 112).
  T circular_radius(const T& momentum) const {
    if (!(momentum != 0) || !is_finite(momentum))
      throw domain_error("kepler_constants::circular_radius: angular momentum " +
                         to_text(momentum) + " (must be non-zero and finite)");
    return momentum * momentum / (mu * k);
  }
  T energy(const vector3<T>& r, const vector3<T>& p) const {
    return p.squaredNorm() / (2 * mu) - k / r.norm();
  }
};

/// Semi-major axis a = -k / (2E) of a bound orbit of energy E (eq 117 with e < 1).
/// Throws domain_error when E >= 0 (the orbit is not bound).
template <class T>
T semi_major_axis(const kepler_constants<T>& c, const T& energy) {
  if (!is_finite(energy))
    throw non_finite_error("semi_major_axis: energy E = " + to_text(energy) + " is not finite");
  if (!(energy < 0))
    throw domain_error("semi_major_axis: energy E = " + to_text(energy) +
                       " >= 0: the orbit is not bound");
  return -c.k / (2 * energy);
}

/// Period of the bound orbit through (r, p): T = 2 pi sqrt(mu a^3 / k) (Kepler's third
/// law). Throws domain_error when E >= 0.
template <class T>
T orbital_period(const kepler_constants<T>& c, const vector3<T>& r, const vector3<T>& p) {
  using std::sqrt;
  require_finite_vector(r, "orbital_period", "r");
  require_finite_vector(p, "orbital_period", "p");
  const T energy = c.energy(r, p);
  if (!(energy < 0))
    throw domain_error("orbital_period: energy E = " + to_text(energy) + " >= 0 at r = " +
                       to_text(r) + ", p = " + to_text(p) + ": the orbit is not bound");
  const T a = semi_major_axis(c, energy);
  return boost::math::constants::two_pi<T>() * sqrt(T(c.mu * a * a * a / c.k));
}

/// The Laplace-Runge-Lenz vector A = p x M - mu k q / |q| (eq 77), for any scalar (a tier
/// or AD over one) as a phase-space function of q, p in three dimensions.
template <class S, class P>
vector3<S> lrl_vector(const dynamic_vector<S>& q, const dynamic_vector<S>& p, const P& mu,
                      const P& k) {
  if (q.size() != 3 || p.size() != 3)
    throw dimension_error("lrl_vector: needs 3 degrees of freedom, got " +
                          std::to_string(q.size()));
  using std::sqrt;
  using R = real_type_t<S>;
  vector3<S> m;
  for (int i = 0; i < 3; ++i) m(i) = cross_component(q, p, i);
  S r2 = lift<S>(0);
  for (int i = 0; i < 3; ++i) {
    const S qi2 = q(i) * q(i);
    r2 += qi2;
  }
  const S inv_r = inverse(S(sqrt(r2)));
  const S strength = lift<S>(R(mu) * R(k));
  vector3<S> a;
  for (int i = 0; i < 3; ++i) {
    const S pm = cross_component(p, m, i);
    const S radial = strength * q(i);
    const S term = radial * inv_r;
    a(i) = pm - term;
  }
  return a;
}

/// Orbit elements of a conic (ellipse, parabola or hyperbola): semi-latus rectum p,
/// eccentricity e, inclination i, longitude of the node Omega, argument of the
/// pericentre omega, true anomaly nu. Conventions for the degenerate cases: an
/// equatorial orbit (i = 0 or pi) has Omega = 0, a circular one omega = 0.
template <class T>
struct orbit_elements {
  T semi_latus_rectum, eccentricity, inclination, node, argument, true_anomaly;
};

namespace detail {
/// x^3/3! + s x^5/5! + s^2 x^7/7! + ...: sinh x - x for s = +1, x - sin x for s = -1,
/// summed without cancellation for |x| < 1.
template <class T>
T odd_series_tail(const T& x, int s) {
  const T x2 = x * x;
  T term = x * x2 / 6, sum = term;
  for (int n = 2; n < 200; ++n) {
    term *= T(s) * x2 / T((2 * n) * (2 * n + 1));
    const T next = sum + term;
    if (next == sum) break;
    sum = next;
  }
  return sum;
}
/// x - sin x without cancellation.
template <class T>
T x_minus_sin(const T& x) {
  using std::abs;
  using std::sin;
  return abs(x) >= 1 ? T(x - sin(x)) : odd_series_tail(x, -1);
}
/// sinh x - x without cancellation.
template <class T>
T sinh_minus_x(const T& x) {
  using std::abs;
  using std::sinh;
  return abs(x) >= 1 ? T(sinh(x) - x) : odd_series_tail(x, 1);
}
template <class T>
void require_eccentricity(const T& e, const char* where, bool elliptic) {
  if (!is_finite(e)) throw non_finite_error(std::string(where) + ": eccentricity " + to_text(e));
  if (elliptic && !(e >= 0 && e < 1))
    throw domain_error(std::string(where) + ": eccentricity " + to_text(e) +
                       " is not in [0, 1) (an ellipse is required)");
  if (!elliptic && !(e > 1))
    throw domain_error(std::string(where) + ": eccentricity " + to_text(e) +
                       " is not above 1 (a hyperbola is required)");
  if (elliptic)
    observe_region(where, "eccentricity", e == 0 ? "circle" : "ellipse", {"circle", "ellipse"});
}
/// Any conic: a finite e >= 0.
template <class T>
void require_conic(const T& e, const char* where) {
  if (!is_finite(e)) throw non_finite_error(std::string(where) + ": eccentricity " + to_text(e));
  if (!(e >= 0))
    throw domain_error(std::string(where) + ": eccentricity " + to_text(e) + " is negative");
  observe_region(where, "eccentricity",
                 e == 0 ? "circle" : e < 1 ? "ellipse" : e == 1 ? "parabola" : "hyperbola",
                 {"circle", "ellipse", "parabola", "hyperbola"});
}
}  // namespace detail

/// Mean anomaly E - e sin E from the eccentric anomaly, without cancellation near e = 1,
/// E = 0: (1 - e) E + e (E - sin E).
template <class T>
T mean_anomaly_from_eccentric(const T& e, const T& eccentric) {
  detail::require_eccentricity(e, "mean_anomaly_from_eccentric", true);
  if (!is_finite(eccentric))
    throw non_finite_error("mean_anomaly_from_eccentric: eccentric anomaly " + to_text(eccentric));
  return (1 - e) * eccentric + e * detail::x_minus_sin(eccentric);
}

/// Kepler's equation E - e sin E = M for 0 <= e < 1 and any M, to the tier's precision:
/// M is reduced to [-pi, pi] (losing |M| eps of absolute accuracy, as any reduction
/// must), E is bracketed in [M, min(M + e, pi)] for 0 <= M <= pi, and Boost.Math's Halley
/// iteration (which falls back to bisection inside the bracket) runs on the
/// cancellation-free residual. Returns E in the same 2 pi period as M. Throws
/// domain_error for e outside [0, 1), non_finite_error for non-finite input and
/// convergence_error if the iteration does not settle.
template <class T>
T solve_kepler(const T& e, const T& mean_anomaly) {
  using std::abs;
  using std::cbrt;
  using std::round;
  detail::require_eccentricity(e, "solve_kepler", true);
  if (!is_finite(mean_anomaly))
    throw non_finite_error("solve_kepler: mean anomaly " + to_text(mean_anomaly));
  const T two_pi = boost::math::constants::two_pi<T>(), pi = boost::math::constants::pi<T>();
  const T turns = round(T(mean_anomaly / two_pi));
  const T reduced = mean_anomaly - turns * two_pi;
  const T m = abs(reduced);
  if (m == 0 || e == 0) return mean_anomaly;
  // |E - M| = e |sin E| <= e, and E - M has the sign of sin E: E in [M, min(M + e, pi)]
  // for M <= pi; M can exceed the rounded pi by an ulp after the reduction, and then
  // E in [max(M - e, pi), M].
  T lo = m, hi = m + e;
  if (m <= pi) {
    if (hi > pi) hi = pi;
  } else {
    hi = m;
    lo = m - e < pi ? pi : T(m - e);
  }
  if (!(lo < hi)) return (reduced < 0 ? -lo : lo) + turns * two_pi;  // M = pi: E = pi
  // Start: cbrt(6 M) is the e -> 1, M -> 0 limit; M + e/2 is good elsewhere.
  T guess = m + e / 2;
  if (e > T(0.5) && m < T(0.25)) guess = cbrt(6 * m);
  if (guess < lo || guess > hi) guess = (lo + hi) / 2;
  const auto residual = [&](const T& x) {
    using std::cos;
    using std::sin;
    const T s = sin(x / 2);
    const T f = mean_anomaly_from_eccentric(e, x) - m;
    const T df = (1 - e) + 2 * e * s * s;  // 1 - e cos x without cancellation
    const T d2f = e * sin(x);
    return std::make_tuple(f, df, d2f);
  };
  std::uintmax_t iterations = 200;
  const T root = boost::math::tools::halley_iterate(residual, guess, lo, hi,
                                                    std::numeric_limits<T>::digits, iterations);
  if (iterations >= 200)
    throw convergence_error("solve_kepler: no convergence for e = " + to_text(e) + ", M = " +
                            to_text(mean_anomaly));
  return (reduced < 0 ? -root : root) + turns * two_pi;
}

/// The hyperbolic Kepler equation e sinh H - H = M for e > 1 and any M.
template <class T>
T solve_hyperbolic_kepler(const T& e, const T& mean_anomaly) {
  using std::abs;
  using std::asinh;
  using std::cbrt;
  detail::require_eccentricity(e, "solve_hyperbolic_kepler", false);
  if (!is_finite(mean_anomaly))
    throw non_finite_error("solve_hyperbolic_kepler: mean anomaly " + to_text(mean_anomaly));
  const T m = abs(mean_anomaly);
  if (m == 0) return mean_anomaly;
  // e sinh H - H >= (e - 1) sinh H and >= sinh H - H >= H^3 / 6.
  T hi = asinh(T(m / (e - 1)));
  const T cubic = cbrt(6 * m);
  if (cubic < hi) hi = cubic;
  const T lo = 0;
  const auto residual = [&](const T& x) {
    using std::sinh;
    const T s = sinh(x / 2);
    const T f = (e - 1) * sinh(x) + detail::sinh_minus_x(x) - m;
    const T df = (e - 1) + 2 * e * s * s;  // e cosh x - 1
    const T d2f = e * sinh(x);
    return std::make_tuple(f, df, d2f);
  };
  std::uintmax_t iterations = 200;
  const T root = boost::math::tools::halley_iterate(residual, T(hi / 2), lo, hi,
                                                    std::numeric_limits<T>::digits, iterations);
  if (iterations >= 200)
    throw convergence_error("solve_hyperbolic_kepler: no convergence for e = " + to_text(e) +
                            ", M = " + to_text(mean_anomaly));
  return mean_anomaly < 0 ? -root : root;
}

/// Elements of the orbit through (r, v) of the relative motion (p = mu v).
/// Throws domain_error for zero angular momentum (a radial orbit has no conic).
template <class T>
orbit_elements<T> elements_from_state(const kepler_constants<T>& c, const vector3<T>& r,
                                      const vector3<T>& v) {
  using std::atan2;
  using std::sqrt;
  for (int i = 0; i < 3; ++i)
    if (!is_finite(r(i)) || !is_finite(v(i)))
      throw non_finite_error("elements_from_state: state r = " + to_text(r) + ", v = " +
                             to_text(v));
  const vector3<T> h = r.cross(v);  // M / mu
  const T h2 = h.squaredNorm();
  if (!(h2 > 0))
    throw domain_error("elements_from_state: zero angular momentum at r = " + to_text(r) +
                       ", v = " + to_text(v) + " (radial motion has no orbit elements)");
  const T gm = c.k / c.mu;
  const vector3<T> ev = v.cross(h) / gm - r / r.norm();  // A / (mu k)
  const T e = ev.norm();
  const T hn = sqrt(h2);
  const vector3<T> w = h / hn;
  const vector3<T> node(-h(1), h(0), T(0));  // z x h
  const T nn = node.norm();
  const vector3<T> n_hat = nn > 0 ? vector3<T>(node / nn) : vector3<T>(T(1), T(0), T(0));
  const vector3<T> p_hat = e > 0 ? vector3<T>(ev / e) : n_hat;
  const vector3<T> q_hat = w.cross(p_hat);
  orbit_elements<T> out;
  out.semi_latus_rectum = h2 / gm;
  out.eccentricity = e;
  out.inclination = atan2(T(sqrt(T(h(0) * h(0) + h(1) * h(1)))), h(2));
  out.node = nn > 0 ? T(atan2(node(1), node(0))) : T(0);
  out.argument = atan2(T(n_hat.cross(p_hat).dot(w)), T(n_hat.dot(p_hat)));
  out.true_anomaly = atan2(T(r.dot(q_hat)), T(r.dot(p_hat)));
  return out;
}

/// Position and velocity on the orbit at its true anomaly (eq 117 and its derivative).
/// Throws domain_error when 1 + e cos nu <= 0 (a hyperbola's asymptote or beyond).
template <class T>
std::pair<vector3<T>, vector3<T>> state_from_elements(const kepler_constants<T>& c,
                                                      const orbit_elements<T>& el) {
  using std::cos;
  using std::sin;
  using std::sqrt;
  const T cn = cos(el.true_anomaly), sn = sin(el.true_anomaly);
  const T denominator = 1 + el.eccentricity * cn;
  if (!(denominator > 0))
    throw domain_error("state_from_elements: 1 + e cos(nu) = " + to_text(denominator) +
                       " <= 0: nu = " + to_text(el.true_anomaly) + " is not on the orbit");
  require_positive(el.semi_latus_rectum, "state_from_elements", "semi-latus rectum");
  const T radius = el.semi_latus_rectum / denominator;
  const T speed = sqrt(T(c.k / c.mu / el.semi_latus_rectum));
  const T co = cos(el.node), so = sin(el.node), ci = cos(el.inclination),
          si = sin(el.inclination), cw = cos(el.argument), sw = sin(el.argument);
  // Columns: the pericentre direction P and Q = h x P in the lab frame.
  const vector3<T> p_hat(co * cw - so * sw * ci, so * cw + co * sw * ci, sw * si);
  const vector3<T> q_hat(-co * sw - so * cw * ci, -so * sw + co * cw * ci, cw * si);
  const vector3<T> r = radius * (cn * p_hat + sn * q_hat);
  const vector3<T> v = speed * (-sn * p_hat + (el.eccentricity + cn) * q_hat);
  return {r, v};
}

/// Mean anomaly at true anomaly nu: elliptic (E - e sin E), parabolic (Barker:
/// D + D^3/3 with D = tan(nu/2)) or hyperbolic (e sinh H - H).
template <class T>
T mean_anomaly_from_true(const T& e, const T& nu) {
  using std::atan2;
  using std::atanh;
  using std::cos;
  using std::sin;
  using std::sqrt;
  using std::tan;
  detail::require_conic(e, "mean_anomaly_from_true");
  if (!is_finite(nu)) throw non_finite_error("mean_anomaly_from_true: true anomaly " + to_text(nu));
  if (e > 1 && !(1 + e * cos(nu) > 0))
    throw domain_error("mean_anomaly_from_true: true anomaly " + to_text(nu) +
                       " is beyond the asymptotes of the hyperbola of eccentricity " + to_text(e));
  if (e < 1) {
    const T ecc = 2 * atan2(T(sqrt(T(1 - e)) * sin(nu / 2)), T(sqrt(T(1 + e)) * cos(nu / 2)));
    return mean_anomaly_from_eccentric(e, ecc);
  }
  if (e == 1) {
    const T d = tan(nu / 2);
    return d + d * d * d / 3;
  }
  const T hyp = 2 * atanh(T(sqrt(T((e - 1) / (e + 1))) * tan(nu / 2)));
  return (e - 1) * sinh(hyp) + detail::sinh_minus_x(hyp);
}

/// True anomaly at mean anomaly M (the three cases as above; Barker's cubic in closed
/// form, D = 2 sinh(asinh(3M/2)/3)).
template <class T>
T true_anomaly_from_mean(const T& e, const T& m) {
  using std::asinh;
  using std::atan;
  using std::atan2;
  using std::cos;
  using std::sin;
  using std::sinh;
  using std::sqrt;
  using std::tanh;
  detail::require_conic(e, "true_anomaly_from_mean");
  if (!is_finite(m)) throw non_finite_error("true_anomaly_from_mean: mean anomaly " + to_text(m));
  if (e < 1) {
    const T ecc = solve_kepler(e, m);
    return 2 * atan2(T(sqrt(T(1 + e)) * sin(ecc / 2)), T(sqrt(T(1 - e)) * cos(ecc / 2)));
  }
  if (e == 1) {
    const T d = 2 * sinh(T(asinh(T(3 * m / 2)) / 3));
    return 2 * atan(d);
  }
  const T hyp = solve_hyperbolic_kepler(e, m);
  return 2 * atan(T(sqrt(T((e + 1) / (e - 1))) * tanh(hyp / 2)));
}

/// A Kepler orbit through (r0, v0) at t = 0, propagated analytically: the mean anomaly
/// advances at n = sqrt(k/mu / |a|^3) (ellipse and hyperbola) or 2 sqrt(k/mu / p^3)
/// (parabola, for Barker's D + D^3/3).
template <class T>
class kepler_orbit {
 public:
  kepler_orbit(kepler_constants<T> c, const vector3<T>& r0, const vector3<T>& v0)
      : c_(std::move(c)), el_(elements(c_, r0, v0)) {
    using std::abs;
    using std::sqrt;
    const T e = el_.eccentricity, p = el_.semi_latus_rectum, gm = c_.k / c_.mu;
    if (e == 1) {
      motion_ = 2 * sqrt(T(gm / (p * p * p)));
    } else {
      const T a = abs(T(p / (1 - e * e)));
      motion_ = sqrt(T(gm / (a * a * a)));
    }
    m0_ = mean_anomaly_from_true(e, el_.true_anomaly);
  }
  const orbit_elements<T>& elements() const { return el_; }
  /// The elements of the orbit through (r0, v0), checked under this class's name.
  static orbit_elements<T> elements(const kepler_constants<T>& c, const vector3<T>& r0,
                                    const vector3<T>& v0) {
    require_finite_vector(r0, "kepler_orbit", "r0");
    require_finite_vector(v0, "kepler_orbit", "v0");
    if (!(r0.cross(v0).squaredNorm() > 0))
      throw domain_error("kepler_orbit: zero angular momentum at r0 = " + to_text(r0) +
                         ", v0 = " + to_text(v0) + " (a radial orbit has no conic)");
    return elements_from_state(c, r0, v0);
  }
  /// Mean motion n (2 pi / n is the period of a bound orbit).
  T mean_motion() const { return motion_; }
  std::pair<vector3<T>, vector3<T>> state_at(const T& t) const {
    orbit_elements<T> el = el_;
    el.true_anomaly = true_anomaly_from_mean(el_.eccentricity, T(m0_ + motion_ * t));
    return state_from_elements(c_, el);
  }

 private:
  kepler_constants<T> c_;
  orbit_elements<T> el_;
  T motion_, m0_;
};

}  // namespace mechcheck
