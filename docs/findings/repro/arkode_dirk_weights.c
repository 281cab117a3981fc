/* ARKODE's CASH_5_2_4, CASH_5_3_4 and BILLINGTON_3_3_2 DIRK tables: their first two order
 * conditions (method b and embedding d), and what ARKStep computes with them at fixed steps.
 * SDIRK_5_3_4 beside them, as a table whose weights sum to 1. Uses SUNDIALS only.
 *
 * 0. The weights' sums and second-order condition, computed from the table as loaded.
 * 1. y' = 1 on [0, 1], y(0) = 0, 64 steps: every Runge-Kutta method whose weights sum to 1
 *    integrates it exactly (y_{n+1} = y_n + h sum(b)), so y(1) - 1 is the weights' defect.
 * 2. q' = p, p' = -q on two degrees of freedom, q(0) = (1, 0), p(0) = (1/4, 3/4), over one
 *    period 2 pi; error |y(2 pi) - y(0)| / |y(0)|, which stops falling at the size the
 *    defect sets (reached at these step counts by the fourth-order CASH tables only).
 * ARKStep with the table as its implicit part (no explicit part), dense linear solver and
 * analytic Jacobian, Newton tolerances 1e-14, fixed step.
 *
 * Build: cc arkode_dirk_weights.c -lsundials_arkode -lsundials_nvecserial
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

static int oscillator(realtype t, N_Vector y, N_Vector ydot, void* user) {
  (void)t, (void)user;
  const realtype* v = N_VGetArrayPointer(y);
  realtype* d = N_VGetArrayPointer(ydot);
  d[0] = v[2], d[1] = v[3], d[2] = -v[0], d[3] = -v[1];
  return 0;
}

static int oscillator_jacobian(realtype t, N_Vector y, N_Vector f, SUNMatrix j, void* user, N_Vector a,
                               N_Vector b, N_Vector c) {
  (void)t, (void)y, (void)f, (void)user, (void)a, (void)b, (void)c;
  SUNMatZero(j);
  SM_ELEMENT_D(j, 0, 2) = 1, SM_ELEMENT_D(j, 1, 3) = 1, SM_ELEMENT_D(j, 2, 0) = -1, SM_ELEMENT_D(j, 3, 1) = -1;
  return 0;
}

static int constant_rate(realtype t, N_Vector y, N_Vector ydot, void* user) {
  (void)t, (void)y, (void)user;
  NV_Ith_S(ydot, 0) = 1;
  return 0;
}

static int zero_jacobian(realtype t, N_Vector y, N_Vector f, SUNMatrix j, void* user, N_Vector a, N_Vector b,
                         N_Vector c) {
  (void)t, (void)y, (void)f, (void)user, (void)a, (void)b, (void)c;
  SUNMatZero(j);
  return 0;
}

/* y(t_end) from y0 by ARKStep with the DIRK table id at n fixed steps; NAN when it fails. */
static int run(SUNContext ctx, ARKODE_DIRKTableID id, ARKRhsFn f, ARKLsJacFn jac, int dim, const double* y0,
               double t_end, long n, double* y_end) {
  N_Vector y = N_VNew_Serial(dim, ctx);
  for (int i = 0; i < dim; ++i) NV_Ith_S(y, i) = y0[i];
  void* mem = ARKStepCreate(NULL, f, 0, y, ctx);
  ARKodeButcherTable table = ARKodeButcherTable_LoadDIRK(id);
  ARKStepSetTables(mem, table->q, table->p, table, NULL);
  ARKStepSStolerances(mem, 1e-14, 1e-14);
  SUNMatrix m = SUNDenseMatrix(dim, dim, ctx);
  SUNLinearSolver ls = SUNLinSol_Dense(y, m, ctx);
  ARKStepSetLinearSolver(mem, ls, m);
  ARKStepSetJacFn(mem, jac);
  ARKStepSetFixedStep(mem, t_end / n);
  ARKStepSetMaxNumSteps(mem, 2 * n);
  realtype t = 0;
  const int status = ARKStepEvolve(mem, t_end, y, &t, ARK_NORMAL);
  for (int i = 0; i < dim; ++i) y_end[i] = status >= 0 ? NV_Ith_S(y, i) : NAN;
  ARKodeButcherTable_Free(table);
  ARKStepFree(&mem);
  SUNLinSolFree(ls);
  SUNMatDestroy(m);
  N_VDestroy(y);
  return status;
}

static double period_error(SUNContext ctx, ARKODE_DIRKTableID id, long n) {
  const double y0[4] = {1, 0, 0.25, 0.75};
  double y[4];
  run(ctx, id, oscillator, oscillator_jacobian, 4, y0, 2 * acos(-1.0), n, y);
  double e2 = 0, n2 = 0;
  for (int i = 0; i < 4; ++i) e2 += (y[i] - y0[i]) * (y[i] - y0[i]), n2 += y0[i] * y0[i];
  return sqrt(e2 / n2);
}

/* The first two order conditions of weights w on the table's A, in long double (64-bit
 * significand: the doubles' products and sums below 1e-18): sum(w) = 1 and w . (A 1) = 1/2,
 * with the stage times A 1 as an autonomous problem sees them. */
static long double weight_sum_minus_one(const realtype* w, int stages) {
  long double sum = 0;
  for (int i = 0; i < stages; ++i) sum += (long double)w[i];
  return sum - 1;
}

/* The scales of the same conditions, the size of their terms (sum |w_i|, and
 * sum |w_i| (|A| 1)_i times the condition's degree 2): each defect over its scale is the
 * relative residual an analyser of the table states for it. */
static long double weight_sum_scale(const realtype* w, int stages) {
  long double sum = 0;
  for (int i = 0; i < stages; ++i) sum += fabsl((long double)w[i]);
  return sum;
}

static long double order2_scale(ARKodeButcherTable t, const realtype* w) {
  long double sum = 0;
  for (int i = 0; i < t->stages; ++i) {
    long double row = 0;
    for (int j = 0; j < t->stages; ++j) row += fabsl((long double)t->A[i][j]);
    sum += fabsl((long double)w[i]) * row;
  }
  return 2 * sum;
}

static long double order2_defect(ARKodeButcherTable t, const realtype* w) {
  long double sum = 0;
  for (int i = 0; i < t->stages; ++i) {
    long double row = 0;
    for (int j = 0; j < t->stages; ++j) row += (long double)t->A[i][j];
    sum += (long double)w[i] * row;
  }
  return sum - 0.5L;
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
  } tables[] = {{"cash_5_2_4", ARKODE_CASH_5_2_4},
                {"cash_5_3_4", ARKODE_CASH_5_3_4},
                {"billington_3_3_2", ARKODE_BILLINGTON_3_3_2},
                {"sdirk_5_3_4", ARKODE_SDIRK_5_3_4}};
  for (int k = 0; k < 4; ++k) {
    ARKodeButcherTable t = ARKodeButcherTable_LoadDIRK(tables[k].id);
    printf("%s_weight_sum_minus_one %.3Le\n", tables[k].name, weight_sum_minus_one(t->b, t->stages));
    printf("%s_embedding_weight_sum_minus_one %.3Le\n", tables[k].name, weight_sum_minus_one(t->d, t->stages));
    printf("%s_order2_defect %.3Le\n", tables[k].name, order2_defect(t, t->b));
    printf("%s_embedding_order2_defect %.3Le\n", tables[k].name, order2_defect(t, t->d));
    printf("%s_weight_sum_relative %.3Le\n", tables[k].name,
           fabsl(weight_sum_minus_one(t->b, t->stages)) / weight_sum_scale(t->b, t->stages));
    printf("%s_embedding_order2_relative %.3Le\n", tables[k].name, fabsl(order2_defect(t, t->d)) / order2_scale(t, t->d));
    printf("%s_gamma %.17g\n", tables[k].name, t->A[0][0]);
    ARKodeButcherTable_Free(t);
    const double zero = 0;
    double y1;
    run(ctx, tables[k].id, constant_rate, zero_jacobian, 1, &zero, 1, 64, &y1);
    printf("%s_constant_rate_error %.3e\n", tables[k].name, y1 - 1);
    for (long n = 4096; n <= 16384; n *= 4)
      printf("%s_error_n%ld %.3e\n", tables[k].name, n, period_error(ctx, tables[k].id, n));
  }
  SUNContext_Free(&ctx);
  return 0;
}
