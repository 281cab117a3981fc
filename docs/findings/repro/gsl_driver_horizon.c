/* GSL's adaptive driver controls the local error of each step: its global error against
 * the tolerance grows with the horizon. rk8pd on a Kepler orbit of eccentricity 0.5 at
 * epsabs = epsrel = 1e-8, over 1, 4, 16 and 64 periods. Uses GSL only.
 *
 * Problem: H = |p|^2/2 - 1/|q| in the plane, a = 1 (period 2 pi), e = 0.5, started at true
 * anomaly 1: r = p / (1 + e cos 1) with p = a (1 - e^2), velocity sqrt(1/p) (-sin 1, e +
 * cos 1). After m periods the exact state is the initial one: error |y(2 pi m) - y(0)| /
 * |y(0)|. Driver: gsl_odeiv2_driver_alloc_y_new(sys, rk8pd, 1e-3 t1, tol, tol).
 *
 * Build: cc gsl_driver_horizon.c -lgsl -lgslcblas -lm
 * Prints: lines "name value" (see ci/findings). */
#include <math.h>
#include <stdio.h>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_odeiv2.h>

static int rhs(double t, const double y[], double f[], void* p) {
  (void)t, (void)p;
  const double r2 = y[0] * y[0] + y[1] * y[1], r3 = r2 * sqrt(r2);
  f[0] = y[2], f[1] = y[3], f[2] = -y[0] / r3, f[3] = -y[1] / r3;
  return GSL_SUCCESS;
}

int main(void) {
  gsl_set_error_handler_off();
  const double e = 0.5, p = 1 - e * e, nu = 1, r = p / (1 + e * cos(nu)), pi = acos(-1.0), tol = 1e-8;
  const double y0[4] = {r * cos(nu), r * sin(nu), -sin(nu) / sqrt(p), (e + cos(nu)) / sqrt(p)};
  const double scale = sqrt(y0[0] * y0[0] + y0[1] * y0[1] + y0[2] * y0[2] + y0[3] * y0[3]);
  gsl_odeiv2_system sys = {rhs, NULL, 4, NULL};
  for (int m = 1; m <= 64; m *= 4) {
    const double t1 = 2 * pi * m;
    double y[4] = {y0[0], y0[1], y0[2], y0[3]}, t = 0;
    gsl_odeiv2_driver* d = gsl_odeiv2_driver_alloc_y_new(&sys, gsl_odeiv2_step_rk8pd, 1e-3 * t1, tol, tol);
    gsl_odeiv2_driver_set_nmax(d, 10000000);
    const int status = gsl_odeiv2_driver_apply(d, &t, t1, y);
    gsl_odeiv2_driver_free(d);
    if (status != GSL_SUCCESS) {
      printf("rk8pd_error_over_tol_after_%d_periods failed_%d\n", m, status);
      continue;
    }
    double e2 = 0;
    for (int k = 0; k < 4; ++k) e2 += (y[k] - y0[k]) * (y[k] - y0[k]);
    printf("rk8pd_error_over_tol_after_%d_periods %.3e\n", m, sqrt(e2) / scale / tol);
  }
  return 0;
}
