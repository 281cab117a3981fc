#pragma once
/// A Runge-Kutta method given by its Butcher tableau (c, A, b), explicit or diagonally
/// implicit, for any Hamiltonian system (its vector field), in any tier and on AD scalars:
/// a published or a library's table of coefficients becomes a stepper the audit can hold
/// to its claims.
///
///   Y_i = y + h sum_{j <= i} a_ij K_j,   K_i = f(Y_i),   y' = y + h sum_i b_i K_i.
///
/// A diagonal entry a_ii != 0 makes stage i implicit: K_i = f(Z_i + h a_ii K_i) with Z_i
/// the explicit part, solved by modified Newton with the Jacobian of f by AD at the step's
/// start (tier scalars) or by fixed-point sweeps (AD scalars, whose derivatives converge with the
/// values), from K_i = f(Z_i), until the change is at the tier's rounding floor or stops
/// shrinking; convergence_error otherwise. The tableau's coefficients are held in the
/// tier: a table given in double is exactly that table, in every tier.

#include <cmath>
#include <string>
#include <vector>

#include "mechcheck/core.hpp"
#include "mechcheck/integrators/systems.hpp"

namespace mechcheck {

/// A Butcher tableau in the real type R: a (s x s, a_ij = 0 for j > i), b and c (s).
template <class R>
struct butcher_tableau {
  std::vector<std::vector<R>> a;
  std::vector<R> b, c;

  int stages() const { return static_cast<int>(b.size()); }
  bool is_explicit() const {
    for (int i = 0; i < stages(); ++i)
      if (a[std::size_t(i)][std::size_t(i)] != 0) return false;
    return true;
  }
  /// The tableau with every coefficient converted to R2 (exact from double into a wider
  /// tier).
  template <class R2>
  butcher_tableau<R2> as() const {
    butcher_tableau<R2> t;
    for (const auto& row : a) t.a.emplace_back(row.begin(), row.end());
    t.b.assign(b.begin(), b.end());
    t.c.assign(c.begin(), c.end());
    return t;
  }
  /// Throws dimension_error for inconsistent sizes, non_finite_error for a non-finite
  /// coefficient and domain_error for a_ij != 0 above the diagonal (a fully implicit
  /// method); `where` names the caller.
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
        if (j > i && a[i][j] != 0)
          throw domain_error(where + ": a(" + std::to_string(i) + "," + std::to_string(j) +
                             ") = " + to_text(a[i][j]) +
                             " above the diagonal: only explicit and diagonally implicit "
                             "tableaus are supported");
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
  // The step's Jacobian at its start and the factors of I - h a_ii J (tier scalars).
  bool jacobian_valid_ = false;
  dynamic_matrix<scalar> jacobian_;
  std::vector<std::pair<real, Eigen::PartialPivLU<dynamic_matrix<scalar>>>> factors_;
};

}  // namespace mechcheck
