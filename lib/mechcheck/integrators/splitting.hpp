#pragma once
/// Splitting methods for separable H = T(p) + V(q): symplectic Euler, Stormer-Verlet, and
/// symmetric drift-kick splittings with given coefficients (McLachlan's SB3A of order 4).

#include <array>
#include <ios>
#include <limits>
#include <string>
#include <type_traits>
#include <utility>

#include "mechcheck/integrators/guards.hpp"
#include "mechcheck/integrators/workspace.hpp"

namespace mechcheck {

/// Symplectic Euler (kick then drift): p' = p + h F(q), q' = q + h v(p'). Order 1.
template <class System, class Vec>
struct symplectic_euler {
  static constexpr int order = 1;
  static constexpr bool symplectic = true;
  static constexpr bool symmetric = false;
  /// The energy error stays bounded over long runs (a symplectic map at small h).
  static constexpr bool bounded_energy = true;
  /// Evaluates velocity and force apart: needs H = |p|^2/2 + V(q).
  static constexpr bool separable = true;
  using scalar = typename Vec::Scalar;
  System system;
  symplectic_euler(System s) : system(std::move(s)) {}  // implicit: Method{system} builds it
  void operator()(phase_state<Vec>& x, const scalar& h) const {
    scratch_.use([&](workspace& w) {
      detail::guarded_step<System>(x, h, "symplectic_euler", w.start, [&](phase_state<Vec>& y) {
        detail::shape_like(w.f, y.q);
        detail::shape_like(w.v, y.p);
        system.force(y.q, w.f);
        detail::axpy(y.p, h, w.f, w.t);
        system.velocity(y.p, w.v);
        detail::axpy(y.q, h, w.v, w.t);
      });
    });
  }

 private:
  struct workspace {
    phase_state<Vec> start;
    Vec f, v;
    scalar t;
  };
  mutable detail::scratch<workspace, scalar> scratch_;
};

/// Stormer-Verlet (kick-drift-kick, velocity Verlet): order 2, symplectic, time
/// reversible. Keeps the last force (first same as last): one force evaluation a step.
template <class System, class Vec>
class stormer_verlet {
 public:
  static constexpr int order = 2;
  static constexpr bool symplectic = true;
  static constexpr bool symmetric = true;
  /// The energy error stays bounded over long runs (a symplectic map at small h).
  static constexpr bool bounded_energy = true;
  static constexpr bool separable = true;  ///< needs H = |p|^2/2 + V(q)
  using scalar = typename Vec::Scalar;
  using real = real_type_t<scalar>;
  explicit stormer_verlet(System system) : system_(std::move(system)) {}

  void operator()(phase_state<Vec>& x, const scalar& h) {
    scratch_.use([&](workspace& w) {
      detail::guarded_step<System>(x, h, "stormer_verlet", w.start,
                                   [&](phase_state<Vec>& y) { substep(y, h, w); });
    });
  }

  /// The step's temporaries (compositions of Verlet steps share one).
  struct workspace {
    phase_state<Vec> start;
    Vec f, v;
    scalar half_h, t;
    real half = real(1) / 2;
  };

  /// One Verlet step without the finiteness check (used by compositions).
  void substep(phase_state<Vec>& x, const scalar& h, workspace& w) {
    detail::shape_like(w.f, x.q);
    detail::shape_like(w.v, x.p);
    detail::scale(w.half_h, w.half, h);
    cache_.force(system_, x.q, w.f);
    detail::axpy(x.p, w.half_h, w.f, w.t);
    system_.velocity(x.p, w.v);
    detail::axpy(x.q, h, w.v, w.t);
    cache_.force(system_, x.q, w.f);
    detail::axpy(x.p, w.half_h, w.f, w.t);
  }

  const System& system() const { return system_; }

 private:
  System system_;
  detail::force_cache<Vec> cache_;
  detail::scratch<workspace, scalar> scratch_;
};

/// Coefficients of a drift-kick splitting: for i = 1..s, q += a_i h v(p), then
/// p += b_i h F(q) (a kick with b_i = 0 is skipped).
template <class R>
struct splitting_coefficients {
  std::vector<R> a, b;
};

/// McLachlan's fourth-order symmetric splitting SB3A (McLachlan 1995, "On the numerical
/// integration of ODEs by symmetric composition methods"), drifts outermost, five kicks:
///   a1 b1 a2 b2 a3 b3 a3 b2 a2 b1 a1,  b1 = -3/73, b2 = 17/59, b3 = 1 - 2 (b1 + b2),
/// a3 = 1/2 - (a1 + a2). McLachlan fixed b1, b2 as rationals and chose a1, a2 to satisfy
/// the two third-order conditions of a symmetric splitting (the coefficients of
/// [A, [A, B]] and [B, [A, B]]; symmetry then gives order 4). In the partitioned
/// Runge-Kutta form they read sum_i b_i c_i^2 = 1/3 and sum_i a_i d_i^2 = 1/3 with
/// c_i = a_1 + ... + a_i (where kick i sees q) and d_i = b_1 + ... + b_(i-1) (where drift
/// i sees p). They are solved here by Newton's method from (0.4, -0.3) in twice R's
/// digits and rounded to R, so that the coefficients are correctly rounded in R.
template <class R>
splitting_coefficients<R> mclachlan_sb3a_coefficients() {
  // The system is solved in twice R's digits and rounded to R: solved in R itself, its
  // conditioning leaves a1 ~15 eps off in double.
  constexpr unsigned wide_digits = 2 * std::numeric_limits<R>::digits10 + 10;
  using W = boost::multiprecision::number<boost::multiprecision::mpfr_float_backend<wide_digits>,
                                          boost::multiprecision::et_off>;
  const W b1 = W(-3) / 73, b2 = W(17) / 59, b3 = 1 - 2 * (b1 + b2);
  const auto conditions = [&](const W& a1, const W& a2) {
    const W a3 = W(1) / 2 - a1 - a2;
    const std::array<W, 6> a{a1, a2, a3, a3, a2, a1}, b{b1, b2, b3, b2, b1, W(0)};
    W c = 0, d = 0, kick = 0, drift = 0;
    for (int i = 0; i < 6; ++i) {
      drift += a[i] * d * d;
      c += a[i];
      kick += b[i] * c * c;
      d += b[i];
    }
    return std::array<W, 2>{kick - W(1) / 3, drift - W(1) / 3};
  };
  // Newton with a difference Jacobian (step 10^-(digits/2)): each iteration gains half
  // of W's digits, so four reach W's rounding.
  W a1 = W(4) / 10, a2 = W(-3) / 10;
  const W delta = pow(W(10), -static_cast<int>(wide_digits / 2));
  for (int iteration = 0;; ++iteration) {
    const auto r = conditions(a1, a2);
    const auto r1 = conditions(a1 + delta, a2), r2 = conditions(a1, a2 + delta);
    const W j00 = (r1[0] - r[0]) / delta, j10 = (r1[1] - r[1]) / delta;
    const W j01 = (r2[0] - r[0]) / delta, j11 = (r2[1] - r[1]) / delta;
    const W det = j00 * j11 - j01 * j10;
    const W s1 = (j11 * r[0] - j01 * r[1]) / det, s2 = (j00 * r[1] - j10 * r[0]) / det;
    a1 -= s1;
    a2 -= s2;
    const W size = abs(s1) + abs(s2);
    if (size <= pow(W(10), -static_cast<int>(wide_digits) + 5)) break;
    if (iteration == 60)
      throw convergence_error("mclachlan_sb3a_coefficients: Newton did not converge (last step " +
                              size.str(6) + ")");
  }
  const auto narrow = [](const W& w) -> R {
    if constexpr (std::is_floating_point_v<R>)
      return w.template convert_to<R>();
    else
      return R(w.str(std::numeric_limits<R>::max_digits10 + 2, std::ios_base::scientific));
  };
  const R r1 = narrow(a1), r2 = narrow(a2), r3 = narrow(W(W(1) / 2 - a1 - a2));
  return {{r1, r2, r3, r3, r2, r1},
          {narrow(b1), narrow(b2), narrow(b3), narrow(b2), narrow(b1), lift<R>(0)}};
}

/// A symmetric drift-kick splitting with given coefficients, for separable H: one force
/// evaluation per nonzero b_i. Symplectic for any coefficients; its order is what they
/// satisfy (mclachlan4 below: 4).
template <class System, class Vec>
class splitting {
 public:
  static constexpr bool symplectic = true;
  /// The energy error stays bounded over long runs (a symplectic map at small h).
  static constexpr bool bounded_energy = true;
  static constexpr bool separable = true;  ///< needs H = |p|^2/2 + V(q)
  using scalar = typename Vec::Scalar;
  using real = real_type_t<scalar>;

  splitting(System system, splitting_coefficients<real> coefficients, const char* name)
      : system_(std::move(system)), coefficients_(std::move(coefficients)), name_(name) {}

  void operator()(phase_state<Vec>& x, const scalar& h) {
    scratch_.use([&](workspace& w) {
      detail::guarded_step<System>(x, h, name_, w.start, [&](phase_state<Vec>& y) {
        detail::shape_like(w.f, y.q);
        detail::shape_like(w.v, y.p);
        for (std::size_t i = 0; i < coefficients_.a.size(); ++i) {
          system_.velocity(y.p, w.v);
          detail::scale(w.ch, coefficients_.a[i], h);
          detail::axpy(y.q, w.ch, w.v, w.t);
          if (coefficients_.b[i] == 0) continue;
          system_.force(y.q, w.f);
          detail::scale(w.ch, coefficients_.b[i], h);
          detail::axpy(y.p, w.ch, w.f, w.t);
        }
      });
    });
  }

  const splitting_coefficients<real>& coefficients() const { return coefficients_; }

 private:
  System system_;
  splitting_coefficients<real> coefficients_;
  const char* name_;
  struct workspace {
    phase_state<Vec> start;
    Vec f, v;
    scalar ch, t;
  };
  detail::scratch<workspace, scalar> scratch_;
};

/// McLachlan's SB3A (see mclachlan_sb3a_coefficients): order 4, symplectic, symmetric,
/// five force evaluations a step; its error constant is far below the triple jump's.
template <class System, class Vec>
class mclachlan4 : public splitting<System, Vec> {
 public:
  static constexpr int order = 4;
  static constexpr bool symmetric = true;
  explicit mclachlan4(System system)
      : splitting<System, Vec>(std::move(system), coefficients(), "mclachlan4") {}

 private:
  using real = real_type_t<typename Vec::Scalar>;
  /// Solved once per tier and program (a Newton solve in twice the tier's digits costs
  /// ~40 us; a stepper is often built for a short run).
  static const splitting_coefficients<real>& coefficients() {
    static const splitting_coefficients<real> solved = mclachlan_sb3a_coefficients<real>();
    return solved;
  }
};

}  // namespace mechcheck
