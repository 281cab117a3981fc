#include "mechcheck/audit/adapters/arkode.hpp"

#include <arkode/arkode_arkstep.h>
#include <arkode/arkode_butcher_dirk.h>
#include <arkode/arkode_butcher_erk.h>
#include <arkode/arkode_erkstep.h>
#include <cvode/cvode.h>
#include <nvector/nvector_serial.h>
#include <sundials/sundials_config.h>
#include <sundials/sundials_context.h>
#include <sunlinsol/sunlinsol_dense.h>
#include <sunnonlinsol/sunnonlinsol_fixedpoint.h>
#include <sunmatrix/sunmatrix_dense.h>

#include <cstdlib>
#include <map>
#include <memory>

namespace mechcheck::audit::arkode {

namespace {
static_assert(sizeof(realtype) == sizeof(double), "mechcheck's ARKODE adapter needs realtype = double");

/// The names of the table ids of this ARKODE's headers (the enumeration itself comes from
/// the library: an id it loads without a name here is named by its number).
const std::map<int, const char*>& names() {
#define MECHCHECK_TABLE(id) {id, #id}
  static const std::map<int, const char*> n{
      MECHCHECK_TABLE(ARKODE_HEUN_EULER_2_1_2),       MECHCHECK_TABLE(ARKODE_BOGACKI_SHAMPINE_4_2_3),
      MECHCHECK_TABLE(ARKODE_ARK324L2SA_ERK_4_2_3),   MECHCHECK_TABLE(ARKODE_ZONNEVELD_5_3_4),
      MECHCHECK_TABLE(ARKODE_ARK436L2SA_ERK_6_3_4),   MECHCHECK_TABLE(ARKODE_SAYFY_ABURUB_6_3_4),
      MECHCHECK_TABLE(ARKODE_CASH_KARP_6_4_5),        MECHCHECK_TABLE(ARKODE_FEHLBERG_6_4_5),
      MECHCHECK_TABLE(ARKODE_DORMAND_PRINCE_7_4_5),   MECHCHECK_TABLE(ARKODE_ARK548L2SA_ERK_8_4_5),
      MECHCHECK_TABLE(ARKODE_VERNER_8_5_6),           MECHCHECK_TABLE(ARKODE_FEHLBERG_13_7_8),
      MECHCHECK_TABLE(ARKODE_KNOTH_WOLKE_3_3),        MECHCHECK_TABLE(ARKODE_ARK437L2SA_ERK_7_3_4),
      MECHCHECK_TABLE(ARKODE_ARK548L2SAb_ERK_8_4_5),  MECHCHECK_TABLE(ARKODE_SDIRK_2_1_2),
      MECHCHECK_TABLE(ARKODE_BILLINGTON_3_3_2),       MECHCHECK_TABLE(ARKODE_TRBDF2_3_3_2),
      MECHCHECK_TABLE(ARKODE_KVAERNO_4_2_3),          MECHCHECK_TABLE(ARKODE_ARK324L2SA_DIRK_4_2_3),
      MECHCHECK_TABLE(ARKODE_CASH_5_2_4),             MECHCHECK_TABLE(ARKODE_CASH_5_3_4),
      MECHCHECK_TABLE(ARKODE_SDIRK_5_3_4),            MECHCHECK_TABLE(ARKODE_KVAERNO_5_3_4),
      MECHCHECK_TABLE(ARKODE_ARK436L2SA_DIRK_6_3_4),  MECHCHECK_TABLE(ARKODE_KVAERNO_7_4_5),
      MECHCHECK_TABLE(ARKODE_ARK548L2SA_DIRK_8_4_5),  MECHCHECK_TABLE(ARKODE_ARK437L2SA_DIRK_7_3_4),
      MECHCHECK_TABLE(ARKODE_ARK548L2SAb_DIRK_8_4_5), MECHCHECK_TABLE(ARKODE_ESDIRK324L2SA_4_2_3),
      MECHCHECK_TABLE(ARKODE_ESDIRK325L2SA_5_2_3),    MECHCHECK_TABLE(ARKODE_ESDIRK32I5L2SA_5_2_3),
      MECHCHECK_TABLE(ARKODE_ESDIRK436L2SA_6_3_4),    MECHCHECK_TABLE(ARKODE_ESDIRK43I6L2SA_6_3_4),
      MECHCHECK_TABLE(ARKODE_QESDIRK436L2SA_6_3_4),   MECHCHECK_TABLE(ARKODE_ESDIRK437L2SA_7_3_4),
      MECHCHECK_TABLE(ARKODE_ESDIRK547L2SA_7_4_5),    MECHCHECK_TABLE(ARKODE_ESDIRK547L2SA2_7_4_5),
  };
#undef MECHCHECK_TABLE
  return n;
}

butcher_table copy_of(ARKodeButcherTable t, int id, bool implicit) {
  butcher_table out;
  const auto it = names().find(id);
  out.name = it != names().end() ? it->second : (implicit ? "DIRK_" : "ERK_") + std::to_string(id);
  out.id = id;
  out.implicit = implicit;
  out.q = t->q;
  out.p = t->p;
  const int s = t->stages;
  out.a.assign(std::size_t(s), std::vector<double>(std::size_t(s)));
  for (int i = 0; i < s; ++i)
    for (int j = 0; j < s; ++j) out.a[std::size_t(i)][std::size_t(j)] = t->A[i][j];
  out.b.assign(t->b, t->b + s);
  out.c.assign(t->c, t->c + s);
  if (t->d) out.d.assign(t->d, t->d + s);
  return out;
}

/// A SUNContext for the process (SUNDIALS 6 needs one for every object).
SUNContext context() {
  static SUNContext ctx = [] {
    SUNContext c = nullptr;
    if (SUNContext_Create(nullptr, &c) != 0) throw error("SUNContext_Create failed");
    return c;
  }();
  return ctx;
}

/// One run of a table by ARKODE on one system.
struct run {
  ode_system ode;
  std::string name;
  bool implicit = false;
  ARKodeButcherTable table = nullptr;
  int q = 0, p = 0;
  double tolerance = 0;
  N_Vector y = nullptr;
  void* mem = nullptr;
  SUNMatrix matrix = nullptr;
  SUNLinearSolver solver = nullptr;
  std::string message;  // ARKODE's last error message
  long long steps = 0;

  ~run() {
    if (mem) implicit ? ARKStepFree(&mem) : ERKStepFree(&mem);
    if (solver) SUNLinSolFree(solver);
    if (matrix) SUNMatDestroy(matrix);
    if (y) N_VDestroy(y);
    if (table) ARKodeButcherTable_Free(table);
  }
};

int rhs(realtype t, N_Vector y, N_Vector ydot, void* user) {
  auto* r = static_cast<run*>(user);
  return r->ode.rhs(t, N_VGetArrayPointer(y), N_VGetArrayPointer(ydot), r->ode.self) == 0 ? 0 : -1;
}

int jac(realtype t, N_Vector y, N_Vector, SUNMatrix j, void* user, N_Vector, N_Vector, N_Vector) {
  auto* r = static_cast<run*>(user);
  const int n = r->ode.dimension;
  std::vector<double> dfdy(std::size_t(n * n));
  if (r->ode.jacobian(t, N_VGetArrayPointer(y), dfdy.data(), r->ode.self) != 0) return -1;
  for (int i = 0; i < n; ++i)
    for (int k = 0; k < n; ++k) SM_ELEMENT_D(j, i, k) = dfdy[std::size_t(i * n + k)];
  return 0;
}

void errors(int, const char* module, const char* function, char* msg, void* user) {
  auto* r = static_cast<run*>(user);
  r->message = std::string(module ? module : "?") + " " + (function ? function : "?") + ": " + (msg ? msg : "");
}

void check(run* r, int flag, const char* call, double t, double h) {
  if (flag >= 0) return;
  // The name is malloc'ed by ARKODE and the caller's to free.
  const std::unique_ptr<char, decltype(&std::free)> flag_name(
      r->implicit ? ARKStepGetReturnFlagName(flag) : ERKStepGetReturnFlagName(flag), &std::free);
  std::string text = std::string(call) + " returned " + std::to_string(flag) + " (" +
                     (flag_name ? flag_name.get() : "?") + ")";
  if (!r->message.empty()) text += ": " + r->message;
  throw convergence_error(r->name + ": " + text + " at step " + std::to_string(r->steps) +
                          ", t = " + to_text(t) + ", h = " + to_text(h));
}

void step(double* y, double t, double h, void* ctx) {
  auto* r = static_cast<run*>(ctx);
  ++r->steps;
  r->message.clear();
  const int n = r->ode.dimension;
  std::copy(y, y + n, N_VGetArrayPointer(r->y));
  if (!r->mem) {  // created at the first step, where t is known
    if (r->implicit) {
      r->mem = ARKStepCreate(nullptr, &rhs, t, r->y, context());
      if (!r->mem) throw error(r->name + ": ARKStepCreate failed");
      check(r, ARKStepSetErrHandlerFn(r->mem, &errors, r), "ARKStepSetErrHandlerFn", t, h);
      check(r, ARKStepSetUserData(r->mem, r), "ARKStepSetUserData", t, h);
      check(r, ARKStepSetTables(r->mem, r->q, r->p, r->table, nullptr), "ARKStepSetTables", t, h);
      check(r, ARKStepSStolerances(r->mem, r->tolerance, r->tolerance), "ARKStepSStolerances", t, h);
      r->matrix = SUNDenseMatrix(n, n, context());
      r->solver = SUNLinSol_Dense(r->y, r->matrix, context());
      check(r, ARKStepSetLinearSolver(r->mem, r->solver, r->matrix), "ARKStepSetLinearSolver", t, h);
      check(r, ARKStepSetJacFn(r->mem, &jac), "ARKStepSetJacFn", t, h);
      // The audit measures the table, not the nonlinear solver's defaults: a Newton matrix
      // set up at every step and up to 10 iterations (ARKODE's defaults, 20 steps between
      // setups and 3 iterations, fail to converge to a tolerance of 1e-14 at fixed steps).
      check(r, ARKStepSetLSetupFrequency(r->mem, 1), "ARKStepSetLSetupFrequency", t, h);
      check(r, ARKStepSetMaxNonlinIters(r->mem, 10), "ARKStepSetMaxNonlinIters", t, h);
    } else {
      r->mem = ERKStepCreate(&rhs, t, r->y, context());
      if (!r->mem) throw error(r->name + ": ERKStepCreate failed");
      check(r, ERKStepSetErrHandlerFn(r->mem, &errors, r), "ERKStepSetErrHandlerFn", t, h);
      check(r, ERKStepSetUserData(r->mem, r), "ERKStepSetUserData", t, h);
      check(r, ERKStepSetTable(r->mem, r->table), "ERKStepSetTable", t, h);
    }
  } else if (r->implicit) {
    check(r, ARKStepReInit(r->mem, nullptr, &rhs, t, r->y), "ARKStepReInit", t, h);
  } else {
    check(r, ERKStepReInit(r->mem, &rhs, t, r->y), "ERKStepReInit", t, h);
  }
  realtype reached = t;
  if (r->implicit) {
    check(r, ARKStepSetFixedStep(r->mem, h), "ARKStepSetFixedStep", t, h);
    check(r, ARKStepEvolve(r->mem, t + h, r->y, &reached, ARK_ONE_STEP), "ARKStepEvolve", t, h);
  } else {
    check(r, ERKStepSetFixedStep(r->mem, h), "ERKStepSetFixedStep", t, h);
    check(r, ERKStepEvolve(r->mem, t + h, r->y, &reached, ARK_ONE_STEP), "ERKStepEvolve", t, h);
  }
  std::copy(N_VGetArrayPointer(r->y), N_VGetArrayPointer(r->y) + n, y);
}

ARKodeButcherTable load(const butcher_table& t, bool embedding) {
  const int s = static_cast<int>(t.b.size());
  std::vector<realtype> a(std::size_t(s * s));
  for (int i = 0; i < s; ++i)
    for (int j = 0; j < s; ++j) a[std::size_t(i * s + j)] = t.a[std::size_t(i)][std::size_t(j)];
  std::vector<realtype> b = embedding ? t.d : t.b, c = t.c, d = embedding ? t.b : t.d;
  ARKodeButcherTable out = ARKodeButcherTable_Create(s, embedding ? t.p : t.q,
                                                     embedding ? t.q : t.p, c.data(), a.data(),
                                                     b.data(), d.empty() ? nullptr : d.data());
  if (!out) throw error("ARKodeButcherTable_Create failed for " + t.name);
  return out;
}
}  // namespace

std::string version() { return SUNDIALS_VERSION; }

std::vector<butcher_table> tables() {
  std::vector<butcher_table> out;
  for (int id = ARKODE_MIN_ERK_NUM; id <= ARKODE_MAX_ERK_NUM; ++id)
    if (ARKodeButcherTable t = ARKodeButcherTable_LoadERK(static_cast<ARKODE_ERKTableID>(id))) {
      out.push_back(copy_of(t, id, false));
      ARKodeButcherTable_Free(t);
    }
  for (int id = ARKODE_MIN_DIRK_NUM; id <= ARKODE_MAX_DIRK_NUM; ++id)
    if (ARKodeButcherTable t = ARKodeButcherTable_LoadDIRK(static_cast<ARKODE_DIRKTableID>(id))) {
      out.push_back(copy_of(t, id, true));
      ARKodeButcherTable_Free(t);
    }
  return out;
}

std::vector<black_box> steppers(const std::vector<butcher_table>& ts, double newton_tolerance) {
  if (!(newton_tolerance > 0 && std::isfinite(newton_tolerance)))
    throw domain_error("arkode::steppers: the Newton tolerance must be positive and finite, got " +
                       to_text(newton_tolerance));
  std::vector<black_box> out;
  for (const butcher_table& t : ts)
    for (const bool embedding : {false, true}) {
      if (embedding && t.d.empty()) continue;
      black_box b;
      b.name = "arkode::" + t.name + (embedding ? "/embedding" : "");
      b.origin = "SUNDIALS " + version() + " ARKODE " + (t.implicit ? "ARKStep" : "ERKStep") +
                 " at fixed steps with the built-in table " + t.name + " (" +
                 (embedding ? "its embedding b = d, declared order p = " + std::to_string(t.p)
                            : "declared order q = " + std::to_string(t.q)) +
                 ")" +
                 (t.implicit ? "; Newton with a dense solver, Jacobian by AD, tolerances " +
                                   to_text(newton_tolerance)
                             : std::string());
      b.declared.order = embedding ? t.p : t.q;
      const auto table = std::make_shared<const butcher_table>(t);
      b.create = [table, embedding, newton_tolerance, name = b.name](const ode_system& ode) -> void* {
        auto r = std::make_unique<run>();
        r->ode = ode;
        r->name = name;
        r->implicit = table->implicit;
        r->q = embedding ? table->p : table->q;
        r->p = embedding ? table->q : table->p;
        r->tolerance = newton_tolerance;
        r->table = load(*table, embedding);
        r->y = N_VNew_Serial(ode.dimension, context());
        return r.release();
      };
      b.step = &step;
      b.destroy = [](void* ctx) { delete static_cast<run*>(ctx); };
      out.push_back(std::move(b));
    }
  return out;
}

namespace {
/// The SUNDIALS objects of one adaptive run, freed in any case.
struct adaptive_run {
  const ode_system* ode = nullptr;
  std::string name, message;
  N_Vector y = nullptr;
  void* mem = nullptr;
  bool cvode = false;
  SUNMatrix matrix = nullptr;
  SUNLinearSolver solver = nullptr;
  SUNNonlinearSolver nonlinear = nullptr;
  ~adaptive_run() {
    if (mem) cvode ? CVodeFree(&mem) : ERKStepFree(&mem);
    if (nonlinear) SUNNonlinSolFree(nonlinear);
    if (solver) SUNLinSolFree(solver);
    if (matrix) SUNMatDestroy(matrix);
    if (y) N_VDestroy(y);
  }
  void check(int flag, const char* call) const {
    if (flag >= 0) return;
    const std::unique_ptr<char, decltype(&std::free)> flag_name(
        cvode ? CVodeGetReturnFlagName(flag) : ERKStepGetReturnFlagName(flag), &std::free);
    throw convergence_error(name + ": " + call + " returned " + std::to_string(flag) + " (" +
                            (flag_name ? flag_name.get() : "?") + ")" +
                            (message.empty() ? "" : ": " + message));
  }
};

int adaptive_rhs(realtype t, N_Vector y, N_Vector ydot, void* user) {
  const auto* r = static_cast<adaptive_run*>(user);
  return r->ode->rhs(t, N_VGetArrayPointer(y), N_VGetArrayPointer(ydot), r->ode->self) == 0 ? 0 : -1;
}
int adaptive_jac(realtype t, N_Vector y, N_Vector, SUNMatrix j, void* user, N_Vector, N_Vector, N_Vector) {
  const auto* r = static_cast<adaptive_run*>(user);
  const int n = r->ode->dimension;
  std::vector<double> dfdy(std::size_t(n * n));
  if (r->ode->jacobian(t, N_VGetArrayPointer(y), dfdy.data(), r->ode->self) != 0) return -1;
  for (int i = 0; i < n; ++i)
    for (int k = 0; k < n; ++k) SM_ELEMENT_D(j, i, k) = dfdy[std::size_t(i * n + k)];
  return 0;
}
void adaptive_errors(int, const char* module, const char* function, char* msg, void* user) {
  static_cast<adaptive_run*>(user)->message =
      std::string(module ? module : "?") + " " + (function ? function : "?") + ": " + (msg ? msg : "");
}
constexpr long max_steps = 10000000;

driver_statistics cvode(int lmm, const std::string& name, const ode_system& ode, double* y,
                        double t0, double t1, double tol) {
  adaptive_run r;
  r.ode = &ode;
  r.name = name;
  r.cvode = true;
  r.y = N_VNew_Serial(ode.dimension, context());
  std::copy(y, y + ode.dimension, N_VGetArrayPointer(r.y));
  r.mem = CVodeCreate(lmm, context());
  if (!r.mem) throw error(name + ": CVodeCreate failed");
  r.check(CVodeSetErrHandlerFn(r.mem, &adaptive_errors, &r), "CVodeSetErrHandlerFn");
  r.check(CVodeInit(r.mem, &adaptive_rhs, t0, r.y), "CVodeInit");
  r.check(CVodeSetUserData(r.mem, &r), "CVodeSetUserData");
  r.check(CVodeSStolerances(r.mem, tol, tol), "CVodeSStolerances");
  r.check(CVodeSetMaxNumSteps(r.mem, max_steps), "CVodeSetMaxNumSteps");
  r.check(CVodeSetStopTime(r.mem, t1), "CVodeSetStopTime");
  if (lmm == CV_BDF) {
    r.matrix = SUNDenseMatrix(ode.dimension, ode.dimension, context());
    r.solver = SUNLinSol_Dense(r.y, r.matrix, context());
    r.check(CVodeSetLinearSolver(r.mem, r.solver, r.matrix), "CVodeSetLinearSolver");
    r.check(CVodeSetJacFn(r.mem, &adaptive_jac), "CVodeSetJacFn");
  } else {
    r.nonlinear = SUNNonlinSol_FixedPoint(r.y, 0, context());
    r.check(CVodeSetNonlinearSolver(r.mem, r.nonlinear), "CVodeSetNonlinearSolver");
  }
  realtype t = t0;
  r.check(CVode(r.mem, t1, r.y, &t, CV_NORMAL), "CVode");
  long steps = 0, fails = 0;
  r.check(CVodeGetNumSteps(r.mem, &steps), "CVodeGetNumSteps");
  r.check(CVodeGetNumErrTestFails(r.mem, &fails), "CVodeGetNumErrTestFails");
  std::copy(N_VGetArrayPointer(r.y), N_VGetArrayPointer(r.y) + ode.dimension, y);
  return {steps, fails};
}

driver_statistics erkstep(const std::string& name, const ode_system& ode, double* y, double t0,
                          double t1, double tol) {
  adaptive_run r;
  r.ode = &ode;
  r.name = name;
  r.y = N_VNew_Serial(ode.dimension, context());
  std::copy(y, y + ode.dimension, N_VGetArrayPointer(r.y));
  r.mem = ERKStepCreate(&adaptive_rhs, t0, r.y, context());
  if (!r.mem) throw error(name + ": ERKStepCreate failed");
  r.check(ERKStepSetErrHandlerFn(r.mem, &adaptive_errors, &r), "ERKStepSetErrHandlerFn");
  r.check(ERKStepSetUserData(r.mem, &r), "ERKStepSetUserData");
  r.check(ERKStepSStolerances(r.mem, tol, tol), "ERKStepSStolerances");
  r.check(ERKStepSetMaxNumSteps(r.mem, max_steps), "ERKStepSetMaxNumSteps");
  r.check(ERKStepSetStopTime(r.mem, t1), "ERKStepSetStopTime");
  realtype t = t0;
  r.check(ERKStepEvolve(r.mem, t1, r.y, &t, ARK_NORMAL), "ERKStepEvolve");
  long steps = 0, fails = 0;
  r.check(ERKStepGetNumSteps(r.mem, &steps), "ERKStepGetNumSteps");
  r.check(ERKStepGetNumErrTestFails(r.mem, &fails), "ERKStepGetNumErrTestFails");
  std::copy(N_VGetArrayPointer(r.y), N_VGetArrayPointer(r.y) + ode.dimension, y);
  return {steps, fails};
}
}  // namespace

std::vector<adaptive_driver> drivers() {
  std::vector<adaptive_driver> out;
  const std::string v = "SUNDIALS " + version();
  adaptive_driver bdf;
  bdf.name = "cvode::BDF";
  bdf.origin = v + " CVODE, CV_BDF with Newton iteration and a dense linear solver (Jacobian by AD), "
                   "CVodeSStolerances(tol, tol), CVodeSetStopTime(t_end); the guide: \"variable-order, "
                   "variable-step BDF methods\" of orders 1 to 5 for stiff problems";
  bdf.integrate = [name = bdf.name](const ode_system& ode, double* y, double t0, double t1, double tol) {
    return cvode(CV_BDF, name, ode, y, t0, t1, tol);
  };
  out.push_back(std::move(bdf));
  adaptive_driver adams;
  adams.name = "cvode::Adams";
  adams.origin = v + " CVODE, CV_ADAMS with fixed-point iteration, CVodeSStolerances(tol, tol), "
                     "CVodeSetStopTime(t_end); the guide: Adams-Moulton formulas of orders 1 to 12 "
                     "for nonstiff problems";
  adams.integrate = [name = adams.name](const ode_system& ode, double* y, double t0, double t1, double tol) {
    return cvode(CV_ADAMS, name, ode, y, t0, t1, tol);
  };
  out.push_back(std::move(adams));
  adaptive_driver erk;
  erk.name = "arkode::ERKStep_default";
  erk.origin = v + " ARKODE ERKStep with its defaults (order 4: ARKODE_ZONNEVELD_5_3_4, the "
                   "PID controller), ERKStepSStolerances(tol, tol), ERKStepSetStopTime(t_end)";
  erk.integrate = [name = erk.name](const ode_system& ode, double* y, double t0, double t1, double tol) {
    return erkstep(name, ode, y, t0, t1, tol);
  };
  out.push_back(std::move(erk));
  return out;
}

}  // namespace mechcheck::audit::arkode
