#pragma once
/// The order conditions of a Runge-Kutta tableau by rooted trees (Butcher's theory): a
/// method has order p when, for every rooted tree t with |t| <= p nodes,
///     Phi(t) = b^T g(t) = 1 / gamma(t),
/// where g(t)_i = prod over the root's subtrees u of (A g(u))_i (g of the one-node tree is
/// the vector of ones) is the elementary weight's stage vector, and the density gamma(t) =
/// |t| prod gamma(u). The trees are enumerated here: a tree is its root's multiset of
/// subtrees, generated in canonical order (each multiset once), and checked in the tests
/// against the known counts 1, 1, 2, 4, 9, 20, 48, 115, 286, 719 (orders 1-10, OEIS
/// A000081) and densities (the bushy tree of order n: n; the tall tree: n!).
///
/// Evaluated in a wide tier (mpfr100 for the audit), the residuals say to what precision a
/// table's coefficients satisfy each order: "order 4 exactly" (residuals at that tier's
/// rounding) is told from "order 4 to 1e-11" (a coefficient typed to 11 digits).

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "mechcheck/core.hpp"
#include "mechcheck/integrators/runge_kutta.hpp"

namespace mechcheck::audit {

/// A rooted tree: the ids of its root's subtrees (non-decreasing), its order and density.
struct rooted_tree {
  std::vector<int> children;
  int order = 1;
  double density = 1;  ///< gamma(t); exact in double up to order 10 (10! < 2^53)
};

/// Every rooted tree of order 1..max_order, grouped by order and in canonical order; a
/// child id always precedes its parent's.
inline const std::vector<rooted_tree>& rooted_trees(int max_order = 10) {
  static std::vector<rooted_tree> trees;
  static int built = 0;
  if (built >= max_order) return trees;
  if (trees.empty()) trees.push_back({{}, 1, 1});
  // Trees of order n: a multiset of subtrees whose orders sum to n - 1, chosen with
  // non-decreasing ids so that each multiset appears once.
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
        if (trees[std::size_t(id)].order > remaining) continue;
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

/// The order conditions of a tableau in the real type R.
template <class R>
struct order_condition_report {
  std::vector<double> residual;  ///< residual[k - 1]: max |Phi(t) - 1/gamma(t)| over |t| = k
  int max_order = 0;             ///< the orders evaluated (1..max_order)
  double row_sum = 0;            ///< max_i |sum_j a_ij - c_i|
  int stage_order = 0;  ///< the largest q with sum_j a_ij c_j^(k-1) = c_i^k / k, k <= q, to `tolerance`
  int stage_order_exact = 0;  ///< the same to `exact_tolerance`
  double symplectic = 0;  ///< max |b_i a_ij + b_j a_ji - b_i b_j| (0: symplectic)
  double symmetric = 0;   ///< max |a_(s+1-i, s+1-j) + a_ij - b_j| and |b_(s+1-i) - b_i|
  /// The relative precision the coefficients are given to (0: exact; 5e-61 for 60 decimal
  /// digits; 2^-53 for double).
  double precision = 0;
  /// What counts as satisfied to R's rounding: 64 eps(R) max(1, |coefficients|) -- a
  /// condition sums products of a few coefficients, each rounded once in R.
  double exact_tolerance = 0;
  /// What counts as satisfied at the precision given: 64 max(eps(R), precision) max(1,
  /// |coefficients|), the same budget with the coefficients' own rounding.
  double tolerance = 0;

  /// The largest p with every order <= p satisfied to `below` (0: not even consistent).
  int order(double below) const {
    int p = 0;
    while (p < max_order && residual[std::size_t(p)] <= below) ++p;
    return p;
  }
  /// The largest residual over orders 1..p.
  double up_to(int p) const {
    double r = 0;
    for (int k = 0; k < p && k < max_order; ++k) r = std::max(r, residual[std::size_t(k)]);
    return r;
  }
};

/// Evaluates the order conditions of (A, b, c) up to max_order in R, for coefficients
/// given to the relative `precision` (0: exact).
template <class R>
order_condition_report<R> order_conditions(const butcher_tableau<R>& t, int max_order = 10,
                                           double precision = 0) {
  using std::abs;
  t.validate("order_conditions");
  const int s = t.stages();
  const auto& trees = rooted_trees(max_order);
  std::vector<std::vector<R>> g(trees.size());
  order_condition_report<R> out;
  out.max_order = max_order;
  out.residual.assign(std::size_t(max_order), 0.0);
  R largest = 1;
  for (int i = 0; i < s; ++i) {
    largest = std::max<R>(largest, R(abs(t.b[std::size_t(i)])));
    for (int j = 0; j < s; ++j) largest = std::max<R>(largest, R(abs(t.a[std::size_t(i)][std::size_t(j)])));
  }
  if (!(precision >= 0 && std::isfinite(precision)))
    throw domain_error("order_conditions: the coefficients' precision must be >= 0 and finite, got " +
                       std::to_string(precision));
  out.precision = precision;
  const double eps_r = static_cast<double>(std::numeric_limits<R>::epsilon());
  out.exact_tolerance = 64 * eps_r * static_cast<double>(largest);
  out.tolerance = 64 * std::max(eps_r, precision) * static_cast<double>(largest);
  for (std::size_t k = 0; k < trees.size(); ++k) {
    const rooted_tree& tree = trees[k];
    if (tree.order > max_order) break;
    std::vector<R> v(std::size_t(s), R(1));
    for (const int child : tree.children) {
      const std::vector<R>& gc = g[std::size_t(child)];
      for (int i = 0; i < s; ++i) {
        R ag = 0;
        for (int j = 0; j < s; ++j) ag += t.a[std::size_t(i)][std::size_t(j)] * gc[std::size_t(j)];
        v[std::size_t(i)] *= ag;
      }
    }
    R phi = 0;
    for (int i = 0; i < s; ++i) phi += t.b[std::size_t(i)] * v[std::size_t(i)];
    const double r = static_cast<double>(R(abs(R(phi - R(1) / R(tree.density)))));
    double& slot = out.residual[std::size_t(tree.order - 1)];
    slot = std::max(slot, r);
    g[k] = std::move(v);
  }
  for (int i = 0; i < s; ++i) {
    R sum = 0;
    for (int j = 0; j < s; ++j) sum += t.a[std::size_t(i)][std::size_t(j)];
    out.row_sum = std::max(out.row_sum, static_cast<double>(R(abs(R(sum - t.c[std::size_t(i)])))));
  }
  // Stage order: C(q) for q = 1, 2, ..., to the precision given and to R's rounding.
  for (int q = 1; q <= s + 1; ++q) {
    double worst = 0;
    for (int i = 0; i < s; ++i) {
      R sum = 0;
      for (int j = 0; j < s; ++j) {
        R power = 1;
        for (int e = 1; e < q; ++e) power *= t.c[std::size_t(j)];
        sum += t.a[std::size_t(i)][std::size_t(j)] * power;
      }
      R ci = 1;
      for (int e = 0; e < q; ++e) ci *= t.c[std::size_t(i)];
      worst = std::max(worst, static_cast<double>(R(abs(R(sum - ci / R(q))))));
    }
    if (worst <= out.exact_tolerance && out.stage_order_exact == q - 1) out.stage_order_exact = q;
    if (worst > out.tolerance) break;
    out.stage_order = q;
  }
  for (int i = 0; i < s; ++i)
    for (int j = 0; j < s; ++j) {
      const R& bi = t.b[std::size_t(i)];
      const R& bj = t.b[std::size_t(j)];
      const R m = bi * t.a[std::size_t(i)][std::size_t(j)] + bj * t.a[std::size_t(j)][std::size_t(i)] - bi * bj;
      out.symplectic = std::max(out.symplectic, static_cast<double>(R(abs(m))));
      const R sym = t.a[std::size_t(s - 1 - i)][std::size_t(s - 1 - j)] + t.a[std::size_t(i)][std::size_t(j)] - bj;
      out.symmetric = std::max(out.symmetric, static_cast<double>(R(abs(sym))));
    }
  for (int i = 0; i < s; ++i)
    out.symmetric = std::max(
        out.symmetric, static_cast<double>(R(abs(R(t.b[std::size_t(s - 1 - i)] - t.b[std::size_t(i)])))));
  return out;
}

}  // namespace mechcheck::audit
