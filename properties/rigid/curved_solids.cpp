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
            "solid cylinder, thin rod, capsule, cone and ellipsoid equal the integral of eq 141 by "
            "Gauss-Legendre quadrature in spherical and cylindrical coordinates or over slices along "
            "the axis",
            {"141", "160"}};
  }
  // Products of 2-4 one-dimensional integrals, each to ~2 eps, and the density's few
  // roundings: k = 32 on the closed form.
  template <class T>
  static void property() {
    const T m = T(*gen::positive()), r = T(*gen::positive()), h = T(*gen::positive());
    const T pi = boost::math::constants::pi<T>();
    using std::abs;
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
    // Solids of revolution about z by slices: a disc of radius s(z) at height z carries
    // I_zz = pi rho s^4 / 2 dz and, about the x axis through the origin, pi rho s^2 (s^2/4 + z^2) dz;
    // elliptic slices (semi-axes s_x, s_y) pi rho s_x s_y ((s_x^2 + s_y^2)/4, s_y^2/4 + z^2) dz.
    // Each piece's integrand is a polynomial in z: the quadrature is exact.
    struct moments {
      T volume = 0, izz = 0, ixx = 0;
    };
    const auto slices = [&](auto sx2, auto sy2, const T& a, const T& b, moments& acc) {
      using std::sqrt;
      acc.volume += integral([&](const T& z) { return T(pi * sqrt(T(sx2(z) * sy2(z)))); }, a, b);
      acc.izz += integral([&](const T& z) { return T(pi * sqrt(T(sx2(z) * sy2(z))) * (sx2(z) + sy2(z)) / 4); }, a, b);
      acc.ixx += integral([&](const T& z) { return T(pi * sqrt(T(sx2(z) * sy2(z))) * (sy2(z) / 4 + z * z)); }, a, b);
    };
    const auto round = [](auto s2) { return [s2](const T& z) { return T(s2(z)); }; };
    {  // capsule: cylinder of length h, caps of radius r, centred at the origin
      moments c;
      const auto cyl = round([&](const T&) { return T(r * r); });
      const auto cap = round([&](const T& z) { const T d = T(abs(z) - h / 2); return T(r * r - d * d); });
      slices(cyl, cyl, T(-h / 2), T(h / 2), c);
      slices(cap, cap, T(h / 2), T(h / 2 + r), c);
      slices(cap, cap, T(-h / 2 - r), T(-h / 2), c);
      const matrix3<T> ref = mc::reference::solid_capsule_inertia(m, r, h);
      check_close("solid capsule I_zz", T(m / c.volume * c.izz), ref(2, 2), T(m * (r + h) * (r + h)), 64);
      check_close("solid capsule I_xx", T(m / c.volume * c.ixx), ref(0, 0), T(m * (r + h) * (r + h)), 64);
    }
    {  // cone: base at z = -h/4, apex at 3h/4 (centre of mass at the origin)
      moments c;
      const auto cone = round([&](const T& z) { const T s = T(r * (T(3) / 4 - z / h)); return T(s * s); });
      slices(cone, cone, T(-h / 4), T(3 * h / 4), c);
      const matrix3<T> ref = mc::reference::solid_cone_inertia(m, r, h);
      check_close("solid cone I_zz", T(m / c.volume * c.izz), ref(2, 2), T(m * (r * r + h * h)), 64);
      check_close("solid cone I_xx", T(m / c.volume * c.ixx), ref(0, 0), T(m * (r * r + h * h)), 64);
    }
    {  // ellipsoid with semi-axes (r, h, cz) along (x, y, z): two draws reused, one new
      moments c;
      const T a = r, b = h, cz = T(*gen::positive());
      const auto sx = round([&](const T& z) { return T(a * a * (1 - z * z / (cz * cz))); });
      const auto sy = round([&](const T& z) { return T(b * b * (1 - z * z / (cz * cz))); });
      slices(sx, sy, T(-cz), cz, c);
      const matrix3<T> ref = mc::reference::solid_ellipsoid_inertia(m, a, b, cz);
      const T scale = T(m * (a * a + b * b + cz * cz));
      check_close("solid ellipsoid I_zz", T(m / c.volume * c.izz), ref(2, 2), scale, 64);
      check_close("solid ellipsoid I_xx", T(m / c.volume * c.ixx), ref(0, 0), scale, 64);
    }
  }
};
MECHCHECK_LAW(curved_solids);

}  // namespace
