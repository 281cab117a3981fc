#pragma once
/// A Runge-Kutta method given by its Butcher tableau (c, A, b) -- explicit, diagonally
/// implicit or fully implicit -- for any Hamiltonian system (its vector field), in any tier and on AD scalars:
/// a published or a library's table of coefficients becomes a stepper the audit can hold
/// to its claims.
///
///   Y_i = y + h sum_{j <= i} a_ij K_j,   K_i = f(Y_i),   y' = y + h sum_i b_i K_i.
///
/// A diagonal entry a_ii != 0 makes stage i implicit: K_i = f(Z_i + h a_ii K_i) with Z_i
/// the explicit part; an entry above the diagonal couples the stages, which are then
/// solved together, K = f(y + h (A (x) I) K). Either is solved by modified Newton with the
/// Jacobian J of f by AD at the step's start (tier scalars; I - h a_ii J, or I - h A (x) J,
/// factored once) or by fixed-point sweeps (AD scalars, whose derivatives converge with
/// the values), until the change is at the tier's rounding floor or stops shrinking;
/// convergence_error otherwise. The tableau's coefficients are held in the
/// tier: a table given in double is exactly that table, in every tier.

#include <cmath>
#include <string>
#include <vector>

#include "mechcheck/core.hpp"
#include "mechcheck/integrators/systems.hpp"

namespace mechcheck {

/// A Butcher tableau in the real type R: a (s x s), b and c (s).
template <class R>
struct butcher_tableau {
  std::vector<std::vector<R>> a;
  std::vector<R> b, c;

  int stages() const { return static_cast<int>(b.size()); }
  /// True when a_ij = 0 on and above the diagonal (every stage from the ones before).
  bool is_explicit() const {
    for (int i = 0; i < stages(); ++i)
      for (int j = i; j < stages(); ++j)
        if (a[std::size_t(i)][std::size_t(j)] != 0) return false;
    return true;
  }
  /// The tableau with every coefficient converted to R2 (exact from double into a wider
  /// tier; rounded to nearest from a wider one).
  template <class R2>
  butcher_tableau<R2> as() const {
    const auto convert = [](const std::vector<R>& v) {
      std::vector<R2> out;
      out.reserve(v.size());
      for (const R& x : v) out.push_back(static_cast<R2>(x));
      return out;
    };
    butcher_tableau<R2> t;
    for (const auto& row : a) t.a.push_back(convert(row));
    t.b = convert(b);
    t.c = convert(c);
    return t;
  }
  /// True when a_ij = 0 above the diagonal (explicit or diagonally implicit).
  bool is_diagonally_implicit() const {
    for (int i = 0; i < stages(); ++i)
      for (int j = i + 1; j < stages(); ++j)
        if (a[std::size_t(i)][std::size_t(j)] != 0) return false;
    return true;
  }
  /// Throws dimension_error for inconsistent sizes and non_finite_error for a non-finite
  /// coefficient; `where` names the caller.
  void validate(const std::string& where) const {
    const std::size_t s = b.size();
    if (s == 0) throw dimension_error(where + ": the tableau has no stages");
    if (a.size() != s || c.size() != s)
      throw dimension_error(where + ": b has " + std::to_string(s) + " entries, c " +
                            std::to_string(c.size()) + ", A " + std::to_string(a.size()) + " rows");
    for (std::size_t i = 0; i < s; ++i) {
      if (a[i].size() != s)
        throw dimension_error(where + ": row " + std::to_string(i) + " of A has " +
                              std::to_string(a[i].size()) + " entries, not " + std::to_string(s));
      for (std::size_t j = 0; j < s; ++j) {
        if (!is_finite(a[i][j]))
          throw non_finite_error(where + ": a(" + std::to_string(i) + "," + std::to_string(j) +
                                 ") = " + to_text(a[i][j]));
      }
      if (!is_finite(b[i]) || !is_finite(c[i]))
        throw non_finite_error(where + ": b(" + std::to_string(i) + ") = " + to_text(b[i]) +
                               ", c(" + std::to_string(i) + ") = " + to_text(c[i]));
    }
  }
};

/// The Runge-Kutta method of a tableau (explicit or diagonally implicit) on (q, p).
template <class System, class Vec>
class runge_kutta {
 public:
  using scalar = typename Vec::Scalar;
  using real = real_type_t<scalar>;

  runge_kutta(System system, butcher_tableau<real> tableau)
      : system_(std::move(system)), tableau_(std::move(tableau)) {
    tableau_.validate("runge_kutta");
    diagonal_ = tableau_.is_diagonally_implicit();
  }

  const butcher_tableau<real>& tableau() const { return tableau_; }

  void operator()(phase_state<Vec>& x, const scalar& h) {
    if (!is_finite(h) || h == 0)
      throw non_finite_error("runge_kutta: the step h must be finite and non-zero, got " +
                             to_text(h));
    const phase_state<Vec> start = x;
    try {
      step(x, h);
    } catch (...) {
      x = start;
      throw;
    }
    if (first_non_finite(x.q) >= 0 || first_non_finite(x.p) >= 0) {
      const phase_state<Vec> produced = x;
      x = start;
      throw non_finite_error("runge_kutta: the step h = " + to_text(h) + " from q = " +
                             to_text(start.q) + ", p = " + to_text(start.p) +
                             " produced q = " + to_text(produced.q) + ", p = " +
                             to_text(produced.p));
    }
  }

 private:
  void field(const Vec& q, const Vec& p, Vec& dq, Vec& dp) const {
    dq = q;
    dp = p;
    system_.vector_field(q, p, dq, dp);
  }

  void step(phase_state<Vec>& x, const scalar& h) {
    jacobian_valid_ = false;
    factors_.clear();
    if (!diagonal_) return coupled_step(x, h);
    const int s = tableau_.stages();
    std::vector<Vec> kq(static_cast<std::size_t>(s)), kp(static_cast<std::size_t>(s));
    for (int i = 0; i < s; ++i) {
      Vec zq = x.q, zp = x.p;
      for (int j = 0; j < i; ++j) {
        const real& a = tableau_.a[std::size_t(i)][std::size_t(j)];
        if (a == 0) continue;
        const scalar ha = lift<scalar>(a) * h;
        zq += ha * kq[std::size_t(j)];
        zp += ha * kp[std::size_t(j)];
      }
      const real& aii = tableau_.a[std::size_t(i)][std::size_t(i)];
      field(zq, zp, kq[std::size_t(i)], kp[std::size_t(i)]);
      if (aii != 0) solve_stage(x, zq, zp, aii, h, kq[std::size_t(i)], kp[std::size_t(i)]);
    }
    for (int i = 0; i < s; ++i) {
      const real& b = tableau_.b[std::size_t(i)];
      if (b == 0) continue;
      const scalar hb = lift<scalar>(b) * h;
      x.q += hb * kq[std::size_t(i)];
      x.p += hb * kp[std::size_t(i)];
    }
  }

  /// dy/dt = f(y) as one vector (q, p) of the tier or AD scalars.
  template <class S>
  dynamic_vector<S> stacked_field(const dynamic_vector<S>& w, Eigen::Index nq) const {
    const Eigen::Index np = w.size() - nq;
    dynamic_vector<S> q = w.head(nq), p = w.tail(np), dq = q, dp = p;
    if constexpr (requires { system_.vector_field_uncounted(q, p, dq, dp); }) {
      if constexpr (!std::is_same_v<S, scalar>) {
        system_.vector_field_uncounted(q, p, dq, dp);
      } else {
        system_.vector_field(q, p, dq, dp);
      }
    } else {
      system_.vector_field(q, p, dq, dp);
    }
    dynamic_vector<S> out(w.size());
    out << dq, dp;
    return out;
  }

  /// A fully implicit step: all stages together.
  void coupled_step(phase_state<Vec>& x, const scalar& h) {
    const int s = tableau_.stages();
    const Eigen::Index nq = x.q.size(), n = nq + x.p.size();
    dynamic_vector<scalar> y(n);
    y << x.q, x.p;
    const dynamic_vector<scalar> f0 = stacked_field(y, nq);
    dynamic_vector<scalar> k(s * n);
    for (int i = 0; i < s; ++i) k.segment(i * n, n) = f0;
    [[maybe_unused]] Eigen::PartialPivLU<dynamic_matrix<scalar>> lu;
    if constexpr (!is_ad_v<scalar>) {
      const auto f = [this, nq]<class S>(const dynamic_vector<S>& w) {
        return stacked_field<S>(w, nq);
      };
      const dynamic_matrix<scalar> j = jacobian(f, y);
      dynamic_matrix<scalar> m = dynamic_matrix<scalar>::Identity(s * n, s * n);
      for (int i = 0; i < s; ++i)
        for (int l = 0; l < s; ++l) {
          const real& a = tableau_.a[std::size_t(i)][std::size_t(l)];
          if (a != 0) m.block(i * n, l * n, n, n) -= (lift<scalar>(a) * h) * j;
        }
      lu.compute(m);
    }
    const real eps = std::numeric_limits<real>::epsilon();
    real previous = -1;
    int extra = is_ad_v<scalar> ? 3 : 0;
    bool converged = false;
    for (int iteration = 0; iteration < 200; ++iteration) {
      dynamic_vector<scalar> r(s * n);
      for (int i = 0; i < s; ++i) {
        dynamic_vector<scalar> yi = y;
        for (int l = 0; l < s; ++l) {
          const real& a = tableau_.a[std::size_t(i)][std::size_t(l)];
          if (a != 0) yi += (lift<scalar>(a) * h) * k.segment(l * n, n);
        }
        r.segment(i * n, n) = stacked_field(yi, nq) - k.segment(i * n, n);
      }
      dynamic_vector<scalar> delta = r;
      if constexpr (!is_ad_v<scalar>) delta = lu.solve(r);
      k += delta;
      using std::abs;
      real change = 0, size = 0;
      for (Eigen::Index i = 0; i < k.size(); ++i) {
        change = std::max(change, real(abs(innermost_value(delta(i)))));
        size = std::max(size, real(abs(innermost_value(k(i)))));
      }
      if (!is_finite(change))
        throw non_finite_error("runge_kutta: the implicit stages became non-finite");
      const real floor = eps * (size > 1 ? size : real(1));
      if (!converged)
        converged = change <= 2 * floor ||
                    (change <= 1024 * floor && previous >= 0 && 2 * change > previous);
      previous = change;
      if (converged && extra-- <= 0) {
        for (int i = 0; i < s; ++i) {
          const real& b = tableau_.b[std::size_t(i)];
          if (b == 0) continue;
          const dynamic_vector<scalar> ki = k.segment(i * n, n);
          x.q += (lift<scalar>(b) * h) * Vec(ki.head(nq));
          x.p += (lift<scalar>(b) * h) * Vec(ki.tail(n - nq));
        }
        return;
      }
    }
    throw convergence_error("runge_kutta: the implicit stages did not converge in 200 "
                            "iterations (last change " + to_text(previous) + ", h = " +
                            to_text(h) + ")");
  }

  /// K = f(Z + h a_ii K) to the tier's precision: modified Newton for tier scalars, with
  /// J = df/dy by AD at the step's start (once a step) and I - h a_ii J factored once per
  /// distinct a_ii (an SDIRK factors once a step); fixed-point sweeps for AD scalars.
  void solve_stage(const phase_state<Vec>& x, const Vec& zq, const Vec& zp, const real& aii,
                   const scalar& h, Vec& kq, Vec& kp) {
    const scalar ha = lift<scalar>(aii) * h;
    const Eigen::Index nq = zq.size(), np = zp.size(), n = nq + np;
    const real eps = std::numeric_limits<real>::epsilon();
    real previous = -1;
    int extra = is_ad_v<scalar> ? 3 : 0;
    bool converged = false;
    [[maybe_unused]] const Eigen::PartialPivLU<dynamic_matrix<scalar>>* lu = nullptr;
    if constexpr (!is_ad_v<scalar>) {
      if (!jacobian_valid_) {
        const auto f = [this, nq, np]<class S>(const dynamic_vector<S>& w) -> dynamic_vector<S> {
          dynamic_vector<S> q = w.head(nq), p = w.tail(np), dq2 = q, dp2 = p;
          if constexpr (requires { system_.vector_field_uncounted(q, p, dq2, dp2); })
            system_.vector_field_uncounted(q, p, dq2, dp2);
          else
            system_.vector_field(q, p, dq2, dp2);
          dynamic_vector<S> out(w.size());
          out << dq2, dp2;
          return out;
        };
        dynamic_vector<scalar> y(n);
        y << x.q, x.p;
        jacobian_ = jacobian(f, y);
        jacobian_valid_ = true;
      }
      for (const auto& [a, factor] : factors_)
        if (a == aii) lu = &factor;
      if (!lu) {
        factors_.emplace_back(aii, Eigen::PartialPivLU<dynamic_matrix<scalar>>(
                                       dynamic_matrix<scalar>(dynamic_matrix<scalar>::Identity(n, n) -
                                                              ha * jacobian_)));
        lu = &factors_.back().second;
      }
    }
    for (int iteration = 0; iteration < 200; ++iteration) {
      const Vec yq = zq + ha * kq, yp = zp + ha * kp;
      Vec fq, fp;
      field(yq, yp, fq, fp);
      Vec dq = fq - kq, dp = fp - kp;  // the residual F(K) - K
      if constexpr (!is_ad_v<scalar>) {
        dynamic_vector<scalar> r(n);
        r << dq, dp;
        const dynamic_vector<scalar> delta = lu->solve(r);
        dq = delta.head(nq);
        dp = delta.tail(np);
      }
      kq += dq;
      kp += dp;
      using std::abs;
      real change = 0, size = 0;
      for (Eigen::Index i = 0; i < nq; ++i) {
        change = std::max(change, real(abs(innermost_value(dq(i)))));
        size = std::max(size, real(abs(innermost_value(kq(i)))));
      }
      for (Eigen::Index i = 0; i < np; ++i) {
        change = std::max(change, real(abs(innermost_value(dp(i)))));
        size = std::max(size, real(abs(innermost_value(kp(i)))));
      }
      if (!is_finite(change))
        throw non_finite_error("runge_kutta: an implicit stage became non-finite");
      const real floor = eps * (size > 1 ? size : real(1));
      if (!converged)
        converged = change <= 2 * floor ||
                    (change <= 1024 * floor && previous >= 0 && 2 * change > previous);
      previous = change;
      if (converged && extra-- <= 0) return;
    }
    throw convergence_error("runge_kutta: an implicit stage did not converge in 200 iterations "
                            "(last change " + to_text(previous) + ", h a_ii = " + to_text(ha) + ")");
  }

  System system_;
  butcher_tableau<real> tableau_;
  bool diagonal_ = true;  // explicit or diagonally implicit: stage by stage
  // The step's Jacobian at its start and the factors of I - h a_ii J (tier scalars).
  bool jacobian_valid_ = false;
  dynamic_matrix<scalar> jacobian_;
  std::vector<std::pair<real, Eigen::PartialPivLU<dynamic_matrix<scalar>>>> factors_;
};

}  // namespace mechcheck
