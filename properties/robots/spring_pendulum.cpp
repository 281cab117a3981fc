#include "robots/robots.hpp"

namespace {
using namespace mechcheck::laws::robots;

struct spring_pendulum {
  static law_info info() {
    return {"robots.spring_pendulum",
            "The notes' spring pendulum as a robot (a revolute joint, then a slide along the rod): "
            "M = diag(m (l + x)^2 + J, m) (eq 7, J the bob's moment about the axis), and the velocity "
            "terms 2 m (l + x) xdot thetadot and -m (l + x) thetadot^2 of eqs 10-11, gravity's "
            "-dV/dq from eq 8 (without the spring, which joints do not have)",
            {"7", "8", "10", "11"}};
  }
  // The pendulum in any orientation: its pivot turned by any roll-pitch-yaw R_o, its axis
  // a = +-e_i and rod u = +-e_j (exactly unit and orthogonal in every tier), gravity any
  // vector, so V = -m (l + x) (G_c cos(theta) + G_s sin(theta)) with G_c = g . R_o u and
  // G_s = g . R_o (a x u) (the notes' case is G_c = g, G_s = 0). The bob: any mass and
  // inertia tensor at the end of the slide. Each closed-form entry is a few products; the
  // robot's a nested-AD jet of two links: k = 128 on the entries' terms (the bob's mass and
  // inertia times the rates).
  template <class T>
  static void property() {
    using std::cos;
    using std::sin;
    const int i = *gen::uniform_int(0, 2), shift = *gen::uniform_int(1, 2);
    const double sa = *rc::gen::element(-1.0, 1.0), su = *rc::gen::element(-1.0, 1.0);
    const Eigen::Vector3d axis = sa * Eigen::Vector3d::Unit(i), rod = su * Eigen::Vector3d::Unit((i + shift) % 3);
    const double length = *gen::dyadic(0.25, 2);
    const rb::robot bob_source = *gen::random_robots(1);
    rb::robot r;
    r.name = "spring_pendulum";
    r.gravity = Eigen::Vector3d(*gen::coordinate(), *gen::coordinate(), *gen::coordinate()) * 8;
    r.links = {{"base", std::nullopt}, {"rod", std::nullopt}, {"bob", bob_source.links.back().body}};
    r.links.back().body->origin.xyz.setZero();
    rb::joint pivot;
    pivot.name = "pivot";
    pivot.type = rb::joint_type::continuous;
    pivot.parent = "base";
    pivot.child = "rod";
    pivot.axis = axis;
    for (int c = 0; c < 3; ++c) {
      pivot.origin.xyz(c) = *gen::coordinate();
      pivot.origin.rpy(c) = *gen::dyadic(-3.14, 3.14);
    }
    rb::joint slide;
    slide.name = "slide";
    slide.type = rb::joint_type::prismatic;
    slide.parent = "rod";
    slide.child = "bob";
    slide.axis = rod;
    slide.origin.xyz = length * rod;
    r.joints = {pivot, slide};
    const rb::robot_model<T> m(r);
    const T theta = T(*gen::dyadic(-3.14, 3.14)), x = T(*gen::dyadic_towards_zero(0.125));
    const T theta_dot = T(*gen::coordinate()) * 4, x_dot = T(*gen::coordinate()) * 4;
    dynamic_vector<T> q(2), qdot(2);
    q << theta, x;
    qdot << theta_dot, x_dot;
    const rb::motion_terms<T> e = rb::motion_terms_at(m, q, qdot);

    const T mass = m.mass[2], arm = T(length) + x;
    const mc::vector3<T> a = axis.cast<T>(), u = rod.cast<T>();
    const T j = T(a.dot(m.inertia[2] * a));
    const mc::matrix3<T> turn = rb::rpy_rotation<T>(pivot.origin.rpy);
    const mc::vector3<T> g = r.gravity.cast<T>();
    const T g_c = T(g.dot(turn * u)), g_s = T(g.dot(turn * mc::vector3<T>(a.cross(u))));
    const T c = cos(theta), sn = sin(theta);
    // dV/dtheta and dV/dx of V = -m (l + x) (G_c cos + G_s sin).
    const T dv_theta = -mass * arm * (g_s * c - g_c * sn), dv_x = -mass * (g_c * c + g_s * sn);
    dynamic_matrix<T> mass_expected(2, 2);
    mass_expected << mass * arm * arm + j, T(0), T(0), mass;
    dynamic_vector<T> bias_expected(2);
    bias_expected << 2 * mass * arm * x_dot * theta_dot + dv_theta, -mass * arm * theta_dot * theta_dot + dv_x;

    using std::abs;
    const T g_norm = T(g.norm());
    // The bob's rotational terms cancel in dT/dtheta only after rounding: their size is the
    // inertia tensor's largest entry times thetadot^2.
    const T inertia = T(m.inertia[2].cwiseAbs().maxCoeff());
    const T scale_m = mass * (arm * arm + 1) + inertia;
    const T scale_h = mass * (abs(arm) + 1) * (T(2 * abs(T(x_dot * theta_dot))) + theta_dot * theta_dot + g_norm) +
                      inertia * theta_dot * theta_dot;
    for (int r_ = 0; r_ < 2; ++r_) {
      for (int c_ = 0; c_ < 2; ++c_)
        check_close("M(" + std::to_string(r_) + "," + std::to_string(c_) + ")", e.mass_matrix(r_, c_),
                    mass_expected(r_, c_), scale_m, 128);
      check_close("h(" + std::to_string(r_) + ")", e.bias(r_), bias_expected(r_), scale_h, 128);
    }
  }
};
MECHCHECK_LAW(spring_pendulum);

}  // namespace
