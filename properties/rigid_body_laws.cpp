/// Rigid bodies: inertia tensors, the parallel-axis theorem, principal axes (notes
/// lectures 13-16, eqs 123-164).
///
/// Tolerance model: a tensor entry of an N-point cloud is a sum of N terms of size
/// m |r|^2; each term has a few roundings, so entries carry error <= (N + 4) eps times
/// sum m |r|^2 (the cloud's scale). Eigen decompositions add O(10) eps of |I|.

#include <array>

#include <boost/math/quadrature/gauss.hpp>

#include "generators.hpp"
#include "mechcheck/harness/law.hpp"
#include "mechcheck/reference.hpp"

namespace {

namespace mc = mechcheck;
namespace gen = mechcheck::generators;
using mc::lift;
using mc::matrix3;
using mc::vector3;
using mc::harness::check_close;
using mc::harness::check_zero;
using mc::harness::law_info;

template <class T>
void check_matrices(const std::string& what, const matrix3<T>& computed,
                    const matrix3<T>& expected, const T& scale, double budget) {
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      check_close(what + "(" + std::to_string(i) + "," + std::to_string(j) + ")", computed(i, j),
                  expected(i, j), scale, budget);
}

/// A cloud of 1 to 6 point masses in [-2, 2]^3.
template <class T>
mc::point_cloud<T> random_cloud() {
  const int n = *rc::gen::inRange(1, 7);
  mc::point_cloud<T> cloud;
  for (int a = 0; a < n; ++a) {
    cloud.masses.push_back(T(*gen::positive()));
    const auto r = *gen::coordinates(3);
    cloud.positions.emplace_back(T(r[0]), T(r[1]), T(r[2]));
  }
  return cloud;
}

/// sum m |r - o|^2 + M |o|^2: the scale of the entries of I about o.
template <class T>
T cloud_scale(const mc::point_cloud<T>& cloud, const vector3<T>& o) {
  T s = lift<T>(1);
  for (std::size_t a = 0; a < cloud.masses.size(); ++a)
    s += cloud.masses[a] * (cloud.positions[a].squaredNorm() + o.squaredNorm());
  return s;
}

struct parallel_axis_theorem {
  static law_info info() {
    return {"rigid.parallel_axis",
            "Parallel-axis theorem: I about c + b = I_cm + M(|b|^2 delta - b b^T), both ways",
            {"157", "158", "159", "160"}};
  }
  // Entries are sums over N points (and the centre of mass a weighted mean): k = 4N + 16
  // on the cloud's scale, for the direct tensor against the shifted one and back.
  template <class T>
  static void property() {
    const auto cloud = random_cloud<T>();
    const vector3<T> b = gen::draw_vector3<T>();
    const vector3<T> c = mc::centre_of_mass(cloud);
    const T m = cloud.total_mass();
    const matrix3<T> about_centre = mc::inertia_tensor(cloud, c);
    const matrix3<T> about_point = mc::inertia_tensor(cloud, vector3<T>(c + b));
    const T scale = cloud_scale(cloud, vector3<T>(c + b));
    const double k = 4.0 * cloud.masses.size() + 16;
    check_matrices("I(c + b) vs shift_from_centre", about_point,
                   mc::shift_from_centre(about_centre, m, b), scale, k);
    check_matrices("round trip shift_to_centre(shift_from_centre)",
                   mc::shift_to_centre(mc::shift_from_centre(about_centre, m, b), m, b),
                   about_centre, scale, k);
    mc::validate_inertia(about_point, "rigid.parallel_axis");  // must not fire on round-off
  }
};
MECHCHECK_LAW(parallel_axis_theorem);

struct trace_minimal_at_centre {
  static law_info info() {
    return {"rigid.trace_minimal_at_centre",
            "The trace of the inertia tensor is smallest about the centre of mass: "
            "tr I(c + b) = tr I_cm + 2 M |b|^2",
            {"138", "160"}};
  }
  // Traces sum 3N terms: k = 4N + 16.
  template <class T>
  static void property() {
    const auto cloud = random_cloud<T>();
    const vector3<T> b = gen::draw_vector3<T>();
    const vector3<T> c = mc::centre_of_mass(cloud);
    const T tc = mc::inertia_tensor(cloud, c).trace();
    const T tb = mc::inertia_tensor(cloud, vector3<T>(c + b)).trace();
    const T scale = cloud_scale(cloud, vector3<T>(c + b));
    check_close("tr I(c + b) - tr I_cm vs 2 M |b|^2", T(tb - tc),
                T(2 * cloud.total_mass() * b.squaredNorm()), scale,
                4.0 * cloud.masses.size() + 16);
    RC_ASSERT(tb >= tc - T(4 * cloud.masses.size() + 16) * mc::tier_epsilon<T>() * scale);
  }
};
MECHCHECK_LAW(trace_minimal_at_centre);

struct cube_tensor {
  static law_info info() {
    return {"rigid.cube",
            "Cube of edge l: I_cm = M l^2/6 times the identity, and about a corner "
            "M l^2 [[2/3, -1/4, -1/4], ...] (eq 164); the box's closed form equals its exact "
            "Gauss point-mass equivalent",
            {"141", "161", "162", "163", "164"}};
  }
  // Closed forms with a few roundings each, point sums over 8 masses: k = 32 on M l^2.
  template <class T>
  static void property() {
    const T m = T(*gen::positive()), l = T(*gen::positive());
    const T ml2 = m * l * l;
    const matrix3<T> cube = mc::reference::cube_inertia(m, l);
    check_matrices("cube I_cm vs M l^2/6", cube, matrix3<T>(ml2 / 6 * matrix3<T>::Identity()), ml2,
                   16);
    matrix3<T> corner;
    const T d = T(2) / 3 * ml2, o = -ml2 / 4;
    corner << d, o, o, o, d, o, o, o, d;
    const vector3<T> b = vector3<T>::Constant(-l / 2);
    check_matrices("cube about a corner vs eq 164", mc::shift_from_centre(cube, m, b), corner, ml2,
                   16);
    const T a = T(*gen::positive()), bb = T(*gen::positive()), c = T(*gen::positive());
    const auto points = mc::reference::box_points(m, a, bb, c);
    check_matrices("box closed form vs Gauss point masses",
                   mc::inertia_tensor(points, vector3<T>(vector3<T>::Zero())),
                   mc::reference::box_inertia(m, a, bb, c), T(m * (a * a + bb * bb + c * c)), 32);
    RC_ASSERT(mc::classify(cube) == mc::top_kind::spherical);
  }
};
MECHCHECK_LAW(cube_tensor);

struct tetrahedron_tensor {
  static law_info info() {
    return {"rigid.tetrahedron",
            "A tetrahedron (no symmetry): the closed form equals its exact Gauss point-mass "
            "equivalent, and it is an asymmetric top in general",
            {"138", "141"}};
  }
  // Sums of 4-10 products of vertex coordinates: k = 64 on M sum |v|^2.
  template <class T>
  static void property() {
    const T m = T(*gen::positive());
    std::array<vector3<T>, 4> v;
    for (auto& x : v) x = gen::draw_vector3<T>();
    const vector3<T> e1 = v[1] - v[0], e2 = v[2] - v[0], e3 = v[3] - v[0];
    using std::abs;
    RC_PRE(abs(T(e1.cross(e2).dot(e3))) > T(1) / 64);  // not flat
    T scale = lift<T>(0);
    for (const auto& x : v) scale += m * x.squaredNorm();
    check_matrices("tetrahedron closed form vs Gauss point masses",
                   mc::inertia_tensor(mc::reference::tetrahedron_points(m, v), vector3<T>(vector3<T>::Zero())),
                   mc::reference::tetrahedron_inertia(m, v), scale, 64);
  }
};
MECHCHECK_LAW(tetrahedron_tensor);

struct triangle_inequality {
  static law_info info() {
    return {"rigid.triangle_inequality",
            "Principal moments satisfy I1 + I2 >= I3 (and are non-negative)",
            {"154", "155", "156"}};
  }
  // Eigenvalues to ~16 eps of |I|, tensor entries to (N + 4) eps of the scale: k = 4N + 32.
  template <class T>
  static void property() {
    const auto cloud = random_cloud<T>();
    const vector3<T> o = gen::draw_vector3<T>();
    const matrix3<T> inertia = mc::inertia_tensor(cloud, o);
    const vector3<T> mom = mc::principal_axes(inertia).moments;
    const T scale = cloud_scale(cloud, o);
    const double k = 4.0 * cloud.masses.size() + 32;
    const T slack = T(k) * mc::tier_epsilon<T>() * scale;
    RC_ASSERT(mom(0) + mom(1) >= mom(2) - slack);
    RC_ASSERT(mom(0) >= -slack);
    // I1 + I2 - I3 = 2 sum m z^2 in the principal frame (eq 155): check it exactly.
    const auto frame = mc::principal_axes(inertia);
    T z2 = lift<T>(0);
    for (std::size_t a = 0; a < cloud.masses.size(); ++a) {
      const T z = frame.axes.col(2).dot(vector3<T>(cloud.positions[a] - o));
      z2 += cloud.masses[a] * z * z;
    }
    check_close("I1 + I2 - I3 vs 2 sum m z^2 (eq 155)", T(mom(0) + mom(1) - mom(2)), T(2 * z2),
                scale, k);
  }
};
MECHCHECK_LAW(triangle_inequality);

struct principal_axes_diagonalise {
  static law_info info() {
    return {"rigid.principal_axes",
            "Principal axes diagonalise the tensor (O I O^T = diag), O is a rotation, and "
            "M = I Omega is parallel to Omega exactly when Omega lies on a principal axis",
            {"142", "145", "146"}};
  }
  // Eigen's symmetric eigensolver: residual ~16 eps |I|; products of 3x3 matrices add
  // 3 roundings per entry: k = 64 on |I|.
  template <class T>
  static void property() {
    const auto cloud = random_cloud<T>();
    const matrix3<T> inertia = mc::inertia_tensor(cloud, mc::centre_of_mass(cloud));
    const auto frame = mc::principal_axes(inertia);
    const T scale = inertia.cwiseAbs().maxCoeff() + 1;
    const matrix3<T> diag = frame.axes.transpose() * inertia * frame.axes;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        check_close("O I O^T", diag(i, j), i == j ? T(frame.moments(i)) : lift<T>(0), scale, 64);
    check_close("det O", T(frame.axes.determinant()), lift<T>(1), lift<T>(1), 64);
    for (int i = 0; i < 3; ++i) {
      const vector3<T> omega = frame.axes.col(i);
      const vector3<T> m = inertia * omega;
      check_zero("|M x Omega| on a principal axis", T(m.cross(omega).norm()), scale, 64);
    }
    // Off the axes of an asymmetric top M is not parallel to Omega.
    if (mc::classify(inertia, 1e6) == mc::top_kind::asymmetric) {
      const vector3<T> omega = frame.axes.col(0) + frame.axes.col(2);
      const vector3<T> m = inertia * omega;
      RC_ASSERT(m.cross(omega).norm() > T(1e3) * mc::tier_epsilon<T>() * scale);
    }
  }
};
MECHCHECK_LAW(principal_axes_diagonalise);

struct symmetry_axis_is_principal {
  static law_info info() {
    return {"rigid.symmetry_axis",
            "An axis of symmetry is a principal axis: a cloud repeated under a rotation by "
            "120 degrees about n has n as an eigenvector, with the other two moments equal",
            {"142", "153"}};
  }
  // |I n x n| to ~8 eps of the scale after 3N-term sums: k = 8N + 32.
  template <class T>
  static void property() {
    const auto base = random_cloud<T>();
    const vector3<T> n = gen::draw_vector3<T>();
    RC_PRE(n.norm() > T(1) / 4);
    const vector3<T> axis = n.normalized();
    using std::cos;
    using std::sin;
    const T angle = 2 * boost::math::constants::pi<T>() / 3;
    mc::point_cloud<T> cloud;
    for (int k = 0; k < 3; ++k) {
      const Eigen::AngleAxis<T> rot(T(k) * angle, axis);
      for (std::size_t a = 0; a < base.masses.size(); ++a) {
        cloud.masses.push_back(base.masses[a]);
        cloud.positions.push_back(rot * base.positions[a]);
      }
    }
    const matrix3<T> inertia = mc::inertia_tensor(cloud, vector3<T>(vector3<T>::Zero()));
    const T scale = cloud_scale(cloud, vector3<T>(vector3<T>::Zero()));
    const double k = 8.0 * cloud.masses.size() + 32;
    check_zero("|I n x n| for the symmetry axis n", T((inertia * axis).cross(axis).norm()), scale, k);
    RC_CLASSIFY(mc::classify(inertia, 1e4) != mc::top_kind::asymmetric, "symmetric top");
  }
};
MECHCHECK_LAW(symmetry_axis_is_principal);

struct two_masses {
  static law_info info() {
    return {"rigid.two_masses",
            "Two masses m at +-a (cos t, sin t, 0): I = 2 m a^2 [[sin^2, -sin cos, 0], "
            "[-sin cos, cos^2, 0], [0, 0, 1]]",
            {"147", "148", "149", "150", "151", "152", "153"}};
  }
  // A handful of roundings per entry: k = 16 on 2 m a^2.
  template <class T>
  static void property() {
    const T m = T(*gen::positive()), a = T(*gen::positive()), t = T(*gen::coordinate());
    using std::cos;
    using std::sin;
    const vector3<T> r(a * cos(t), a * sin(t), lift<T>(0));
    const mc::point_cloud<T> cloud{{m, m}, {r, vector3<T>(-r)}};
    const T s = sin(t), c = cos(t), k2 = 2 * m * a * a;
    matrix3<T> expected;
    expected << s * s, -s * c, 0, -s * c, c * c, 0, 0, 0, 1;
    check_matrices("two-mass tensor vs eq 153", mc::inertia_tensor(cloud, vector3<T>(vector3<T>::Zero())),
                   matrix3<T>(k2 * expected), k2, 16);
  }
};
MECHCHECK_LAW(two_masses);

struct rigid_kinematics {
  static law_info info() {
    return {"rigid.kinematics",
            "For v_a = V + Omega x r_a: Omega does not depend on the reference point "
            "(V' = V + Omega x a), T = M V^2/2 + Omega^T I Omega / 2 about the centre of "
            "mass, and M = I Omega",
            {"123", "126", "127", "128", "129", "131", "136", "137", "143", "144", "145"}};
  }
  // Sums over N points of products of 3-vectors: k = 8N + 16 on sum m |v|^2 and
  // sum m |r||v|.
  template <class T>
  static void property() {
    const auto cloud = random_cloud<T>();
    const vector3<T> big_v = gen::draw_vector3<T>(), omega = gen::draw_vector3<T>(), a = gen::draw_vector3<T>();
    const vector3<T> c = mc::centre_of_mass(cloud);
    const std::size_t n = cloud.masses.size();
    // velocities of the points, from the centre of mass as reference
    std::vector<vector3<T>> v(n);
    for (std::size_t i = 0; i < n; ++i) v[i] = big_v + omega.cross(vector3<T>(cloud.positions[i] - c));
    // reference point c + a: V' = V + Omega x a reproduces every velocity with the same Omega
    const vector3<T> big_v2 = big_v + omega.cross(a);
    T v_scale = lift<T>(1), m_scale = lift<T>(1);
    for (std::size_t i = 0; i < n; ++i) {
      const vector3<T> again = big_v2 + omega.cross(vector3<T>(cloud.positions[i] - c - a));
      for (int k = 0; k < 3; ++k)
        check_close("v from reference c + a", again(k), v[i](k),
                    T(big_v.norm() + omega.norm() * (cloud.positions[i] - c).norm() +
                      omega.norm() * a.norm() + 1),
                    16);
      v_scale += cloud.masses[i] * v[i].squaredNorm();
      m_scale += cloud.masses[i] * (cloud.positions[i] - c).norm() * v[i].norm();
    }
    const matrix3<T> inertia = mc::inertia_tensor(cloud, c);
    T kinetic = lift<T>(0);
    vector3<T> ang = vector3<T>::Zero();
    for (std::size_t i = 0; i < n; ++i) {
      kinetic += cloud.masses[i] * v[i].squaredNorm() / 2;
      ang += cloud.masses[i] * vector3<T>(cloud.positions[i] - c).cross(vector3<T>(v[i] - big_v));
    }
    const double k = 8.0 * n + 16;
    const T rot = omega.dot(inertia * omega) / 2;
    check_close("T vs M V^2/2 + Omega.I.Omega/2", kinetic,
                T(cloud.total_mass() * big_v.squaredNorm() / 2 + rot), v_scale, k);
    const vector3<T> io = inertia * omega;
    for (int j = 0; j < 3; ++j) check_close("M_cm vs I Omega", ang(j), io(j), m_scale, k);
  }
};
MECHCHECK_LAW(rigid_kinematics);

/// int_a^b f by 30-point Gauss-Legendre quadrature (Boost.Math): exact for the
/// polynomial integrands here (degree <= 59), and for sin^2, sin^3 over a period its
/// error is far below 10^-50 (measured <= 3 eps in every tier).
template <class T, class F>
T integral(F f, const T& a, const T& b) {
  return boost::math::quadrature::gauss<T, 30>::integrate(f, a, b);
}

struct curved_solids {
  static law_info info() {
    return {"rigid.curved_solids",
            "The closed forms of the solid sphere (2/5 M R^2), spherical shell (2/3 M R^2), "
            "solid cylinder and thin rod equal the integral of eq 141 by Gauss-Legendre "
            "quadrature in spherical and cylindrical coordinates",
            {"141"}};
  }
  // Products of 2-4 one-dimensional integrals, each to ~2 eps, and the density's few
  // roundings: k = 32 on the closed form.
  template <class T>
  static void property() {
    const T m = T(*gen::positive()), r = T(*gen::positive()), h = T(*gen::positive());
    const T pi = boost::math::constants::pi<T>();
    using std::sin;
    const T sin3 = integral([](const T& t) { const T s = sin(t); return T(s * s * s); }, T(0), pi);
    const T sin2 = integral([](const T& t) { const T s = sin(t); return T(s * s); }, T(0), T(2 * pi));
    const auto power = [](int k) { return [k](const T& x) { T y = 1; for (int i = 0; i < k; ++i) y *= x; return y; }; };
    // solid sphere: rho 2pi int r^4 dr int sin^3
    const T rho_sphere = m / (T(4) / 3 * pi * r * r * r);
    const T sphere = rho_sphere * 2 * pi * integral(power(4), T(0), r) * sin3;
    check_close("solid sphere I_zz", sphere, T(mc::reference::solid_sphere_inertia(m, r)(2, 2)),
                T(m * r * r), 32);
    // shell: sigma R^4 2pi int sin^3
    const T shell = m / (4 * pi * r * r) * r * r * r * r * 2 * pi * sin3;
    check_close("spherical shell I_zz", shell,
                T(mc::reference::spherical_shell_inertia(m, r)(2, 2)), T(m * r * r), 32);
    // cylinder, axis z, z in [-h/2, h/2]
    const T rho_cyl = m / (pi * r * r * h);
    const T izz = rho_cyl * h * 2 * pi * integral(power(3), T(0), r);
    const T ixx = rho_cyl * (sin2 * integral(power(3), T(0), r) * h +
                             integral(power(2), T(-h / 2), T(h / 2)) * integral(power(1), T(0), r) * 2 * pi);
    const matrix3<T> cyl = mc::reference::solid_cylinder_inertia(m, r, h);
    check_close("solid cylinder I_zz", izz, cyl(2, 2), T(m * (r * r + h * h)), 32);
    check_close("solid cylinder I_xx", ixx, cyl(0, 0), T(m * (r * r + h * h)), 32);
    // thin rod along z
    const T rod = m / h * integral(power(2), T(-h / 2), T(h / 2));
    check_close("thin rod I_xx", rod, T(mc::reference::thin_rod_inertia(m, h)(0, 0)), T(m * h * h), 32);
  }
};
MECHCHECK_LAW(curved_solids);

// --- Euler angles ------------------------------------------------------------------------

/// Euler angles (phi, theta, psi) and rates.
template <class T>
std::array<T, 6> random_angles_and_rates() {
  std::array<T, 6> a;
  for (auto& x : a) x = T(*gen::coordinate());
  return a;
}

struct euler_rotation_matrix {
  static law_info info() {
    return {"rigid.euler_rotation",
            "The ZXZ rotation R_3(psi) R_1(theta) R_3(phi) is orthogonal with determinant 1 "
            "and equals the matrix printed in eq 208",
            {"205", "206", "207", "208"}};
  }
  // Products of three 3x3 rotations and the closed form's 2-3 products per entry: k = 16.
  template <class T>
  static void property() {
    const auto a = random_angles_and_rates<T>();
    const T phi = a[0], theta = a[1], psi = a[2];
    const matrix3<T> r = mc::euler_rotation(phi, theta, psi);
    check_matrices("R R^T", matrix3<T>(r * r.transpose()), matrix3<T>(matrix3<T>::Identity()),
                   lift<T>(1), 16);
    check_close("det R", T(r.determinant()), lift<T>(1), lift<T>(1), 16);
    using std::cos;
    using std::sin;
    const T cf = cos(phi), sf = sin(phi), ct = cos(theta), st = sin(theta), cp = cos(psi),
            sp = sin(psi);
    matrix3<T> printed;  // eq 208 as printed
    printed << cp * cf - ct * sf * sp, sf * cp + ct * sp * cf, st * sp,
        -cf * sp - ct * cp * sf, -sp * sf + ct * cp * cf, st * cp,
        st * sf, -st * cf, ct;
    check_matrices("R vs eq 208", r, printed, lift<T>(1), 16);
  }
};
MECHCHECK_LAW(euler_rotation_matrix);

/// Body angular velocity from dR/dt: the rows of R are the body axes, d x_i/dt =
/// Omega x x_i, so A = Rdot R^T has A_23 = Omega_1, A_31 = Omega_2, A_12 = Omega_3.
template <class T>
vector3<T> angular_velocity_from_rotation(const std::array<T, 6>& a) {
  using A = mc::ad<T>;
  const mc::ad_width_scope<A> width(1);
  const auto seeded = [](const T& x, const T& rate) {
    return A(x, mc::dynamic_vector<T>::Constant(1, rate));
  };
  const matrix3<A> r = mc::euler_rotation(seeded(a[0], a[3]), seeded(a[1], a[4]), seeded(a[2], a[5]));
  matrix3<T> value, rate;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      value(i, j) = r(i, j).value();
      rate(i, j) = mc::derivatives_of(r(i, j), 1)(0);
    }
  const matrix3<T> m = rate * value.transpose();
  return vector3<T>(m(1, 2), m(2, 0), m(0, 1));
}

struct euler_angular_velocity {
  static law_info info() {
    return {"rigid.euler_angular_velocity",
            "The body angular velocity from the Euler-angle rates (eqs 213-215, eq 214 "
            "corrected) equals the one from differentiating R (by AD)",
            {"209", "210", "211", "212", "213", "214", "215"}};
  }
  // Both sides are sums of 2-3 products of rates and trigonometric values; R Rdot^T adds
  // a 3-term sum: scale |rates|, k = 32.
  template <class T>
  static void property() {
    const auto a = random_angles_and_rates<T>();
    const vector3<T> from_rates =
        mc::body_angular_velocity(a[0], a[1], a[2], a[3], a[4], a[5]);
    const vector3<T> from_r = angular_velocity_from_rotation(a);
    using std::abs;
    const T scale = abs(a[3]) + abs(a[4]) + abs(a[5]) + 1;
    for (int i = 0; i < 3; ++i)
      check_close("Omega_" + std::to_string(i + 1) + " from the rates vs from dR/dt", from_rates(i),
                  from_r(i), scale, 32);
  }
};
MECHCHECK_LAW(euler_angular_velocity);

struct erratum_214 {
  static law_info info() {
    return {"rigid.erratum_214",
            "Printed eq 214 drops sin(theta) from Omega_2",
            {"214"},
            mc::harness::expectation::falsified,
            "printed: Omega_2 = phidot cos(psi) - thetadot sin(psi); correct: Omega_2 = "
            "phidot sin(theta) cos(psi) - thetadot sin(psi)"};
  }
  template <class T>
  static void property() {
    const auto a = random_angles_and_rates<T>();
    using std::abs;
    using std::cos;
    using std::sin;
    const T printed = a[3] * cos(a[2]) - a[4] * sin(a[2]);
    const T scale = abs(a[3]) + abs(a[4]) + abs(a[5]) + 1;
    check_close("printed Omega_2 vs from dR/dt", printed, angular_velocity_from_rotation(a)(1),
                scale, 32);
  }
};
MECHCHECK_LAW(erratum_214);

}  // namespace
