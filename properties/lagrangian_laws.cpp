/// Lagrangian and Hamiltonian mechanics, Noether's theorem, Galilean and similarity laws
/// (notes lectures 1-8, 21). These are pointwise identities at random states: the
/// Euler-Lagrange accelerations, momenta and charges come from L by nested AD.
///
/// Tolerance model: each quantity is a short sum of products of AD derivatives, plus for
/// accelerations a linear solve with the kinetic matrix W (error ~ n eps cond(W)). Each
/// law names its scale (the magnitude of the terms that cancel) and a budget k counted
/// from those operations; residuals are reported in eps * scale.

#include <cmath>

#include "generators.hpp"
#include "mechcheck/harness/law.hpp"

namespace {

namespace mc = mechcheck;
namespace gen = mechcheck::generators;
namespace models = mechcheck::models;
using mc::dynamic_matrix;
using mc::dynamic_vector;
using mc::lift;
using mc::harness::check_close;
using mc::harness::check_zero;
using mc::harness::law_info;

template <class T>
T inf_norm(const dynamic_vector<T>& v) {
  return v.size() ? T(v.template lpNorm<Eigen::Infinity>()) : lift<T>(0);
}

template <class T>
T at_least_one(const T& x) {
  return x > 1 ? x : lift<T>(1);
}

template <class T>
void check_vectors(const std::string& what, const dynamic_vector<T>& computed,
                   const dynamic_vector<T>& expected, const T& scale, double budget) {
  for (Eigen::Index i = 0; i < computed.size(); ++i)
    check_close(what + "[" + std::to_string(i) + "]", computed(i), expected(i), scale, budget);
}

using closed_system = models::particle_system<double, gen::pair_potential>;
using field_system =
    models::particle_system<double, gen::pair_potential, models::vertical_field<double>>;

/// The Noether charge of (L, G, F) as a function of (q, qdot, t), for d/dt by AD.
template <class L, class G, class F>
struct charge_function {
  const L& lag;
  const G& generator;
  const F& f;
  template <class S>
  S operator()(const dynamic_vector<S>& q, const dynamic_vector<S>& qdot, const S& t) const {
    return mc::noether_charge(lag, generator, f, q, qdot, t);
  }
};

/// d/dt of the charge on the solution through (q, qdot, t) as the sum of its terms
/// dQ/dz_i dz_i/dt, z = (q, qdot, t), dz/dt = (qdot, qddot, 1), and the sum of their
/// magnitudes as its scale.
template <class T, class L, class G, class F>
std::pair<T, T> charge_rate(const L& lag, const G& generator, const F& f,
                            const dynamic_vector<T>& q, const dynamic_vector<T>& qdot,
                            const T& t) {
  using std::abs;
  const Eigen::Index n = q.size();
  const dynamic_vector<T> a = mc::accelerations(lag, q, qdot, t);
  const charge_function<L, G, F> charge{lag, generator, f};
  const auto stacked = [&charge, n]<class S>(const dynamic_vector<S>& z) -> S {
    const dynamic_vector<S> qq = z.head(n), vv = z.segment(n, n);
    return charge(qq, vv, z(2 * n));
  };
  dynamic_vector<T> z(2 * n + 1), rate_of_z(2 * n + 1);
  z << q, qdot, t;
  rate_of_z << qdot, a, lift<T>(1);
  const dynamic_vector<T> g = mc::gradient(stacked, z);
  T rate = lift<T>(0), scale = lift<T>(0);
  for (Eigen::Index i = 0; i < z.size(); ++i) {
    const T term = g(i) * rate_of_z(i);
    rate += term;
    scale += abs(term);
  }
  return {rate, at_least_one(scale)};
}

// ---------------------------------------------------------------------------------------

struct euler_lagrange_is_newton {
  static law_info info() {
    return {"lagrange.euler_lagrange_is_newton",
            "Euler-Lagrange in Cartesian coordinates is Newton's m a = -grad V",
            {"1", "2", "3", "4", "5", "6"}};
  }
  // W = diag(m) is solved exactly up to one division; grad V by first- and second-order
  // AD differ by the rounding of the pair sums (<= 4N terms): k = 4N + 8.
  template <class T>
  static void property() {
    const auto s = *gen::particle_samples();
    const auto u = *gen::pair_potentials();
    const closed_system sys(s.masses, u);
    const auto q = s.template positions<T>();
    const auto v = s.template velocities<T>();
    const dynamic_vector<T> a = mc::accelerations(sys, q, v, lift<T>(0));
    const auto potential = [&sys]<class S>(const dynamic_vector<S>& x) -> S { return sys.potential(x); };
    const dynamic_vector<T> grad = mc::gradient(potential, q);
    dynamic_vector<T> newton(q.size());
    for (Eigen::Index i = 0; i < q.size(); ++i) newton(i) = -grad(i) / T(s.masses[i / 3]);
    check_vectors("EL acceleration vs -grad V / m", a, newton, at_least_one(inf_norm(newton)),
                  4.0 * s.particles() + 8);
  }
};
MECHCHECK_LAW(euler_lagrange_is_newton);

/// A model system chosen at random, with a state where its kinetic matrix is regular.
struct model_case {
  int which = 0;                  // 0 spring pendulum, 1 spherical, 2 rotating pivot, 3 N-body
  std::vector<double> params, q, qdot;
  double t = 0;
  gen::pair_potential pair;
  gen::particle_sample particles;
};

inline void showValue(const model_case& c, std::ostream& os) {
  static const char* names[] = {"spring pendulum", "spherical pendulum", "rotating pivot",
                                "particles"};
  os << names[c.which] << " params (";
  for (double p : c.params) os << p << " ";
  os << ") q (";
  for (double x : c.q) os << x << " ";
  os << ") qdot (";
  for (double x : c.qdot) os << x << " ";
  os << ") t " << c.t;
  if (c.which == 3) {
    os << " ";
    gen::showValue(c.pair, os);
    os << " ";
    gen::showValue(c.particles, os);
  }
}

rc::Gen<model_case> model_cases() {
  return rc::gen::exec([] {
    model_case c;
    c.which = *rc::gen::inRange(0, 4);
    switch (c.which) {
      case 0:  // m, k, l, g; x in [-1/2, 1/2] with l >= 1
        c.params = {*gen::positive(), *gen::positive(), *gen::dyadic(1, 3), *gen::positive()};
        c.q = {*gen::dyadic_towards_zero(0.5), *gen::coordinate()};
        c.qdot = *gen::coordinates(2);
        break;
      case 1:  // m, l, g; theta in [1/2, 3/2] keeps sin^2(theta) >= 0.23
        c.params = {*gen::positive(), *gen::positive(), *gen::positive()};
        c.q = {*gen::dyadic(0.5, 1.5), *gen::coordinate()};
        c.qdot = *gen::coordinates(2);
        break;
      case 2:  // m, l, g, R, w
        c.params = {*gen::positive(), *gen::positive(), *gen::positive(), *gen::positive(),
                    *gen::coefficient()};
        c.q = {*gen::coordinate()};
        c.qdot = {*gen::coordinate()};
        c.t = *gen::coordinate();
        break;
      default:
        c.pair = *gen::pair_potentials();
        c.particles = *gen::particle_samples(2, 3);
        c.q = c.particles.q;
        c.qdot = c.particles.qdot;
    }
    return c;
  });
}

/// Call body(lagrangian) with the case's model.
template <class Body>
void with_model(const model_case& c, Body&& body) {
  const auto& p = c.params;
  switch (c.which) {
    case 0:
      return body(models::spring_pendulum<double>{p[0], p[1], p[2], p[3]});
    case 1:
      return body(models::spherical_pendulum<double>(p[0], p[1], p[2]));
    case 2:
      return body(models::rotating_pivot_pendulum<double>{p[0], p[1], p[2], p[3], p[4]});
    default:
      return body(closed_system(c.particles.masses, c.pair));
  }
}

struct hamilton_equals_euler_lagrange {
  static law_info info() {
    return {"hamilton.equals_euler_lagrange",
            "Hamilton's equations of the Legendre transform reproduce Euler-Lagrange: "
            "dH/dp = qdot, -dH/dq = dL/dq = pdot, dH/dt = -dL/dt",
            {"244", "245", "250", "253", "255", "256", "257"}};
  }
  // H is evaluated through Newton's solution of p = dL/dqdot (converged to 4 eps) and
  // differentiated by AD; each rate is a sum over n of products: k = 16n + 16.
  template <class T>
  static void property() {
    const auto c = *model_cases();
    RC_TAG(c.which);
    with_model(c, [&](const auto& lag) {
      const auto q = gen::to_tier<T>(c.q);
      const auto v = gen::to_tier<T>(c.qdot);
      const T t = T(c.t);
      const auto jet = mc::lagrangian_jet_at(lag, q, v, t);
      const mc::legendre_hamiltonian<std::decay_t<decltype(lag)>> h{lag};
      const auto rates = mc::hamilton_equations(h, q, jet.momenta, t);
      const double k = 16.0 * q.size() + 16;
      check_vectors("dH/dp vs qdot", rates.qdot, v, at_least_one(inf_norm(v)), k);
      check_vectors("-dH/dq vs dL/dq", rates.pdot, jet.dq, at_least_one(inf_norm(jet.dq)), k);
      using std::abs;
      check_close("dH/dt vs -dL/dt", rates.dh_dt, T(-jet.dt), at_least_one(abs(jet.dt)), k);
    });
  }
};
MECHCHECK_LAW(hamilton_equals_euler_lagrange);

struct legendre_round_trip {
  static law_info info() {
    return {"hamilton.legendre_round_trip",
            "The Legendre transform and its inverse: L = p.qdot - H(q, p) for the H of L, and "
            "the L of H = |p|^2/2m + U(r) is m|qdot|^2/2 - U(r)",
            {"245", "253", "254", "255"}};
  }
  // One Newton solve each way (to 4 eps) and sums p.qdot - H over n terms:
  // scale |p||qdot| + |L|, k = 8n + 16.
  template <class T>
  static void property() {
    const auto c = *model_cases();
    using std::abs;
    with_model(c, [&](const auto& lag) {
      using L = std::decay_t<decltype(lag)>;
      const auto q = gen::to_tier<T>(c.q);
      const auto v = gen::to_tier<T>(c.qdot);
      const T t = T(c.t);
      const mc::legendre_hamiltonian<L> h{lag};
      const T l = lag(q, v, t);
      const auto p = mc::generalized_momenta(lag, q, v, t);
      const T scale = at_least_one(T(abs(l) + p.norm() * v.norm()));
      check_close("p.qdot - H(q, p)", T(p.dot(v) - h(q, p, t)), l, scale, 8.0 * q.size() + 16);
    });
    const auto x = *gen::points_away_from_origin();
    const auto u = *gen::radial_potentials();
    const double m = *gen::positive();
    const mc::central_force_hamiltonian<double, gen::radial_potential> hc(m, u);
    const auto h3 = [&hc]<class S>(const dynamic_vector<S>& q, const dynamic_vector<S>& p,
                                   const S&) -> S { return hc(q, p); };
    const mc::legendre_lagrangian<decltype(h3)> back{h3};
    const auto q = gen::to_tier<T>(x.q);
    const auto v = gen::to_tier<T>(x.p);
    const T r = q.norm();
    const T expected = T(m) * v.squaredNorm() / 2 - u(r);
    check_close("L of H_central", back(q, v, lift<T>(0)), expected,
                at_least_one(T(T(m) * v.squaredNorm() + abs(u(r)))), 40);
  }
};
MECHCHECK_LAW(legendre_round_trip);

struct coordinate_invariance {
  static law_info info() {
    return {"lagrange.coordinate_invariance",
            "The spring pendulum in (x, theta) and in Cartesian coordinates moves alike",
            {"7", "8", "9", "10", "11", "12", "14", "15"}};
  }
  // Cartesian accelerations against J qddot + qdot^T Hess(X) qdot of the polar ones:
  // two 2x2 solves and sums of 2-4 products, scale |a| + |J||qddot| + |Hess||qdot|^2:
  // k = 64.
  template <class T>
  static void property() {
    const double m = *gen::positive(), k = *gen::positive(), l = *gen::dyadic(1, 3),
                 g = *gen::positive();
    const models::spring_pendulum<double> polar{m, k, l, g};
    const models::spring_pendulum_cartesian<double> cartesian{m, k, l, g};
    dynamic_vector<T> q(2), v(2);
    q << T(*gen::dyadic_towards_zero(0.5)), T(*gen::coordinate());
    v << T(*gen::coordinate()), T(*gen::coordinate());
    const T t = lift<T>(0);
    const dynamic_vector<T> a_polar = mc::accelerations(polar, q, v, t);
    const auto position = [&polar]<class S>(const dynamic_vector<S>& x) -> dynamic_vector<S> {
      return polar.position(x);
    };
    const dynamic_matrix<T> jac = mc::jacobian(position, q);
    const dynamic_vector<T> x = polar.position(q);
    const dynamic_vector<T> xdot = jac * v;
    const dynamic_vector<T> a_cart = mc::accelerations(cartesian, x, xdot, t);
    dynamic_vector<T> predicted = jac * a_polar;
    T curvature = lift<T>(0);
    for (int c = 0; c < 2; ++c) {
      const auto component = [&position, c]<class S>(const dynamic_vector<S>& y) -> S {
        return position(y)(c);
      };
      const dynamic_matrix<T> hess = mc::hessian(component, q);
      predicted(c) += v.dot(hess * v);
      const T hn = hess.norm();
      curvature = curvature > hn ? curvature : hn;
    }
    const T scale = at_least_one(T(inf_norm(a_cart) + jac.norm() * inf_norm(a_polar) +
                                   curvature * v.squaredNorm()));
    check_vectors("Cartesian acceleration vs mapped polar acceleration", a_cart, predicted,
                  scale, 64);
  }
};
MECHCHECK_LAW(coordinate_invariance);

/// L + d/dt f(q, t) for f(q, t) = sum_i (c_i q_i^2 t + d_i sin(q_i + t)), with the total
/// derivative written out (an AD layer more would exceed what Eigen's AutoDiffScalar
/// supports over multiprecision types inside an acceleration, which is already two deep):
///   df/dt = sum_i (2 c_i q_i qdot_i t + c_i q_i^2 + d_i cos(q_i + t) (qdot_i + 1)).
template <class L>
struct gauge_transformed {
  L lag;
  std::vector<double> c, d;
  template <class S>
  S operator()(const dynamic_vector<S>& q, const dynamic_vector<S>& qdot, const S& t) const {
    using std::cos;
    S df = lift<S>(0);
    for (Eigen::Index i = 0; i < q.size(); ++i) {
      const S ci = lift<S>(c[i]), di = lift<S>(d[i]);
      const S a = lift<S>(2) * ci * q(i) * qdot(i) * t;
      const S b = ci * q(i) * q(i);
      const S angle = q(i) + t;
      const S rate = qdot(i) + lift<S>(1);
      const S e = di * cos(angle) * rate;
      df += a;
      df += b;
      df += e;
    }
    const S l = lag(q, qdot, t);
    return l + df;
  }
};

/// a L.
template <class L>
struct scaled_lagrangian {
  L lag;
  double factor;
  template <class S>
  S operator()(const dynamic_vector<S>& q, const dynamic_vector<S>& qdot, const S& t) const {
    const S l = lag(q, qdot, t);
    return lift<S>(factor) * l;
  }
};

struct non_uniqueness {
  static law_info info() {
    return {"lagrange.non_uniqueness",
            "a L and L + df(q,t)/dt give the same equations of motion", {"17", "57"}};
    // The notes state this in lecture 3 (eqs 16-17) and use it in eq 57.
  }
  // The added terms change dL/dq and the mixed derivatives by amounts that cancel in the
  // solve; scale |a| + |W^-1| |df terms| ~ |a| + |d2f|(1 + |qdot|)^2: k = 32n + 32.
  template <class T>
  static void property() {
    const auto c = *model_cases();
    RC_PRE(c.which != 3);  // the pendulums: n = 1, 2
    const double alpha = *gen::coefficient();
    with_model(c, [&](const auto& lag) {
      using L = std::decay_t<decltype(lag)>;
      const auto q = gen::to_tier<T>(c.q);
      const auto v = gen::to_tier<T>(c.qdot);
      const T t = T(c.t);
      const auto c = *rc::gen::container<std::vector<double>>(q.size(), gen::coefficient());
      const auto d = *rc::gen::container<std::vector<double>>(q.size(), gen::coefficient());
      const dynamic_vector<T> a = mc::accelerations(lag, q, v, t);
      const dynamic_vector<T> a_scaled =
          mc::accelerations(scaled_lagrangian<L>{lag, alpha}, q, v, t);
      const dynamic_vector<T> a_gauge = mc::accelerations(gauge_transformed<L>{lag, c, d}, q, v, t);
      const auto w = mc::lagrangian_jet_at(lag, q, v, t).kinetic;
      // The gauge term's second derivatives are bounded by 2|c|(1 + |q| + |t|) + |d|(1 + |qdot|).
      using std::abs;
      const T f_size = T(4) * (1 + inf_norm(q) + abs(t)) + T(2) * (1 + inf_norm(v));
      const T inv_w = w.inverse().norm();
      const T one_v = 1 + inf_norm(v);
      const T scale = at_least_one(T(inf_norm(a) + inv_w * f_size * one_v * one_v));
      const double k = 32.0 * q.size() + 32;
      check_vectors("qddot of a L", a_scaled, a, scale, k);
      check_vectors("qddot of L + df/dt", a_gauge, a, scale, k);
    });
  }
};
MECHCHECK_LAW(non_uniqueness);

struct energy_is_t_plus_v {
  static law_info info() {
    return {"lagrange.energy_is_t_plus_v",
            "With T quadratic in qdot, h = qdot.p - L = T + V (Euler: qdot.dT/dqdot = 2T)",
            {"68", "69", "71", "72"}};
  }
  // qdot.p sums 3N products, then - L: scale T + |V|, k = 3N + 8.
  template <class T>
  static void property() {
    const auto s = *gen::particle_samples();
    const auto u = *gen::pair_potentials();
    const closed_system sys(s.masses, u);
    const auto q = s.template positions<T>();
    const auto v = s.template velocities<T>();
    const T t = lift<T>(0);
    const T kinetic = sys.kinetic(v), potential = sys.potential(q);
    using std::abs;
    const T scale = at_least_one(T(kinetic + abs(potential)));
    const double k = 3.0 * q.size() + 8;
    check_close("h vs T + V", mc::energy_function(sys, q, v, t), T(kinetic + potential), scale, k);
    const auto p = mc::generalized_momenta(sys, q, v, t);
    check_close("qdot.dT/dqdot vs 2T", T(v.dot(p)), T(2 * kinetic), at_least_one(kinetic), k);
  }
};
MECHCHECK_LAW(energy_is_t_plus_v);

/// The symmetries of a closed N-particle system, one at a time.
enum class symmetry { translation, rotation, time_translation, boost };

template <class T, class Body>
void with_symmetry(symmetry which, const closed_system& sys, const std::vector<double>& n,
                   Body&& body) {
  const double d[3] = {n[0], n[1], n[2]};
  switch (which) {
    case symmetry::translation:
      return body(mc::translation_generator<double>{{d[0], d[1], d[2]}}, mc::zero_function{});
    case symmetry::rotation:
      return body(mc::rotation_generator<double>{{d[0], d[1], d[2]}}, mc::zero_function{});
    case symmetry::time_translation:
      return body(mc::time_translation_generator{}, sys);
    default:
      return body(mc::boost_generator<double>{{d[0], d[1], d[2]}},
                  mc::boost_gauge_function<double>{sys.masses, {d[0], d[1], d[2]}});
  }
}

struct noether_symmetry_condition {
  static law_info info() {
    return {"noether.symmetry_condition",
            "Translations, rotations, time translation and boosts satisfy dL/dlambda = dF/dt "
            "on every path",
            {"53", "56", "57", "58", "62", "66", "73", "74", "78"}};
  }
  // dL/dlambda and dF/dt are sums over 3N coordinates of products of AD derivatives:
  // scale (|dL/dq| + |p|)(|G| + |dG/dt|) + |dF/dt|, k = 6N + 8.
  template <class T>
  static void property() {
    const auto s = *gen::particle_samples();
    const auto u = *gen::pair_potentials();
    const auto n = *gen::directions();
    const auto which = *rc::gen::element(symmetry::translation, symmetry::rotation,
                                         symmetry::time_translation, symmetry::boost);
    RC_TAG(static_cast<int>(which));
    const closed_system sys(s.masses, u);
    const auto q = s.template positions<T>();
    const auto v = s.template velocities<T>();
    const auto acc = gen::to_tier<T>(*gen::coordinates(static_cast<int>(q.size())));  // any path
    const T t = T(*gen::coordinate());
    with_symmetry<T>(which, sys, n, [&](const auto& g, const auto& f) {
      const T defect = mc::symmetry_defect(sys, g, f, q, v, acc, t);
      const auto jet = mc::lagrangian_jet_at(sys, q, v, t);
      const dynamic_vector<T> gv = g(q, v, t);
      const dynamic_vector<T> gdot = mc::total_time_derivative_vector(g, q, v, acc, t);
      using std::abs;
      const T df = mc::total_time_derivative(f, q, v, acc, t);
      const T scale = at_least_one(
          T((jet.dq.norm() + jet.momenta.norm()) * (gv.norm() + gdot.norm()) + abs(df)));
      check_zero("dL/dlambda - dF/dt", defect, scale, 6.0 * s.particles() + 8);
    });
  }
};
MECHCHECK_LAW(noether_symmetry_condition);

struct noether_conservation {
  static law_info info() {
    return {"noether.charge_conservation",
            "Noether charges sum p.G - F are conserved on solutions: total momentum, angular "
            "momentum, energy h, and the boost charge (centre of mass moves uniformly)",
            {"61", "63", "64", "65", "68", "75", "76", "79", "80", "81"}};
  }
  // d/dt Q = sum over 6N + 1 terms dQ/dz_i dz_i/dt with Euler-Lagrange accelerations
  // (a diagonal solve): scale sum |terms|, k = 8N + 16.
  template <class T>
  static void property() {
    const auto s = *gen::particle_samples();
    const auto u = *gen::pair_potentials();
    const auto n = *gen::directions();
    const auto which = *rc::gen::element(symmetry::translation, symmetry::rotation,
                                         symmetry::time_translation, symmetry::boost);
    RC_TAG(static_cast<int>(which));
    const closed_system sys(s.masses, u);
    const auto q = s.template positions<T>();
    const auto v = s.template velocities<T>();
    const T t = T(*gen::coordinate());
    with_symmetry<T>(which, sys, n, [&](const auto& g, const auto& f) {
      const auto [rate, scale] = charge_rate(sys, g, f, q, v, t);
      check_zero("dQ/dt on shell", rate, scale, 8.0 * s.particles() + 16);
    });
  }
};
MECHCHECK_LAW(noether_conservation);

struct cyclic_coordinates {
  static law_info info() {
    return {"noether.cyclic_coordinates",
            "The spherical pendulum's p_phi = m l^2 sin^2(theta) phidot is its momentum and is "
            "conserved; a free particle's momenta are conserved",
            {"40", "41", "48", "49", "50"}};
  }
  // p_phi by AD against the closed form (5 roundings): k = 8. d/dt p_phi on shell, a
  // sum of 5 terms dp/dz_i dz_i/dt after a 2x2 diagonal solve: scale sum |terms|, k = 16.
  template <class T>
  static void property() {
    const double m = *gen::positive(), l = *gen::positive(), g = *gen::positive();
    const models::spherical_pendulum<double> lag(m, l, g);
    dynamic_vector<T> q(2), v(2);
    q << T(*gen::dyadic(0.5, 1.5)), T(*gen::coordinate());
    v << T(*gen::coordinate()), T(*gen::coordinate());
    const T t = lift<T>(0);
    using std::sin;
    const T s = sin(q(0));
    const T closed = T(m) * T(l) * T(l) * s * s * v(1);
    const auto p = mc::generalized_momenta(lag, q, v, t);
    using std::abs;
    check_close("p_phi vs m l^2 sin^2(theta) phidot", p(1), closed, at_least_one(abs(closed)), 8);
    const mc::coordinate_shift_generator shift{1};
    const auto [rate, scale] = charge_rate(lag, shift, mc::zero_function{}, q, v, t);
    check_zero("dp_phi/dt on shell", rate, scale, 16);
    const models::free_particle<double> free(m);
    for (Eigen::Index k = 0; k < 2; ++k) {
      const auto [r, sc] = charge_rate(free, mc::coordinate_shift_generator{k}, mc::zero_function{},
                                       q, v, t);
      check_zero("dp/dt of a free particle", r, sc, 4);
    }
  }
};
MECHCHECK_LAW(cyclic_coordinates);

struct broken_symmetry {
  static law_info info() {
    return {"noether.broken_symmetry",
            "In a field V(z), P_x, P_y and M_z are conserved while P_z and M_x, M_y change "
            "at the rate of the external force and torque",
            {"61", "65", "76"}};
  }
  // Rates by AD on shell against the external force -sum V'(z_i) and its torque (sums of
  // N terms): scale as in noether.charge_conservation plus the force and torque sizes,
  // k = 8N + 16.
  template <class T>
  static void property() {
    const auto s = *gen::particle_samples();
    const auto u = *gen::pair_potentials();
    const double fa = *gen::coefficient(), fb = *gen::coefficient();
    const field_system sys(s.masses, u, models::vertical_field<double>{fa, fb});
    const auto q = s.template positions<T>();
    const auto v = s.template velocities<T>();
    const T t = lift<T>(0);
    T force = lift<T>(0), torque_x = lift<T>(0), torque_y = lift<T>(0);
    for (Eigen::Index i = 0; i < s.particles(); ++i) {
      const T fz = -(T(fa) + 2 * T(fb) * q(3 * i + 2));  // -V'(z_i)
      force += fz;
      torque_x += q(3 * i + 1) * fz;   // (r x F)_x = y F_z
      torque_y -= q(3 * i) * fz;       // (r x F)_y = -x F_z
    }
    const double k = 8.0 * s.particles() + 16;
    const double axes[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    const T expected_p[3] = {lift<T>(0), lift<T>(0), force};
    const T expected_m[3] = {torque_x, torque_y, lift<T>(0)};
    for (int c = 0; c < 3; ++c) {
      const mc::translation_generator<double> tr{{axes[c][0], axes[c][1], axes[c][2]}};
      const auto [rp, sp] = charge_rate(sys, tr, mc::zero_function{}, q, v, t);
      check_close("dP_" + std::string(1, "xyz"[c]) + "/dt vs external force", rp, expected_p[c],
                  sp, k);
      const mc::rotation_generator<double> rot{{axes[c][0], axes[c][1], axes[c][2]}};
      const auto [rm, sm] = charge_rate(sys, rot, mc::zero_function{}, q, v, t);
      check_close("dM_" + std::string(1, "xyz"[c]) + "/dt vs external torque", rm, expected_m[c],
                  sm, k);
    }
    using std::abs;
    RC_CLASSIFY(abs(force) > 0, "P_z changes");
  }
};
MECHCHECK_LAW(broken_symmetry);

struct galilean_boost {
  static law_info info() {
    return {"mechanics.galilean_boost",
            "Under a boost v_i -> v_i + V the total momentum becomes P + V sum(m)", {"78"}};
  }
  // Momenta by AD are m_i v_i with one rounding; sums over N: scale sum m |v| + M |V|,
  // k = 2N + 4.
  template <class T>
  static void property() {
    const auto s = *gen::particle_samples();
    const auto u = *gen::pair_potentials();
    const auto boost = *gen::directions();
    const closed_system sys(s.masses, u);
    const auto q = s.template positions<T>();
    const auto v = s.template velocities<T>();
    dynamic_vector<T> vb = v;
    for (Eigen::Index i = 0; i < v.size(); ++i) vb(i) += T(boost[i % 3]);
    const auto p = mc::generalized_momenta(sys, q, v, lift<T>(0));
    const auto pb = mc::generalized_momenta(sys, q, vb, lift<T>(0));
    T total_mass = lift<T>(0), scale = lift<T>(0);
    for (double m : s.masses) total_mass += T(m);
    for (Eigen::Index i = 0; i < pb.size(); ++i) {
      using std::abs;
      scale += abs(pb(i));
    }
    for (int c = 0; c < 3; ++c) {
      T big_p = lift<T>(0), big_pb = lift<T>(0);
      for (Eigen::Index i = 0; i < s.particles(); ++i) {
        big_p += p(3 * i + c);
        big_pb += pb(3 * i + c);
      }
      check_close("P' vs P + V sum m", big_pb, T(big_p + T(boost[c]) * total_mass),
                  at_least_one(scale), 2.0 * s.particles() + 4);
    }
  }
};
MECHCHECK_LAW(galilean_boost);

struct origin_shift {
  static law_info info() {
    return {"mechanics.origin_shift",
            "Shifting the origin by a changes the angular momentum to M + a x P",
            {"82", "83"}};
  }
  // M_i is r x p summed over N (2 products each): scale sum |r+a||p|, k = 4N + 4.
  template <class T>
  static void property() {
    const auto s = *gen::particle_samples();
    const auto a = *gen::directions();
    const auto q = s.template positions<T>();
    const auto v = s.template velocities<T>();
    dynamic_vector<T> p(v.size());
    for (Eigen::Index i = 0; i < v.size(); ++i) p(i) = T(s.masses[i / 3]) * v(i);
    const auto angular = [&](const dynamic_vector<T>& r, int c) {
      T m = lift<T>(0);
      for (Eigen::Index i = 0; i < s.particles(); ++i) {
        const int j = (c + 1) % 3, k = (c + 2) % 3;
        m += r(3 * i + j) * p(3 * i + k) - r(3 * i + k) * p(3 * i + j);
      }
      return m;
    };
    dynamic_vector<T> shifted = q;
    for (Eigen::Index i = 0; i < q.size(); ++i) shifted(i) += T(a[i % 3]);
    T total_p[3] = {lift<T>(0), lift<T>(0), lift<T>(0)};
    for (Eigen::Index i = 0; i < q.size(); ++i) total_p[i % 3] += p(i);
    const T scale = at_least_one(T(inf_norm(shifted) * p.template lpNorm<1>()));
    for (int c = 0; c < 3; ++c) {
      const int j = (c + 1) % 3, k = (c + 2) % 3;
      const T axp = T(a[j]) * total_p[k] - T(a[k]) * total_p[j];
      check_close("M' vs M + a x P", angular(shifted, c), T(angular(q, c) + axp), scale,
                  4.0 * s.particles() + 4);
    }
  }
};
MECHCHECK_LAW(origin_shift);

struct mechanical_similarity {
  static law_info info() {
    return {"mechanics.similarity",
            "For U homogeneous of degree k, a r(t/b) with b = a^(1-k/2) is again a solution",
            {"84", "85"}};
  }
  // Accelerations at (a q, (a/b) qdot) against (a/b^2) times those at (q, qdot): two
  // diagonal solves and pow(): scale |a/b^2| |qddot|, k = 8N + 16.
  template <class T>
  static void property() {
    const auto s = *gen::particle_samples();
    const auto u = *gen::homogeneous_pair_potentials();
    const double alpha = *gen::dyadic(0.25, 4);
    const closed_system sys(s.masses, u);
    using std::pow;
    const T a = T(alpha);
    const T b = pow(a, T(1) - T(u.k) / 2);
    const auto q = s.template positions<T>();
    const auto v = s.template velocities<T>();
    const dynamic_vector<T> acc = mc::accelerations(sys, q, v, lift<T>(0));
    const dynamic_vector<T> qs = a * q;
    const dynamic_vector<T> vs = (a / b) * v;
    const dynamic_vector<T> acc_scaled = mc::accelerations(sys, qs, vs, lift<T>(0));
    const dynamic_vector<T> predicted = (a / (b * b)) * acc;
    check_vectors("scaled solution's acceleration", acc_scaled, predicted,
                  at_least_one(inf_norm(predicted)), 8.0 * s.particles() + 16);
  }
};
MECHCHECK_LAW(mechanical_similarity);

struct simple_pendulum_equations {
  static law_info info() {
    return {"lagrange.simple_pendulum",
            "Simple pendulum: thetaddot = -(g/l) sin(theta); p = m l^2 thetadot; "
            "H = p^2/(2 m l^2) - m g l cos(theta) and its Hamilton equations",
            {"31", "33", "258", "259", "260", "261", "262"}};
  }
  // Closed forms with 3-5 roundings against AD: scale of each term, k = 16.
  template <class T>
  static void property() {
    const double m = *gen::positive(), l = *gen::positive(), g = *gen::positive();
    const models::simple_pendulum<double> lag(m, l, g);
    dynamic_vector<T> q(1), v(1);
    q << T(*gen::coordinate());
    v << T(*gen::coordinate());
    const T t = lift<T>(0), tm = T(m), tl = T(l), tg = T(g);
    using std::abs;
    using std::cos;
    using std::sin;
    const T a = mc::accelerations(lag, q, v, t)(0);
    const T expected_a = -(tg / tl) * sin(q(0));
    check_close("thetaddot (eq 33)", a, expected_a, at_least_one(T(tg / tl)), 16);
    const T p = mc::generalized_momenta(lag, q, v, t)(0);
    check_close("p_theta (eq 259)", p, T(tm * tl * tl * v(0)), at_least_one(abs(p)), 16);
    const mc::legendre_hamiltonian<models::simple_pendulum<double>> h{lag};
    dynamic_vector<T> pv(1);
    pv << p;
    const T hv = h(q, pv, t);
    const T expected_h = p * p / (2 * tm * tl * tl) - tm * tg * tl * cos(q(0));
    check_close("H (eq 260)", hv, expected_h, at_least_one(T(p * p / (tm * tl * tl) + tm * tg * tl)),
                16);
    const auto rates = mc::hamilton_equations(h, q, pv, t);
    check_close("pdot (eq 261)", rates.pdot(0), T(-tm * tg * tl * sin(q(0))),
                at_least_one(T(tm * tg * tl)), 16);
    check_close("thetadot (eq 262)", rates.qdot(0), T(p / (tm * tl * tl)), at_least_one(abs(v(0))),
                16);
  }
};
MECHCHECK_LAW(simple_pendulum_equations);

struct rotating_pivot {
  static law_info info() {
    return {"lagrange.rotating_pivot",
            "Pendulum on a rotating pivot: thetaddot + (g/l) sin(theta) = (R w^2/l) "
            "cos(theta + w t)",
            {"42", "44", "45", "47"}};
  }
  // The Lagrangian is built from the bob's velocity (eqs 44-45); AD and a 1x1 solve
  // against the closed form: scale g/l + R w^2/l + |terms|, k = 32.
  template <class T>
  static void property() {
    const double m = *gen::positive(), l = *gen::positive(), g = *gen::positive(),
                 r = *gen::positive(), w = *gen::coefficient();
    const models::rotating_pivot_pendulum<double> lag{m, l, g, r, w};
    dynamic_vector<T> q(1), v(1);
    q << T(*gen::coordinate());
    v << T(*gen::coordinate());
    const T t = T(*gen::coordinate());
    using std::cos;
    using std::sin;
    const T tl = T(l), tg = T(g), tr = T(r), tw = T(w);
    const T a = mc::accelerations(lag, q, v, t)(0);
    const T expected = -(tg / tl) * sin(q(0)) + tr * tw * tw / tl * cos(q(0) + tw * t);
    const T scale = at_least_one(T(tg / tl + tr * tw * tw / tl * (1 + abs(v(0)))));
    check_close("thetaddot vs eq 47", a, expected, scale, 32);
  }
};
MECHCHECK_LAW(rotating_pivot);

// ---------------------------------------------------------------------------------------
// Errata.

struct erratum_51 {
  static law_info info() {
    return {"lagrange.erratum_51",
            "Printed eq 51 defines the momentum as dL/dq",
            {"51"},
            mc::harness::expectation::falsified,
            "printed: p_i = dL/dq_i; correct: p_i = dL/dqdot_i (eq 252: p = m rdot)"};
  }
  template <class T>
  static void property() {
    const auto s = *gen::particle_samples();
    const auto u = *gen::pair_potentials();
    const closed_system sys(s.masses, u);
    const auto q = s.template positions<T>();
    const auto v = s.template velocities<T>();
    const auto jet = mc::lagrangian_jet_at(sys, q, v, lift<T>(0));
    dynamic_vector<T> mv(v.size());
    for (Eigen::Index i = 0; i < v.size(); ++i) mv(i) = T(s.masses[i / 3]) * v(i);
    check_vectors("printed p = dL/dq vs m v", jet.dq, mv, at_least_one(inf_norm(mv)), 8);
  }
};
MECHCHECK_LAW(erratum_51);

struct erratum_52 {
  static law_info info() {
    return {"lagrange.erratum_52",
            "Printed eq 52 gives p_phi with phi^2 instead of phidot",
            {"52"},
            mc::harness::expectation::falsified,
            "printed: p_phi = m l^2 sin^2(theta) phi^2; correct: m l^2 sin^2(theta) phidot "
            "(eq 41)"};
  }
  template <class T>
  static void property() {
    const double m = *gen::positive(), l = *gen::positive(), g = *gen::positive();
    const models::spherical_pendulum<double> lag(m, l, g);
    dynamic_vector<T> q(2), v(2);
    q << T(*gen::dyadic(0.5, 1.5)), T(*gen::coordinate());
    v << T(*gen::coordinate()), T(*gen::coordinate());
    using std::abs;
    using std::sin;
    const T s = sin(q(0));
    const T printed = T(m) * T(l) * T(l) * s * s * q(1) * q(1);
    const T p = mc::generalized_momenta(lag, q, v, lift<T>(0))(1);
    check_close("printed p_phi vs dL/dphidot", printed, p, at_least_one(abs(p)), 8);
  }
};
MECHCHECK_LAW(erratum_52);

struct erratum_70 {
  static law_info info() {
    return {"lagrange.erratum_70",
            "Printed eq 70 (Euler's theorem) drops the factor x_i",
            {"70"},
            mc::harness::expectation::falsified,
            "printed: sum_i df/dx_i = n f; correct: sum_i x_i df/dx_i = n f for f "
            "homogeneous of degree n"};
  }
  template <class T>
  static void property() {
    const auto s = *gen::particle_samples();
    const closed_system sys(s.masses, gen::pair_potential{});
    const auto v = s.template velocities<T>();
    const auto kinetic = [&sys]<class S>(const dynamic_vector<S>& x) -> S { return sys.kinetic(x); };
    const dynamic_vector<T> grad = mc::gradient(kinetic, v);
    const T t2 = 2 * sys.kinetic(v);
    check_close("printed sum dT/dqdot vs 2T", T(grad.sum()), t2, at_least_one(t2), 8);
  }
};
MECHCHECK_LAW(erratum_70);

struct erratum_85 {
  static law_info info() {
    return {"mechanics.erratum_85",
            "Printed family of similar solutions a r(b t) is not a family of solutions",
            {"85"},
            mc::harness::expectation::falsified,
            "printed: r'(t) = a r(b t) with b = a^(1-k/2); correct: r'(t) = a r(t/b) "
            "(time scales as t -> b t)"};
  }
  template <class T>
  static void property() {
    const auto s = *gen::particle_samples();
    const auto u = *gen::homogeneous_pair_potentials();
    const double alpha = *gen::dyadic(0.25, 4);
    const closed_system sys(s.masses, u);
    using std::pow;
    const T a = T(alpha);
    const T b = pow(a, T(1) - T(u.k) / 2);
    const auto q = s.template positions<T>();
    const auto v = s.template velocities<T>();
    const dynamic_vector<T> acc = mc::accelerations(sys, q, v, lift<T>(0));
    // r'(t) = a r(b t): velocity a b v, acceleration a b^2 qddot.
    const dynamic_vector<T> qs = a * q;
    const dynamic_vector<T> vs = (a * b) * v;
    const dynamic_vector<T> acc_scaled = mc::accelerations(sys, qs, vs, lift<T>(0));
    const dynamic_vector<T> printed = (a * b * b) * acc;
    check_vectors("printed family's acceleration", acc_scaled, printed,
                  at_least_one(inf_norm(printed)), 8.0 * s.particles() + 16);
  }
};
MECHCHECK_LAW(erratum_85);

/// The Lagrangian as printed in eq 46.
struct printed_eq46 {
  double m, l, g, r, w;
  template <class S>
  S operator()(const dynamic_vector<S>& q, const dynamic_vector<S>& qdot, const S& t) const {
    using std::cos;
    using std::sin;
    const S ms = lift<S>(m), ls = lift<S>(l), gs = lift<S>(g), rs = lift<S>(r), ws = lift<S>(w);
    const S wt = ws * t;
    const S a = rs * rs * ws * ws;
    const S b = lift<S>(2) * ls * qdot(0) * rs * ws * cos(q(0) + wt);
    const S c = ls * ls * qdot(0) * qdot(0);
    const S kinetic = ms * (a - b + c) * mc::half<S>();
    const S h1 = rs * sin(wt);
    const S h2 = ls * sin(q(0));
    const S potential_term = ms * gs * (h1 + h2);
    return kinetic + potential_term;
  }
};

struct erratum_46 {
  static law_info info() {
    return {"lagrange.erratum_46",
            "Printed eq 46 (rotating pivot Lagrangian) does not give eq 47",
            {"46"},
            mc::harness::expectation::falsified,
            "printed: L = m(R^2 w^2 - 2 l thetadot R w cos(theta + wt) + l^2 thetadot^2)/2 + "
            "m g (R sin wt + l sin theta); correct (pivot of eq 45): sin(theta + wt) in the "
            "cross term and l cos(theta) in the potential"};
  }
  template <class T>
  static void property() {
    const double m = *gen::positive(), l = *gen::positive(), g = *gen::positive(),
                 r = *gen::positive(), w = *gen::coefficient();
    dynamic_vector<T> q(1), v(1);
    q << T(*gen::coordinate());
    v << T(*gen::coordinate());
    const T t = T(*gen::coordinate());
    using std::cos;
    using std::sin;
    const T a = mc::accelerations(printed_eq46{m, l, g, r, w}, q, v, t)(0);
    const T expected = -(T(g) / T(l)) * sin(q(0)) + T(r) * T(w) * T(w) / T(l) * cos(q(0) + T(w) * t);
    check_close("printed L's thetaddot vs eq 47", a, expected,
                at_least_one(T(T(g) / T(l) + T(r) * T(w) * T(w) / T(l))), 32);
  }
};
MECHCHECK_LAW(erratum_46);

}  // namespace
