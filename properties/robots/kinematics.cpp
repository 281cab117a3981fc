#include "mechcheck/robots/kinematics.hpp"
#include "robots/robots.hpp"

// The kinematics of robots/kinematics.hpp against the derivatives of the poses along a
// motion. The Jacobians come from the velocity recursion of link_states (each joint adds its
// axis times its rate, eqs 126-128); here the same frames' positions and rotations alone,
// differentiated by forward AD along q + t qdot, give what those velocities must be
// (eqs 121-123: a point's displacement is the origin's plus d phi x r). Tolerance: each link's
// frame composes a rotation and an offset a level, about 8 n roundings of its terms (the tree's
// lengths L = 1 + the joints' offsets, the slides and the points' offsets, against |qdot|):
// k = 64 n on |qdot| L for velocities and momenta per unit mass, |qdot|^2 L for accelerations,
// twice that where a second derivative is taken through two AD layers.

namespace {
using namespace mechcheck::laws::robots;

/// The lengths a robot's points lie within: 1 + every joint offset and slide + the largest
/// centre of mass offset + |p|.
template <class T>
double length_scale(const robot_sample<T>& s, const Eigen::Vector3d& p) {
  double l = 1 + p.norm();
  for (std::size_t j = 0; j < s.c.robot.joints.size(); ++j) {
    l += s.c.robot.joints[j].origin.xyz.norm();
    const int k = s.model.tree.coordinate[j];
    if (k >= 0 && s.c.robot.joints[j].type == rb::joint_type::prismatic) l += std::abs(s.c.q[std::size_t(k)]);
  }
  double com = 0;
  for (const auto& link : s.c.robot.links)
    if (link.body) com = std::max(com, link.body->origin.xyz.norm());
  return l + com;
}

template <class T>
double speed_scale(const robot_sample<T>& s) {
  double v = 0;
  for (double x : s.c.qdot) v = std::max(v, std::abs(x));
  return v;
}

/// Point p of link l and its rotation, at q + t qdot, as 12 numbers (x_p, then R row by row),
/// in the AD scalar S of t.
template <class S, class T>
dynamic_vector<S> pose_along(const rb::robot_model<T>& m, const dynamic_vector<T>& q, const dynamic_vector<T>& qdot,
                             const S& t, std::size_t l, const mc::vector3<T>& p) {
  const Eigen::Index n = q.size();
  dynamic_vector<S> qs(n), zero(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    const S step = t * mc::lift<S>(qdot(i));
    qs(i) = mc::lift<S>(q(i)) + step;
    zero(i) = mc::lift<S>(0);
  }
  const rb::link_state<S> st = rb::link_states(m, qs, zero)[l];
  const mc::vector3<S> x = st.origin + rb::detail::times(st.rotation, rb::detail::lifted<S>(p));
  dynamic_vector<S> out(12);
  for (int i = 0; i < 3; ++i) out(i) = x(i);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) out(3 + 3 * i + j) = st.rotation(i, j);
  return out;
}

/// A point on a link, in its frame: dyadic, exact in every tier.
Eigen::Vector3d draw_point() { return Eigen::Vector3d(*gen::dyadic(-1, 1), *gen::dyadic(-1, 1), *gen::dyadic(-1, 1)); }

template <class T>
mc::vector3<T> in_tier(const Eigen::Vector3d& x) {
  return mc::vector3<T>(T(x(0)), T(x(1)), T(x(2)));
}

struct frame_jacobian {
  static law_info info() {
    return {"robots.frame_jacobian",
            "A link's geometric Jacobian J_p (world frame, rows v_p and omega) times qdot is the derivative of the "
            "link's pose along the motion: the velocity of any point p fixed on it, d/dt (o + R p), and the "
            "angular velocity from dR/dt R^T = [omega]x (eqs 123, 126-129)",
            {"123", "126", "127", "128", "129"}};
  }
  template <class T>
  static void property() {
    const auto s = draw_robot<T>();
    const rb::robot_model<T>& m = s.model;
    const Eigen::Vector3d pd = draw_point();
    const mc::vector3<T> p = in_tier<T>(pd);
    const double v = speed_scale(s) * length_scale(s, pd);
    const T scale = T(std::max(v, 1e-300));
    const double k = 64.0 * s.links;
    for (std::size_t l = 0; l < m.description.links.size(); ++l) {
      const dynamic_vector<T> twist = rb::point_jacobian(m, s.q, int(l), p) * s.qdot;
      const dynamic_matrix<T> d = mc::jacobian(
          [&](const dynamic_vector<mc::ad<T>>& t) -> dynamic_vector<mc::ad<T>> { return pose_along(m, s.q, s.qdot, t(0), l, p); },
          dynamic_vector<T>(dynamic_vector<T>::Zero(1)));
      const dynamic_vector<T> pose = pose_along(m, s.q, s.qdot, T(0), l, p);
      const dynamic_vector<T> rate = d.col(0);
      const mc::matrix3<T> r = rotation_of(pose), rdot = rotation_of(rate);
      const mc::vector3<T> omega = vee_antisymmetric<T>(rdot * r.transpose());
      const std::string at = "link " + m.description.links[l].name;
      for (int i = 0; i < 3; ++i) {
        check_close(at + ": (J_p qdot)_v(" + std::to_string(i) + ") = d/dt (o + R p)", twist(i), rate(i), scale, k);
        check_close(at + ": (J_p qdot)_omega(" + std::to_string(i) + ") = vee(dR/dt R^T)", twist(3 + i), omega(i), scale, k);
      }
    }
  }
};
MECHCHECK_LAW(frame_jacobian);

struct bias_acceleration {
  static law_info info() {
    return {"robots.bias_acceleration",
            "Jdot_p qdot, the derivative of the twist J_p(q) qdot along the motion at fixed qdot, is the second "
            "derivative of the pose along q + t qdot: the point's acceleration d^2/dt^2 (o + R p) and the angular "
            "acceleration from the antisymmetric part of d^2R/dt^2 R^T (eqs 123, 126-128)",
            {"123", "126", "127", "128"}};
  }
  // d/dt [w]x = d/dt (Rdot R^T) = Rddot R^T + Rdot Rdot^T, the second term symmetric: the
  // antisymmetric part of Rddot R^T is [wdot]x.
  template <class T>
  static void property() {
    const auto s = draw_robot<T>();
    const rb::robot_model<T>& m = s.model;
    const Eigen::Vector3d pd = draw_point();
    const mc::vector3<T> p = in_tier<T>(pd);
    const double v = speed_scale(s);
    const double scale_d = v * v * length_scale(s, pd);
    const T scale = T(std::max(scale_d, 1e-300));
    const double k = 128.0 * s.links;
    for (std::size_t l = 0; l < m.description.links.size(); ++l) {
      const dynamic_vector<T> jdqd = rb::point_bias_acceleration(m, s.q, s.qdot, int(l), p);
      const dynamic_vector<T> pose = pose_along(m, s.q, s.qdot, T(0), l, p);
      dynamic_vector<T> second(12);
      for (int c = 0; c < 12; ++c)
        second(c) = mc::second_order_expansion(
                        [&](const dynamic_vector<mc::ad<mc::ad<T>>>& t) -> mc::ad<mc::ad<T>> {
                          return pose_along(m, s.q, s.qdot, t(0), l, p)(c);
                        },
                        dynamic_vector<T>(dynamic_vector<T>::Zero(1)))
                        .hessian(0, 0);
      const mc::vector3<T> alpha = vee_antisymmetric<T>(rotation_of(second) * rotation_of(pose).transpose());
      const std::string at = "link " + m.description.links[l].name;
      for (int i = 0; i < 3; ++i) {
        check_close(at + ": (Jdot_p qdot)_v(" + std::to_string(i) + ") = d2/dt2 (o + R p)", jdqd(i), second(i), scale, k);
        check_close(at + ": (Jdot_p qdot)_omega(" + std::to_string(i) + ") = vee(d2R/dt2 R^T)", jdqd(3 + i), alpha(i), scale,
                    k);
      }
    }
  }
};
MECHCHECK_LAW(bias_acceleration);

struct centroidal_momentum {
  static law_info info() {
    return {"robots.centroidal_momentum",
            "The centroidal momentum matrix A_G qdot gives the links' total momentum, which is the mass times the "
            "centre of mass's velocity d/dt c (eqs 79-81, J_c qdot the same), and their angular momentum about the "
            "centre of mass, which with c x P is their angular momentum about the world's origin, sum (R I R^T "
            "omega + m x x v) (eqs 82-83)",
            {"79", "80", "81", "82", "83"}};
  }
  template <class T>
  static void property() {
    const auto s = draw_robot<T>();
    const rb::robot_model<T>& m = s.model;
    const dynamic_vector<T> h = rb::centroidal_momentum_matrix(m, s.q) * s.qdot;
    const dynamic_vector<T> jc = rb::com_jacobian(m, s.q) * s.qdot;
    T total = T(0);
    for (const T& mi : m.mass) total += mi;
    // d/dt c along q + t qdot, from the positions alone.
    const auto com_along = [&](const dynamic_vector<mc::ad<T>>& t) -> dynamic_vector<mc::ad<T>> {
      using A = mc::ad<T>;
      dynamic_vector<A> c = dynamic_vector<A>::Constant(3, mc::lift<A>(0));
      for (std::size_t l = 0; l < m.description.links.size(); ++l) {
        if (!(m.mass[l] > 0)) continue;
        const dynamic_vector<A> x = pose_along(m, s.q, s.qdot, t(0), l, m.com[l]);
        for (int i = 0; i < 3; ++i) c(i) += mc::lift<A>(m.mass[l] / total) * x(i);
      }
      return c;
    };
    const dynamic_vector<T> cdot =
        mc::jacobian(com_along, dynamic_vector<T>(dynamic_vector<T>::Zero(1))).col(0);
    // The angular momentum about the origin, link by link.
    const summed_momenta<T> sums(m, rb::link_states(m, s.q, s.qdot));
    const mc::vector3<T>&about_origin = sums.about_origin, &momentum = sums.linear;
    const mc::vector3<T> c = rb::centre_of_mass(m, s.q);
    const mc::vector3<T> transferred = mc::vector3<T>(h.template tail<3>()) + c.cross(mc::vector3<T>(h.template head<3>()));
    const double v = speed_scale(s), len = length_scale(s, Eigen::Vector3d::Zero());
    const rb::term_scale ts = rb::term_scales(m, gen::to_tier<double>(s.c.q));
    const T linear_scale = T(std::max(ts.mass * v * len, 1e-300));
    const T angular_scale = T(std::max((ts.inertia + ts.mass * len * len) * v, 1e-300));
    const double k = 64.0 * s.links;
    for (int i = 0; i < 3; ++i) {
      const std::string at = "(" + std::to_string(i) + ")";
      check_close("(A_G qdot)_linear" + at + " = m d/dt c", h(i), T(total * cdot(i)), linear_scale, k);
      check_close("(A_G qdot)_linear" + at + " = sum m v", h(i), momentum(i), linear_scale, k);
      check_close("(J_c qdot)" + at + " = d/dt c", jc(i), cdot(i), T(linear_scale / total), 2 * k);
      check_close("(A_G qdot)_angular" + at + " + (c x P)" + at + " = sum (R I R^T omega + m x x v)", transferred(i),
                  about_origin(i), angular_scale, 2 * k);
    }
  }
};
MECHCHECK_LAW(centroidal_momentum);

}  // namespace
