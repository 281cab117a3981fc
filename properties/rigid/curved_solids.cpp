#include "rigid/bodies.hpp"

namespace {
using namespace mechcheck::laws::bodies;

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

}  // namespace
