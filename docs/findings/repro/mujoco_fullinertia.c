/* MuJoCo's compiler given a body's full inertia tensor (MJCF's fullinertia, or a URDF
 * <inertia> with products of inertia, which its URDF reader passes the same way): the tensor
 * the compiled model holds, R diag(body_inertia) R^T with R from body_iquat, against the
 * tensor given; and the joint-space mass matrix of a hinge through the centre of mass,
 * which is a^T I a exactly (a the unit axis). Uses MuJoCo only.
 *
 * 1. One body, mass 1, centre of mass on a hinge about z: M = I_zz, the double the text
 *    gives. The tensor is the shrunk counterexample of mechcheck's equations-of-motion audit
 *    (docs/findings/dynamics.md).
 * 2. mju_eig3, the function the compiler calls on the tensor (src/user/user_objects.cc),
 *    on the same tensor: its iterations, the off-diagonal element it leaves and the
 *    rotation that element still asks for.
 * 3. mju_eig3 on 10000 tensors R diag(l) R^T with principal moments uniform in [0.1, 1]
 *    (triangle inequality held) and R uniform: the largest and the median relative error
 *    max_ij |R' diag(l') R'^T - I|_ij / max(l) of what it returns.
 *
 * Build: cc mujoco_fullinertia.c -lmujoco -lm
 * Prints: lines "name value" (see ci/findings). */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <mujoco/mujoco.h>

/* ixx iyy izz ixy ixz iyz of the counterexample, as its URDF gives them. */
static const double given[6] = {0.65228281870983662, 0.99999469420290399, 0.85162873708725917,
                                -0.0013582771479765583, 0.23139648338362692, 0.00090389711068041825};

static mjModel* load(const char* xml) {
  mjVFS vfs;
  mj_defaultVFS(&vfs);
  mj_makeEmptyFileVFS(&vfs, "body.xml", (int)strlen(xml));
  memcpy(vfs.filedata[mj_findFileVFS(&vfs, "body.xml")], xml, strlen(xml));
  char error[1000] = "";
  mjModel* m = mj_loadXML("body.xml", &vfs, error, sizeof error);
  mj_deleteVFS(&vfs);
  if (!m) {
    fprintf(stderr, "mj_loadXML: %s\n", error);
    exit(1);
  }
  return m;
}

/* The symmetric matrix of ixx iyy izz ixy ixz iyz (MuJoCo's fullinertia order). */
static void full_of(const double f[6], double a[9]) {
  a[0] = f[0], a[1] = f[3], a[2] = f[4];
  a[3] = f[3], a[4] = f[1], a[5] = f[5];
  a[6] = f[4], a[7] = f[5], a[8] = f[2];
}

/* max_ij |R diag(l) R^T - a|_ij / max(l), R of quaternion q. */
static double tensor_error(const double q[4], const double l[3], const double a[9]) {
  double r[9], back[9], worst = 0, largest = fmax(l[0], fmax(l[1], l[2]));
  mju_quat2Mat(r, q);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      back[3 * i + j] = 0;
      for (int k = 0; k < 3; ++k) back[3 * i + j] += r[3 * i + k] * l[k] * r[3 * j + k];
      worst = fmax(worst, fabs(back[3 * i + j] - a[3 * i + j]));
    }
  return worst / largest;
}

/* Deterministic uniform numbers in [0, 1) (xorshift64*, fixed seed). */
static uint64_t state = 20261126;
static double uniform(void) {
  state ^= state >> 12, state ^= state << 25, state ^= state >> 27;
  return (double)((state * 2685821657736338717ull) >> 11) * 0x1p-53;
}

static int by_value(const void* x, const void* y) {
  const double a = *(const double*)x, b = *(const double*)y;
  return (a > b) - (a < b);
}

int main(void) {
  const double eps = 0x1p-52;
  double a[9];
  full_of(given, a);

  /* 1. The compiled model. */
  char xml[1000];
  snprintf(xml, sizeof xml,
           "<mujoco><option gravity=\"0 0 0\"/><worldbody><body><joint type=\"hinge\" axis=\"0 0 1\"/>"
           "<inertial pos=\"0 0 0\" mass=\"1\" fullinertia=\"%.17g %.17g %.17g %.17g %.17g %.17g\"/>"
           "</body></worldbody></mujoco>",
           given[0], given[1], given[2], given[3], given[4], given[5]);
  mjModel* m = load(xml);
  mjData* d = mj_makeData(m);
  mj_forward(m, d);
  double mass_matrix[1];
  mj_fullM(m, mass_matrix, d->qM);
  const double exact = given[2];
  printf("mass_matrix %.17g\n", mass_matrix[0]);
  printf("exact %.17g\n", exact);
  printf("mass_matrix_error %.6e\n", fabs(mass_matrix[0] - exact));
  printf("mass_matrix_relative_error %.3e\n", fabs(mass_matrix[0] - exact) / exact);
  printf("mass_matrix_error_eps %.3e\n", fabs(mass_matrix[0] - exact) / (eps * exact));
  printf("compiled_tensor_relative_error %.3e\n", tensor_error(m->body_iquat + 4, m->body_inertia + 3, a));
  mj_deleteData(d);
  mj_deleteModel(m);

  /* 2. mju_eig3 on the same tensor. */
  double l[3], vec[9], q[4];
  const int iterations = mju_eig3(l, vec, q, a);
  double rot[9], tmp[9], diag[9];
  mju_quat2Mat(rot, q);
  mju_mulMatTMat(tmp, rot, a, 3, 3, 3);
  mju_mulMatMat(diag, tmp, rot, 3, 3, 3);
  double off = fabs(diag[1]);
  int rk = 0, ck = 1;
  if (fabs(diag[2]) > off) off = fabs(diag[2]), rk = 0, ck = 2;
  if (fabs(diag[5]) > off) off = fabs(diag[5]), rk = 1, ck = 2;
  /* The Jacobi rotation tan(theta) = t that would annihilate it, as mju_eig3 computes it. */
  const double tau = (diag[4 * ck] - diag[4 * rk]) / (2 * diag[3 * rk + ck]);
  const double t = (tau >= 0 ? 1 : -1) / (fabs(tau) + sqrt(1 + tau * tau));
  printf("eig3_iterations %d\n", iterations);
  printf("eig3_offdiagonal_left %.3e\n", off);
  printf("eig3_rotation_left %.3e\n", fabs(t));
  printf("eig3_cosine_left_minus_one %.3e\n", 1 / sqrt(1 + t * t) - 1);
  printf("eig3_tensor_relative_error %.3e\n", tensor_error(q, l, a));

  /* 3. 10000 random tensors. */
  enum { count = 10000 };
  static double errors[count];
  for (int n = 0; n < count;) {
    double p[3] = {0.1 + 0.9 * uniform(), 0.1 + 0.9 * uniform(), 0.1 + 0.9 * uniform()};
    if (p[0] > p[1] + p[2] || p[1] > p[0] + p[2] || p[2] > p[0] + p[1]) continue;
    /* A uniform rotation (Shoemake's subgroup algorithm). */
    const double u1 = uniform(), u2 = 2 * mjPI * uniform(), u3 = 2 * mjPI * uniform();
    const double qr[4] = {sqrt(1 - u1) * sin(u2), sqrt(1 - u1) * cos(u2), sqrt(u1) * sin(u3), sqrt(u1) * cos(u3)};
    double r[9], t9[9];
    mju_quat2Mat(r, qr);
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        t9[3 * i + j] = 0;
        for (int k = 0; k < 3; ++k) t9[3 * i + j] += r[3 * i + k] * p[k] * r[3 * j + k];
      }
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < i; ++j) t9[3 * i + j] = t9[3 * j + i]; /* exactly symmetric */
    mju_eig3(l, vec, q, t9);
    errors[n++] = tensor_error(q, l, t9);
  }
  qsort(errors, count, sizeof errors[0], by_value);
  printf("random_tensors %d\n", count);
  printf("random_largest_relative_error %.3e\n", errors[count - 1]);
  printf("random_median_relative_error %.3e\n", errors[count / 2]);
  int above = 0;
  for (int n = 0; n < count; ++n) above += errors[n] > 1e-12;
  printf("random_above_1e-12 %d\n", above);
  return 0;
}
