/// Integrators and canonical transformations (notes lecture 23, eqs 285-319).
///
/// Symplecticity is checked on the Jacobian of a map taken by AD, M = d(Q,P)/d(q,p):
/// the defect M J M^T - J (eq 302) of an exactly canonical map is rounding, bounded by
/// k eps |M|^2 with k counted from the operations per map (substeps, stages, dof).
/// Orders are checked against the truncation model e(h) = C h^p (1 + O(h)): the fitted
/// exponent log2(e(h) / e(h/2)) must be within 0.4 of p.

#include <cmath>
#include <optional>

#include "convergence.hpp"
#include "generators.hpp"
#include "mechcheck/harness/law.hpp"
#include "mechcheck/reference.hpp"

namespace {

namespace mc = mechcheck;
namespace gen = mechcheck::generators;
using mc::dynamic_matrix;
using mc::dynamic_vector;
using mc::lift;
using mc::harness::check_close;
using mc::properties::check_exponent;
using mc::properties::converged_exponent;
using mc::harness::check_zero;
using mc::harness::law_info;

template <class Sys, class V>
using yoshida4 = mc::composition<Sys, V, 4>;
template <class Sys, class V>
using yoshida6 = mc::composition<Sys, V, 6>;
template <class Sys, class V>
using yoshida8 = mc::composition<Sys, V, 8>;
template <class Sys, class V>
using gauss1 = mc::gauss_legendre<Sys, V, 1>;
template <class Sys, class V>
using gauss2 = mc::gauss_legendre<Sys, V, 2>;
template <class Sys, class V>
using gauss3 = mc::gauss_legendre<Sys, V, 3>;
template <class Sys, class V>
using gauss4 = mc::gauss_legendre<Sys, V, 4>;

/// The symplectic form J = [[0, I], [-I, 0]] of eq 300.
template <class T>
dynamic_matrix<T> symplectic_form(Eigen::Index n) {
  dynamic_matrix<T> j = dynamic_matrix<T>::Zero(2 * n, 2 * n);
  for (Eigen::Index i = 0; i < n; ++i) {
    j(i, n + i) = lift<T>(1);
    j(n + i, i) = lift<T>(-1);
  }
  return j;
}

/// max |M J M^T - J| (eq 302).
template <class T>
T symplectic_defect(const dynamic_matrix<T>& m) {
  const Eigen::Index n = m.rows() / 2;
  const dynamic_matrix<T> j = symplectic_form<T>(n);
  const dynamic_matrix<T> d = m * j * m.transpose() - j;
  return d.cwiseAbs().maxCoeff();
}

/// Jacobian of one step of Method on System at z = (q, p) with step h.
template <template <class, class> class Method, class System, class T>
dynamic_matrix<T> step_jacobian(const System& system, const dynamic_vector<T>& z, const T& h) {
  const Eigen::Index n = z.size() / 2;
  const auto step = [&system, &h, n]<class S>(const dynamic_vector<S>& w) -> dynamic_vector<S> {
    Method<System, dynamic_vector<S>> method{system};
    mc::phase_state<dynamic_vector<S>> x{w.head(n), w.tail(n)};
    method(x, lift<S>(h));
    dynamic_vector<S> out(2 * n);
    out << x.q, x.p;
    return out;
  };
  return mc::jacobian(step, z);
}

/// A generic bound Kepler state (k = m = 1): |q| = r in [1/2, 2], tangential speed
/// f sqrt(1/r) with f in [3/4, 9/8] (eccentricity well below 1, far from collision) and a
/// radial speed of 1/8 to 1/4 of the circular speed, never zero: an apsis is a symmetric
/// point of the time-reversible flow, where leading error terms can vanish.
template <class T>
dynamic_vector<T> kepler_state() {
  const double r = *gen::dyadic(0.5, 2), angle = *gen::dyadic(-3, 3);
  const double f = *gen::dyadic(0.75, 1.125), radial = *gen::dyadic(0.125, 0.25);
  const bool inward = *rc::gen::arbitrary<bool>();
  using std::cos;
  using std::sin;
  using std::sqrt;
  const T rt = T(r), c = cos(T(angle)), s = sin(T(angle));
  const T vc = sqrt(1 / rt);
  const T vt = T(f) * vc, vr = (inward ? -1 : 1) * T(radial) * vc;
  dynamic_vector<T> z(4);
  z << rt * c, rt * s, vr * c - vt * s, vr * s + vt * c;
  return z;
}

struct symplectic_integrators {
  static law_info info() {
    return {"integrators.symplectic_condition",
            "One step of every symplectic integrator is a canonical map: M J M^T = J, "
            "det M = 1",
            {"285", "292", "300", "301", "302"}};
  }
  // Rounding in a map made of m force evaluations on n dof: k = 16 m n, with m = 1
  // (Euler), 1 (Verlet), 3, 9, 27 (compositions), 2 s (Gauss-Legendre: converged
  // stages, each stage one evaluation and an s-term sum).
  template <class T>
  static void property() {
    const auto z = kepler_state<T>();
    const double hd = *gen::dyadic(1.0 / 64, 1.0 / 8);
    const T h = T(hd);
    const mc::kepler_system<T> kepler(T(1), T(1));
    const auto check = [&]<template <class, class> class Method>(const char* name, int evals) {
      const dynamic_matrix<T> m = step_jacobian<Method>(kepler, z, h);
      const T scale = m.squaredNorm();
      const double k = 16.0 * evals * 2;
      check_zero(std::string(name) + ": max|M J M^T - J|", symplectic_defect(m), scale, k);
      check_close(std::string(name) + ": det M", T(m.determinant()), lift<T>(1), scale * scale, k);
    };
    check.template operator()<mc::symplectic_euler>("symplectic Euler", 1);
    check.template operator()<mc::stormer_verlet>("Stormer-Verlet", 1);
    check.template operator()<yoshida4>("composition 4", 3);
    check.template operator()<yoshida6>("composition 6", 9);
    check.template operator()<yoshida8>("composition 8", 27);
    check.template operator()<gauss1>("Gauss-Legendre 1", 2);
    check.template operator()<gauss2>("Gauss-Legendre 2", 4);
    check.template operator()<gauss3>("Gauss-Legendre 3", 6);
    check.template operator()<gauss4>("Gauss-Legendre 4", 8);
  }
};
MECHCHECK_LAW(symplectic_integrators);

struct non_symplectic_integrators {
  static law_info info() {
    return {"integrators.not_symplectic",
            "Explicit Euler and RK4 are not symplectic: on the nonlinear Kepler problem "
            "their defect |M J M^T - J| grows as h^2 and h^6",
            {"292", "302"}};
  }
  // Truncation model: defect(h) = C h^e (1 + O(h)); the fitted exponent
  // log2(defect(h)/defect(h/2)) is within 0.4 of e, and the defect is far above rounding
  // (> 10^6 eps): the law asserts the failure, and its rate. Euler: e = p + 1 = 2. RK4:
  // e = 6, one more than p + 1: the h^5 term of RK4's local error is a Hamiltonian
  // vector field, so the first non-canonical term is h^6 (measured in mpfr50 at
  // h = 1/16 ... 1/512: 5.885, 5.926, 5.967, 5.984, 5.992, 5.996).
  template <class T>
  static void property() {
    const auto z = kepler_state<T>();
    const mc::kepler_system<T> kepler(T(1), T(1));
    const auto check = [&]<template <class, class> class Method>(const char* name, int e,
                                                                 double hd) {
      const auto defect = [&](const T& h) {
        return symplectic_defect(step_jacobian<Method>(kepler, z, h));
      };
      check_exponent(std::string(name) + ": fitted exponent of the defect",
                     converged_exponent(defect, T(hd), e, lift<T>(1)), e);
    };
    check.template operator()<mc::explicit_euler>("explicit Euler", 2, 1.0 / 64);
    check.template operator()<mc::rk4>("RK4", 6, 1.0 / 8);
  }
};
MECHCHECK_LAW(non_symplectic_integrators);

/// State at time 1 after `steps` steps.
template <template <class, class> class Method, class System, class T>
dynamic_vector<T> state_at_one(const System& system, const dynamic_vector<T>& z, long steps) {
  const Eigen::Index n = z.size() / 2;
  Method<System, dynamic_vector<T>> method{system};
  mc::phase_state<dynamic_vector<T>> x{z.head(n), z.tail(n)};
  mc::integrate(method, x, T(1) / T(steps), steps);
  dynamic_vector<T> out(2 * n);
  out << x.q, x.p;
  return out;
}

/// Richardson convergence study of the global error at time 1: e(h) = |y_h - y_{h/2}|.
template <template <class, class> class Method, class System, class T>
std::optional<T> fitted_order(const System& system, const dynamic_vector<T>& z, long steps,
                              int p) {
  const auto error = [&](const T& h) {
    const long n = mc::properties::steps_for(h);
    return T((state_at_one<Method>(system, z, n) - state_at_one<Method>(system, z, 2 * n)).norm());
  };
  return converged_exponent(error, T(T(1) / T(steps)), p, T(z.norm() + 1));
}

struct integrator_orders {
  static law_info info() {
    return {"integrators.order",
            "Every integrator converges with its order p: 1 (Euler), 2 (Verlet), 4/6/8 "
            "(compositions), 4 (RK4), 2s (Gauss-Legendre s = 1..4)",
            {"250", "258", "260", "261", "262"}};
  }
  // Truncation model e(h) = C h^p (1 + O(h)) for the pendulum over t in [0, 1]; the
  // Richardson exponent from h, h/2, h/4 settles within 0.4 of p before rounding decides
  // (converged_exponent).
  template <class T>
  static void property() {
    const double m = *gen::dyadic(0.5, 2), l = *gen::dyadic(0.5, 2), g = *gen::dyadic(0.5, 2);
    const mc::pendulum_system<T> pendulum{T(m), T(l), T(g)};
    dynamic_vector<T> z(2);
    z << T(*gen::dyadic(-2, 2)), T(*gen::dyadic(-1, 1));
    const auto check = [&]<template <class, class> class Method>(const char* name, int p,
                                                                 long steps) {
      check_exponent(std::string(name) + ": fitted order",
                     fitted_order<Method>(pendulum, z, steps, p), p);
    };
    check.template operator()<mc::explicit_euler>("explicit Euler", 1, 256);
    check.template operator()<mc::symplectic_euler>("symplectic Euler", 1, 256);
    check.template operator()<mc::stormer_verlet>("Stormer-Verlet", 2, 32);
    check.template operator()<mc::rk4>("RK4", 4, 32);
    check.template operator()<yoshida4>("composition 4", 4, 16);
    check.template operator()<yoshida6>("composition 6", 6, 8);
    check.template operator()<yoshida8>("composition 8", 8, 8);
    check.template operator()<gauss1>("Gauss-Legendre 1", 2, 32);
    check.template operator()<gauss2>("Gauss-Legendre 2", 4, 8);
    check.template operator()<gauss3>("Gauss-Legendre 3", 6, 4);
    check.template operator()<gauss4>("Gauss-Legendre 4", 8, 2);
  }
};
MECHCHECK_LAW(integrator_orders);

/// max |H(t) - H(0)| over t in [0, T] with step h.
template <template <class, class> class Method, class System, class T>
T max_energy_error(const System& system, const dynamic_vector<T>& z, const T& h, long steps) {
  const Eigen::Index n = z.size() / 2;
  Method<System, dynamic_vector<T>> method{system};
  mc::phase_state<dynamic_vector<T>> x{z.head(n), z.tail(n)};
  const T e0 = system.energy(x.q, x.p);
  T worst = lift<T>(0);
  for (long i = 0; i < steps; ++i) {
    method(x, h);
    using std::abs;
    const T e = abs(T(system.energy(x.q, x.p) - e0));
    worst = worst > e ? worst : e;
  }
  return worst;
}

struct symplectic_energy_error {
  static law_info info() {
    return {"integrators.energy_error_order",
            "A symplectic method of order p keeps the energy error bounded at O(h^p): "
            "the fitted exponent of max|H - H0| over a fixed time is p",
            {"263", "264"}};
  }
  // Truncation model: max|H - H0| = C h^p (1 + O(h)) over t in [0, 4] (no secular
  // drift); the exponent from h and h/2 settles within 0.4 of p (converged_exponent).
  template <class T>
  static void property() {
    const auto z = kepler_state<T>();
    const mc::kepler_system<T> kepler(T(1), T(1));
    const auto check = [&]<template <class, class> class Method>(const char* name, int p,
                                                                 long steps) {
      const auto error = [&](const T& h) {
        using std::round;
        const long n = static_cast<long>(static_cast<double>(round(T(4 / h))));
        return max_energy_error<Method>(kepler, z, h, n);
      };
      check_exponent(std::string(name) + ": fitted exponent of the energy error",
                     converged_exponent(error, T(T(4) / T(steps)), p, lift<T>(1)), p);
    };
    check.template operator()<mc::stormer_verlet>("Stormer-Verlet", 2, 128);
    check.template operator()<yoshida4>("composition 4", 4, 64);
    check.template operator()<gauss2>("Gauss-Legendre 2", 4, 32);
  }
};
MECHCHECK_LAW(symplectic_energy_error);

struct verlet_momenta {
  static law_info info() {
    return {"integrators.verlet_preserves_momenta",
            "Stormer-Verlet with pair forces keeps total momentum and angular momentum to "
            "rounding (Noether's charges of the discrete map)",
            {"62", "65", "73", "76"}};
  }
  // Each step adds rounding of the N-term force sums and of the kicks and drifts to P
  // and M: k = 8 N per step, over the steps taken, against sum |p_i| (sum |r_i||p_i|).
  // Domain: motions that exist for the 100 steps. U = c r^3 with c < 0 pushes the
  // particles apart with a force growing as r^2, so r'' ~ r^2 reaches infinity in finite
  // time (light particles within t = 100/256: the step then overflows, and reports it);
  // there is no motion left whose momenta could be conserved, so those are not drawn.
  template <class T>
  static void property() {
    const auto s = *gen::particle_samples(2, 4);
    const auto u = *rc::gen::suchThat(gen::pair_potentials(), [](const gen::pair_potential& v) {
      return !(v.kind == gen::pair_potential::shape::power_law && v.k > 2 && v.a < 0);
    });
    const mc::pair_force_system<T, gen::pair_potential> sys{s.template tier_masses<T>(), u};
    dynamic_vector<T> q = s.template positions<T>(), v = s.template velocities<T>(), p(v.size());
    for (Eigen::Index i = 0; i < v.size(); ++i) p(i) = T(s.masses[i / 3]) * v(i);
    const auto totals = [&](const dynamic_vector<T>& qq, const dynamic_vector<T>& pp) {
      std::array<T, 6> out{};
      out.fill(lift<T>(0));
      for (Eigen::Index i = 0; i < s.particles(); ++i)
        for (int c = 0; c < 3; ++c) {
          const int a = (c + 1) % 3, b = (c + 2) % 3;
          out[c] += pp(3 * i + c);
          out[3 + c] += qq(3 * i + a) * pp(3 * i + b) - qq(3 * i + b) * pp(3 * i + a);
        }
      return out;
    };
    const auto before = totals(q, p);
    mc::stormer_verlet<decltype(sys), dynamic_vector<T>> verlet(sys);
    mc::phase_state<dynamic_vector<T>> x{q, p};
    const long steps = 100;
    T p_scale = lift<T>(0), m_scale = lift<T>(0);
    for (long i = 0; i < steps; ++i) {
      verlet(x, T(1) / 256);
      for (Eigen::Index j = 0; j < s.particles(); ++j) {
        const T pn = x.p.segment(3 * j, 3).norm(), rn = x.q.segment(3 * j, 3).norm();
        p_scale = p_scale > pn ? p_scale : pn;
        m_scale = m_scale > rn * pn ? m_scale : rn * pn;
      }
    }
    const auto after = totals(x.q, x.p);
    const double k = 8.0 * s.particles() * steps;
    for (int c = 0; c < 3; ++c) {
      check_close("P_" + std::string(1, "xyz"[c]), after[c], before[c],
                  T(s.particles() * p_scale + 1), k);
      check_close("M_" + std::string(1, "xyz"[c]), after[3 + c], before[3 + c],
                  T(s.particles() * m_scale + 1), k);
    }
  }
};
MECHCHECK_LAW(verlet_momenta);

// --- canonical transformations -----------------------------------------------------------

/// Maps (q, p) -> (Q, P) for n = 1 or 2, each generic in the scalar.
enum class canonical_map { swap, scaling, point, linear_point, kick_drift, oscillator_flow };

struct map_case {
  canonical_map kind;
  std::vector<double> values;  // parameters
};

inline void showValue(const map_case& c, std::ostream& os) {
  static const char* names[] = {"swap", "scaling (eq 311)", "point Q = q + e sin q",
                                "linear point Q = A q", "kick-drift of random potentials",
                                "exact oscillator flow"};
  os << names[static_cast<int>(c.kind)] << " params (";
  for (double v : c.values) os << v << " ";
  os << ")";
}

template <class S>
dynamic_vector<S> apply_map(const map_case& c, const dynamic_vector<S>& z) {
  using std::cos;
  using std::sin;
  using std::sqrt;
  const auto& v = c.values;
  dynamic_vector<S> out(z.size());
  switch (c.kind) {
    case canonical_map::swap:  // Q = p, P = -q (notes after eq 304)
      out << z(1), -z(0);
      break;
    case canonical_map::scaling: {  // Q = sqrt(m w) q, P = p / sqrt(m w) (eq 311)
      using R = mc::real_type_t<S>;
      const R root = sqrt(R(v[0]) * R(v[1]));
      out << lift<S>(root) * z(0), lift<S>(R(1) / root) * z(1);
      break;
    }
    case canonical_map::point: {  // Q = q + e sin q, P = p / (1 + e cos q), |e| < 1
      const S e = lift<S>(v[0]);
      const S s = sin(z(0)), co = cos(z(0));
      const S dq = lift<S>(1) + e * co;
      out << z(0) + e * s, z(1) * mc::inverse(dq);
      break;
    }
    case canonical_map::linear_point: {  // Q = A q, P = A^-T p on two dof
      using R = mc::real_type_t<S>;
      Eigen::Matrix<R, 2, 2> a;
      a << R(v[0]), R(v[1]), R(v[2]), R(v[3]);
      const Eigen::Matrix<R, 2, 2> ait = a.inverse().transpose();
      for (int i = 0; i < 2; ++i) {
        const S x = lift<S>(a(i, 0)) * z(0), y = lift<S>(a(i, 1)) * z(1);
        const S u = lift<S>(ait(i, 0)) * z(2), w = lift<S>(ait(i, 1)) * z(3);
        out(i) = x + y;
        out(2 + i) = u + w;
      }
      break;
    }
    case canonical_map::kick_drift: {
      // generating functions F2 = q P + e U(q) (kick) and F2 = q P + e K(P) (drift) with
      // U = a cos(q) + b q^3, K = c P^4 / 4 + d sin(P): explicit canonical maps.
      const S a = lift<S>(v[0]), b = lift<S>(v[1]), cc = lift<S>(v[2]), d = lift<S>(v[3]);
      const S s = sin(z(0));
      const S q2 = z(0) * z(0);
      const S du = b * lift<S>(3) * q2 - a * s;
      const S p_new = z(1) - du;
      const S p3 = p_new * p_new * p_new;
      const S c2 = cos(p_new);
      const S dk = cc * p3 + d * c2;
      out << z(0) + dk, p_new;
      break;
    }
    case canonical_map::oscillator_flow: {
      const mechcheck::reference::oscillator_flow<double> flow(v[0], v[1]);
      const dynamic_vector<S> q = z.head(1), p = z.tail(1);
      const auto x = flow(q, p, lift<S>(v[2]));
      out << x.q()(0), x.p()(0);
      break;
    }
  }
  return out;
}

rc::Gen<map_case> map_cases() {
  return rc::gen::exec([] {
    map_case c;
    c.kind = *rc::gen::element(canonical_map::swap, canonical_map::scaling, canonical_map::point,
                               canonical_map::linear_point, canonical_map::kick_drift,
                               canonical_map::oscillator_flow);
    switch (c.kind) {
      case canonical_map::swap:
        break;
      case canonical_map::scaling:
      case canonical_map::oscillator_flow:
        c.values = {*gen::positive(), *gen::positive(), *gen::coordinate()};
        break;
      case canonical_map::point:
        c.values = {*gen::dyadic_towards_zero(0.75)};
        break;
      case canonical_map::linear_point:
        c.values = *rc::gen::suchThat(rc::gen::container<std::vector<double>>(4, gen::coordinate()),
                                      [](const std::vector<double>& m) {
                                        return std::abs(m[0] * m[3] - m[1] * m[2]) >= 0.25;
                                      });
        break;
      default:
        c.values = *rc::gen::container<std::vector<double>>(4, gen::dyadic_towards_zero(1));
    }
    return c;
  });
}

struct canonical_maps {
  static law_info info() {
    return {"canonical.symplectic_condition",
            "Canonical maps (swap, the scaling of eq 311, point transformations, maps from "
            "generating functions, the exact oscillator flow) satisfy M J M^T = J, "
            "det M = 1, and {Q_i,Q_j} = {P_i,P_j} = 0, {Q_i,P_j} = delta_ij",
            {"285", "289", "293", "299", "300", "302", "303", "304", "311"}};
  }
  // A map of a few operations: k = 32 on |M|^2 for M J M^T - J and det M; the brackets
  // of its components by AD (2n products): k = 32.
  template <class T>
  static void property() {
    const auto c = *map_cases();
    RC_TAG(static_cast<int>(c.kind));
    const int n = c.kind == canonical_map::linear_point ? 2 : 1;
    const dynamic_vector<T> z = gen::to_tier<T>(*gen::coordinates(2 * n));
    const auto map = [&c]<class S>(const dynamic_vector<S>& w) -> dynamic_vector<S> {
      return apply_map(c, w);
    };
    const dynamic_matrix<T> m = mc::jacobian(map, z);
    const T scale = m.squaredNorm();
    check_zero("max|M J M^T - J|", symplectic_defect(m), scale, 32);
    const T det = m.determinant();
    check_close("det M (Liouville)", det, lift<T>(1), T(scale * scale), 32);
    const mc::phase_point<T> x = mc::phase_point<T>::from_stacked(z);
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) {
        const auto component = [&map, n](int k) {
          return [&map, n, k]<class S>(const dynamic_vector<S>& q, const dynamic_vector<S>& p) -> S {
            dynamic_vector<S> w(2 * n);
            w << q, p;
            return map(w)(k);
          };
        };
        check_close("{Q_i,P_j}", mc::poisson_bracket(component(i), component(n + j), x),
                    lift<T>(i == j ? 1 : 0), scale, 32);
        check_zero("{Q_i,Q_j}", mc::poisson_bracket(component(i), component(j), x), scale, 32);
      }
  }
};
MECHCHECK_LAW(canonical_maps);

struct oscillator_action_angle {
  static law_info info() {
    return {"canonical.oscillator_action_angle",
            "Oscillator action-angle variables: Q = sqrt(2I) sin(theta), P = sqrt(2I) "
            "cos(theta) is canonical, H = I w and thetadot = w",
            {"305", "311", "315", "316", "317", "319"}};
  }
  // (theta, I) -> (q, p) through eq 315-316 and the scaling of eq 311: a few roundings;
  // H by AD: k = 16 on the natural scales.
  template <class T>
  static void property() {
    const double m = *gen::positive(), k = *gen::positive();
    const double theta = *gen::coordinate(), action = *gen::dyadic(1.0 / 16, 2);
    using std::sqrt;
    const T w = sqrt(T(k) / T(m));
    const T mw = T(m) * w;
    // (theta, I) -> (q, p)
    const auto to_qp = [&]<class S>(const dynamic_vector<S>& a) -> dynamic_vector<S> {
      using std::cos;
      using std::sin;
      using std::sqrt;
      const S r = sqrt(lift<S>(2) * a(1));
      const S big_q = r * sin(a(0)), big_p = r * cos(a(0));
      dynamic_vector<S> out(2);
      out << big_q * lift<S>(T(1 / sqrt(mw))), big_p * lift<S>(T(sqrt(mw)));
      return out;
    };
    dynamic_vector<T> a(2);
    a << T(theta), T(action);
    const dynamic_matrix<T> jac = mc::jacobian(to_qp, a);
    const T scale = jac.squaredNorm();
    check_zero("max|M J M^T - J| of (theta, I) -> (q, p)", symplectic_defect(jac), scale, 16);
    const mc::harmonic_oscillator<T> ham{T(m), T(k)};
    // H(q(theta, I), p(theta, I)) = I w, and its derivatives give thetadot = w, Idot = 0
    const auto h_of_angle_action = [&]<class S>(const dynamic_vector<S>& v) -> S {
      const dynamic_vector<S> qp = to_qp(v);
      const dynamic_vector<S> qq = qp.head(1), pp = qp.tail(1);
      return ham(qq, pp);
    };
    const auto [hv, dh] = mc::value_and_gradient(h_of_angle_action, a);
    check_close("H = I w", hv, T(T(action) * w), T(T(action) * w + 1), 16);
    check_close("thetadot = dH/dI = w", dh(1), w, T(w + 1), 16);
    check_zero("Idot = -dH/dtheta = 0", dh(0), T(T(action) * w + 1), 16);
  }
};
MECHCHECK_LAW(oscillator_action_angle);

struct erratum_318 {
  static law_info info() {
    return {"canonical.erratum_318",
            "Printed eq 318 inverts the angle as arctan(P/Q)",
            {"318"},
            mc::harness::expectation::falsified,
            "printed: theta = arctan(P/Q); correct: theta = arctan(Q/P) (from eqs 315-316: "
            "tan theta = Q/P)"};
  }
  template <class T>
  static void property() {
    const double theta = *gen::dyadic(-1.5, 1.5), action = *gen::dyadic(1.0 / 16, 2);
    using std::atan;
    using std::cos;
    using std::sin;
    using std::sqrt;
    const T r = sqrt(T(2) * T(action));
    const T q = r * sin(T(theta)), p = r * cos(T(theta));
    check_close("printed arctan(P/Q) vs theta", T(atan(p / q)), T(theta), lift<T>(1), 16);
  }
};
MECHCHECK_LAW(erratum_318);

}  // namespace
