#pragma once
/// Equations of motion of one's own under audit (dynamics.hpp), in two forms:
///
///  - behind C calls (`c_dynamics`): the robot goes in as URDF text and its gravity, a handle
///    comes out, and each quantity is a function that returns 0 or the library's status
///    (C code cannot throw); judged in double like any dynamics_library;
///  - templated on the scalar (`templated_dynamics<Model>`): Model<T> is built from the
///    robot description and has any of the four quantities in T; judged in every tier
///    (double, float128, mpfr50), each against the exact Lagrangian with its own epsilon.
///
/// The residual and its scale are dynamics.hpp's, in the tier's epsilon. The budget is
/// 16 n, as for any library, and in mpfr50 16 n + 64 n: there the reference is computed in
/// the tier itself, whose nested AD rounds at most 64 n eps on the same scale (the budget of
/// the robots laws, properties/robots); in double and float128 it is mpfr50's, rounded once.

#include <algorithm>
#include <cmath>
#include <concepts>
#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "mechcheck/audit/dynamics/dynamics.hpp"
#include "mechcheck/audit/problems/urdf.hpp"
#include "mechcheck/core.hpp"

namespace mechcheck::audit {

/// A dynamics library behind C calls. `load` gets the robot as URDF text (every number to
/// 17 digits) and its gravity (URDF has none) and returns a handle, or null for a robot it
/// cannot express, with the reason written into `why` (at most why_size bytes, terminated).
/// Each quantity returns 0, or a status that is reported as the library's failure; a null
/// function is a quantity not offered. Coordinates are the robot's (its moving joints in
/// the file's order); M is written column-major, n x n.
struct c_dynamics {
  std::string name;    ///< e.g. "my_rnea"
  std::string origin;  ///< where it comes from and what it computes
  void* (*load)(const char* urdf, const double* gravity, char* why, int why_size) = nullptr;
  void (*unload)(void* handle) = nullptr;
  int (*mass_matrix)(void* handle, int n, const double* q, double* m) = nullptr;
  int (*bias)(void* handle, int n, const double* q, const double* qdot, double* h) = nullptr;
  int (*inverse)(void* handle, int n, const double* q, const double* qdot, const double* qddot, double* tau) = nullptr;
  int (*forward)(void* handle, int n, const double* q, const double* qdot, const double* tau, double* qddot) = nullptr;
};

/// The C library as a dynamics_library (domain_error when `load` is null).
dynamics_library c_dynamics_library(const c_dynamics& library);

namespace detail {

template <class T>
dynamic_vector<T> in_tier(const Eigen::VectorXd& v) {
  dynamic_vector<T> out(v.size());
  for (Eigen::Index i = 0; i < v.size(); ++i) out(i) = T(v(i));
  return out;
}

template <class T>
Eigen::MatrixXd to_double(const dynamic_matrix<T>& m) {
  Eigen::MatrixXd out(m.rows(), m.cols());
  for (Eigen::Index i = 0; i < m.size(); ++i) out(i) = static_cast<double>(m(i));
  return out;
}

/// One quantity in tier T: max |library - reference| / (eps(T) scale), the reference from
/// mpfr50 converted to T once.
template <class T>
dynamics_residual tier_residual(dynamics_quantity quantity, const dynamic_matrix<T>& library,
                                const dynamic_matrix<mpfr50>& reference, double scale, int links,
                                const std::string& who) {
  if (library.rows() != reference.rows() || library.cols() != reference.cols())
    throw library_failure(who + ": its " + dynamics_quantity_name(quantity) + " is " + std::to_string(library.rows()) +
                          "x" + std::to_string(library.cols()) + ", the robot's " + std::to_string(reference.rows()) +
                          "x" + std::to_string(reference.cols()));
  dynamics_residual r;
  r.quantity = quantity;
  r.library = to_double(library);
  r.reference = to_double(reference);
  r.scale = scale;
  const double n = static_cast<double>(std::max(links, 1));
  r.budget = std::is_same_v<T, mpfr50> ? 16.0 * n + 64.0 * n : 16.0 * n;
  T largest = T(0);
  using std::abs;
  for (Eigen::Index i = 0; i < library.size(); ++i) {
    if (!is_finite(library(i)))
      throw non_finite_error(who + ": its " + dynamics_quantity_name(quantity) + " is not finite (entry " +
                             std::to_string(i) + " = " + to_text(library(i)) + ")");
    const T d = abs(T(library(i) - T(reference(i))));
    if (d > largest) largest = d;
  }
  const double eps = static_cast<double>(tier_epsilon<T>());
  const double d = static_cast<double>(largest);
  r.residual = scale > 0 ? d / (eps * scale) : (d == 0 ? 0 : INFINITY);
  return r;
}

template <class M, class T>
concept offers_mass_matrix = requires(M& m, const dynamic_vector<T>& x) {
  { m.mass_matrix(x) } -> std::convertible_to<dynamic_matrix<T>>;
};
template <class M, class T>
concept offers_bias = requires(M& m, const dynamic_vector<T>& x) {
  { m.bias(x, x) } -> std::convertible_to<dynamic_vector<T>>;
};
template <class M, class T>
concept offers_inverse = requires(M& m, const dynamic_vector<T>& x) {
  { m.inverse(x, x, x) } -> std::convertible_to<dynamic_vector<T>>;
};
template <class M, class T>
concept offers_forward = requires(M& m, const dynamic_vector<T>& x) {
  { m.forward(x, x, x) } -> std::convertible_to<dynamic_vector<T>>;
};
template <class M, class T>
concept offers_frame_poses = requires(M& m, const dynamic_vector<T>& x) {
  { m.frame_poses(x) } -> std::convertible_to<dynamic_matrix<T>>;
};
template <class M, class T>
concept offers_frame_jacobians = requires(M& m, const dynamic_vector<T>& x) {
  { m.frame_jacobians(x) } -> std::convertible_to<dynamic_matrix<T>>;
};
template <class M, class T>
concept offers_frame_bias_accelerations = requires(M& m, const dynamic_vector<T>& x) {
  { m.frame_bias_accelerations(x, x) } -> std::convertible_to<dynamic_vector<T>>;
};

template <class M, class T>
concept offers_link_com_jacobians = requires(M& m, const dynamic_vector<T>& x) {
  { m.link_com_jacobians(x) } -> std::convertible_to<dynamic_matrix<T>>;
};
template <class M, class T>
concept offers_centre_of_mass = requires(M& m, const dynamic_vector<T>& x) {
  { m.centre_of_mass(x) } -> std::convertible_to<dynamic_vector<T>>;
};
template <class M, class T>
concept offers_com_jacobian = requires(M& m, const dynamic_vector<T>& x) {
  { m.com_jacobian(x) } -> std::convertible_to<dynamic_matrix<T>>;
};
template <class M, class T>
concept offers_centroidal_momentum_matrix = requires(M& m, const dynamic_vector<T>& x) {
  { m.centroidal_momentum_matrix(x) } -> std::convertible_to<dynamic_matrix<T>>;
};

}  // namespace detail

/// A library of one's own templated on the scalar: Model<T>(const robots::robot&) builds its
/// model of the robot in T (throw robot_refused for a robot it cannot express) and offers
/// any of
///   dynamic_matrix<T> mass_matrix(const dynamic_vector<T>& q);
///   dynamic_vector<T> bias(const dynamic_vector<T>& q, const dynamic_vector<T>& qdot);
///   dynamic_vector<T> inverse(q, qdot, qddot);
///   dynamic_vector<T> forward(q, qdot, tau);
/// (found by their signatures; at least one), and of the kinematics (dynamics_quantity's
/// layouts, the links in the robot's order)
///   dynamic_matrix<T> frame_poses(q);               12 x L
///   dynamic_matrix<T> frame_jacobians(q);           6 L x v
///   dynamic_vector<T> frame_bias_accelerations(q, qdot);   6 L: Jdot qdot
///   dynamic_matrix<T> link_com_jacobians(q);        6 L x v: at each link's centre of mass
///   dynamic_vector<T> centre_of_mass(q);            3
///   dynamic_matrix<T> com_jacobian(q);              3 x v
///   dynamic_matrix<T> centroidal_momentum_matrix(q);  6 x v: A_G, rows (P; L_G)
/// check<T> holds it in tier T to the exact Lagrangian and forward kinematics at one robot
/// and state.
template <template <class> class Model>
struct templated_dynamics {
  std::string name, origin;
  /// Whether Model sets a joint's armature and damping (robots::joint); a robot with one it
  /// does not set is refused (unset_joint_terms).
  bool sets_armature = false, sets_damping = false;
  /// As dynamics_library's: empty where Model takes a floating base in dynamics_state's layout.
  std::string no_floating_base = "its model takes robots fixed to the world only";

  template <class T>
  dynamics_check check(const robots::robot& robot, const dynamics_state& x) const {
    static_assert(detail::offers_mass_matrix<Model<T>, T> || detail::offers_bias<Model<T>, T> ||
                      detail::offers_inverse<Model<T>, T> || detail::offers_forward<Model<T>, T>,
                  "templated_dynamics: Model<T> offers none of mass_matrix, bias, inverse, forward");
    dynamics_check out;
    out.refused = unset_joint_terms(robot, name, sets_armature, sets_damping);
    if (out.refused.empty() && robot.floating && !no_floating_base.empty()) out.refused = name + ": " + no_floating_base;
    if (!out.refused.empty()) return out;
    std::optional<Model<T>> model;
    try {
      model.emplace(robot);
    } catch (const robot_refused& e) {
      out.refused = e.what();
      return out;
    }
    const reference_terms e = reference_terms_at(robot, x);
    const std::string who = name + " (" + std::string(tier_traits<T>::name) + ") on robot " + robot.name;
    const dynamic_vector<T> q = detail::in_tier<T>(x.q), qdot = detail::in_tier<T>(x.qdot);
    const int n = e.moving_links;
    if constexpr (detail::offers_mass_matrix<Model<T>, T>)
      out.residuals.push_back(detail::tier_residual<T>(dynamics_quantity::mass_matrix,
                                                       dynamic_matrix<T>(model->mass_matrix(q)), e.mass, e.scale_m, n, who));
    if constexpr (detail::offers_bias<Model<T>, T>)
      out.residuals.push_back(detail::tier_residual<T>(dynamics_quantity::bias, dynamic_matrix<T>(model->bias(q, qdot)),
                                                       dynamic_matrix<mpfr50>(e.bias), e.scale_h, n, who));
    if constexpr (detail::offers_inverse<Model<T>, T>)
      out.residuals.push_back(detail::tier_residual<T>(
          dynamics_quantity::inverse, dynamic_matrix<T>(model->inverse(q, qdot, detail::in_tier<T>(x.qddot))),
          dynamic_matrix<mpfr50>(e.tau), e.scale_tau, n, who));
    if constexpr (detail::offers_forward<Model<T>, T>)
      out.residuals.push_back(detail::tier_residual<T>(
          dynamics_quantity::forward, dynamic_matrix<T>(model->forward(q, qdot, detail::in_tier<T>(x.tau))),
          dynamic_matrix<mpfr50>(e.qddot), e.scale_forward, n, who));
    constexpr bool poses = detail::offers_frame_poses<Model<T>, T>, jacobians = detail::offers_frame_jacobians<Model<T>, T>,
                   accelerations = detail::offers_frame_bias_accelerations<Model<T>, T>,
                   com_jacobians = detail::offers_link_com_jacobians<Model<T>, T>,
                   com = detail::offers_centre_of_mass<Model<T>, T>, com_jacobian = detail::offers_com_jacobian<Model<T>, T>,
                   momentum_matrix = detail::offers_centroidal_momentum_matrix<Model<T>, T>;
    if constexpr (poses || jacobians || accelerations || com_jacobians || com || com_jacobian || momentum_matrix) {
      const kinematic_reference k = kinematic_reference_at(robot, x, accelerations);
      if constexpr (poses)
        out.residuals.push_back(detail::tier_residual<T>(dynamics_quantity::frame_poses,
                                                         dynamic_matrix<T>(model->frame_poses(q)), k.poses, k.scale,
                                                         k.moving_links, who));
      if constexpr (jacobians)
        out.residuals.push_back(detail::tier_residual<T>(dynamics_quantity::frame_jacobians,
                                                         dynamic_matrix<T>(model->frame_jacobians(q)), k.jacobians,
                                                         k.scale, k.moving_links, who));
      if constexpr (accelerations)
        out.residuals.push_back(detail::tier_residual<T>(
            dynamics_quantity::frame_bias_accelerations, dynamic_matrix<T>(model->frame_bias_accelerations(q, qdot)),
            dynamic_matrix<mpfr50>(k.bias_accelerations), k.scale_bias, k.moving_links, who));
      if constexpr (com_jacobians)
        out.residuals.push_back(detail::tier_residual<T>(dynamics_quantity::link_com_jacobians,
                                                         dynamic_matrix<T>(model->link_com_jacobians(q)),
                                                         k.com_jacobians, k.scale, k.moving_links, who));
      // A robot without mass has no centre of mass (k.com empty): nothing to hold Model's to.
      if constexpr (com)
        if (k.com.size() == 3)
          out.residuals.push_back(detail::tier_residual<T>(dynamics_quantity::centre_of_mass,
                                                           dynamic_matrix<T>(model->centre_of_mass(q)),
                                                           dynamic_matrix<mpfr50>(k.com), k.scale, k.moving_links, who));
      if constexpr (com_jacobian)
        if (k.com.size() == 3)
          out.residuals.push_back(detail::tier_residual<T>(dynamics_quantity::com_jacobian,
                                                           dynamic_matrix<T>(model->com_jacobian(q)), k.com_jacobian,
                                                           k.scale, k.moving_links, who));
      if constexpr (momentum_matrix)
        if (k.com.size() == 3)
          out.residuals.push_back(detail::tier_residual<T>(dynamics_quantity::centroidal_momentum_matrix,
                                                           dynamic_matrix<T>(model->centroidal_momentum_matrix(q)),
                                                           k.momentum_matrix, k.scale_momentum, k.moving_links, who));
    }
    return out;
  }

  /// The campaign in tier T: random robots (robot null) or the given robot at random states.
  template <class T>
  dynamics_campaign run(const dynamics_options& options, const robots::robot* robot = nullptr) const {
    const dynamics_checker check = [this](const robots::robot& r, const dynamics_state& x) { return this->template check<T>(r, x); };
    dynamics_options dressed = options;  // the joint terms Model sets
    dressed.armature = sets_armature;
    dressed.damping = sets_damping;
    return run_dynamics_checker(name + " (" + std::string(tier_traits<T>::name) + ")", origin, check, dressed, robot);
  }

  /// The campaign in every tier: double, float128, mpfr50 (the same robots and states: one
  /// seed).
  std::vector<dynamics_campaign> run_every_tier(const dynamics_options& options,
                                                const robots::robot* robot = nullptr) const {
    return {run<double>(options, robot), run<float128>(options, robot), run<mpfr50>(options, robot)};
  }
};

}  // namespace mechcheck::audit
