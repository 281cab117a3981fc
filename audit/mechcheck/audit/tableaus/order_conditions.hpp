#pragma once
/// The order conditions of a Runge-Kutta tableau by rooted trees (Butcher's theory): a
/// method has order p when, for every rooted tree t with |t| <= p nodes,
///     Phi(t) = b^T g(t) = 1 / gamma(t),
/// where g(t)_i = prod over the root's subtrees u of (A g(u))_i (g of the one-node tree is
/// the vector of ones) is the elementary weight's stage vector, and the density gamma(t) =
/// |t| prod gamma(u). The trees are enumerated to any order: a tree is its root's multiset
/// of subtrees, generated in canonical order (each multiset once), counted against OEIS
/// A000081 (1, 1, 2, 4, 9, 20, 48, 115, 286, 719, 1842, 4766, 12486, 32973, ...).
///
/// Cost and memory: the trees of order n are enumerated depth-first from the stored vectors
/// A g(u) of the trees of order <= P - 2 (P the highest order evaluated); a tree [u] with
/// one subtree of order P - 1 needs no stored vector, Phi([u]) = (A^T b)^T g(u). The work is
/// about s x (number of trees) multiplications (stage-trees) and the storage s x (trees of order <= P - 2)
/// values: bench/ measures it. Beyond a budget the orders are evaluated as far as it goes,
/// and the report says where it stopped and why.
///
/// Beyond the orders evaluated by trees, Butcher's simplifying assumptions decide where they
/// can (Butcher 1964; Hairer, Norsett & Wanner I, Thm II.7.4):
///     B(p): b^T c^(k-1) = 1/k,                         k <= p
///     C(e): sum_j a_ij c_j^(k-1) = c_i^k / k,           k <= e
///     D(z): sum_i b_i c_i^(k-1) a_ij = b_j (1 - c_j^k) / k, k <= z
/// and B(p), C(e), D(z) with p <= e + z + 1 and p <= 2 e + 2 give order p. B(k) is itself
/// the condition of the bushy tree of order k, so a failing B(k) bounds the order by k - 1
/// at any k. A claim neither the trees nor these decide is never confirmed. They are taken
/// with c = A 1, the row sums the trees use (the theorem assumes it): the c a tableau writes
/// is held to A 1 apart, so that a c rounded on its own (a table of doubles whose c is its
/// rows' sum in double) does not move a condition the trees hold.
///
/// Every condition is a polynomial in the coefficients, homogeneous of degree d (|t| for a
/// tree). Coefficients off by a relative delta move it by at most about d delta times the
/// same polynomial in the coefficients' absolute values, its scale; each residual is also
/// kept relative to d x scale, so "holds to the precision given" is one test for every
/// condition: relative residual <= max(2 delta, the rounding of R). One scale serves a
/// condition wherever it is evaluated: B(k) takes c_i^(k-1) at the scale (|A| 1)_i^(k-1), as
/// the bushy tree does.
///
/// Evaluated in a wide tier (mpfr100 for the audit), the residuals say to what precision a
/// table's coefficients satisfy each order: "order 4 exactly" (residuals at that tier's
/// rounding) is told from "order 4 to 1e-11" (a coefficient typed to 11 digits).

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "mechcheck/core.hpp"
#include "mechcheck/integrators/runge_kutta.hpp"

namespace mechcheck::audit {

/// The number of rooted trees with n nodes (OEIS A000081), n = 1..40, by the recurrence
/// a(n+1) = (1/n) sum_{k=1..n} (sum_{d | k} d a(d)) a(n-k+1). Throws domain_error outside.
inline std::uint64_t rooted_tree_count(int n) {
  if (n < 1 || n > 40)
    throw domain_error("rooted_tree_count: the order must be 1..40, got " + std::to_string(n));
  std::vector<unsigned __int128> a(std::size_t(n) + 1, 0);
  a[1] = 1;
  for (int m = 1; m < n; ++m) {
    unsigned __int128 sum = 0;
    for (int k = 1; k <= m; ++k) {
      unsigned __int128 divisors = 0;
      for (int d = 1; d <= k; ++d)
        if (k % d == 0) divisors += static_cast<unsigned __int128>(d) * a[std::size_t(d)];
      sum += divisors * a[std::size_t(m - k + 1)];
    }
    a[std::size_t(m) + 1] = sum / static_cast<unsigned __int128>(m);
  }
  return static_cast<std::uint64_t>(a[std::size_t(n)]);
}

/// The trees of orders 1..n together.
inline std::uint64_t rooted_trees_up_to(int n) {
  std::uint64_t total = 0;
  for (int k = 1; k <= n; ++k) total += rooted_tree_count(k);
  return total;
}

/// A rooted tree: the ids of its root's subtrees (non-decreasing), its order and density.
struct rooted_tree {
  std::vector<int> children;
  int order = 1;
  double density = 1;  ///< gamma(t); exact in double up to order 18 (18! < 2^53)
};

/// Every rooted tree of order 1..max_order (at most 18), grouped by order and in canonical
/// order; a child id always precedes its parent's. For listing and tests: the order
/// conditions enumerate their trees without storing them.
inline const std::vector<rooted_tree>& rooted_trees(int max_order = 10) {
  if (max_order > 18)
    throw domain_error("rooted_trees: lists trees to order 18 (their densities exact in double), asked for " +
                       std::to_string(max_order));
  static std::vector<rooted_tree> trees;
  static int built = 0;
  if (built >= max_order) return trees;
  if (trees.empty()) trees.push_back({{}, 1, 1});
  for (int n = std::max(2, built + 1); n <= max_order; ++n) {
    const std::size_t existing = trees.size();
    std::vector<int> chosen;
    const auto extend = [&](auto&& self, int remaining, int min_id) -> void {
      if (remaining == 0) {
        rooted_tree t;
        t.children = chosen;
        t.order = n;
        t.density = n;
        for (const int c : chosen) t.density *= trees[std::size_t(c)].density;
        trees.push_back(t);
        return;
      }
      for (int id = min_id; id < static_cast<int>(existing); ++id) {
        if (trees[std::size_t(id)].order > remaining) break;  // ids are sorted by order
        chosen.push_back(id);
        self(self, remaining - trees[std::size_t(id)].order, id);
        chosen.pop_back();
      }
    };
    extend(extend, n - 1, 0);
    built = n;
  }
  if (built < 1) built = 1;
  return trees;
}

/// How far the trees may go: the values stored (s per tree of order <= P - 2) and the
/// stage-trees (s per tree of order <= P). Measured in mpfr100 (bench/order_conditions_bench.cpp,
/// docs/performance.md): 1.5 us a stage-tree, 210 bytes a stored value, so the defaults keep
/// one analysis under about 50 s and 0.9 GB.
struct order_condition_budget {
  std::uint64_t stored_values = std::uint64_t(1) << 22;
  std::uint64_t work = std::uint64_t(1) << 25;
};

/// The order conditions of a tableau in the real type R.
template <class R>
struct order_condition_report {
  std::vector<double> residual;  ///< residual[k - 1]: max |Phi(t) - 1/gamma(t)| over |t| = k
  /// relative[k - 1]: max over |t| = k of |Phi(t) - 1/gamma(t)| / (k scale(t)), scale(t) =
  /// |b|^T g_|A|(t): the relative error of the coefficients that would explain the residual.
  std::vector<double> relative;
  std::vector<std::uint64_t> trees;  ///< trees[k - 1]: the trees of order k evaluated
  int max_order = 0;        ///< the orders evaluated by trees (1..max_order)
  int requested_order = 0;  ///< the orders asked for
  std::string limit;        ///< why max_order < requested_order ("" when not)
  /// The simplifying assumptions, relative as above: b_relative[k - 1] for B(k),
  /// c_relative[k - 1] for C(k) (max over the stages), d_relative[k - 1] for D(k).
  std::vector<double> b_relative, c_relative, d_relative;
  double row_sum = 0;  ///< max_i |sum_j a_ij - c_i|
  int stage_order = 0;  ///< the largest q with C(q) to `tolerance` (mechcheck's stage order)
  int stage_order_exact = 0;  ///< the same to `exact_tolerance`
  /// The largest q with both B(q) and C(q) to `tolerance` (the stage order of Hairer and
  /// Wanner's and the common analysers' definition).
  int stage_order_bc = 0;
  double symplectic = 0;  ///< max |b_i a_ij + b_j a_ji - b_i b_j| (0: symplectic)
  double symmetric = 0;   ///< max |a_(s+1-i, s+1-j) + a_ij - b_j| and |b_(s+1-i) - b_i|
  double symplectic_relative = 0, symmetric_relative = 0;  ///< relative as above
  /// The relative precision the coefficients are given to (0: exact; 5e-61 for 60 decimal
  /// digits; 2^-53 for double).
  double precision = 0;
  /// What counts as satisfied to R's rounding, relative: a condition of degree d is d nested
  /// sums of at most s products, each rounded in R, so its relative rounding stays below
  /// (s + 2) eps(R); the tolerance is max(64, 4 (s + 2)) eps(R).
  double exact_tolerance = 0;
  /// What counts as satisfied at the precision given, relative: max(2 precision,
  /// exact_tolerance) -- an author's last digit rounded (5 10^-N) or truncated (10^(1-N)).
  double tolerance = 0;

  /// The largest k with B(k), C(k), D(k) to `below` (0: none).
  int largest(const std::vector<double>& v, double below) const {
    int k = 0;
    while (k < static_cast<int>(v.size()) && v[std::size_t(k)] <= below) ++k;
    return k;
  }
  /// The order the simplifying assumptions give: min(B, e + z + 1, 2 e + 2) (0: none).
  int simplified_order(double below) const {
    const int e = largest(c_relative, below), z = largest(d_relative, below);
    return std::min({largest(b_relative, below), e + z + 1, 2 * e + 2});
  }
  /// The first order whose bushy-tree condition B(k) fails (0: none within 2s + 2).
  int bushy_failure(double below) const {
    const int k = largest(b_relative, below);
    return k < static_cast<int>(b_relative.size()) ? k + 1 : 0;
  }
  /// The largest p with every order <= p satisfied to `below` (relative): by trees, and
  /// past the orders they evaluated by the simplifying assumptions (0: not even consistent).
  int order(double below) const {
    int p = 0;
    while (p < max_order && relative[std::size_t(p)] <= below) ++p;
    if (p == max_order) p = std::max(p, simplified_order(below));
    return p;
  }
  /// Whether order p is decided at `below`: holds (+1), fails (-1), or neither the trees
  /// evaluated nor the simplifying assumptions decide it (0).
  int decides(int p, double below) const {
    for (int k = 0; k < std::min(p, max_order); ++k)
      if (relative[std::size_t(k)] > below) return -1;
    const int bushy = bushy_failure(below);
    if (bushy > 0 && bushy <= p) return -1;
    if (p <= max_order || p <= simplified_order(below)) return 1;
    return 0;
  }
  /// The largest residual over orders 1..p (absolute, and relative).
  double up_to(int p) const {
    double r = 0;
    for (int k = 0; k < p && k < max_order; ++k) r = std::max(r, residual[std::size_t(k)]);
    return r;
  }
  double relative_up_to(int p) const {
    double r = 0;
    for (int k = 0; k < p && k < max_order; ++k) r = std::max(r, relative[std::size_t(k)]);
    if (p > max_order)  // beyond the trees: the bushy conditions are still evaluated
      for (int k = max_order; k < p && k < static_cast<int>(b_relative.size()); ++k)
        r = std::max(r, b_relative[std::size_t(k)]);
    return r;
  }
};

namespace detail {
/// |x| / (degree * scale), 0 for an exact zero; a residual with no scale is an order-one
/// failure (1).
template <class R>
double relative_residual(const R& residual, const R& scale, int degree) {
  using std::abs;
  const R r = abs(residual);
  if (r == 0) return 0;
  if (!(scale > 0)) return 1;
  return static_cast<double>(R(r / (scale * degree)));
}
}  // namespace detail

/// Evaluates the order conditions of (A, b, c) up to max_order in R (as far as `budget`
/// allows: see `limit`), for coefficients given to the relative `precision` (0: exact).
template <class R>
order_condition_report<R> order_conditions(const butcher_tableau<R>& t, int max_order = 10,
                                           double precision = 0, order_condition_budget budget = {}) {
  using std::abs;
  t.validate("order_conditions");
  if (max_order < 1 || max_order > 40)
    throw domain_error("order_conditions: max_order must be 1..40, got " + std::to_string(max_order));
  if (!(precision >= 0 && std::isfinite(precision)))
    throw domain_error("order_conditions: the coefficients' precision must be >= 0 and finite, got " +
                       std::to_string(precision));
  const std::size_t s = std::size_t(t.stages());
  order_condition_report<R> out;
  out.requested_order = max_order;
  out.precision = precision;
  const double eps_r = static_cast<double>(std::numeric_limits<R>::epsilon());
  out.exact_tolerance = std::max(64.0, 4.0 * double(s + 2)) * eps_r;
  out.tolerance = std::max(2 * precision, out.exact_tolerance);

  // The orders the budget allows.
  int P = max_order;
  const auto stored = [s](int p) { return p <= 2 ? std::uint64_t(0) : rooted_trees_up_to(p - 2) * s; };
  while (P > 1 && (stored(P) > budget.stored_values || rooted_trees_up_to(P) * s > budget.work)) --P;
  if (P < max_order)
    out.limit = "order " + std::to_string(P + 1) + " needs " + std::to_string(rooted_trees_up_to(P + 1)) +
                " trees (" + std::to_string(stored(P + 1)) + " stored stage values, budget " +
                std::to_string(budget.stored_values) + "; " + std::to_string(rooted_trees_up_to(P + 1) * s) +
                " stage-trees, budget " + std::to_string(budget.work) + ")";
  out.max_order = P;
  out.residual.assign(std::size_t(P), 0.0);
  out.relative.assign(std::size_t(P), 0.0);
  out.trees.assign(std::size_t(P), 0);

  // |A|, |b| and A^T b, |A|^T |b| (the last order's one-subtree trees).
  std::vector<R> abs_a(s * s), atb(s, R(0)), abs_atb(s, R(0));
  for (std::size_t i = 0; i < s; ++i)
    for (std::size_t j = 0; j < s; ++j) {
      abs_a[i * s + j] = abs(t.a[i][j]);
      atb[j] += t.a[i][j] * t.b[i];
      abs_atb[j] += abs_a[i * s + j] * abs(t.b[i]);
    }
  // The stored trees (order <= P - 2), sorted by order: A g, |A| g_|A|, 1/gamma.
  std::vector<R> ag, abs_ag, inv_gamma;
  std::vector<int> order_of;
  // Depth-first products: level d holds prod of the first d chosen subtrees' vectors.
  std::vector<std::vector<R>> v(std::size_t(P) + 1, std::vector<R>(s, R(1))),
      va(std::size_t(P) + 1, std::vector<R>(s, R(1)));
  std::vector<R> vinv(std::size_t(P) + 1, R(1));

  const auto record = [&out](int k, const R& phi, const R& scale, const R& inv) {
    const R res = phi - inv;
    double& slot = out.residual[std::size_t(k - 1)];
    slot = std::max(slot, static_cast<double>(R(abs(res))));
    double& rel = out.relative[std::size_t(k - 1)];
    rel = std::max(rel, detail::relative_residual(res, scale, k));
    out.trees[std::size_t(k - 1)] += 1;
  };
  for (int n = 1; n <= P; ++n) {
    const std::size_t available = order_of.size();
    const R inv_n = R(1) / R(n);
    const auto finish = [&](int depth) {
      const std::vector<R>& g = v[std::size_t(depth)];
      const std::vector<R>& ga = va[std::size_t(depth)];
      const R ig = vinv[std::size_t(depth)] * inv_n;
      R phi = 0, scale = 0;
      for (std::size_t i = 0; i < s; ++i) {
        phi += t.b[i] * g[i];
        scale += abs(t.b[i]) * ga[i];
      }
      record(n, phi, scale, ig);
      if (n == P - 1) {  // the tree [t] of order P
        R phi2 = 0, scale2 = 0;
        for (std::size_t i = 0; i < s; ++i) {
          phi2 += atb[i] * g[i];
          scale2 += abs_atb[i] * ga[i];
        }
        record(P, phi2, scale2, ig / R(P));
      }
      if (n <= P - 2) {
        order_of.push_back(n);
        inv_gamma.push_back(ig);
        for (std::size_t i = 0; i < s; ++i) {
          R x = 0, xa = 0;
          for (std::size_t j = 0; j < s; ++j) {
            x += t.a[i][j] * g[j];
            xa += abs_a[i * s + j] * ga[j];
          }
          ag.push_back(x);
          abs_ag.push_back(xa);
        }
      }
    };
    const auto extend = [&](auto&& self, int remaining, std::size_t min_id, int depth) -> void {
      if (remaining == 0) {
        finish(depth);
        return;
      }
      std::vector<R>& next = v[std::size_t(depth) + 1];
      std::vector<R>& next_a = va[std::size_t(depth) + 1];
      for (std::size_t id = min_id; id < available; ++id) {
        if (order_of[id] > remaining) break;  // ids are sorted by order
        for (std::size_t i = 0; i < s; ++i) {
          next[i] = v[std::size_t(depth)][i] * ag[id * s + i];
          next_a[i] = va[std::size_t(depth)][i] * abs_ag[id * s + i];
        }
        vinv[std::size_t(depth) + 1] = vinv[std::size_t(depth)] * inv_gamma[id];
        self(self, remaining - order_of[id], id, depth + 1);
      }
    };
    extend(extend, n - 1, 0, 0);
  }

  // The simplifying assumptions B(k) (k <= 2s + 2), C(k) and D(k) (k <= s + 1), with c the
  // row sums A 1 as the trees have them (the bushy tree of order k is B(k) with c = A 1) and
  // each condition's scale its terms' as the trees take them: c_i^k by (|A| 1)_i^k. A
  // condition is then judged on one scale whether a tree or B(k) evaluates it; the c
  // written in the tableau is held to A 1 apart (row_sum).
  std::vector<R> c1(s, R(0)), ca(s, R(0));
  for (std::size_t i = 0; i < s; ++i)
    for (std::size_t j = 0; j < s; ++j) {
      c1[i] += t.a[i][j];
      ca[i] += abs_a[i * s + j];
    }
  std::vector<R> cpow(s, R(1)), capow(s, R(1));  // (A 1)_j^(k-1), (|A| 1)_j^(k-1)
  for (int k = 1; k <= 2 * static_cast<int>(s) + 2; ++k) {
    R sum = 0, scale = 0;
    for (std::size_t i = 0; i < s; ++i) {
      sum += t.b[i] * cpow[i];
      scale += abs(t.b[i]) * capow[i];
    }
    out.b_relative.push_back(detail::relative_residual(R(sum - R(1) / R(k)), scale, k));
    if (k <= static_cast<int>(s) + 1) {
      double worst_c = 0, worst_d = 0;
      for (std::size_t i = 0; i < s; ++i) {
        R cs = 0, ca_sum = 0;
        for (std::size_t j = 0; j < s; ++j) {
          cs += t.a[i][j] * cpow[j];
          ca_sum += abs_a[i * s + j] * capow[j];
        }
        const R ck = cpow[i] * c1[i], cak = capow[i] * ca[i];
        worst_c = std::max(worst_c, detail::relative_residual(R(cs - ck / R(k)), R(ca_sum + cak / R(k)), k));
      }
      for (std::size_t j = 0; j < s; ++j) {
        R ds = 0, da = 0;
        for (std::size_t i = 0; i < s; ++i) {
          ds += t.b[i] * cpow[i] * t.a[i][j];
          da += abs(t.b[i]) * capow[i] * abs_a[i * s + j];
        }
        const R rhs = t.b[j] * (R(1) - cpow[j] * c1[j]) / R(k);
        worst_d = std::max(worst_d, detail::relative_residual(R(ds - rhs), R(da + abs(t.b[j]) * (1 + capow[j] * ca[j]) / R(k)), k + 1));
      }
      out.c_relative.push_back(worst_c);
      out.d_relative.push_back(worst_d);
    }
    for (std::size_t i = 0; i < s; ++i) {
      cpow[i] *= c1[i];
      capow[i] *= ca[i];
    }
  }
  for (std::size_t i = 0; i < s; ++i) {
    R sum = 0;
    for (std::size_t j = 0; j < s; ++j) sum += t.a[i][j];
    out.row_sum = std::max(out.row_sum, static_cast<double>(R(abs(R(sum - t.c[i])))));
  }
  // Stage order: C(q) for q = 1, 2, ..., to the precision given and to R's rounding; with
  // B(q) as well in the second definition.
  for (int q = 1; q <= static_cast<int>(out.c_relative.size()); ++q) {
    const double worst = out.c_relative[std::size_t(q - 1)];
    if (worst <= out.exact_tolerance && out.stage_order_exact == q - 1) out.stage_order_exact = q;
    if (worst > out.tolerance) break;
    out.stage_order = q;
  }
  out.stage_order_bc = std::min(out.stage_order, out.largest(out.b_relative, out.tolerance));
  for (std::size_t i = 0; i < s; ++i)
    for (std::size_t j = 0; j < s; ++j) {
      const R& bi = t.b[i];
      const R& bj = t.b[j];
      const R m = bi * t.a[i][j] + bj * t.a[j][i] - bi * bj;
      out.symplectic = std::max(out.symplectic, static_cast<double>(R(abs(m))));
      out.symplectic_relative = std::max(
          out.symplectic_relative,
          detail::relative_residual(m, R(abs(bi * t.a[i][j]) + abs(bj * t.a[j][i]) + abs(bi * bj)), 2));
      const R sym = t.a[s - 1 - i][s - 1 - j] + t.a[i][j] - bj;
      out.symmetric = std::max(out.symmetric, static_cast<double>(R(abs(sym))));
      out.symmetric_relative = std::max(
          out.symmetric_relative,
          detail::relative_residual(sym, R(abs(t.a[s - 1 - i][s - 1 - j]) + abs(t.a[i][j]) + abs(bj)), 1));
    }
  for (std::size_t i = 0; i < s; ++i) {
    const R d = t.b[s - 1 - i] - t.b[i];
    out.symmetric = std::max(out.symmetric, static_cast<double>(R(abs(d))));
    out.symmetric_relative = std::max(
        out.symmetric_relative, detail::relative_residual(d, R(abs(t.b[s - 1 - i]) + abs(t.b[i])), 1));
  }
  return out;
}

}  // namespace mechcheck::audit
