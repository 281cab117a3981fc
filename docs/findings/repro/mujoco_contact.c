/* MuJoCo's friction cone and its soft contact on a sliding box and a box on a slope, against
 * Coulomb's friction: a box sent at v0 in any direction theta with any yaw psi stops after
 * v0^2 / (2 mu g) whatever theta and psi, and a box on a slope with tan(alpha) <= mu never
 * moves. MuJoCo documents its default cone as pyramidal (XML reference, option/cone:
 * "[pyramidal, elliptic], 'pyramidal'. The type of contact friction cone.") and its contacts
 * as soft constraints (solref, solimp; Computation chapter, "Soft contacts"). Uses MuJoCo only.
 *
 * Setup: a box of half-edges 0.1, 0.1, 0.05 m and 1 kg (its principal moments m (e_y^2 + e_z^2)
 * / 12 and so on, e its edges) on a plane, both geoms condim 3 with friction "0.5 0 0" (MuJoCo takes the
 * larger of two geoms' friction), g = 9.81, mjINT_EULER, timestep 1/60 s (the default step of
 * Bullet, Rapier, Jolt, Havok and cannon-es; MuJoCo's own default is 0.002 s), the cone
 * pyramidal (the default) or elliptic. The slide: the box resting on level ground, sent at 2 m/s
 * along (cos theta, sin theta, 0), turned by psi about z, 60 steps (1 s; it stops at 0.408 s):
 * its horizontal displacement over v0^2 / (2 mu g) = 0.408 m, theta 0 to 90 degrees by 15 and
 * psi 0 and 30, and the spread of those 14 ratios. The slope: the plane turned by 0.25 rad
 * about y (tan 0.25 = 0.255 <= mu = 0.5), the box at rest on it, 180 steps (3 s): the creep
 * down the fall line and its rate over the second half, also with MuJoCo's NoSlip pass
 * (noslip_iterations 10; 0, off, by default).
 *
 * Build: cc mujoco_contact.c -lmujoco -lm
 * Prints: lines "name value" (see ci/findings). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <mujoco/mujoco.h>

static const double g = 9.81, mu = 0.5, h = 1.0 / 60;
static const double a = 0.1, b = 0.1, c = 0.05; /* half-edges */

/* A model from an MJCF string (through MuJoCo's virtual file system); exits naming MuJoCo's error. */
static mjModel* load_xml(const char* xml) {
  char error[1000];
  mjVFS vfs;
  mj_defaultVFS(&vfs);
  mj_makeEmptyFileVFS(&vfs, "model.xml", (int)strlen(xml));
  memcpy(vfs.filedata[mj_findFileVFS(&vfs, "model.xml")], xml, strlen(xml));
  mjModel* m = mj_loadXML("model.xml", &vfs, error, sizeof error);
  mj_deleteVFS(&vfs);
  if (!m) {
    fprintf(stderr, "mj_loadXML: %s\n", error);
    exit(1);
  }
  return m;
}

static mjModel* load(int elliptic, int noslip, double slope) {
  const double ex = 2 * a, ey = 2 * b, ez = 2 * c;
  char xml[2048];
  snprintf(xml, sizeof xml,
           "<mujoco><compiler angle=\"radian\"/><option timestep=\"0.01\" gravity=\"0 0 -9.81\" integrator=\"Euler\" "
           "cone=\"%s\" noslip_iterations=\"%d\"/><worldbody><geom name=\"ground\" type=\"plane\" size=\"0 0 1\" "
           "euler=\"0 %.17g 0\" condim=\"3\" friction=\"0.5 0 0\"/><body><freejoint/><inertial pos=\"0 0 0\" mass=\"1\" "
           "diaginertia=\"%.17g %.17g %.17g\"/><geom type=\"box\" size=\"%.17g %.17g %.17g\" condim=\"3\" "
           "friction=\"0.5 0 0\"/></body></worldbody></mujoco>",
           elliptic ? "elliptic" : "pyramidal", noslip, slope, (ey * ey + ez * ez) / 12, (ex * ex + ez * ez) / 12,
           (ex * ex + ey * ey) / 12, a, b, c);
  mjModel* m = load_xml(xml);
  m->opt.timestep = h;
  return m;
}

/* The bouncing ball: r = 0.05 m, 0.1 kg (moments 2/5 m r^2), its lowest point dropped from 1 m
 * onto the level plane, friction 0.5, and a restitution e = 0.5 asked of MuJoCo's soft contact
 * the only way its solref allows: the damping ratio of the contact's reference dynamics, a
 * damped oscillator whose rebound over an impact is exp(-zeta pi / sqrt(1 - zeta^2)), so
 * zeta = -ln e / sqrt(pi^2 + ln^2 e) = 0.2155, with MuJoCo's default time constant 0.02 s (both
 * geoms' solref "0.02 zeta"). Printed: its first two apexes (the lowest point's local maxima
 * after the first contact, as the audit finds them) at h = 1/60 and 1/960, against e^2 h = 0.25
 * and e^4 h = 0.0625; nan for an apex that does not come within the 2.5 s (at h = 1/60 the ball
 * is still in the air after its first). */
static void bounce(int n, double apex[2]) {
  const double e = 0.5, zeta = -log(e) / sqrt(M_PI * M_PI + log(e) * log(e)), r = 0.05, m = 0.1, h0 = 1;
  char xml[2048];
  snprintf(xml, sizeof xml,
           "<mujoco><compiler angle=\"radian\"/><option timestep=\"0.01\" gravity=\"0 0 -9.81\" integrator=\"Euler\" "
           "cone=\"pyramidal\"/><worldbody><geom name=\"ground\" type=\"plane\" size=\"0 0 1\" euler=\"0 0 0\" "
           "condim=\"3\" friction=\"0.5 0 0\" solref=\"0.02 %.17g\"/><body><freejoint/><inertial pos=\"0 0 0\" "
           "mass=\"%.17g\" diaginertia=\"%.17g %.17g %.17g\"/><geom type=\"sphere\" size=\"%.17g\" condim=\"3\" "
           "friction=\"0.5 0 0\" solref=\"0.02 %.17g\"/></body></worldbody></mujoco>",
           zeta, m, 0.4 * m * r * r, 0.4 * m * r * r, 0.4 * m * r * r, r, zeta);
  mjModel* model = load_xml(xml);
  const double h = 2.5 / n; /* 2.5 s */
  model->opt.timestep = h;
  mjData* d = mj_makeData(model);
  d->qpos[2] = h0 + r;
  mj_forward(model, d);
  double* z = malloc(sizeof(double) * (size_t)(n + 1));
  z[0] = d->qpos[2] - r;
  for (int k = 1; k <= n; ++k) {
    mj_step(model, d);
    z[k] = d->qpos[2] - r;
  }
  /* The audit's apexes: after the ball has come within a tenth of half the expected apex
   * (e^(2k) h0 / 2) past half the fall time, the next local maximum above 0.1 mm. */
  const double fall = sqrt(2 * h0 / 9.81);
  int k = 0, touched = 0;
  apex[0] = apex[1] = NAN;
  for (int i = 1; i + 1 <= n && k < 2; ++i) {
    if (z[i] < 0.5 * h0 * pow(e, 2 * k) * 0.1 + 1e-9 && !touched && i * h > fall * 0.5) touched = 1;
    if (touched && z[i] > z[i - 1] && z[i] >= z[i + 1] && z[i] > 1e-4) {
      apex[k++] = z[i];
      touched = 0;
    }
  }
  free(z);
  mj_deleteData(d);
  mj_deleteModel(model);
}

/* The start and every step are read as the audit reads them: mj_kinematics, mj_comPos and
 * mj_comVel after the start's mj_forward and after each mj_step. The box starts exactly on the
 * plane, and whether MuJoCo's first step on the slope finds the contact depends on the last bit
 * of the start's quaternion, which MuJoCo 2.2.2 normalizes in qpos in place at each such call
 * (mj_forward and mj_kinematics each move it by an ulp): with the reading, the first step finds
 * no contact and the box falls g h^2 = 2.7 mm onto the slope; without it, the contact holds it
 * from the first step. That changes the creep's total by 5e-4 m (printed both ways), not its
 * rate over the second half, which is what the audit's verdict uses. */
static void read_state(const mjModel* m, mjData* d) {
  mj_kinematics(m, d);
  mj_comPos(m, d);
  mj_comVel(m, d);
}

/* The quaternion (w, x, y, z) of a turn by `angle` about the coordinate axis `axis` (1: y, 2: z),
 * computed as the audit computes it: the rotation matrix (Eigen's AngleAxis, whose diagonal
 * entry on the axis is (1 - cos) + cos), then the trace method (Eigen's Quaternion from a
 * matrix). */
static void turn_quaternion(int axis, double angle, double q[4]) {
  const double c = cos(angle), s = sin(angle);
  double m[3][3] = {{c, 0, 0}, {0, c, 0}, {0, 0, c}};
  m[axis][axis] = (1 - c) + c;
  const int i = (axis + 1) % 3, j = (axis + 2) % 3; /* m(i, j) = -s, m(j, i) = s */
  m[i][j] = -s, m[j][i] = s;
  double t = m[0][0] + m[1][1] + m[2][2];
  t = sqrt(t + 1);
  q[0] = 0.5 * t;
  t = 0.5 / t;
  q[1] = (m[2][1] - m[1][2]) * t;
  q[2] = (m[0][2] - m[2][0]) * t;
  q[3] = (m[1][0] - m[0][1]) * t;
}

/* The slide at theta, psi (degrees): the horizontal displacement after 60 steps over v0^2 / (2 mu g). */
static double slide(int elliptic, double theta_degrees, double psi_degrees) {
  mjModel* m = load(elliptic, 0, 0);
  mjData* d = mj_makeData(m);
  const double theta = theta_degrees * M_PI / 180, psi = psi_degrees * M_PI / 180, v0 = 2;
  d->qpos[0] = 0, d->qpos[1] = 0, d->qpos[2] = c;
  turn_quaternion(2, psi, d->qpos + 3);
  d->qvel[0] = v0 * cos(theta), d->qvel[1] = v0 * sin(theta);
  mj_forward(m, d);
  read_state(m, d);
  for (int k = 0; k < 60; ++k) {
    mj_step(m, d);
    read_state(m, d);
  }
  const double dx = d->qpos[0], dy = d->qpos[1];
  mj_deleteData(d);
  mj_deleteModel(m);
  return sqrt(dx * dx + dy * dy) / (v0 * v0 / (2 * mu * g));
}

/* The box at rest on the slope for 180 steps: the creep down the fall line and its rate over the second half. */
static void creep(int elliptic, int noslip, int read, double* total, double* rate) {
  const double slope = 0.25;
  mjModel* m = load(elliptic, noslip, slope);
  mjData* d = mj_makeData(m);
  const double n[3] = {sin(slope), 0, cos(slope)}, fall[3] = {cos(slope), 0, -sin(slope)};
  for (int i = 0; i < 3; ++i) d->qpos[i] = c * n[i];
  turn_quaternion(1, slope, d->qpos + 3);
  mj_forward(m, d);
  if (read) read_state(m, d);
  double start[3], half = 0;
  for (int i = 0; i < 3; ++i) start[i] = d->qpos[i];
  for (int k = 1; k <= 180; ++k) {
    mj_step(m, d);
    if (read) read_state(m, d);
    if (k == 90)
      for (int i = 0; i < 3; ++i) half += (d->qpos[i] - start[i]) * fall[i];
  }
  *total = 0;
  for (int i = 0; i < 3; ++i) *total += (d->qpos[i] - start[i]) * fall[i];
  *rate = (*total - half) / 1.5;
  mj_deleteData(d);
  mj_deleteModel(m);
}

int main(void) {
  printf("mujoco_version %s\n", mj_versionString());
  const char* cones[2] = {"pyramidal", "elliptic"};
  for (int elliptic = 0; elliptic < 2; ++elliptic) {
    double lo = INFINITY, hi = 0;
    for (int psi = 0; psi <= 30; psi += 30)
      for (int theta = 0; theta <= 90; theta += 15) {
        const double r = slide(elliptic, theta, psi);
        printf("%s_slide_theta%d_psi%d_over_exact %.9f\n", cones[elliptic], theta, psi, r);
        lo = fmin(lo, r), hi = fmax(hi, r);
      }
    printf("%s_slide_spread %.6e\n", cones[elliptic], hi - lo);
    double total, rate;
    creep(elliptic, 0, 1, &total, &rate);
    printf("%s_slope_creep %.6e\n", cones[elliptic], total);
    printf("%s_slope_creep_rate %.6e\n", cones[elliptic], rate);
    creep(elliptic, 0, 0, &total, &rate);
    printf("%s_slope_creep_unread %.6e\n", cones[elliptic], total);
    printf("%s_slope_creep_rate_unread %.6e\n", cones[elliptic], rate);
    /* MuJoCo's NoSlip pass (option noslip_iterations, 0 by default; Computation chapter: "This
     * suppresses the contact slip that is inherent to soft-constraint models"), 10 iterations. */
    creep(elliptic, 10, 1, &total, &rate);
    printf("%s_noslip10_slope_creep %.6e\n", cones[elliptic], total);
    printf("%s_noslip10_slope_creep_rate %.6e\n", cones[elliptic], rate);
  }
  for (int n = 150; n <= 2400; n *= 16) {
    double apex[2];
    bounce(n, apex);
    printf("bounce_apex1_n%d %.9e\n", n, apex[0]);
    printf("bounce_apex2_n%d %.9e\n", n, apex[1]);
  }
  return 0;
}
