/* MuJoCo's RK4 (mjINT_RK4) on a free symmetric top: the order of the orientation, the
 * one-step orientation error against h^3/12 |w x w'|, and the same four mj_forward
 * evaluations with each stage's body angular velocity corrected by the dexp^-1 series.
 * Uses MuJoCo only.
 *
 * The body: I = (1, 1, 2), body angular velocity w0 = (0.6, 0, 1), no gravity, starting
 * at the identity orientation. Exact motion: w turns about the body's x3 at rate
 * (I3 - I1) w3 / I1 = 1; the symmetry axis x3 turns about the angular momentum
 * M = (0.6, 0, 2) at |M| / I1 (Landau & Lifshitz section 33).
 *
 * Build: cc mujoco_rk4_orientation.c -lmujoco -lm
 * Prints: lines "name value" (see ci/findings). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <mujoco/mujoco.h>

static const char* model_xml =
    "<mujoco><option timestep=\"0.01\" gravity=\"0 0 0\" integrator=\"RK4\"/>"
    "<worldbody><body><freejoint/><inertial pos=\"0 0 0\" mass=\"1\" diaginertia=\"1 1 2\"/>"
    "</body></worldbody></mujoco>";

static mjModel* load(void) {
  mjVFS vfs;
  mj_defaultVFS(&vfs);
  mj_makeEmptyFileVFS(&vfs, "top.xml", (int)strlen(model_xml));
  memcpy(vfs.filedata[mj_findFileVFS(&vfs, "top.xml")], model_xml, strlen(model_xml));
  char error[1000] = "";
  mjModel* m = mj_loadXML("top.xml", &vfs, error, sizeof error);
  mj_deleteVFS(&vfs);
  if (!m) {
    fprintf(stderr, "mj_loadXML: %s\n", error);
    exit(1);
  }
  return m;
}

static void start(const mjModel* m, mjData* d) {
  mj_resetData(m, d);
  d->qpos[3] = 1; /* identity quaternion (w x y z) */
  d->qvel[3] = 0.6, d->qvel[4] = 0, d->qvel[5] = 1; /* body frame */
  mj_forward(m, d);
}

/* The exact symmetry axis (world frame) at time t. */
static void exact_axis(double t, double x3[3]) {
  const double mvec[3] = {0.6, 0, 2}, mn = sqrt(0.36 + 4);
  const double k[3] = {mvec[0] / mn, mvec[1] / mn, mvec[2] / mn}, e3[3] = {0, 0, 1};
  const double phi = mn / 1.0 * t, c = cos(phi), s = sin(phi);
  const double kxe[3] = {k[1] * e3[2] - k[2] * e3[1], k[2] * e3[0] - k[0] * e3[2], k[0] * e3[1] - k[1] * e3[0]};
  const double kd = k[2];
  for (int i = 0; i < 3; ++i) x3[i] = e3[i] * c + kxe[i] * s + k[i] * kd * (1 - c);
}

static void axis_of(const mjData* d, double x3[3]) {
  double r[9];
  mju_quat2Mat(r, d->qpos + 3);
  x3[0] = r[2], x3[1] = r[5], x3[2] = r[8]; /* third column */
}

static void cross(const double a[3], const double b[3], double c[3]) {
  c[0] = a[1] * b[2] - a[2] * b[1];
  c[1] = a[2] * b[0] - a[0] * b[2];
  c[2] = a[0] * b[1] - a[1] * b[0];
}

/* RK4 with the orientation as a Runge-Kutta-Munthe-Kaas method: mj_forward per stage,
 * stage orientation q0 exp(Theta_j), k_j = w_j + Theta_j x w_j / 2 + Theta_j x (Theta_j x
 * w_j) / 12 for the body angular velocity w_j. */
static void rk4_dexp(const mjModel* m, mjData* d, double h) {
  const int nq = m->nq, nv = m->nv;
  double q0[7], v0[6], k[4][6], acc[4][6], mix[6], v[6];
  static const double a[4][3] = {{0, 0, 0}, {0.5, 0, 0}, {0, 0.5, 0}, {0, 0, 1}};
  static const double b[4] = {1.0 / 6, 1.0 / 3, 1.0 / 3, 1.0 / 6};
  memcpy(q0, d->qpos, sizeof(double) * nq);
  memcpy(v0, d->qvel, sizeof(double) * nv);
  for (int j = 0; j < 4; ++j) {
    for (int i = 0; i < nv; ++i) {
      mix[i] = 0, v[i] = v0[i];
      for (int l = 0; l < j; ++l) mix[i] += a[j][l] * k[l][i], v[i] += h * a[j][l] * acc[l][i];
    }
    memcpy(d->qpos, q0, sizeof(double) * nq);
    mj_integratePos(m, d->qpos, mix, h);
    memcpy(d->qvel, v, sizeof(double) * nv);
    mj_forward(m, d);
    memcpy(acc[j], d->qacc, sizeof(double) * nv);
    memcpy(k[j], v, sizeof(double) * nv);
    double theta[3], w[3] = {v[3], v[4], v[5]}, tw[3], ttw[3];
    for (int i = 0; i < 3; ++i) theta[i] = h * mix[3 + i];
    cross(theta, w, tw);
    cross(theta, tw, ttw);
    for (int i = 0; i < 3; ++i) k[j][3 + i] = w[i] + tw[i] / 2 + ttw[i] / 12;
  }
  for (int i = 0; i < nv; ++i) {
    mix[i] = 0, v[i] = v0[i];
    for (int j = 0; j < 4; ++j) mix[i] += b[j] * k[j][i], v[i] += h * b[j] * acc[j][i];
  }
  memcpy(d->qpos, q0, sizeof(double) * nq);
  mj_integratePos(m, d->qpos, mix, h);
  memcpy(d->qvel, v, sizeof(double) * nv);
  d->time += h;
}

static double axis_error(mjModel* m, mjData* d, int n, double t_end, int corrected) {
  start(m, d);
  const double h = t_end / n;
  m->opt.timestep = h;
  for (int i = 0; i < n; ++i) {
    if (corrected)
      rk4_dexp(m, d, h);
    else
      mj_step(m, d);
  }
  double x[3], e[3];
  axis_of(d, x);
  exact_axis(t_end, e);
  return sqrt((x[0] - e[0]) * (x[0] - e[0]) + (x[1] - e[1]) * (x[1] - e[1]) + (x[2] - e[2]) * (x[2] - e[2]));
}

int main(void) {
  mjModel* m = load();
  mjData* d = mj_makeData(m);
  printf("mujoco_version %d\n", mj_version());
  /* Global order of the axis at t = 5: log2 of the error ratio as n doubles. */
  for (int corrected = 0; corrected <= 1; ++corrected) {
    double previous = 0, order = 0;
    for (int n = 64; n <= 2048; n *= 2) {
      const double e = axis_error(m, d, n, 5.0, corrected);
      if (previous > 0) order = log2(previous / e);
      previous = e;
    }
    printf("%s_axis_order %.3f\n", corrected ? "rk4_dexp_corrected" : "rk4", order);
  }
  /* One step of h from the start: the angle of the orientation error against the
   * predicted h^3/12 |w x w'|. Euler's equations at t = 0 (I = (1, 1, 2), w = (0.6, 0, 1)):
   * I2 w2' = (I3 - I1) w3 w1 = 0.6, the others 0. The exact rotation is
   * R(t) = Rot(M, |M| t / I1) Rot(e3, (I1 - I3) w3 t / I1), the second in the body frame. */
  const double w[3] = {0.6, 0, 1}, wdot[3] = {0, 0.6, 0};
  double wxw[3];
  cross(w, wdot, wxw);
  const double predicted_per_h3 = sqrt(wxw[0] * wxw[0] + wxw[1] * wxw[1] + wxw[2] * wxw[2]) / 12;
  const double h = 1e-3;
  start(m, d);
  m->opt.timestep = h;
  mj_step(m, d);
  {
    const double mn = sqrt(0.36 + 4), ka[3] = {0.6 / mn, 0, 2 / mn};
    const double angle_a = mn * h, angle_b = (1.0 - 2.0) * 1.0 * h;
    double qa[4], qb[4], qe[4], conj[4], qerr[4];
    qa[0] = cos(angle_a / 2);
    for (int i = 0; i < 3; ++i) qa[1 + i] = ka[i] * sin(angle_a / 2);
    qb[0] = cos(angle_b / 2), qb[1] = 0, qb[2] = 0, qb[3] = sin(angle_b / 2);
    mju_mulQuat(qe, qa, qb);
    mju_negQuat(conj, qe);
    mju_mulQuat(qerr, conj, d->qpos + 3);
    const double sinhalf = sqrt(qerr[1] * qerr[1] + qerr[2] * qerr[2] + qerr[3] * qerr[3]);
    const double angle = 2 * atan2(sinhalf, fabs(qerr[0]));
    printf("one_step_error_over_prediction %.6f\n", angle / (predicted_per_h3 * h * h * h));
  }
  mj_deleteData(d);
  mj_deleteModel(m);
  return 0;
}
