/// The Poisson algebra (notes lectures 21-22, eqs 263-284).
///
/// Tolerance model. A bracket {f, g} = sum over 2n products of AD derivatives; by
/// Cauchy-Schwarz its terms are bounded by |grad f| |grad g|, and a sum of m rounded
/// products has error <= m eps sum|terms| (Higham's gamma_m, first order). Each law
/// states its scale (a product of gradient and Hessian norms) and its budget k in units
/// of eps * scale, counted from the brackets and combinations it evaluates.

#include "generators.hpp"
#include "mechcheck/harness/law.hpp"
#include "mechcheck/reference.hpp"

namespace {

namespace mc = mechcheck;
namespace gen = mechcheck::generators;
using mc::dynamic_vector;
using mc::lift;
using mc::phase_point;
using mc::poisson_bracket;
using mc::harness::check_close;
using mc::harness::check_zero;
using mc::harness::law_info;

/// Scales of a function's derivatives for the tolerance model: the magnitude of the
/// terms an evaluation sums. For a generated smooth function those are its term-wise
/// bounds (a sum that cancels, f = -1.05859 q0 + 1.03516 q0 say, has a small gradient
/// but the rounding of its terms); for the library's functions, whose derivatives are
/// products without cancellation, the derivatives themselves.
template <class T, class F>
T grad_norm(const F& f, const phase_point<T>& x) {
  return mc::phase_gradient(f, x, "law", "f").second.norm();
}
template <class T>
T grad_norm(const gen::smooth_function& f, const phase_point<T>& x) {
  return f.gradient_magnitude(x);
}
template <class T>
T hessian_norm(const gen::smooth_function& f, const phase_point<T>& x) {
  return f.hessian_magnitude(x);
}
template <class T>
T value_norm(const gen::smooth_function& f, const phase_point<T>& x) {
  return f.magnitude(x);
}

/// a f + b g with constant a, b.
template <class F, class G>
struct linear_combination {
  double a;
  F f;
  double b;
  G g;
  template <class S>
  S operator()(const dynamic_vector<S>& q, const dynamic_vector<S>& p) const {
    const S af = lift<S>(a) * f(q, p);
    const S bg = lift<S>(b) * g(q, p);
    return af + bg;
  }
};

/// f g.
template <class F, class G>
struct product {
  F f;
  G g;
  template <class S>
  S operator()(const dynamic_vector<S>& q, const dynamic_vector<S>& p) const {
    const S fs = f(q, p), gs = g(q, p);
    return fs * gs;
  }
};

/// Levi-Civita symbol on 0-based indices.
int levi_civita(int i, int j, int k) {
  if (i == j || j == k || k == i) return 0;
  return ((j - i + 3) % 3 == 1) ? 1 : -1;
}

struct canonical_brackets {
  static law_info info() {
    return {"poisson.canonical_brackets",
            "Canonical brackets {q_i,q_j} = 0, {p_i,p_j} = 0, {q_i,p_j} = delta_ij",
            {"272", "273", "274", "275"}};
  }
  // Derivatives of coordinate functions are exactly 0 and 1, so every bracket is exact:
  // budget 0.
  template <class T>
  static void property() {
    const int n = *gen::degrees_of_freedom();
    RC_TAG(n);
    const auto x = (*gen::phase_points(n)).template at<T>();
    const T one = lift<T>(1);
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) {
        const std::string ij = "[" + std::to_string(i) + "," + std::to_string(j) + "]";
        check_zero("{q_i,q_j}" + ij, poisson_bracket(mc::q_component{i}, mc::q_component{j}, x),
                   one, 0);
        check_zero("{p_i,p_j}" + ij, poisson_bracket(mc::p_component{i}, mc::p_component{j}, x),
                   one, 0);
        check_close("{q_i,p_j}" + ij,
                    poisson_bracket(mc::q_component{i}, mc::p_component{j}, x),
                    lift<T>(i == j ? 1 : 0), one, 0);
      }
  }
};
MECHCHECK_LAW(canonical_brackets);

struct antisymmetry {
  static law_info info() {
    return {"poisson.antisymmetry", "Antisymmetry {f,g} = -{g,f}", {"269"}};
  }
  // Two brackets of 2n products each: k = 2 * 2n.
  template <class T>
  static void property() {
    const int n = *gen::degrees_of_freedom();
    const auto f = *gen::smooth_functions(n);
    const auto g = *gen::smooth_functions(n);
    const auto x = (*gen::phase_points(n)).template at<T>();
    RC_CLASSIFY(f.has_wave() || g.has_wave(), "trigonometric");
    const T scale = grad_norm(f, x) * grad_norm(g, x);
    check_close("{f,g} + {g,f}", poisson_bracket(f, g, x), T(-poisson_bracket(g, f, x)), scale,
                4.0 * n);
  }
};
MECHCHECK_LAW(antisymmetry);

struct bilinearity {
  static law_info info() {
    return {"poisson.bilinearity",
            "Bilinearity {af+bg,h} = a{f,h} + b{g,h}, in both slots", {"269"}};
  }
  // Three brackets of 2n products, plus the combinations a f' + b g' (2 roundings) and
  // a{f,h} + b{g,h} (2 roundings) per slot: k = 6n + 6.
  template <class T>
  static void property() {
    const int n = *gen::degrees_of_freedom();
    const auto f = *gen::smooth_functions(n);
    const auto g = *gen::smooth_functions(n);
    const auto h = *gen::smooth_functions(n);
    const double a = *gen::coefficient(), b = *gen::coefficient();
    const auto x = (*gen::phase_points(n)).template at<T>();
    const linear_combination<gen::smooth_function, gen::smooth_function> afbg{a, f, b, g};
    const T ta = lift<T>(a), tb = lift<T>(b);
    using std::abs;
    const T scale = (abs(ta) * grad_norm(f, x) + abs(tb) * grad_norm(g, x)) * grad_norm(h, x);
    check_close("{af+bg,h}", poisson_bracket(afbg, h, x),
                T(ta * poisson_bracket(f, h, x) + tb * poisson_bracket(g, h, x)), scale,
                6.0 * n + 6);
    check_close("{h,af+bg}", poisson_bracket(h, afbg, x),
                T(ta * poisson_bracket(h, f, x) + tb * poisson_bracket(h, g, x)), scale,
                6.0 * n + 6);
  }
};
MECHCHECK_LAW(bilinearity);

struct leibniz_rule {
  static law_info info() {
    return {"poisson.leibniz", "Leibniz rule {fg,h} = f{g,h} + {f,h}g", {"269"}};
  }
  // Three brackets of 2n products; the product rule f g' + g f' (2 roundings) and the
  // right-hand side (3 roundings): k = 6n + 6.
  template <class T>
  static void property() {
    const int n = *gen::degrees_of_freedom();
    const auto f = *gen::smooth_functions(n);
    const auto g = *gen::smooth_functions(n);
    const auto h = *gen::smooth_functions(n);
    const auto x = (*gen::phase_points(n)).template at<T>();
    const T fv = f(x.q(), x.p()), gv = g(x.q(), x.p());
    const T scale =
        (value_norm(f, x) * grad_norm(g, x) + value_norm(g, x) * grad_norm(f, x)) * grad_norm(h, x);
    const product<gen::smooth_function, gen::smooth_function> fg{f, g};
    check_close("{fg,h}", poisson_bracket(fg, h, x),
                T(fv * poisson_bracket(g, h, x) + poisson_bracket(f, h, x) * gv), scale,
                6.0 * n + 6);
  }
};
MECHCHECK_LAW(leibniz_rule);

struct jacobi_identity {
  static law_info info() {
    return {"poisson.jacobi", "Jacobi identity {f,{g,h}} + {g,{h,f}} + {h,{f,g}} = 0",
            {"269", "279"}};
  }
  // Each term {a,{b,c}} sums 2n products of grad a with grad {b,c}, whose components
  // sum 4n products of a Hessian entry and a gradient entry: error <= 6n eps times
  // |grad a| (|H_b| |grad c| + |grad b| |H_c|). Three terms: k = 3 * 6n = 18n.
  template <class T>
  static void property() {
    const int n = *gen::degrees_of_freedom();
    const auto f = *gen::smooth_functions(n);
    const auto g = *gen::smooth_functions(n);
    const auto h = *gen::smooth_functions(n);
    const auto x = (*gen::phase_points(n)).template at<T>();
    RC_CLASSIFY(f.has_wave() || g.has_wave() || h.has_wave(), "trigonometric");
    const T df = grad_norm(f, x), dg = grad_norm(g, x), dh = grad_norm(h, x);
    const T hf = hessian_norm(f, x), hg = hessian_norm(g, x), hh = hessian_norm(h, x);
    const T scale = df * (hg * dh + dg * hh) + dg * (hh * df + dh * hf) + dh * (hf * dg + df * hg);
    const T sum = poisson_bracket(f, mc::bracket_function{g, h}, x) +
                  poisson_bracket(g, mc::bracket_function{h, f}, x) +
                  poisson_bracket(h, mc::bracket_function{f, g}, x);
    check_zero("{f,{g,h}} + {g,{h,f}} + {h,{f,g}}", sum, scale, 18.0 * n);
  }
};
MECHCHECK_LAW(jacobi_identity);

struct angular_momentum_algebra {
  static law_info info() {
    return {"poisson.angular_momentum_algebra", "{M_i,M_j} = eps_ijk M_k",
            {"281", "282", "283", "284"}};
  }
  // Gradients of M_i are exact (components of r and p); the bracket sums 6 products
  // (gamma_6) and M_k has 2 products (gamma_2), all bounded by |r||p|: k = 8.
  template <class T>
  static void property() {
    const auto x = (*gen::phase_points(3)).template at<T>();
    const T scale = x.q().norm() * x.p().norm();
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        T expected = lift<T>(0);
        for (int k = 0; k < 3; ++k)
          if (const int e = levi_civita(i, j, k); e != 0)
            expected += lift<T>(e) * mc::angular_momentum{k}(x.q(), x.p());
        check_close("{M_" + std::to_string(i + 1) + ",M_" + std::to_string(j + 1) + "}",
                    poisson_bracket(mc::angular_momentum{i}, mc::angular_momentum{j}, x),
                    expected, scale, 8);
      }
  }
};
MECHCHECK_LAW(angular_momentum_algebra);

struct m_squared_commutes {
  static law_info info() {
    return {"poisson.m_squared_commutes", "{M^2, M_i} = 0", {"281", "284"}};
  }
  // grad M^2 = 2 sum_j M_j grad M_j (3 terms of size <= |r||p|(|r|+|p|)); the bracket
  // sums 6 products with grad M_i (size <= |r|+|p|): scale |r||p|(|r|+|p|)^2, k = 32.
  template <class T>
  static void property() {
    const auto x = (*gen::phase_points(3)).template at<T>();
    const T rp = x.q().norm() + x.p().norm();
    const T scale = x.q().norm() * x.p().norm() * rp * rp;
    for (int i = 0; i < 3; ++i)
      check_zero("{M^2,M_" + std::to_string(i + 1) + "}",
                 poisson_bracket(mc::angular_momentum_squared{}, mc::angular_momentum{i}, x),
                 scale, 32);
  }
};
MECHCHECK_LAW(m_squared_commutes);

struct time_derivative {
  static law_info info() {
    return {"poisson.time_derivative",
            "df/dt = {f,H}: the bracket equals the derivative of f along Hamilton's flow",
            {"250", "267", "268", "270", "271"}};
  }
  // The derivative along X_H = (H_p, -H_q) is a forward-mode directional derivative
  // (2n products in f's own evaluation order); the bracket sums 2n products:
  // k = 4n + 4.
  template <class T>
  static void property() {
    const int n = *gen::degrees_of_freedom();
    const auto f = *gen::smooth_functions(n);
    const auto hamiltonian = *gen::smooth_functions(n);
    const auto x = (*gen::phase_points(n)).template at<T>();
    const dynamic_vector<T> v = mc::hamiltonian_vector_field(hamiltonian, x);
    const auto stacked = [&f, n]<class S>(const dynamic_vector<S>& z) -> S {
      const dynamic_vector<S> q = z.head(n), p = z.tail(n);
      return f(q, p);
    };
    const T along_flow = mc::directional_derivative(stacked, x.stacked(), v);
    const T scale = grad_norm(f, x) * grad_norm(hamiltonian, x);
    check_close("{f,H} vs d/dt f along X_H", poisson_bracket(f, hamiltonian, x), along_flow,
                scale, 4.0 * n + 4);
  }
};
MECHCHECK_LAW(time_derivative);

struct oscillator_flow_reference {
  static law_info info() {
    return {"poisson.oscillator_flow_reference",
            "df/dt along the exact oscillator flow equals {f,H}",
            {"268", "270", "315"}};
  }
  // d/dt f(phi_t(x)) at t = 0 through the analytic flow (reference/) by AD in t; the
  // flow's velocity carries ~6 roundings (w, m w, divisions) on top of the 2n products
  // on each side: k = 4n + 12.
  template <class T>
  static void property() {
    const int n = *gen::degrees_of_freedom();
    const auto f = *gen::smooth_functions(n);
    const T m = lift<T>(*gen::positive()), k = lift<T>(*gen::positive());
    const auto x = (*gen::phase_points(n)).template at<T>();
    const mc::harmonic_oscillator<T> hamiltonian(m, k);
    const mc::reference::oscillator_flow<T> flow(m, k);
    using A = mc::ad<T>;
    dynamic_vector<A> q0(n), p0(n);
    for (int i = 0; i < n; ++i) {
      q0(i) = lift<A>(x.q()(i));
      p0(i) = lift<A>(x.p()(i));
    }
    const A t(lift<T>(0), dynamic_vector<T>::Constant(1, lift<T>(1)));
    const auto xt = flow(q0, p0, t);
    const A ft = f(xt.q(), xt.p());
    const T along_flow = mc::derivatives_of(ft, 1)(0);
    const T scale = grad_norm(f, x) * mc::hamiltonian_vector_field(hamiltonian, x).norm();
    check_close("{f,H_osc} vs d/dt f(flow_t(x))", poisson_bracket(f, hamiltonian, x), along_flow,
                scale, 4.0 * n + 12);
  }
};
MECHCHECK_LAW(oscillator_flow_reference);

struct cyclic_coordinate {
  static law_info info() {
    return {"poisson.cyclic_coordinate",
            "A cyclic coordinate q_k (dH/dq_k = 0) gives {p_k,H} = 0: p_k is conserved",
            {"265", "276", "277"}};
  }
  // {p_k, H} = -dH/dq_k, and AD gives an exact zero derivative for a variable H does not
  // use: budget 0.
  template <class T>
  static void property() {
    const int n = *gen::degrees_of_freedom();
    const int k = *rc::gen::inRange(0, n);
    const auto hamiltonian = *gen::smooth_functions_without_q(n, k);
    const auto x = (*gen::phase_points(n)).template at<T>();
    RC_TAG(n);
    const T scale = grad_norm(hamiltonian, x);
    check_zero("{p_k,H}", poisson_bracket(mc::p_component{k}, hamiltonian, x),
               scale == 0 ? lift<T>(1) : scale, 0);
  }
};
MECHCHECK_LAW(cyclic_coordinate);

struct energy_conservation {
  static law_info info() {
    return {"poisson.energy_conservation",
            "dH/dt = {H,H} = 0 for a time-independent Hamiltonian", {"263", "264", "271"}};
  }
  // One bracket of 2n products: k = 2n.
  template <class T>
  static void property() {
    const int n = *gen::degrees_of_freedom();
    const auto hamiltonian = *gen::smooth_functions(n);
    const auto x = (*gen::phase_points(n)).template at<T>();
    const T g = grad_norm(hamiltonian, x);
    check_zero("{H,H}", poisson_bracket(hamiltonian, hamiltonian, x), g * g, 2.0 * n);
  }
};
MECHCHECK_LAW(energy_conservation);

struct poisson_theorem {
  static law_info info() {
    return {"poisson.poisson_theorem",
            "Poisson's theorem: {H,M_i} = {H,M_j} = 0 implies {H,{M_i,M_j}} = 0 for a "
            "central force",
            {"278", "279", "280"}};
  }
  // H = |p|^2/2m + U(|r|), a random radial U. {H, M_i}: 6 products bounded by
  // |grad H| |grad M_i| (k = 6). {H, {M_i, M_j}}: the inner bracket's gradient has
  // entries up to 2(|r| + |p|), computed with 6-term sums: k = 6 + 12 = 18.
  template <class T>
  static void property() {
    const auto potential = *gen::radial_potentials();
    const T m = lift<T>(*gen::positive());
    const auto x = (*gen::points_away_from_origin()).template at<T>();
    const mc::central_force_hamiltonian<T, gen::radial_potential> hamiltonian(m, potential);
    const T dh = grad_norm(hamiltonian, x);
    const T rp = x.q().norm() + x.p().norm();
    for (int i = 0; i < 3; ++i) {
      const mc::angular_momentum mi{i};
      check_zero("{H,M_" + std::to_string(i + 1) + "}", poisson_bracket(hamiltonian, mi, x),
                 dh * grad_norm(mi, x), 6);
      for (int j = i + 1; j < 3; ++j) {
        const mc::bracket_function mij{mi, mc::angular_momentum{j}};
        check_zero("{H,{M_" + std::to_string(i + 1) + ",M_" + std::to_string(j + 1) + "}}",
                   poisson_bracket(hamiltonian, mij, x), dh * 2 * rp, 18);
      }
    }
  }
};
MECHCHECK_LAW(poisson_theorem);

// ---------------------------------------------------------------------------------------
// Errata: the printed forms below are falsified; the shrunk counterexample is the evidence.

struct erratum_266 {
  static law_info info() {
    return {"poisson.erratum_266",
            "Printed eq 266 for df/dt (dpdot replaced by qdot) is false",
            {"266"},
            mc::harness::expectation::falsified,
            "printed: df/dt = sum_i (df/dp_i qdot_i + df/dq_i qdot_i) + df/dt; correct: "
            "df/dt = sum_i (df/dq_i qdot_i + df/dp_i pdot_i) + df/dt"};
  }
  template <class T>
  static void property() {
    const int n = *gen::degrees_of_freedom();
    const auto f = *gen::smooth_functions(n);
    const auto hamiltonian = *gen::smooth_functions(n);
    const auto x = (*gen::phase_points(n)).template at<T>();
    const auto df = mc::phase_gradient(f, x, "erratum_266", "f").second;
    const dynamic_vector<T> v = mc::hamiltonian_vector_field(hamiltonian, x);  // (qdot, pdot)
    T printed = lift<T>(0);
    for (int i = 0; i < n; ++i) printed += df(n + i) * v(i) + df(i) * v(i);
    const T scale = df.norm() * v.norm();
    check_close("printed eq 266 vs {f,H}", printed, poisson_bracket(f, hamiltonian, x),
                scale == 0 ? lift<T>(1) : scale, 4.0 * n + 4);
  }
};
MECHCHECK_LAW(erratum_266);

struct erratum_263 {
  static law_info info() {
    return {"poisson.erratum_263",
            "Printed eq 263 for dH/dt (pdot missing from the second term) is false",
            {"263"},
            mc::harness::expectation::falsified,
            "printed: dH/dt = sum_i (dH/dq_i qdot_i + dH/dp_i) + dH/dt; correct: "
            "dH/dt = sum_i (dH/dq_i qdot_i + dH/dp_i pdot_i) + dH/dt = 0 (eq 264)"};
  }
  template <class T>
  static void property() {
    const int n = *gen::degrees_of_freedom();
    const auto hamiltonian = *gen::smooth_functions(n);
    const auto x = (*gen::phase_points(n)).template at<T>();
    const auto dh = mc::phase_gradient(hamiltonian, x, "erratum_263", "H").second;
    T printed = lift<T>(0);
    for (int i = 0; i < n; ++i) printed += dh(i) * dh(n + i) + dh(n + i);  // qdot_i = dH/dp_i
    const T scale = dh.squaredNorm() + dh.norm();
    check_zero("printed eq 263 (should vanish, eq 264)", printed,
               scale == 0 ? lift<T>(1) : scale, 2.0 * n + 2);
  }
};
MECHCHECK_LAW(erratum_263);

}  // namespace
