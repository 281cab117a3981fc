#pragma once
/// s-stage Gauss-Legendre collocation (order 2s, symplectic, symmetric, implicit) for any
/// Hamiltonian system, and its Butcher tableau computed in any precision.

#include <array>
#include <cmath>
#include <limits>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include <boost/math/special_functions/legendre.hpp>
#include <Eigen/LU>

#include "mechcheck/integrators/guards.hpp"
#include "mechcheck/integrators/workspace.hpp"

namespace mechcheck {

/// Butcher tableau of the s-stage Gauss-Legendre collocation method (order 2s), in R:
/// nodes c_i = (1 + x_i)/2 with x_i the roots of the Legendre polynomial P_s (Newton on
/// Boost.Math's legendre_p), weights b_i, and a_ij = int_0^{c_i} l_j = c_i sum_k b_k
/// l_j(c_i c_k) (Gauss quadrature, exact for the degree s-1 Lagrange basis l_j).
template <class R>
struct gauss_legendre_tableau {
  int stages;
  std::vector<R> c, b;
  std::vector<std::vector<R>> a;

  /// Throws domain_error unless 1 <= s <= 12 (before any storage is sized by s); the
  /// certified references of audit/problems use 10 stages in mpfr50.
  static int checked(int s) {
    if (s < 1 || s > 12)
      throw domain_error("gauss_legendre_tableau: stages must be in 1..12, got " +
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
  /// The energy error stays bounded over long runs (a symplectic map at small h).
  static constexpr bool bounded_energy = true;
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
  /// Vector-field evaluations in the tier since construction: the sweeps' and, in the
  /// tiers beyond double, those of the difference Jacobians behind the Newton iteration
  /// (for a system that evaluates in double, those are in double and not counted).
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

  /// The system's vector field on double vectors, where it has one (a system templated on
  /// its vector type): the Newton matrix is only needed in double.
  using double_vec = Eigen::Matrix<double, Vec::RowsAtCompileTime, 1, 0, Vec::MaxRowsAtCompileTime, 1>;
  static constexpr bool field_in_double =
      requires(const System& s, const double_vec& a, double_vec& b) { s.vector_field(a, a, b, b); };

  /// M = I - h (A (x) J_i) in double and its LU, J_i = f'(Y_i) at the stage points of the
  /// current K (F(K) is in w.nq, w.np). Where the system evaluates in double, J_i comes from
  /// central differences of step cbrt(eps) max(|Y_i|, 1) in double (relative error ~1e-11,
  /// so that each Newton iteration gains ~11 digits): 2m evaluations in double instead of m
  /// in the tier (on the Pleiades in mpfr50, m = 28 and 8 stages, those were four fifths of a
  /// step's cost). Otherwise forward differences of step sqrt(eps) |Y_i| in the tier.
  void newton_matrix(const phase_state<Vec>& x, workspace& w) {
    const Eigen::Index nq = x.q.size(), m = nq + x.p.size(), n = Stages * m;
    matrix_.setIdentity(n, n);
    jacobian_.resize(m, m);
    if constexpr (field_in_double) {
      const Eigen::Index np = x.p.size();
      double_vec yq(nq), yp(np), fq(nq), fp(np), gq(nq), gp(np);
      const double step = std::cbrt(std::numeric_limits<double>::epsilon());
      for (int i = 0; i < Stages; ++i) {
        stage_point(x, i, w);
        for (Eigen::Index r = 0; r < nq; ++r) yq(r) = static_cast<double>(w.yq(r));
        for (Eigen::Index r = 0; r < np; ++r) yp(r) = static_cast<double>(w.yp(r));
        for (Eigen::Index c = 0; c < m; ++c) {
          double& coordinate = c < nq ? yq(c) : yp(c - nq);
          const double saved = coordinate;
          const double delta = step * std::max(std::abs(saved), 1.0);
          coordinate = saved + delta;
          const double up = coordinate;
          system_.vector_field(yq, yp, fq, fp);
          coordinate = saved - delta;
          const double width = up - coordinate;  // the steps actually taken
          system_.vector_field(yq, yp, gq, gp);
          coordinate = saved;
          for (Eigen::Index r = 0; r < m; ++r)
            jacobian_(r, c) = (r < nq ? fq(r) - gq(r) : fp(r - nq) - gp(r - nq)) / width;
        }
        for (int j = 0; j < Stages; ++j)
          matrix_.block(i * m, j * m, m, m) -= static_cast<double>(ha_[i][j]) * jacobian_;
      }
      lu_.compute(matrix_);
      return;
    }
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

}  // namespace mechcheck
