#pragma once
/// The Jacobian of a map by finite differences, with an error model: for steppers that
/// cannot run on AD scalars (black boxes, double-only libraries).
///
/// Column j of M = dZ/dz at z is the central difference D(d) = (Z(z + d e_j) -
/// Z(z - d e_j)) / (2d) = M e_j + c d^2 + O(d^4), improved by Richardson extrapolation
/// R(d) = (4 D(d/2) - D(d)) / 3 = M e_j + O(d^4). The result is R(d/2); its error model,
/// per entry, is
///   truncation  |R(d) - R(d/2)| / 15   (the d^4 terms of R(d) and R(d/2) differ by 15/16
///                                       of R(d)'s; R(d/2)'s is 1/16 of it), plus
///   rounding    6 rho / d              (each value of Z is off by rho = k eps |Z|_max, a
///                                       difference quotient at step d' by rho / d', and
///                                       R(d/2) = (4 D(d/4) - D(d/2)) / 3 adds them up to
///                                       (4 * 4 + 2) rho / (3 d) = 6 rho / d).
/// The step d = 2^-10 |z| (at least 2^-10) balances the d^4 truncation against the
/// rounding's 1/d near d ~ eps^(1/5) for a map of unit scale; it is a power of two, so
/// z +- d e_j is exact where |z_j| <= |z|.

#include <algorithm>
#include <cmath>
#include <functional>

#include "mechcheck/core.hpp"

namespace mechcheck::audit {

/// A Jacobian and the resolution of each entry (absolute).
template <class T>
struct fd_jacobian {
  dynamic_matrix<T> value;
  dynamic_matrix<double> error;  ///< the error model's bound per entry
  double step = 0;               ///< the difference step d
};

/// dZ/dz at z of map(z) -> Z by Richardson-extrapolated central differences.
/// `rounding_units` is k in rho = k eps |Z|_max, the rounding of one evaluation of the map
/// (for a step of m evaluations, 4 (m + 1): one rounding per evaluation and per update,
/// with margin 4).
template <class T>
fd_jacobian<T> finite_difference_jacobian(
    const std::function<dynamic_vector<T>(const dynamic_vector<T>&)>& map,
    const dynamic_vector<T>& z, double rounding_units) {
  using std::abs;
  using std::max;
  const Eigen::Index n = z.size();
  const double scale = std::max(1.0, static_cast<double>(T(z.cwiseAbs().maxCoeff())));
  const T d = T(std::ldexp(scale, -10));
  const dynamic_vector<T> z0 = map(z);
  const auto difference = [&](Eigen::Index j, const T& step) {
    dynamic_vector<T> plus = z, minus = z;
    plus(j) += step;
    minus(j) -= step;
    const T taken = T(plus(j) - minus(j)) / 2;  // the step actually represented
    return dynamic_vector<T>((map(plus) - map(minus)) / (2 * taken));
  };
  fd_jacobian<T> out;
  out.value = dynamic_matrix<T>(z0.size(), n);
  out.error = dynamic_matrix<double>(z0.size(), n);
  out.step = static_cast<double>(d);
  double size = static_cast<double>(T(z0.cwiseAbs().maxCoeff()));
  for (Eigen::Index j = 0; j < n; ++j) {
    const dynamic_vector<T> d1 = difference(j, d), d2 = difference(j, T(d / 2)),
                            d4 = difference(j, T(d / 4));
    const dynamic_vector<T> r1 = (4 * d2 - d1) / 3, r2 = (4 * d4 - d2) / 3;
    out.value.col(j) = r2;
    for (Eigen::Index i = 0; i < z0.size(); ++i) {
      const double truncation = static_cast<double>(T(abs(T(r1(i) - r2(i))))) / 15;
      out.error(i, j) = truncation;
    }
  }
  const double eps = static_cast<double>(tier_epsilon<T>());
  const double rounding = 6 * rounding_units * eps * size / out.step;
  out.error.array() += rounding;
  return out;
}

/// The resolution of det M for a 2 x 2 matrix whose entries carry errors E: det is linear
/// in each entry with its cofactor as coefficient, so |d det| <= |m11| e00 + |m00| e11 +
/// |m10| e01 + |m01| e10 to first order in E.
template <class Matrix>
double determinant_resolution(const Matrix& m, const Matrix& e) {
  using std::abs;
  return static_cast<double>(abs(m(1, 1)) * e(0, 0) + abs(m(0, 0)) * e(1, 1) + abs(m(1, 0)) * e(0, 1) +
                             abs(m(0, 1)) * e(1, 0));
}

}  // namespace mechcheck::audit
