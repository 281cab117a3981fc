#include <utility>
#include <vector>

#include "mechcheck/robots/floating.hpp"
#include "mechcheck/robots/recursive.hpp"
#include "robots/robots.hpp"

namespace {
using namespace mechcheck::laws::robots;

/// A random robot of at most 3 moving links on a floating base (6 + 3 coordinates: the mpfr50
/// tier's nested AD of L takes 0.1 s a case, 0.3 s with three links), with armature and
/// damping, in T.
template <class T>
struct floating_sample {
  gen::floating_robot_case c;
  rb::robot_model<T> model;
  rb::base_pose<T> base;
  dynamic_vector<T> q, u, udot, force;
  int links;
  explicit floating_sample(gen::floating_robot_case fc)
      : c(std::move(fc)), model(c.joints.robot), base(rb::base_pose_from<T>(c.base)), q(gen::to_tier<T>(c.joints.q)),
        u(model.dofs() + 6), udot(model.dofs() + 6), force(model.dofs() + 6), links(model.dofs() + 1) {
    u << gen::to_tier<T>(c.twist), gen::to_tier<T>(c.joints.qdot);
    udot << gen::to_tier<T>(c.twist_rate), gen::to_tier<T>(c.joints.qddot);
    force << gen::to_tier<T>(c.wrench), gen::to_tier<T>(c.joints.tau);
    RC_TAG(std::to_string(model.dofs()) + (model.dofs() == 1 ? " joint" : " joints") + " on a floating base");
  }
};

rc::Gen<gen::floating_robot_case> floating_cases() { return gen::floating_robot_cases(dressed_robot_cases(3)); }

/// The size of the terms the floating equations of motion sum: term_scales from the base's
/// distance to the world's origin (the recursive side works about that origin), the largest
/// component of u and of udot.
template <class T>
struct floating_scales {
  T inertia, momentum, forces, generalized_force;
  explicit floating_scales(const floating_sample<T>& s, const dynamic_matrix<T>& mass) {
    using std::abs;
    const rb::robot_model<T>& m = s.model;
    T vmax = T(0), amax = T(0), rotor = T(0), damping = T(0);
    for (Eigen::Index i = 0; i < s.u.size(); ++i) {
      vmax = std::max<T>(vmax, T(abs(s.u(i))));
      amax = std::max<T>(amax, T(abs(s.udot(i))));
    }
    for (std::size_t k = 0; k < m.armature.size(); ++k) {
      rotor = std::max<T>(rotor, m.armature[k]);
      damping = std::max<T>(damping, m.damping[k]);
    }
    const rb::term_scale ts = rb::term_scales(m, gen::to_tier<double>(s.c.joints.q), s.c.base.xyz.norm());
    inertia = std::max<T>(max_abs(mass), T(ts.inertia + ts.mass) + rotor);
    momentum = inertia * T(double(s.u.size())) * vmax;
    forces = T(ts.gravity) + inertia * vmax * vmax + damping * vmax;
    generalized_force = forces + inertia * T(double(s.u.size())) * amax;
  }
};

struct floating_base_dynamics {
  static law_info info() {
    return {"robots.floating_base_dynamics",
            "On a floating base, in the base's body twist u = (v_b; w_b; qdot): Newton-Euler's Q = M udot + h "
            "and the composite rigid bodies' M equal the Euler-Lagrange equations' in a chart of SE(3) about "
            "the pose (where udot is the chart's acceleration), and M's base block is the robot's spatial "
            "inertia about the base's origin by the parallel-axis theorem (eq 160), armature and damping "
            "included",
            {"1", "160"}};
  }
  // As robots.recursive_dynamics (k = 128 n on the terms, n the links with the base), the
  // levers measured from the world's origin, which the base is up to sqrt 3 from; the base's
  // linear rows carry sum m where the angular ones carry sum m r^2 (ts.mass added).
  template <class T>
  static void property() {
    const floating_sample<T> s(*floating_cases());
    const rb::robot_model<T>& m = s.model;
    const rb::motion_terms<T> e = rb::floating_motion_terms_at(m, s.base, s.q, s.u);
    const dynamic_matrix<T> mass = rb::floating_recursive_mass_matrix(m, s.base, s.q);
    const dynamic_vector<T> bias = rb::floating_recursive_bias(m, s.base, s.q, s.u);
    const dynamic_vector<T> q_force = rb::floating_recursive_inverse_dynamics(m, s.base, s.q, s.u, s.udot);
    const dynamic_matrix<T> spatial = rb::base_spatial_inertia(m, s.base, s.q);
    const floating_scales<T> sc(s, e.mass_matrix);
    const double k = 128.0 * s.links;
    const Eigen::Index n = s.u.size();
    for (Eigen::Index i = 0; i < n; ++i) {
      const std::string at = "(" + std::to_string(i);
      for (Eigen::Index j = 0; j < n; ++j) {
        const std::string ij = at + "," + std::to_string(j) + ")";
        check_close("composite rigid bodies' M" + ij + " = d2T/du2", mass(i, j), e.mass_matrix(i, j), sc.inertia, k);
        if (i < 6 && j < 6)
          check_close("the spatial inertia" + ij + " = M's base block", spatial(i, j), e.mass_matrix(i, j), sc.inertia, k);
      }
      check_close("Newton-Euler's h" + at + ") = the Euler-Lagrange bias", bias(i), e.bias(i), sc.forces, k);
    }
    const dynamic_vector<T> lagrange = e.mass_matrix * s.udot + e.bias;
    for (Eigen::Index i = 0; i < n; ++i)
      check_close("Newton-Euler's Q(" + std::to_string(i) + ") = M udot + h", q_force(i), lagrange(i),
                  sc.generalized_force, k + 2.0 * double(n));
  }
};
MECHCHECK_LAW(floating_base_dynamics);

struct floating_momentum {
  static law_info info() {
    return {"robots.floating_momentum",
            "A robot on a floating base, moved by its joints' torques and damping (internal forces), a wrench "
            "on its base and gravity: the rate of its total momentum P is the external force, m g + R f_b, and "
            "of its angular momentum about the world's origin the external moment, c x m g + p x R f_b + "
            "R n_b, and M u's base rows are that momentum in the base's frame (about its origin); in zero gravity with no wrench both are conserved, and the centre of mass, P / m, moves "
            "uniformly (Noether, eqs 73-76 and 79-81)",
            {"75", "76", "79", "81", "83"}};
  }
  // The rates are the base rows of M udot + h - Q turned into the world (R, and the moment
  // moved from the base's origin p to the world's: |p| <= sqrt 3) at udot = M^-1 (Q - h):
  // a Cholesky solve's backward error, within k n eps of |M| |udot| (no cond(M)), beside the
  // terms of h and Q; the rate's own kinematics (forward AD along the chart) within the
  // same k = 128 n on those terms.
  template <class T>
  static void property() {
    floating_sample<T> s(*floating_cases());
    using std::abs;
    const bool free = *rc::gen::arbitrary<bool>();
    if (free) {
      s.model.gravity = vector3<T>::Zero();
      s.force.head(6).setZero();
      RC_TAG("zero gravity, no wrench");
    }
    const rb::robot_model<T>& m = s.model;
    const dynamic_vector<T> udot = rb::floating_forward_dynamics(m, s.base, s.q, s.u, s.force);
    const dynamic_vector<T> rate = rb::floating_momentum_rate(m, s.base, s.q, s.u, udot);
    // The external wrench: gravity on each link's mass at its centre, and the base's.
    const dynamic_vector<T> rest = dynamic_vector<T>::Zero(s.u.size());
    const auto centre = rb::detail::momenta_of(m, rb::link_states(m, s.q, dynamic_vector<T>(rest.tail(m.dofs())),
                                                                  rb::detail::floating_root(s.base, rest)));
    const vector3<T> f = s.base.rotation * rb::detail::segment3(s.force, 0);
    const vector3<T> n_b = s.base.rotation * rb::detail::segment3(s.force, 3);
    const vector3<T> weight = m.gravity * centre.mass;
    const vector3<T> force = weight + f;
    const vector3<T> moment = centre.first_moment.cross(m.gravity) + s.base.position.cross(f) + n_b;
    // |udot| and the scales of M and h at it.
    floating_sample<T> at_udot = s;
    at_udot.udot = udot;
    const dynamic_matrix<T> mass = rb::floating_recursive_mass_matrix(m, s.base, s.q);
    const floating_scales<T> sc(at_udot, mass);
    // The base rows of M u (dT/du, the power of a base force on u) are the momentum in the
    // base's frame: R^T P and R^T L about the base's origin, L_O - p x P (eqs 82-83).
    const dynamic_vector<T> world = rb::floating_momentum(m, s.base, s.q, s.u);
    const vector3<T> p_world = rb::detail::segment3(world, 0), l_world = rb::detail::segment3(world, 3);
    const matrix3<T> rt = s.base.rotation.transpose();
    const vector3<T> p_base = rt * p_world, l_base = rt * vector3<T>(l_world - s.base.position.cross(p_world));
    const dynamic_vector<T> generalized_momentum = mass * s.u;
    T wrench = T(0);
    for (Eigen::Index i = 0; i < s.force.size(); ++i) wrench = std::max<T>(wrench, T(abs(s.force(i))));
    const T scale = sc.generalized_force + wrench * T(3);
    const double k = 128.0 * s.links;
    for (int i = 0; i < 3; ++i) {
      const std::string axis(1, "xyz"[i]);
      check_close("dP" + axis + "/dt = the external force", rate(i), force(i), scale, k);
      check_close("dL" + axis + "/dt = the external moment about the origin", rate(3 + i), moment(i), scale, k);
      check_close("(M u)'s linear row " + axis + " = R^T P", generalized_momentum(i), p_base(i), sc.momentum, k);
      check_close("(M u)'s angular row " + axis + " = R^T L about the base", generalized_momentum(3 + i), l_base(i),
                  sc.momentum, k);
    }
  }
};
MECHCHECK_LAW(floating_momentum);

/// The base's pose at t under a constant body twist u = (v_b; w_b) (udot = 0), in the AD
/// scalar S of t: R(t) = R0 Exp(t w_b) by Rodrigues' formula, p(t) = p0 + t R0 v_b + t^2/2 R0
/// (w_b x v_b), exact to second order at t = 0 (pdot = R v_b, pddot = d/dt (R v_b) = R (w_b x
/// v_b)).
template <class S, class T>
rb::base_pose<S> base_along(const rb::base_pose<T>& b, const dynamic_vector<T>& u, const S& t) {
  using std::cos;
  using std::sin;
  using std::sqrt;
  const mc::vector3<T> v(u(0), u(1), u(2)), w(u(3), u(4), u(5));
  const T theta = sqrt(T(w.squaredNorm()));
  mc::matrix3<T> k;
  k << T(0), -w(2), w(1), w(2), T(0), -w(0), -w(1), w(0), T(0);
  const mc::matrix3<T> k2 = k * k;
  S a = mc::lift<S>(0), c = mc::lift<S>(0);
  if (theta > 0) {
    a = sin(t * mc::lift<S>(theta)) / mc::lift<S>(theta);
    c = (mc::lift<S>(1) - cos(t * mc::lift<S>(theta))) / mc::lift<S>(T(theta * theta));
  }
  const mc::vector3<T> first = b.rotation * v, second = b.rotation * mc::vector3<T>(w.cross(v));
  rb::base_pose<S> out;
  for (int i = 0; i < 3; ++i) {
    out.position(i) = mc::lift<S>(b.position(i)) + t * mc::lift<S>(first(i)) + t * t * mc::lift<S>(T(second(i) / 2));
    for (int j = 0; j < 3; ++j) {
      S e = mc::lift<S>(T(i == j ? 1 : 0)) + a * mc::lift<S>(k(i, j)) + c * mc::lift<S>(k2(i, j));
      out.rotation(i, j) = e;
    }
  }
  out.rotation = mc::matrix3<S>(rb::detail::times(rb::detail::lifted<S>(b.rotation), out.rotation));
  return out;
}

/// Link l's origin and rotation (12 numbers, rotation row by row) at t along the motion: the
/// base along its twist, the joints along q + t qdot.
template <class S, class T>
dynamic_vector<S> link_pose_along(const floating_sample<T>& s, const S& t, std::size_t l) {
  const Eigen::Index n = s.q.size();
  dynamic_vector<S> q(n), still = dynamic_vector<S>::Constant(n, mc::lift<S>(0));
  for (Eigen::Index i = 0; i < n; ++i) q(i) = mc::lift<S>(s.q(i)) + t * mc::lift<S>(s.u(6 + i));
  const dynamic_vector<S> rest = dynamic_vector<S>::Constant(6, mc::lift<S>(0));
  const rb::link_state<S> st =
      rb::link_states(s.model, q, still, rb::detail::floating_root(base_along(s.base, s.u, t), rest))[l];
  dynamic_vector<S> out(12);
  for (int i = 0; i < 3; ++i) out(i) = st.origin(i);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) out(3 + 3 * i + j) = st.rotation(i, j);
  return out;
}

/// The lengths and speeds of a floating sample's motion: lengths within L = 1 + |p| + the
/// joints' offsets and slides, speeds within v = the sum of |u|.
template <class T>
std::pair<double, double> motion_scales(const floating_sample<T>& s) {
  double length = 1 + s.c.base.xyz.norm(), speed = 0;
  for (std::size_t j = 0; j < s.c.joints.robot.joints.size(); ++j) {
    length += s.c.joints.robot.joints[j].origin.xyz.norm();
    const int k = s.model.tree.coordinate[j];
    if (k >= 0 && s.c.joints.robot.joints[j].type == rb::joint_type::prismatic) length += std::abs(s.c.joints.q[std::size_t(k)]);
  }
  for (Eigen::Index i = 0; i < s.u.size(); ++i) speed += std::abs(static_cast<double>(s.u(i)));
  return {length, speed};
}

struct floating_jacobian {
  static law_info info() {
    return {"robots.floating_jacobian",
            "On a floating base, each link's twist at u = (v_b; w_b; qdot) (the geometric Jacobian times u) is the "
            "derivative of its pose along the motion -- the base along its body twist, the joints along q + t qdot "
            "-- and Jdot u, the links' accelerations at udot = 0 (the base's origin R (w_b x v_b)), is the second "
            "derivative (eqs 123, 126-129)",
            {"123", "126", "127", "128", "129"}};
  }
  template <class T>
  static void property() {
    const floating_sample<T> s(*floating_cases());
    const rb::robot_model<T>& m = s.model;
    const Eigen::Index n = s.q.size();
    const dynamic_vector<T> qdot = s.u.tail(n), still = dynamic_vector<T>::Zero(n);
    const std::vector<rb::link_state<T>> states = rb::link_states(m, s.q, qdot, rb::detail::floating_root(s.base, s.u));
    const mc::vector3<T> v_b(s.u(0), s.u(1), s.u(2)), w_b(s.u(3), s.u(4), s.u(5));
    const rb::detail::link_acceleration<T> root{mc::vector3<T>::Zero(), mc::vector3<T>(s.base.rotation * mc::vector3<T>(w_b.cross(v_b)))};
    const std::vector<rb::detail::link_acceleration<T>> accelerations =
        rb::detail::link_accelerations(m, states, s.q, qdot, still, root);
    // Scales: velocities within v L, accelerations v^2 L (motion_scales).
    const std::pair<double, double> motion = motion_scales(s);  // named: Clang 14 captures no binding
    const double length = motion.first, speed = motion.second;
    const T velocity_scale = T(std::max(speed * length, 1e-300)), acceleration_scale = T(std::max(speed * speed * length, 1e-300));
    const double k = 64.0 * s.links;
    for (std::size_t l = 0; l < m.description.links.size(); ++l) {
      const dynamic_vector<T> pose = link_pose_along(s, T(0), l);
      const dynamic_vector<T> rate =
          mc::jacobian([&](const dynamic_vector<mc::ad<T>>& t) -> dynamic_vector<mc::ad<T>> { return link_pose_along(s, t(0), l); },
                       dynamic_vector<T>(dynamic_vector<T>::Zero(1)))
              .col(0);
      dynamic_vector<T> second(12);
      for (int c = 0; c < 12; ++c)
        second(c) = mc::second_order_expansion(
                        [&](const dynamic_vector<mc::ad<mc::ad<T>>>& t) -> mc::ad<mc::ad<T>> { return link_pose_along(s, t(0), l)(c); },
                        dynamic_vector<T>(dynamic_vector<T>::Zero(1)))
                        .hessian(0, 0);
      const mc::matrix3<T> r = rotation_of(pose);
      const mc::vector3<T> omega = vee_antisymmetric<T>(mc::matrix3<T>(rotation_of(rate) * r.transpose()));
      const mc::vector3<T> alpha = vee_antisymmetric<T>(mc::matrix3<T>(rotation_of(second) * r.transpose()));
      const std::string at = "link " + m.description.links[l].name;
      for (int i = 0; i < 3; ++i) {
        const std::string c = "(" + std::to_string(i) + ")";
        check_close(at + ": v_o" + c + " = d/dt o", states[l].velocity(i), rate(i), velocity_scale, k);
        check_close(at + ": omega" + c + " = vee(dR/dt R^T)", states[l].omega(i), omega(i), velocity_scale, k);
        check_close(at + ": (Jdot u)_a" + c + " = d2/dt2 o", accelerations[l].accel(i), second(i), acceleration_scale, 2 * k);
        check_close(at + ": (Jdot u)_alpha" + c + " = vee(d2R/dt2 R^T)", accelerations[l].alpha(i), alpha(i),
                    acceleration_scale, 2 * k);
      }
    }
  }
};
MECHCHECK_LAW(floating_jacobian);


/// The centre of mass at t along the motion: the base along its body twist, the joints along
/// q + t qdot.
template <class S, class T>
mc::vector3<S> com_along(const floating_sample<T>& s, const S& t) {
  const Eigen::Index n = s.q.size();
  dynamic_vector<S> q(n), still = dynamic_vector<S>::Constant(n, mc::lift<S>(0));
  for (Eigen::Index i = 0; i < n; ++i) q(i) = mc::lift<S>(s.q(i)) + t * mc::lift<S>(s.u(6 + i));
  const dynamic_vector<S> rest = dynamic_vector<S>::Constant(6, mc::lift<S>(0));
  const std::vector<rb::link_state<S>> links =
      rb::link_states(s.model, q, still, rb::detail::floating_root(base_along(s.base, s.u, t), rest));
  T total = T(0);
  for (const T& mi : s.model.mass) total += mi;
  mc::vector3<S> c(mc::lift<S>(0), mc::lift<S>(0), mc::lift<S>(0));
  for (std::size_t l = 0; l < links.size(); ++l) {
    if (!(s.model.mass[l] > 0)) continue;
    const mc::vector3<S> x = links[l].origin + rb::detail::times(links[l].rotation, rb::detail::lifted<S>(s.model.com[l]));
    c += x * mc::lift<S>(T(s.model.mass[l] / total));
  }
  return c;
}

struct floating_centroidal {
  static law_info info() {
    return {"robots.floating_centroidal",
            "On a floating base, in the base's body twist u: A_G u gives the links' total momentum, which is the "
            "mass times d/dt c along the motion (J_c u the same), and their angular momentum about the centre of "
            "mass, which with c x P is their angular momentum about the world's origin, sum (R I R^T omega + m x x "
            "v) (eqs 79-83)",
            {"79", "80", "81", "82", "83"}};
  }
  // As robots.centroidal_momentum: k = 64 n on the terms, the levers from the world's origin.
  template <class T>
  static void property() {
    const floating_sample<T> s(*floating_cases());
    const rb::robot_model<T>& m = s.model;
    const Eigen::Index n = s.q.size();
    const dynamic_vector<T> h = rb::floating_centroidal_momentum_matrix(m, s.base, s.q) * s.u;
    const dynamic_vector<T> jc = rb::floating_com_jacobian(m, s.base, s.q) * s.u;
    T total = T(0);
    for (const T& mi : m.mass) total += mi;
    const dynamic_vector<T> cdot =
        mc::jacobian(
            [&](const dynamic_vector<mc::ad<T>>& t) -> dynamic_vector<mc::ad<T>> {
              const mc::vector3<mc::ad<T>> c = com_along(s, t(0));
              dynamic_vector<mc::ad<T>> out(3);
              out << c(0), c(1), c(2);
              return out;
            },
            dynamic_vector<T>(dynamic_vector<T>::Zero(1)))
            .col(0);
    // The links' momenta one by one, about the world's origin.
    const summed_momenta<T> sums(
        m, rb::link_states(m, s.q, dynamic_vector<T>(s.u.tail(n)), rb::detail::floating_root(s.base, s.u)));
    const mc::vector3<T>&about_origin = sums.about_origin, &momentum = sums.linear;
    const mc::vector3<T> c = rb::floating_centre_of_mass(m, s.base, s.q);
    const mc::vector3<T> transferred = mc::vector3<T>(h.template tail<3>()) + c.cross(mc::vector3<T>(h.template head<3>()));
    const std::pair<double, double> motion = motion_scales(s);  // named: Clang 14 captures no binding
    const double length = motion.first, speed = motion.second;
    const rb::term_scale ts = rb::term_scales(m, gen::to_tier<double>(s.c.joints.q), s.c.base.xyz.norm());
    const T linear_scale = T(std::max(ts.mass * speed * length, 1e-300));
    const T angular_scale = T(std::max((ts.inertia + ts.mass * length * length) * speed, 1e-300));
    const double k = 64.0 * s.links;
    for (int i = 0; i < 3; ++i) {
      const std::string at = "(" + std::to_string(i) + ")";
      check_close("(A_G u)_linear" + at + " = m d/dt c", h(i), T(total * cdot(i)), linear_scale, k);
      check_close("(A_G u)_linear" + at + " = sum m v", h(i), momentum(i), linear_scale, k);
      check_close("(J_c u)" + at + " = d/dt c", jc(i), cdot(i), T(linear_scale / total), 2 * k);
      check_close("(A_G u)_angular" + at + " + (c x P)" + at + " = sum (R I R^T omega + m x x v)", transferred(i),
                  about_origin(i), angular_scale, 2 * k);
    }
  }
};
MECHCHECK_LAW(floating_centroidal);

}  // namespace
