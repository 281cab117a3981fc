/* GSL's one-step types at fixed steps: what gsl_odeiv2_step_order returns against the
 * order of the solution gsl_odeiv2_step_apply propagates, and the order of the embedded
 * formula rk2 uses for its error estimate (y + yerr: rk2.c sets yerr = h (k2 - (k1 + 4 k2 +
 * k3)/6), the midpoint rule's step less the propagated one). Uses GSL only.
 *
 * Problem: q' = p, p' = -q on two degrees of freedom, q(0) = (1, 0), p(0) = (1/4, 3/4),
 * over one period 2 pi; error |y(2 pi) - y(0)| / |y(0)|; the order from n = 256 to 512
 * steps.
 *
 * Build: cc gsl_step_order.c -lgsl -lgslcblas -lm
 * Prints: lines "name value" (see ci/findings). */
#include <math.h>
#include <stdio.h>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_odeiv2.h>
#include <gsl/gsl_version.h>

static int rhs(double t, const double y[], double f[], void* p) {
  (void)t, (void)p;
  f[0] = y[2], f[1] = y[3], f[2] = -y[0], f[3] = -y[1];
  return GSL_SUCCESS;
}

static double period_error(const gsl_odeiv2_step_type* type, long n, int embedded) {
  const double y0[4] = {1, 0, 0.25, 0.75}, pi = acos(-1.0), h = 2 * pi / n;
  double y[4] = {1, 0, 0.25, 0.75}, yerr[4];
  gsl_odeiv2_system sys = {rhs, NULL, 4, NULL};
  gsl_odeiv2_step* s = gsl_odeiv2_step_alloc(type, 4);
  for (long i = 0; i < n; ++i) {
    gsl_odeiv2_step_apply(s, i * h, h, y, yerr, NULL, NULL, &sys);
    if (embedded)
      for (int k = 0; k < 4; ++k) y[k] += yerr[k];
  }
  gsl_odeiv2_step_free(s);
  double e2 = 0, n2 = 0;
  for (int k = 0; k < 4; ++k) e2 += (y[k] - y0[k]) * (y[k] - y0[k]), n2 += y0[k] * y0[k];
  return sqrt(e2 / n2);
}

int main(void) {
  printf("gsl_version %s\n", GSL_VERSION);
  const struct {
    const char* name;
    const gsl_odeiv2_step_type* const* type;
  } types[] = {{"rk2", &gsl_odeiv2_step_rk2},   {"rk4", &gsl_odeiv2_step_rk4},
               {"rkf45", &gsl_odeiv2_step_rkf45}, {"rkck", &gsl_odeiv2_step_rkck},
               {"rk8pd", &gsl_odeiv2_step_rk8pd}};
  for (int i = 0; i < 5; ++i) {
    gsl_odeiv2_step* s = gsl_odeiv2_step_alloc(*types[i].type, 4);
    printf("%s_step_order %u\n", types[i].name, gsl_odeiv2_step_order(s));
    gsl_odeiv2_step_free(s);
    /* rk8pd reaches the rounding floor before 256 steps: coarser steps for it. */
    const long n = i == 4 ? 16 : 256;
    printf("%s_propagated_order %.3f\n", types[i].name,
           log2(period_error(*types[i].type, n, 0) / period_error(*types[i].type, 2 * n, 0)));
  }
  printf("rk2_embedded_order %.3f\n", log2(period_error(gsl_odeiv2_step_rk2, 256, 1) /
                                            period_error(gsl_odeiv2_step_rk2, 512, 1)));
  return 0;
}
