// Bullet's calculateLocalInertia for a capsule, a cone, a compound of two spheres and a convex hull
// against the solids' exact moments, axis by axis; the cone's bounding box against its
// margin. Uses Bullet (double build) only.
//
// Shapes (mass 2): capsule of radius 0.2 and cylinder length 0.6 along z; cone of radius
// 0.3 and height 0.8 along z; two spheres of radius 0.1 and mass 1 at x = +-0.4.
// Exact moments about the centre of mass (uniform density):
//   capsule: cylinder mass mc = m L / (L + 4r/3), two half-balls mh = m - mc;
//     Izz = mc r^2/2 + mh 2r^2/5,
//     Ixx = mc (r^2/4 + L^2/12) + mh (2r^2/5 + L^2/4 + 3Lr/8)
//     (each half-ball: 2r^2/5 about the sphere's centre, shifted by L/2 along the axis; the
//     cross term 2 (L/2) (3r/8) of its centroid at 3r/8 from the centre);
//   cone: Izz = 3 m r^2 / 10, Ixx = 3 m r^2 / 20 + 3 m h^2 / 80;
//   two spheres: Ixx = 2 (2/5) (m/2) r^2, Iyy = Izz = 2 ((2/5) (m/2) r^2 + (m/2) d^2).
//
// Build: c++ -DBT_USE_DOUBLE_PRECISION bullet_inertia.cpp $(pkg-config --cflags --libs bullet-float64)
// Prints: lines "name value" (see ci/findings).
#include <btBulletCollisionCommon.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace {
void report(const char* name, const btVector3& bullet, const double exact[3]) {
  for (int i = 0; i < 3; ++i)
    std::printf("%s_%c_bullet_over_exact %.6f\n", name, "xyz"[i], bullet[i] / exact[i]);
}
}  // namespace

int main() {
  std::printf("bullet_version %d\n", btGetVersion());
  const double m = 2;
  {
    const double r = 0.2, L = 0.6;
    btCapsuleShapeZ capsule(r, L);
    btVector3 in;
    capsule.calculateLocalInertia(m, in);
    const double mc = m * L / (L + 4 * r / 3), mh = m - mc;
    const double izz = mc * r * r / 2 + mh * 2 * r * r / 5;
    const double ixx = mc * (r * r / 4 + L * L / 12) + mh * (2 * r * r / 5 + L * L / 4 + 3 * L * r / 8);
    const double exact[3] = {ixx, ixx, izz};
    report("capsule", in, exact);
    // Bullet's: the box 2r x 2r x (2r + L) with 0.08333333 for 1/12.
    const double box_x = m / 12 * (4 * r * r + (2 * r + L) * (2 * r + L));
    std::printf("capsule_x_bullet_over_bounding_box %.9f\n", in[0] / box_x);
  }
  {
    const double r = 0.3, h = 0.8;
    btConeShapeZ cone(r, h);
    btVector3 in;
    cone.calculateLocalInertia(m, in);
    const double exact[3] = {3 * m * r * r / 20 + 3 * m * h * h / 80, 3 * m * r * r / 20 + 3 * m * h * h / 80,
                             3 * m * r * r / 10};
    report("cone", in, exact);
    // The box Bullet takes: half extents (r, r, h/2) grown by k margins; which k matches?
    const double margin = cone.getMargin();
    std::printf("cone_margin %.6f\n", margin);
    for (int k = 0; k <= 3; ++k) {
      const double lx = 2 * (r + k * margin), lz = 2 * (h / 2 + k * margin);
      const double ixx = m / 12 * (lx * lx + lz * lz);
      std::printf("cone_x_bullet_over_box_with_%d_margins %.9f\n", k, in[0] / ixx);
    }
  }
  {
    const double r = 0.1, d = 0.4;
    btSphereShape sphere(r);
    btCompoundShape compound;
    btTransform t;
    t.setIdentity();
    t.setOrigin(btVector3(d, 0, 0));
    compound.addChildShape(t, &sphere);
    t.setOrigin(btVector3(-d, 0, 0));
    compound.addChildShape(t, &sphere);
    btVector3 in;
    compound.calculateLocalInertia(m, in);
    const double ixx = 2 * 0.4 * (m / 2) * r * r, iyy = 2 * (0.4 * (m / 2) * r * r + (m / 2) * d * d);
    const double exact[3] = {ixx, iyy, iyy};
    report("two_spheres", in, exact);
    // calculatePrincipalAxisTransform with the children's masses: exact.
    const btScalar masses[2] = {m / 2, m / 2};
    btTransform principal;
    btVector3 pin;
    compound.calculatePrincipalAxisTransform(masses, principal, pin);
    // pin is in the principal frame; the largest moment is across the line of centres.
    double p[3] = {pin[0], pin[1], pin[2]}, e[3] = {ixx, iyy, iyy};
    std::sort(p, p + 3);
    std::sort(e, e + 3);
    double worst = 0;
    for (int i = 0; i < 3; ++i) worst = std::fmax(worst, std::fabs(p[i] / e[i] - 1));
    std::printf("two_spheres_principal_axis_transform_largest_relative_error %.3e\n", worst);
  }
  {
    // The convex hull of (+-a, 0, c) and (0, +-b, -c), a tetrahedron with its centroid at
    // the origin: C = (m/20) sum_i v_i v_i^T = m diag(a^2/10, b^2/10, c^2/5), I = tr(C) - C.
    const double a = 0.3, b = 0.4, c = 0.25;
    btConvexHullShape hull;
    for (const btVector3& p : {btVector3(a, 0, c), btVector3(-a, 0, c), btVector3(0, b, -c), btVector3(0, -b, -c)})
      hull.addPoint(p);
    btVector3 in;
    hull.calculateLocalInertia(m, in);
    const double exact[3] = {m * (b * b / 10 + c * c / 5), m * (a * a / 10 + c * c / 5), m * (a * a + b * b) / 10};
    report("convex_hull", in, exact);
    // The moments in ascending order, as the audit compares principal moments (x, y and z are
    // not in the same order in Bullet's and the exact ones).
    double g[3] = {in[0], in[1], in[2]}, e[3] = {exact[0], exact[1], exact[2]};
    std::sort(g, g + 3);
    std::sort(e, e + 3);
    double worst = 0;
    for (int i = 0; i < 3; ++i) worst = std::fmax(worst, std::fabs(g[i] / e[i] - 1));
    std::printf("convex_hull_ascending_largest_relative_error %.6f\n", worst);
    // The box Bullet takes: half extents (a, b, c) grown by k margins.
    const double margin = hull.getMargin();
    std::printf("convex_hull_margin %.6f\n", margin);
    for (int k = 0; k <= 3; ++k) {
      const double lx = 2 * (a + k * margin), ly = 2 * (b + k * margin), lz = 2 * (c + k * margin);
      std::printf("convex_hull_x_bullet_over_box_with_%d_margins %.9f\n", k, in[0] / (m / 12 * (ly * ly + lz * lz)));
    }
  }
  return 0;
}
