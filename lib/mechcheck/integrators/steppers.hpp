#pragma once
/// One-step integrators for Hamiltonian systems (see systems.hpp).
///
/// Every stepper is a callable `stepper(state, h)` that advances a phase_state<Vec> by
/// one step h in place; a user's own stepper satisfying the same call is audited the
/// same way (mechcheck::stepper concept). Steppers are templated on the system and on
/// the state vector type Vec, whose scalar may be a tier or an AD type over one (the
/// Jacobian of a step is taken by running the stepper on AD scalars).
///
/// Method               order  symplectic  symmetric  needs
/// explicit_euler        1      no          no         vector_field
/// rk4                   4      no          no         vector_field
/// symplectic_euler      1      yes         no         separable (velocity, force)
/// stormer_verlet        2      yes         yes        separable
/// composition<4|6|8>    4/6/8  yes         yes        separable (triple-jump of Verlet)
/// mclachlan4            4      yes         yes        separable (McLachlan's SB3A splitting)
/// gauss_legendre<1..4>  2s     yes         yes        vector_field (implicit, any H)
/// The static members order, symplectic and symmetric declare these; mechcheck::audit
/// confirms or contradicts them.

#include <array>
#include <cmath>
#include <concepts>
#include <ios>
#include <limits>
#include <string>
#include <type_traits>
#include <variant>
#include <vector>

#include <boost/math/special_functions/legendre.hpp>
#include <Eigen/LU>

#include "mechcheck/core.hpp"
#include "mechcheck/core/inplace.hpp"
#include "mechcheck/integrators/systems.hpp"

namespace mechcheck {

/// A stepper advances a state by h in place.
template <class F, class Vec>
concept stepper = requires(F f, phase_state<Vec>& x, const typename Vec::Scalar& h) { f(x, h); };

/// A system whose state is not a canonical pair (q, p) of equal lengths (the free rigid
/// body: q = M, p = the attitude) declares `static constexpr bool canonical = false;`.
template <class System>
constexpr bool is_canonical() {
  if constexpr (requires { System::canonical; })
    return System::canonical;
  else
    return true;
}

namespace detail {
template <bool Canonical = true, class Vec>
void require_finite_state(const phase_state<Vec>& x, const char* where) {
  if (Canonical && x.q.size() != x.p.size()) [[unlikely]]
    throw dimension_error(std::string(where) + ": state has " + std::to_string(x.q.size()) +
                          " q components but p has " + std::to_string(x.p.size()));
  if constexpr (std::is_floating_point_v<typename Vec::Scalar>) {
    if (x.q.allFinite() && x.p.allFinite()) [[likely]]
      return;
  }
  if (const auto i = first_non_finite(x.q); i >= 0)
    throw non_finite_error(std::string(where) + ": state has q[" + std::to_string(i) +
                           "] = " + to_text(x.q(i)));
  if (const auto i = first_non_finite(x.p); i >= 0)
    throw non_finite_error(std::string(where) + ": state has p[" + std::to_string(i) +
                           "] = " + to_text(x.p(i)));
}

/// Throws for a step h that is not finite or is zero (a negative h steps backwards).
template <class S>
[[gnu::cold, gnu::noinline]] void refuse_step(const S& h, const char* where) {
  if (!is_finite(h))
    throw non_finite_error(std::string(where) + ": step h must be finite, got " + to_text(h));
  throw domain_error(std::string(where) + ": step h must be non-zero, got " + to_text(h));
}

/// Checks the step h: finite and non-zero.
template <class S>
void require_step(const S& h, const char* where) {
  if (!is_finite(h) || h == 0) [[unlikely]]
    refuse_step(h, where);
}

/// True when every entry of a built-in floating vector is finite: 0 * x is 0 for finite
/// x and NaN otherwise, so one comparison of the sum answers for the whole vector.
template <class Vec>
bool all_finite_floating(const Vec& v) {
  typename Vec::Scalar zero_unless_bad = 0;
  for (Eigen::Index i = 0; i < v.size(); ++i) zero_unless_bad += 0 * v(i);
  return zero_unless_bad == 0;
}

/// The state a step produced is not finite (or, for built-in types, h or the start was
/// not): names the bad h, the bad start, or the step and its first non-finite entry. The
/// caller has restored its state to `start`. Takes its arguments by value: a call that
/// receives the address of the state or of h, even one never taken, makes the compiler
/// keep them in memory through the step (a Verlet step in double was 1.14x slower).
template <class System, class Vec>
[[gnu::cold, gnu::noinline, noreturn]] void refuse_result(phase_state<Vec> produced,
                                                          phase_state<Vec> start,
                                                          typename Vec::Scalar h, const char* where) {
  require_step(h, where);
  require_finite_state<is_canonical<System>()>(start, where);  // a bad start is named as such
  const auto bad_q = first_non_finite(produced.q), bad_p = first_non_finite(produced.p);
  const std::string what =
      bad_q >= 0 ? "q[" + std::to_string(bad_q) + "] = " + to_text(produced.q(bad_q))
                 : "p[" + std::to_string(bad_p) + "] = " + to_text(produced.p(bad_p));
  throw non_finite_error(std::string(where) + ": the step of h = " + to_text(h) + " from q = " +
                         to_text(start.q) + ", p = " + to_text(start.p) + " produced " + what);
}

/// One guarded step: checks the state and h, runs body(x), and checks that the state it
/// leaves is finite. A step that overflows (a force blowing up, h far too large) throws
/// non_finite_error from that step, naming h and the state it started from, and leaves
/// x exactly as it was; so does any error thrown inside the step.
///
/// For built-in types the state and h are checked once, after the step: a non-finite
/// start gives a non-finite result, and only then is the start examined (so that the
/// error names the bad input, as the check before the step would have); a bad h is named
/// before anything else. The failure path is out of line, so that the check costs a few
/// instructions in the step.
///
/// `start` is where the step keeps the state it began from (the stepper's scratch).
template <class System, class Vec, class Body>
void guarded_step(phase_state<Vec>& x, const typename Vec::Scalar& h, const char* where,
                  phase_state<Vec>& start, Body&& body) {
  constexpr bool floating = std::is_floating_point_v<typename Vec::Scalar>;
  if constexpr (floating) {
    if (is_canonical<System>() && x.q.size() != x.p.size()) [[unlikely]]
      require_finite_state<true>(x, where);  // names the mismatch
  } else {
    require_finite_state<is_canonical<System>()>(x, where);
    require_step(h, where);
  }
  start = x;
  try {
    body(x);
  } catch (...) {
    x = start;  // an error inside the step (a system refusing a state) leaves no half step
    if constexpr (floating) {
      require_step(h, where);
      require_finite_state<is_canonical<System>()>(x, where);
    }
    throw;
  }
  bool good;
  if constexpr (floating)
    good = all_finite_floating(x.q) && all_finite_floating(x.p) && is_finite(h) && h != 0;
  else
    good = first_non_finite(x.q) < 0 && first_non_finite(x.p) < 0;
  if (!good) [[unlikely]] {
    const phase_state<Vec> produced = x;
    x = start;
    refuse_result<System>(produced, start, h, where);
  }
}

/// Largest |new - old| and |new| over the components, innermost values (for the
/// iterations of the implicit methods); d is scratch.
template <class Vec, class Real>
void track_change(const Vec& next, const Vec& last, Real& change, Real& size, Real& d) {
  for (Eigen::Index m = 0; m < next.size(); ++m) {
    const Real& n = innermost_value(next(m));
    if constexpr (std::is_floating_point_v<Real>) {  // branch-free: signs are random
      using std::abs;
      const Real dm = abs(n - innermost_value(last(m))), a = abs(n);
      change = change > dm ? change : dm;
      size = size > a ? size : a;
    } else {  // in place
      d = n;
      d -= innermost_value(last(m));
      if (d < 0) inplace::negate(d);
      if (change < d) change = d;
      d = n;
      if (d < 0) inplace::negate(d);
      if (size < d) size = d;
    }
  }
}

/// Zeros the entries of v (in place for tier scalars).
template <class Vec>
void set_zero(Vec& v) {
  using S = typename Vec::Scalar;
  for (Eigen::Index m = 0; m < v.size(); ++m) {
    if constexpr (is_ad_v<S>)
      v(m) = lift<S>(0);
    else
      v(m) = 0;
  }
}

/// A tier constant as S: itself when S is the tier, else lifted into `kept`.
template <class S>
const S& as_scalar(const real_type_t<S>& c, S& kept) {
  if constexpr (std::is_same_v<S, real_type_t<S>>) {
    return c;
  } else {
    kept = lift<S>(c);
    return kept;
  }
}

/// y += a * v: an Eigen expression for built-in types (vectorised), in place through the
/// scratch t for multiprecision numbers, element by element for AD scalars (each product
/// stored before it is added).
template <class Vec, class S>
void axpy(Vec& y, const S& a, const Vec& v, S& t) {
  if constexpr (std::is_floating_point_v<S>) {
    y.noalias() += a * v;
  } else if constexpr (inplace::is_number_v<S>) {
    for (Eigen::Index i = 0; i < y.size(); ++i) inplace::add_product(y(i), a, v(i), t);
  } else {
    for (Eigen::Index i = 0; i < y.size(); ++i) {
      t = a * v(i);
      y(i) += t;
    }
  }
}

/// y += a * v with a scratch of its own.
template <class Vec, class S>
void axpy(Vec& y, const S& a, const Vec& v) {
  S t = a;
  axpy(y, a, v, t);
}

/// r = c h for a constant c of the tier: in place for tier scalars, c lifted for AD
/// scalars (whose constants take the derivative width of the current differentiation).
template <class S>
void scale(S& r, const real_type_t<S>& c, const S& h) {
  if constexpr (std::is_same_v<S, real_type_t<S>>)
    inplace::multiply(r, c, h);
  else
    r = lift<S>(c) * h;
}

/// Gives the workspace vector v the size of `like`, reusing its storage when the size
/// already matches (the first step of a stepper on a dynamic state sizes it).
template <class Vec>
void shape_like(Vec& v, const Vec& like) {
  if (v.size() != like.size()) v = like;
}

/// A step's temporaries W. Kept in the stepper for multiprecision and AD scalars, so that
/// each step reuses them (for mpfr50 every new number is an MPFR allocation); made fresh
/// on the stack for built-in types, where the compiler keeps them in registers (kept in
/// the object they go through memory: a Verlet step in double measured 1.5x slower).
template <class W, class Scalar>
class scratch {
 public:
  template <class F>
  void use(F&& f) {
    if constexpr (std::is_floating_point_v<Scalar>) {
      W local;
      f(local);
    } else {
      f(kept_);
    }
  }

 private:
  [[no_unique_address]] std::conditional_t<std::is_floating_point_v<Scalar>, std::monostate, W> kept_;
};

/// Remembers the force at the last position, for methods whose last kick and next first
/// kick use the same position (first same as last). Off for AD scalars, where equal
/// values can carry different derivatives.
template <class Vec>
class force_cache {
 public:
  template <class System>
  void force(const System& system, const Vec& q, Vec& f) {
    if constexpr (!is_ad_v<typename Vec::Scalar>) {
      if (valid_ && q == q_) {
        f = f_;
        return;
      }
    }
    system.force(q, f);
    if constexpr (!is_ad_v<typename Vec::Scalar>) {
      q_ = q;
      f_ = f;
      valid_ = true;
    }
  }

 private:
  Vec q_, f_;
  bool valid_ = false;
};
}  // namespace detail

/// Explicit Euler: q' = q + h dH/dp(q, p), p' = p - h dH/dq(q, p). Order 1, not symplectic.
///
/// Like every stepper here it keeps the temporaries of a step (detail::scratch): a step on
/// a fixed-size or already-sized state allocates nothing, in any tier, and one stepper
/// object serves one thread at a time.
template <class System, class Vec>
struct explicit_euler {
  static constexpr int order = 1;
  static constexpr bool symplectic = false;
  static constexpr bool symmetric = false;
  using scalar = typename Vec::Scalar;
  System system;
  explicit_euler(System s) : system(std::move(s)) {}  // implicit: Method{system} builds it
  void operator()(phase_state<Vec>& x, const scalar& h) const {
    scratch_.use([&](workspace& w) {
      detail::guarded_step<System>(x, h, "explicit_euler", w.start, [&](phase_state<Vec>& y) {
        detail::shape_like(w.dq, y.q);
        detail::shape_like(w.dp, y.p);
        system.vector_field(y.q, y.p, w.dq, w.dp);
        detail::axpy(y.q, h, w.dq, w.t);
        detail::axpy(y.p, h, w.dp, w.t);
      });
    });
  }

 private:
  struct workspace {
    phase_state<Vec> start;
    Vec dq, dp;
    scalar t;
  };
  mutable detail::scratch<workspace, scalar> scratch_;
};

/// Classical fourth-order Runge-Kutta on (q, p). Order 4, not symplectic.
template <class System, class Vec>
struct rk4 {
  static constexpr int order = 4;
  static constexpr bool symplectic = false;
  static constexpr bool symmetric = false;
  using scalar = typename Vec::Scalar;
  using real = real_type_t<scalar>;
  System system;
  rk4(System s) : system(std::move(s)) {}  // implicit: Method{system} builds it
  void operator()(phase_state<Vec>& x, const scalar& h) const {
    scratch_.use([&](workspace& w) {
      detail::guarded_step<System>(x, h, "rk4", w.start, [&](phase_state<Vec>& y) { step(y, h, w); });
    });
  }

 private:
  struct workspace {
    phase_state<Vec> start;
    Vec k1q, k1p, k2q, k2p, k3q, k3p, k4q, k4p, yq, yp;
    scalar half_h, sixth_h, t, u;
    real half = real(1) / 2, sixth = real(1) / 6;
  };
  mutable detail::scratch<workspace, scalar> scratch_;

  void step(phase_state<Vec>& x, const scalar& h, workspace& w) const {
    for (Vec* k : {&w.k1q, &w.k2q, &w.k3q, &w.k4q, &w.yq}) detail::shape_like(*k, x.q);
    for (Vec* k : {&w.k1p, &w.k2p, &w.k3p, &w.k4p, &w.yp}) detail::shape_like(*k, x.p);
    detail::scale(w.half_h, w.half, h);
    detail::scale(w.sixth_h, w.sixth, h);
    system.vector_field(x.q, x.p, w.k1q, w.k1p);
    stage(x, w.half_h, w.k1q, w.k1p, w.k2q, w.k2p, w);
    stage(x, w.half_h, w.k2q, w.k2p, w.k3q, w.k3p, w);
    stage(x, h, w.k3q, w.k3p, w.k4q, w.k4p, w);
    combine(x.q, w.k1q, w.k2q, w.k3q, w.k4q, w);
    combine(x.p, w.k1p, w.k2p, w.k3p, w.k4p, w);
  }

  /// (kq, kp) = f(x + a (dq, dp)).
  void stage(const phase_state<Vec>& x, const scalar& a, const Vec& dq, const Vec& dp, Vec& kq,
             Vec& kp, workspace& w) const {
    w.yq = x.q;
    w.yp = x.p;
    detail::axpy(w.yq, a, dq, w.t);
    detail::axpy(w.yp, a, dp, w.t);
    system.vector_field(w.yq, w.yp, kq, kp);
  }

  /// y += h/6 ((k1 + k4) + 2 (k2 + k3)), per block (q and p may differ in length). For
  /// built-in types y += h/6 (k1 + 2 (k2 + k3)) and then y += h/6 k4, in whole-vector
  /// operations: the last stage enters through one multiply and one add, and y is stored
  /// as it is loaded (per-entry stores of a state the next step loads as one packet
  /// defeat store forwarding). Together 1.08x faster steps in double (GCC 12).
  static void combine(Vec& y, const Vec& k1, const Vec& k2, const Vec& k3, const Vec& k4,
                      workspace& w) {
    if constexpr (std::is_floating_point_v<scalar>) {
      y.noalias() += w.sixth_h * ((k2 + k3) * scalar(2) + k1);
      y.noalias() += w.sixth_h * k4;
    } else {
      scalar& a = w.t;
      scalar& b = w.u;
      for (Eigen::Index i = 0; i < y.size(); ++i) {
        a = k2(i);
        a += k3(i);
        a += a;  // 2 (k2 + k3), exact
        b = k1(i);
        b += k4(i);
        b += a;
        inplace::multiply(b, w.sixth_h, b);
        y(i) += b;
      }
    }
  }
};

/// Symplectic Euler (kick then drift): p' = p + h F(q), q' = q + h v(p'). Order 1.
template <class System, class Vec>
struct symplectic_euler {
  static constexpr int order = 1;
  static constexpr bool symplectic = true;
  static constexpr bool symmetric = false;
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

/// Triple-jump weights (Yoshida 1990; Suzuki 1990) of a symmetric composition of
/// Stormer-Verlet of the given even order: S_{2k+2}(h) = S_{2k}(w1 h) S_{2k}(w0 h)
/// S_{2k}(w1 h) with w1 = 1 / (2 - 2^(1/(2k+1))), w0 = 1 - 2 w1, computed in S.
template <class S>
std::vector<S> triple_jump_weights(int order) {
  if (order < 2 || order % 2 != 0)
    throw domain_error("triple_jump_weights: order must be even and >= 2, got " +
                       std::to_string(order));
  using std::pow;
  std::vector<S> w{lift<S>(1)};
  for (int k = 1; 2 * k < order; ++k) {
    const S root = pow(lift<S>(2), lift<S>(1) / lift<S>(2 * k + 1));
    const S w1 = lift<S>(1) / (lift<S>(2) - root);
    const S w0 = lift<S>(1) - lift<S>(2) * w1;
    std::vector<S> next;
    for (const S& f : {w1, w0, w1})
      for (const S& x : w) next.push_back(f * x);
    w = std::move(next);
  }
  return w;
}

/// Symmetric composition of Stormer-Verlet of order 4, 6 or 8 (3, 9 or 27 Verlet steps,
/// one force evaluation each). Symplectic for any weights; the order needs them exact.
template <class System, class Vec, int Order>
class composition {
 public:
  static constexpr int order = Order;
  static constexpr bool symplectic = true;
  static constexpr bool symmetric = true;
  using scalar = typename Vec::Scalar;

  explicit composition(System system)
      : verlet_(std::move(system)), weights_(triple_jump_weights<real_type_t<scalar>>(Order)) {}

  void operator()(phase_state<Vec>& x, const scalar& h) {
    scratch_.use([&](workspace& w) {
      detail::guarded_step<System>(x, h, "composition", w.start, [&](phase_state<Vec>& y) {
        for (const auto& weight : weights_) {
          detail::scale(w.hw, weight, h);
          verlet_.substep(y, w.hw, w.verlet);
        }
      });
    });
  }

  const std::vector<real_type_t<scalar>>& weights() const { return weights_; }

 private:
  struct workspace {
    phase_state<Vec> start;
    typename stormer_verlet<System, Vec>::workspace verlet;
    scalar hw;
  };
  stormer_verlet<System, Vec> verlet_;
  std::vector<real_type_t<scalar>> weights_;
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

/// Butcher tableau of the s-stage Gauss-Legendre collocation method (order 2s), in R:
/// nodes c_i = (1 + x_i)/2 with x_i the roots of the Legendre polynomial P_s (Newton on
/// Boost.Math's legendre_p), weights b_i, and a_ij = int_0^{c_i} l_j = c_i sum_k b_k
/// l_j(c_i c_k) (Gauss quadrature, exact for the degree s-1 Lagrange basis l_j).
template <class R>
struct gauss_legendre_tableau {
  int stages;
  std::vector<R> c, b;
  std::vector<std::vector<R>> a;

  /// Throws domain_error unless 1 <= s <= 8 (before any storage is sized by s).
  static int checked(int s) {
    if (s < 1 || s > 8)
      throw domain_error("gauss_legendre_tableau: stages must be in 1..8, got " +
                         std::to_string(s));
    return s;
  }

  explicit gauss_legendre_tableau(int s)
      : stages(checked(s)), c(s), b(s), a(s, std::vector<R>(s)) {
    using boost::math::legendre_p;
    using boost::math::legendre_p_prime;
    using std::abs;
    using std::cos;
    const R pi = boost::math::constants::pi<R>();
    for (int i = 0; i < s; ++i) {
      R x = -cos(pi * (R(i) + R(3) / 4) / (R(s) + R(1) / 2));  // ascending roots
      for (int it = 0; it < 200; ++it) {
        const R dx = legendre_p(s, x) / legendre_p_prime(s, x);
        x -= dx;
        if (abs(dx) <= 2 * std::numeric_limits<R>::epsilon()) break;
      }
      const R dp = legendre_p_prime(s, x);
      c[i] = (1 + x) / 2;
      b[i] = 1 / ((1 - x * x) * dp * dp);  // Gauss weight 2/((1-x^2)P'^2), halved for [0,1]
    }
    for (int i = 0; i < s; ++i)
      for (int j = 0; j < s; ++j) {
        R sum = 0;
        for (int k = 0; k < s; ++k) sum += b[k] * lagrange(j, c[i] * c[k]);
        a[i][j] = c[i] * sum;
      }
    // The collocation polynomial's derivative, interpolated through the stage derivatives
    // at the nodes c_j, evaluated at 1 + c_i: the next step's stages, extrapolated.
    extrapolation.assign(s, std::vector<R>(s));
    for (int i = 0; i < s; ++i)
      for (int j = 0; j < s; ++j) extrapolation[i][j] = lagrange(j, 1 + c[i]);
    // a_ij = b_j (1/2 + alpha_ij) with alpha antisymmetric: the form in which the
    // symplecticity condition b_i a_ij + b_j a_ji = b_i b_j holds for any alpha.
    alpha.assign(s, std::vector<R>(s, R(0)));
    for (int i = 0; i < s; ++i)
      for (int j = i + 1; j < s; ++j) {
        alpha[i][j] = a[i][j] / b[j] - R(1) / 2;
        alpha[j][i] = -alpha[i][j];
      }
  }

  /// alpha[i][j] = a_ij / b_j - 1/2, exactly antisymmetric as stored.
  std::vector<std::vector<R>> alpha;

  /// extrapolation[i][j] = l_j(1 + c_i).
  std::vector<std::vector<R>> extrapolation;

  /// The Lagrange basis polynomial l_j on the nodes, at t.
  R lagrange(int j, const R& t) const {
    R l = 1;
    for (int m = 0; m < stages; ++m)
      if (m != j) l *= (t - c[m]) / (c[j] - c[m]);
    return l;
  }
};

/// s-stage Gauss-Legendre collocation (order 2s, symplectic, implicit) for any
/// Hamiltonian system. Stages are solved by fixed-point iteration to the tier's
/// precision (until the change is at the rounding floor or stops shrinking); the update
/// uses compensated (Kahan) summation, so long runs in double follow Brouwer's law.
/// Throws convergence_error when the iteration does not converge (h too large).
template <class System, class Vec, int Stages>
class gauss_legendre {
 public:
  static constexpr int order = 2 * Stages;
  static constexpr bool symplectic = true;
  static constexpr bool symmetric = true;
  using scalar = typename Vec::Scalar;
  using real = real_type_t<scalar>;

  explicit gauss_legendre(System system) : system_(std::move(system)), tableau_(Stages) {
    detail::set_zero(comp_q_);  // fixed-size states: no compensation before the first step
    detail::set_zero(comp_p_);
  }

  void operator()(phase_state<Vec>& x, const scalar& h) {
    scratch_.use([&](workspace& w) {
      detail::guarded_step<System>(x, h, "gauss_legendre", w.start,
                                   [&](phase_state<Vec>& y) { step(y, h, w); });
    });
  }

  const gauss_legendre_tableau<real>& tableau() const { return tableau_; }
  /// Stage sweeps (one vector-field evaluation per stage each) since construction.
  long long sweeps() const { return sweeps_; }
  /// Vector-field evaluations since construction: the sweeps' and, in the tiers beyond
  /// double, those of the difference Jacobians behind the Newton iteration.
  long long evaluations() const { return evaluations_; }
  /// The rounding the compensated update carries into the next step: the stepper's
  /// state is x + compensation, known more accurately than x alone (zero, or empty for
  /// dynamic states, before the first step; zero for AD scalars).
  const Vec& compensation_q() const { return comp_q_; }
  const Vec& compensation_p() const { return comp_p_; }

 private:
  /// The stage iteration's temporaries (detail::scratch: on the stack in double).
  struct workspace {
    phase_state<Vec> start;
    std::array<Vec, Stages> kq, kp, nq, np, gq, gp;
    Vec yq, yp, fq, fp, bq, bp;
    scalar t, c, incr, next;
    real change, size, diff;
  };

  /// Tiers beyond double solve the stages by Newton's method with a Jacobian in double
  /// (below); double itself and AD scalars by fixed-point sweeps.
  static constexpr bool newton =
      !is_ad_v<scalar> && std::numeric_limits<real>::digits > std::numeric_limits<double>::digits;

  void step(phase_state<Vec>& x, const scalar& h, workspace& w) {
    // Continuing a run with the same h (not for AD scalars), the stages start from the
    // last step's collocation polynomial extrapolated (error O(h^s) instead of O(h)).
    const bool continued = compensated_ && h == last_h_ && x.q == last_q_ && x.p == last_p_;
    for (int i = 0; i < Stages; ++i) detail::scale(hb_[i], tableau_.b[i], h);
    if constexpr (!std::is_floating_point_v<scalar>)
      for (int i = 0; i < Stages; ++i)
        for (int j = 0; j < Stages; ++j) detail::scale(ha_[i][j], tableau_.a[i][j], h);
    if (continued) {
      for (int i = 0; i < Stages; ++i) {
        w.kq[i] = last_kq_[i];  // sized like the state
        w.kp[i] = last_kp_[i];
        detail::set_zero(w.kq[i]);
        detail::set_zero(w.kp[i]);
        for (int j = 0; j < Stages; ++j) {
          detail::axpy(w.kq[i], detail::as_scalar(tableau_.extrapolation[i][j], w.c), last_kq_[j], w.t);
          detail::axpy(w.kp[i], detail::as_scalar(tableau_.extrapolation[i][j], w.c), last_kp_[j], w.t);
        }
      }
    } else {
      detail::shape_like(w.yq, x.q);
      detail::shape_like(w.yp, x.p);
      system_.vector_field(x.q, x.p, w.yq, w.yp);
      ++evaluations_;
      for (int i = 0; i < Stages; ++i) {
        w.kq[i] = w.yq;
        w.kp[i] = w.yp;
      }
    }
    solve_stages(x, h, w);
    // y' = y + h sum b_i k_i with Kahan compensation carried between steps (reset when
    // the state was changed outside the stepper).
    if (!continued && !(compensated_ && x.q == last_q_ && x.p == last_p_)) {
      comp_q_ = x.q;
      comp_p_ = x.p;
      detail::set_zero(comp_q_);
      detail::set_zero(comp_p_);
    }
    add_compensated(x.q, w.kq, comp_q_, w);
    add_compensated(x.p, w.kp, comp_p_, w);
    last_q_ = x.q;
    last_p_ = x.p;
    last_h_ = h;
    std::swap(last_kq_, w.kq);
    std::swap(last_kp_, w.kp);
    compensated_ = !is_ad_v<scalar>;
  }

  /// Y_i = y + h sum_j a_ij K_j into (w.yq, w.yp).
  /// (For built-in floating types from the sweep's shared parts, see shared_stage_part.)
  void stage_point(const phase_state<Vec>& x, int i, workspace& w) const {
    if constexpr (std::is_floating_point_v<scalar>) {
      w.yq = w.bq;
      w.yp = w.bp;
      for (int j = 0; j < Stages; ++j) {
        if (j == i) continue;  // alpha_ii = 0
        const scalar alpha = tableau_.alpha[i][j];
        w.yq.noalias() += alpha * w.gq[j];
        w.yp.noalias() += alpha * w.gp[j];
      }
    } else {
      w.yq = x.q;
      w.yp = x.p;
      for (int j = 0; j < Stages; ++j) {
        detail::axpy(w.yq, ha_[i][j], w.kq[j], w.t);
        detail::axpy(w.yp, ha_[i][j], w.kp[j], w.t);
      }
    }
  }

  /// For built-in floating types the stage coefficients h a_ij are never rounded. With
  /// D_j = fl(h b_j), the weights the update uses, G_j = D_j K_j and a_ij = b_j (1/2 +
  /// alpha_ij) (alpha antisymmetric as stored), the stage points are
  ///   Y_i = (y + sum_j G_j / 2) + sum_j alpha_ij G_j,
  /// so every rounding falls on data (G_j, the products and sums), none on a coefficient:
  /// the method computed has the coefficients D_j (1/2 + alpha_ij) / h and D_i / h exactly,
  /// which satisfy the symplecticity condition b_i a_ij + b_j a_ji = b_i b_j exactly.
  /// Rounded h a_ij violate it by ~eps in the same way every step: an energy drift that
  /// outgrows the random walk of rounding errors (10^6 steps of Kepler, e = 0.21:
  /// |dE/E| 1.9e-14 and growth exponent 0.53-0.79 over five orbits with rounded h a_ij,
  /// 3e-15 to 1e-14 and 0.23-0.48 in this form).
  void shared_stage_part(const phase_state<Vec>& x, workspace& w) const {
    if constexpr (std::is_floating_point_v<scalar>) {
      w.bq = x.q;
      w.bp = x.p;
      for (int j = 0; j < Stages; ++j) {
        w.gq[j].noalias() = hb_[j] * w.kq[j];
        w.gp[j].noalias() = hb_[j] * w.kp[j];
        w.bq.noalias() += scalar(0.5) * w.gq[j];
        w.bp.noalias() += scalar(0.5) * w.gp[j];
      }
    }
  }

  /// Solves K_i = f(y + h sum_j a_ij K_j) to the tier's precision, leaving K = f(Y(K)).
  ///
  /// Each sweep evaluates F(K) = f(Y(K)) at every stage. In double (and for AD scalars) the
  /// next K is F(K): a fixed point that gains a factor ~h |A| |f'| a sweep, enough from
  /// the extrapolated start (5 sweeps a step on Kepler, h = 2 pi/500). In the tiers beyond
  /// double that factor would take 18 sweeps in mpfr50, 33 at h = 2 pi/32. There the
  /// next K is K - M^-1 (K - F(K)), Newton's method with M = I - h (A (x) f'(Y_i)) built
  /// once a step in double from difference quotients of f at the first sweep's stage
  /// points: each iteration then gains min(double's 16 digits, a factor h |f''| |Y - Y_0|),
  /// and mpfr50 converges in ~4 sweeps plus the Jacobian's evaluations.
  void solve_stages(const phase_state<Vec>& x, const scalar& h, workspace& w) {
    for (int i = 0; i < Stages; ++i) {
      w.nq[i] = w.kq[i];
      w.np[i] = w.kp[i];
    }
    const real eps = std::numeric_limits<real>::epsilon();
    real previous = -1;
    // One sweep past convergence (three for AD scalars, whose derivative parts converge
    // later): stopping at the first small change leaves a stage error correlated from step
    // to step (the extrapolated start is smooth), which shows as an energy drift.
    int extra = newton ? 0 : is_ad_v<scalar> ? 3 : 1;
    bool converged = false;
    [[maybe_unused]] bool have_jacobian = false;
    for (int iteration = 0; iteration < 500; ++iteration) {
      ++sweeps_;
      evaluations_ += Stages;
      w.change = 0;
      w.size = 0;
      shared_stage_part(x, w);
      for (int i = 0; i < Stages; ++i) {
        stage_point(x, i, w);
        system_.vector_field(w.yq, w.yp, w.nq[i], w.np[i]);
        detail::track_change(w.nq[i], w.kq[i], w.change, w.size, w.diff);
        detail::track_change(w.np[i], w.kp[i], w.change, w.size, w.diff);
      }
      const real floor = eps * (w.size > 1 ? w.size : real(1));
      if (!converged)
        converged = w.change <= 2 * floor ||
                    (w.change <= 1024 * floor && previous >= 0 && 2 * w.change > previous);
      previous = w.change;
      if (!is_finite(w.change))
        throw non_finite_error("gauss_legendre: stage derivatives became non-finite at h = " +
                               to_text(h) + ", q = " + to_text(x.q) + ", p = " + to_text(x.p));
      if constexpr (newton) {
        if (!converged) {
          if (!have_jacobian) {
            newton_matrix(x, w);
            have_jacobian = true;
          }
          newton_update(w);
          continue;
        }
      }
      std::swap(w.kq, w.nq);  // K = F(K)
      std::swap(w.kp, w.np);
      if (converged && extra-- <= 0) return;
    }
    throw convergence_error(std::string("gauss_legendre: the ") +
                            (newton ? "Newton" : "fixed-point") + " iteration for the " +
                            std::to_string(Stages) + " stages did not converge in 500 "
                            "iterations (last change " + to_text(previous) + ") at h = " +
                            to_text(h) + ", q = " + to_text(x.q) + ", p = " + to_text(x.p));
  }

  /// M = I - h (A (x) J_i) in double, J_i = f'(Y_i) by forward differences of step
  /// sqrt(eps) |Y_i| at the stage points of the current K (F(K) is in w.nq, w.np), and its LU.
  void newton_matrix(const phase_state<Vec>& x, workspace& w) {
    const Eigen::Index nq = x.q.size(), m = nq + x.p.size(), n = Stages * m;
    matrix_.setIdentity(n, n);
    jacobian_.resize(m, m);
    detail::shape_like(w.fq, x.q);
    detail::shape_like(w.fp, x.p);
    using std::abs;
    using std::sqrt;
    const real root_eps = sqrt(std::numeric_limits<real>::epsilon());
    for (int i = 0; i < Stages; ++i) {
      stage_point(x, i, w);
      for (Eigen::Index c = 0; c < m; ++c) {
        scalar& coordinate = c < nq ? w.yq(c) : w.yp(c - nq);
        const scalar saved = coordinate;
        scalar delta = root_eps * (abs(saved) > 1 ? abs(saved) : real(1));
        coordinate += delta;
        delta = coordinate - saved;  // the step actually taken
        system_.vector_field(w.yq, w.yp, w.fq, w.fp);
        ++evaluations_;
        coordinate = saved;
        for (Eigen::Index r = 0; r < m; ++r) {
          const scalar slope = r < nq ? scalar((w.fq(r) - w.nq[i](r)) / delta)
                                      : scalar((w.fp(r - nq) - w.np[i](r - nq)) / delta);
          jacobian_(r, c) = static_cast<double>(slope);
        }
      }
      for (int j = 0; j < Stages; ++j)
        matrix_.block(i * m, j * m, m, m) -= static_cast<double>(ha_[i][j]) * jacobian_;
    }
    lu_.compute(matrix_);
  }

  /// K += M^-1 (F(K) - K), the residual and the correction in double.
  void newton_update(workspace& w) {
    const Eigen::Index nq = w.kq[0].size(), m = nq + w.kp[0].size();
    residual_.resize(Stages * m);
    for (int i = 0; i < Stages; ++i)
      for (Eigen::Index r = 0; r < m; ++r) {
        w.t = r < nq ? w.nq[i](r) : w.np[i](r - nq);
        w.t -= r < nq ? w.kq[i](r) : w.kp[i](r - nq);
        residual_(i * m + r) = static_cast<double>(w.t);
      }
    correction_ = lu_.solve(residual_);
    for (int i = 0; i < Stages; ++i)
      for (Eigen::Index r = 0; r < m; ++r) {
        w.t = correction_(i * m + r);
        (r < nq ? w.kq[i](r) : w.kp[i](r - nq)) += w.t;
      }
  }

  /// y += sum_i (h b_i) k_i, compensated: comp carries the rounding of the last update.
  void add_compensated(Vec& y, const std::array<Vec, Stages>& k, Vec& comp, workspace& w) const {
    for (Eigen::Index m = 0; m < y.size(); ++m) {
      w.incr = comp(m);
      for (int i = 0; i < Stages; ++i) inplace::add_product(w.incr, hb_[i], k[i](m), w.t);
      w.next = y(m);
      w.next += w.incr;
      w.t = w.next;
      w.t -= y(m);  // what the sum moved
      comp(m) = w.incr;
      comp(m) -= w.t;
      y(m) = w.next;
    }
  }

  System system_;
  gauss_legendre_tableau<real> tableau_;
  detail::scratch<workspace, scalar> scratch_;
  Vec comp_q_, comp_p_, last_q_, last_p_;
  std::array<Vec, Stages> last_kq_, last_kp_;
  std::array<std::array<scalar, Stages>, Stages> ha_;
  std::array<scalar, Stages> hb_;
  scalar last_h_{};
  Eigen::MatrixXd matrix_, jacobian_;
  Eigen::VectorXd residual_, correction_;
  Eigen::PartialPivLU<Eigen::MatrixXd> lu_;
  bool compensated_ = false;
  long long sweeps_ = 0, evaluations_ = 0;
};

/// Advance x by `steps` steps of size h.
template <class Stepper, class Vec>
void integrate(Stepper& step, phase_state<Vec>& x, const typename Vec::Scalar& h, long steps) {
  if (steps < 0)
    throw domain_error("integrate: steps must be non-negative, got " + std::to_string(steps));
  for (long i = 0; i < steps; ++i) step(x, h);
}

}  // namespace mechcheck
