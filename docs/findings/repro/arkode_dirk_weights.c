/* ARKODE's CASH_5_2_4 and CASH_5_3_4 DIRK tables: the sum of their weights, and the
 * global error of ARKStep at fixed steps on a harmonic oscillator, which stops falling at
 * the size that sum's defect sets. Uses SUNDIALS only.
 *
 * Problem: q' = p, p' = -q on two degrees of freedom, q(0) = (1, 0), p(0) = (1/4, 3/4),
 * over one period 2 pi; error |y(2 pi) - y(0)| / |y(0)|. ARKStep with the table as its
 * implicit part (no explicit part), dense linear solver and analytic Jacobian, Newton
 * tolerances 1e-14, fixed step 2 pi / n.
 *
 * Build: cc arkode_cash_weights.c -lsundials_arkode -lsundials_nvecserial
 *        -lsundials_sunlinsoldense -lsundials_sunmatrixdense -lm
 * Prints: lines "name value" (see ci/findings). */
#include <math.h>
#include <stdio.h>

#include <arkode/arkode_arkstep.h>
#include <arkode/arkode_butcher_dirk.h>
#include <nvector/nvector_serial.h>
#include <sundials/sundials_version.h>
#include <sunlinsol/sunlinsol_dense.h>
#include <sunmatrix/sunmatrix_dense.h>

static int rhs(realtype t, N_Vector y, N_Vector ydot, void* user) {
  (void)t, (void)user;
  const realtype* v = N_VGetArrayPointer(y);
  realtype* d = N_VGetArrayPointer(ydot);
  d[0] = v[2], d[1] = v[3], d[2] = -v[0], d[3] = -v[1];
  return 0;
}

static int jac(realtype t, N_Vector y, N_Vector f, SUNMatrix j, void* user, N_Vector a, N_Vector b, N_Vector c) {
  (void)t, (void)y, (void)f, (void)user, (void)a, (void)b, (void)c;
  SUNMatZero(j);
  SM_ELEMENT_D(j, 0, 2) = 1, SM_ELEMENT_D(j, 1, 3) = 1, SM_ELEMENT_D(j, 2, 0) = -1, SM_ELEMENT_D(j, 3, 1) = -1;
  return 0;
}

static double period_error(SUNContext ctx, ARKODE_DIRKTableID id, long n) {
  const double y0[4] = {1, 0, 0.25, 0.75}, pi = acos(-1.0), h = 2 * pi / n;
  N_Vector y = N_VNew_Serial(4, ctx);
  for (int i = 0; i < 4; ++i) NV_Ith_S(y, i) = y0[i];
  void* mem = ARKStepCreate(NULL, rhs, 0, y, ctx);
  ARKodeButcherTable table = ARKodeButcherTable_LoadDIRK(id);
  ARKStepSetTables(mem, table->q, table->p, table, NULL);
  ARKStepSStolerances(mem, 1e-14, 1e-14);
  SUNMatrix m = SUNDenseMatrix(4, 4, ctx);
  SUNLinearSolver ls = SUNLinSol_Dense(y, m, ctx);
  ARKStepSetLinearSolver(mem, ls, m);
  ARKStepSetJacFn(mem, jac);
  ARKStepSetFixedStep(mem, h);
  ARKStepSetMaxNumSteps(mem, 2 * n);
  realtype t = 0;
  double error = NAN;
  if (ARKStepEvolve(mem, 2 * pi, y, &t, ARK_NORMAL) >= 0) {
    double e2 = 0, n2 = 0;
    for (int i = 0; i < 4; ++i) e2 += (NV_Ith_S(y, i) - y0[i]) * (NV_Ith_S(y, i) - y0[i]), n2 += y0[i] * y0[i];
    error = sqrt(e2 / n2);
  }
  ARKodeButcherTable_Free(table);
  ARKStepFree(&mem);
  SUNLinSolFree(ls);
  SUNMatDestroy(m);
  N_VDestroy(y);
  return error;
}

int main(void) {
  char version[64];
  SUNDIALSGetVersion(version, sizeof version);
  printf("sundials_version %s\n", version);
  SUNContext ctx;
  SUNContext_Create(NULL, &ctx);
  const struct {
    const char* name;
    ARKODE_DIRKTableID id;
  } tables[] = {{"cash_5_2_4", ARKODE_CASH_5_2_4}, {"cash_5_3_4", ARKODE_CASH_5_3_4}, {"sdirk_5_3_4", ARKODE_SDIRK_5_3_4}};
  for (int k = 0; k < 3; ++k) {
    ARKodeButcherTable t = ARKodeButcherTable_LoadDIRK(tables[k].id);
    long double sum = 0;
    for (int i = 0; i < t->stages; ++i) sum += (long double)t->b[i];
    printf("%s_weight_sum_minus_one %.3Le\n", tables[k].name, sum - 1);
    printf("%s_gamma %.17g\n", tables[k].name, t->A[0][0]);
    ARKodeButcherTable_Free(t);
    for (long n = 4096; n <= 16384; n *= 4)
      printf("%s_error_n%ld %.3e\n", tables[k].name, n, period_error(ctx, tables[k].id, n));
  }
  SUNContext_Free(&ctx);
  return 0;
}
