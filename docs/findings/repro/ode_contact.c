/* ODE's friction pyramid on a sliding box and its two step functions on a box resting on a
 * slope, against Coulomb's friction: a box sent at v0 in any direction theta with any yaw psi
 * stops after v0^2 / (2 mu g) whatever theta and psi, and a box on a slope with
 * tan(alpha) <= mu never moves. ODE's words (contact.h and the manual): dSurfaceParameters::mu
 * "Coulomb friction coefficient"; dContactApprox1 "Use the friction pyramid approximation for
 * friction direction 1" (and 2); objects.h on dWorldQuickStep: "This uses an iterative method
 * ... but it is less accurate", and on its iterations: "More iterations will give a more
 * accurate solution, but will take longer to compute. The default is 20 iterations." Uses ODE
 * only.
 *
 * Setup: a box of half-edges 0.1, 0.1, 0.05 m and 1 kg (dMassSetParameters with its principal
 * moments m (e_y^2 + e_z^2) / 12 and so on, e its edges), a dCreateBox geom of its edges, a
 * dCreatePlane through the origin with the slope's normal, a simple space; each contact
 * dContactApprox1 with mu = 0.5 (no bounce); g = 9.81; h = 1/60. The slide: the box resting on
 * level ground (centre at z = 0.05), sent at 2 m/s along (cos theta, sin theta, 0), turned by
 * psi about z, 60 steps (1 s; it stops at 0.408 s): its horizontal displacement over
 * v0^2 / (2 mu g) = 0.408 m at theta 0 to 90 degrees by 15 and psi 0 and 30, and the spread of
 * those 14 ratios. The slope: the plane's normal (sin 0.25, 0, cos 0.25) (tan 0.25 = 0.255 <=
 * mu), the box at rest on it, 180 steps (3 s): the creep down the fall line and its rate over
 * the second half. Each with dWorldStep and dWorldQuickStep (20 iterations, the default; on
 * the slope also 160).
 *
 * Build: cc ode_contact.c $(pkg-config --cflags --libs ode) -lm
 * Prints: lines "name value" (see ci/findings). */
#include <math.h>
#include <stdio.h>

#include <ode/ode.h>

static const double g = 9.81, mu = 0.5, h = 1.0 / 60;
static const double a = 0.1, b = 0.1, c = 0.05; /* half-edges */

static dWorldID world;
static dJointGroupID contacts;

static void near_callback(void* data, dGeomID g1, dGeomID g2) {
  (void)data;
  dContact found[8];
  const int n = dCollide(g1, g2, 8, &found[0].geom, sizeof(dContact));
  for (int i = 0; i < n; ++i) {
    dContact* k = &found[i];
    dSurfaceParameters none = {0};
    k->surface = none;
    k->surface.mode = dContactApprox1;
    k->surface.mu = mu;
    dJointID j = dJointCreateContact(world, contacts, k);
    dJointAttach(j, dGeomGetBody(g1), dGeomGetBody(g2));
  }
}

/* A turn by `angle` about the coordinate axis `axis` (1: y, 2: z) as the audit builds it
 * (Eigen's AngleAxis: the diagonal entry on the axis is (1 - cos) + cos), in ODE's 3 x 4 rows. */
static void turn(int axis, double angle, dMatrix3 r) {
  const double co = cos(angle), si = sin(angle);
  double m[3][3] = {{co, 0, 0}, {0, co, 0}, {0, 0, co}};
  m[axis][axis] = (1 - co) + co;
  const int i = (axis + 1) % 3, j = (axis + 2) % 3;
  m[i][j] = -si, m[j][i] = si;
  for (int row = 0; row < 3; ++row) {
    for (int col = 0; col < 3; ++col) r[4 * row + col] = m[row][col];
    r[4 * row + 3] = 0;
  }
}

/* A world with the plane of normal n and the box at position p, turned about `axis` by
 * `angle`, moving at v; `steps` steps; the box's position at `half` steps and at the end. */
static void run(int quick, int iterations, const double n[3], const double p[3], int axis, double angle,
                const double v[3], int steps, int half, double at_half[3], double at_end[3]) {
  dRandSetSeed(0); /* QuickStep orders its rows with ODE's random generator */
  world = dWorldCreate();
  dWorldSetGravity(world, 0, 0, -g);
  if (iterations > 0) dWorldSetQuickStepNumIterations(world, iterations);
  dSpaceID space = dSimpleSpaceCreate(NULL);
  contacts = dJointGroupCreate(0);
  dCreatePlane(space, n[0], n[1], n[2], 0);
  dBodyID body = dBodyCreate(world);
  dMass mass;
  const double ex = 2 * a, ey = 2 * b, ez = 2 * c;
  dMassSetParameters(&mass, 1, 0, 0, 0, (ey * ey + ez * ez) / 12, (ex * ex + ez * ez) / 12, (ex * ex + ey * ey) / 12, 0,
                     0, 0);
  dBodySetMass(body, &mass);
  dMatrix3 r;
  turn(axis, angle, r);
  dBodySetRotation(body, r);
  dBodySetPosition(body, p[0], p[1], p[2]);
  dBodySetLinearVel(body, v[0], v[1], v[2]);
  dBodySetAngularVel(body, 0, 0, 0);
  dGeomID box = dCreateBox(space, ex, ey, ez);
  dGeomSetBody(box, body);
  for (int k = 1; k <= steps; ++k) {
    dSpaceCollide(space, NULL, &near_callback);
    if (quick)
      dWorldQuickStep(world, h);
    else
      dWorldStep(world, h);
    dJointGroupEmpty(contacts);
    if (k == half)
      for (int i = 0; i < 3; ++i) at_half[i] = dBodyGetPosition(body)[i];
  }
  for (int i = 0; i < 3; ++i) at_end[i] = dBodyGetPosition(body)[i];
  dJointGroupDestroy(contacts);
  dSpaceDestroy(space);
  dWorldDestroy(world);
}

int main(void) {
  dInitODE2(0);
  const char* names[2] = {"step", "quickstep"};
  for (int quick = 0; quick < 2; ++quick) {
    const double level[3] = {0, 0, 1}, start[3] = {0, 0, c}, v0 = 2;
    double lo = INFINITY, hi = 0, mid[3], end[3];
    for (int psi = 0; psi <= 30; psi += 30)
      for (int theta = 0; theta <= 90; theta += 15) {
        const double th = theta * M_PI / 180, v[3] = {v0 * cos(th), v0 * sin(th), 0};
        run(quick, 0, level, start, 2, psi * M_PI / 180, v, 60, 0, mid, end);
        const double ratio = sqrt(end[0] * end[0] + end[1] * end[1]) / (v0 * v0 / (2 * mu * g));
        printf("%s_slide_theta%d_psi%d_over_exact %.9f\n", names[quick], theta, psi, ratio);
        lo = fmin(lo, ratio), hi = fmax(hi, ratio);
      }
    printf("%s_slide_spread %.6e\n", names[quick], hi - lo);
    const int counts[2] = {0, 160};
    for (int k = 0; k < (quick ? 2 : 1); ++k) {
      const double s = 0.25, n[3] = {sin(s), 0, cos(s)}, fall[3] = {cos(s), 0, -sin(s)};
      const double p[3] = {c * n[0], c * n[1], c * n[2]}, rest[3] = {0, 0, 0};
      run(quick, counts[k], n, p, 1, s, rest, 180, 90, mid, end);
      double total = 0, half = 0;
      for (int i = 0; i < 3; ++i) total += (end[i] - p[i]) * fall[i], half += (mid[i] - p[i]) * fall[i];
      char name[64];
      snprintf(name, sizeof name, k ? "%s_%d" : "%s", names[quick], counts[k]);
      printf("%s_slope_creep %.6e\n", name, total);
      printf("%s_slope_creep_rate %.6e\n", name, (total - half) / 1.5);
    }
  }
  dCloseODE();
  return 0;
}
