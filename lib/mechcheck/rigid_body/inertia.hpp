#pragma once
/// Inertia tensors (notes lectures 13-16, eqs 130-164): point clouds, the parallel-axis
/// shift, rotation, principal axes, classification and physical validity.

#include <string>
#include <vector>

#include <Eigen/Eigenvalues>

#include "mechcheck/core.hpp"

namespace mechcheck {

/// Point masses m_a at positions r_a.
template <class T>
struct point_cloud {
  std::vector<T> masses;
  std::vector<vector3<T>> positions;

  /// Throws domain_error for a non-positive or non-finite mass, non_finite_error for a
  /// non-finite position, dimension_error when the counts differ or the cloud is empty.
  void validate(const std::string& where) const {
    if (masses.size() != positions.size() || masses.empty())
      throw dimension_error(where + ": " + std::to_string(masses.size()) + " masses for " +
                            std::to_string(positions.size()) + " positions");
    for (std::size_t a = 0; a < masses.size(); ++a) {
      require_positive(masses[a], where.c_str(), ("mass " + std::to_string(a)).c_str());
      if (const auto i = first_non_finite(positions[a]); i >= 0)
        throw non_finite_error(where + ": position " + std::to_string(a) + " has component " +
                               std::to_string(i) + " = " + to_text(positions[a](i)));
    }
  }

  T total_mass() const {
    T m = 0;
    for (const T& x : masses) m += x;
    return m;
  }
};

/// Centre of mass sum m_a r_a / sum m_a (notes eq 80).
template <class T>
vector3<T> centre_of_mass(const point_cloud<T>& cloud) {
  cloud.validate("centre_of_mass");
  vector3<T> s = vector3<T>::Zero();
  for (std::size_t a = 0; a < cloud.masses.size(); ++a) s += cloud.masses[a] * cloud.positions[a];
  return s / cloud.total_mass();
}

/// I_ij = sum_a m_a (delta_ij |r_a - o|^2 - (r_a - o)_i (r_a - o)_j) about the point o
/// (notes eqs 138, 140).
template <class T>
matrix3<T> inertia_tensor(const point_cloud<T>& cloud, const vector3<T>& origin) {
  cloud.validate("inertia_tensor");
  require_finite_vector(origin, "inertia_tensor", "origin");
  matrix3<T> inertia = matrix3<T>::Zero();
  for (std::size_t a = 0; a < cloud.masses.size(); ++a) {
    const vector3<T> r = cloud.positions[a] - origin;
    inertia += cloud.masses[a] * (r.squaredNorm() * matrix3<T>::Identity() - r * r.transpose());
  }
  return inertia;
}

/// The term mu (|b|^2 delta_ij - b_i b_j) of the parallel-axis theorem (eq 160).
namespace detail {
template <class T>
void require_finite_matrix(const matrix3<T>& m, const std::string& where, const char* what) {
  for (int k = 0; k < 9; ++k)
    if (!is_finite(m(k / 3, k % 3)))
      throw non_finite_error(where + ": " + what + " entry (" + std::to_string(k / 3) + "," +
                             std::to_string(k % 3) + ") = " + to_text(m(k / 3, k % 3)));
}
}  // namespace detail

template <class T>
matrix3<T> parallel_axis_term(const T& total_mass, const vector3<T>& b) {
  require_positive(total_mass, "parallel_axis_term", "total mass");
  require_finite_vector(b, "parallel_axis_term", "offset b");
  return total_mass * (b.squaredNorm() * matrix3<T>::Identity() - b * b.transpose());
}

/// Inertia about the point c + b from the inertia about the centre of mass c (eq 160).
template <class T>
matrix3<T> shift_from_centre(const matrix3<T>& about_centre, const T& total_mass,
                             const vector3<T>& b) {
  require_positive(total_mass, "shift_from_centre", "total mass");
  detail::require_finite_matrix(about_centre, "shift_from_centre", "inertia tensor");
  require_finite_vector(b, "shift_from_centre", "offset b");
  return about_centre + parallel_axis_term(total_mass, b);
}

/// Inertia about the centre of mass c from the inertia about the point c + b.
template <class T>
matrix3<T> shift_to_centre(const matrix3<T>& about_point, const T& total_mass,
                           const vector3<T>& b) {
  require_positive(total_mass, "shift_to_centre", "total mass");
  detail::require_finite_matrix(about_point, "shift_to_centre", "inertia tensor");
  require_finite_vector(b, "shift_to_centre", "offset b");
  return about_point - parallel_axis_term(total_mass, b);
}

/// The tensor in axes rotated by R: R I R^T (notes eq 142 with O = R). Throws
/// domain_error unless R is a rotation (R R^T = I and det R = 1 to 64 eps).
template <class T>
matrix3<T> rotate(const matrix3<T>& inertia, const matrix3<T>& rotation) {
  using std::abs;
  detail::require_finite_matrix(inertia, "rotate", "inertia tensor");
  detail::require_finite_matrix(rotation, "rotate", "rotation");
  const T defect = (rotation * rotation.transpose() - matrix3<T>::Identity()).cwiseAbs().maxCoeff();
  const T det = rotation.determinant();
  if (!(defect <= 64 * tier_epsilon<T>()) || !(abs(T(det - 1)) <= 64 * tier_epsilon<T>()))
    throw domain_error("rotate: rotation is not a rotation matrix: |R R^T - I| = " +
                       to_text(defect) + ", det R = " + to_text(det));
  return rotation * inertia * rotation.transpose();
}

/// Principal moments (ascending) and axes (columns, a right-handed orthonormal basis):
/// I = axes diag(moments) axes^T (eq 142 with O = axes^T).
template <class T>
struct principal_frame {
  vector3<T> moments;
  matrix3<T> axes;
};

namespace detail {
template <class T>
principal_frame<T> principal_axes_at(const matrix3<T>& inertia, const std::string& where) {
  using std::abs;
  require_finite_matrix(inertia, where, "inertia tensor");
  // The eigensolver reads one triangle only: a non-symmetric tensor would pass silently.
  const T tol = 64 * tier_epsilon<T>() * inertia.cwiseAbs().maxCoeff();
  for (int i = 0; i < 3; ++i)
    for (int j = i + 1; j < 3; ++j)
      if (abs(T(inertia(i, j) - inertia(j, i))) > tol)
        throw domain_error(where + ": inertia tensor is not symmetric: I(" +
                           std::to_string(i) + "," + std::to_string(j) + ") = " +
                           to_text(inertia(i, j)) + " but I(" + std::to_string(j) + "," +
                           std::to_string(i) + ") = " + to_text(inertia(j, i)));
  const Eigen::SelfAdjointEigenSolver<matrix3<T>> solver(inertia);
  if (solver.info() != Eigen::Success)
    throw convergence_error(where + ": the symmetric eigensolver did not converge");
  matrix3<T> axes = solver.eigenvectors();
  if (axes.determinant() < 0) axes.col(2) = -axes.col(2);
  return {solver.eigenvalues(), axes};
}
}  // namespace detail

template <class T>
principal_frame<T> principal_axes(const matrix3<T>& inertia) {
  return detail::principal_axes_at(inertia, "principal_axes");
}

enum class top_kind { spherical, symmetric, asymmetric };

/// Spherical (I1 = I2 = I3), symmetric (two equal) or asymmetric top (notes lecture 16):
/// moments equal when they differ by at most tolerance_eps * eps(T) * I_max.
template <class T>
top_kind classify(const matrix3<T>& inertia, double tolerance_eps = 64) {
  const vector3<T> m = detail::principal_axes_at(inertia, "classify").moments;
  const T tol = T(tolerance_eps) * tier_epsilon<T>() * m.cwiseAbs().maxCoeff();
  using std::abs;
  const bool e01 = abs(T(m(1) - m(0))) <= tol, e12 = abs(T(m(2) - m(1))) <= tol;
  if (e01 && e12) return top_kind::spherical;
  if (e01 || e12) return top_kind::symmetric;
  return top_kind::asymmetric;
}

/// Physical validity of an inertia tensor: symmetric, positive semi-definite, and the
/// triangle inequality I1 + I2 >= I3 of the principal moments (eqs 154-156), each up to
/// tolerance_eps * eps(T) * |I|, so that round-off after a shift never fires. Throws
/// domain_error naming what is wrong and the offending value.
template <class T>
void validate_inertia(const matrix3<T>& inertia, const std::string& where,
                      double tolerance_eps = 64) {
  for (int k = 0; k < 9; ++k)
    if (!is_finite(inertia(k / 3, k % 3)))
      throw non_finite_error(where + ": inertia tensor entry (" + std::to_string(k / 3) + "," +
                             std::to_string(k % 3) + ") = " + to_text(inertia(k / 3, k % 3)));
  const T scale = inertia.cwiseAbs().maxCoeff();
  const T tol = T(tolerance_eps) * tier_epsilon<T>() * scale;
  for (int i = 0; i < 3; ++i)
    for (int j = i + 1; j < 3; ++j) {
      using std::abs;
      if (abs(T(inertia(i, j) - inertia(j, i))) > tol)
        throw domain_error(where + ": inertia tensor is not symmetric: I(" + std::to_string(i) +
                           "," + std::to_string(j) + ") = " + to_text(inertia(i, j)) + " but I(" +
                           std::to_string(j) + "," + std::to_string(i) + ") = " +
                           to_text(inertia(j, i)));
    }
  const vector3<T> m = detail::principal_axes_at(inertia, where).moments;
  if (m(0) < -tol)
    throw domain_error(where + ": inertia tensor is not positive semi-definite: principal moment " +
                       to_text(m(0)));
  if (m(0) + m(1) < m(2) - tol)
    throw domain_error(where + ": principal moments violate the triangle inequality I1 + I2 >= I3: " +
                       to_text(m(0)) + " + " + to_text(m(1)) + " < " + to_text(m(2)));
}

}  // namespace mechcheck
