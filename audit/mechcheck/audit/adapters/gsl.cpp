#include "mechcheck/audit/adapters/gsl.hpp"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_odeiv2.h>
#include <gsl/gsl_version.h>

#include <memory>

namespace mechcheck::audit::gsl {

namespace {
/// The GSL manual's description of each one-step type (GSL 2.7, "Ordinary Differential
/// Equations: Stepping Functions").
struct type_info {
  const char* name;
  const gsl_odeiv2_step_type* const* type;
  const char* manual;
};

const std::vector<type_info>& types() {
  static const std::vector<type_info> t{
      {"rk2", &gsl_odeiv2_step_rk2, "Explicit embedded Runge-Kutta (2, 3) method."},
      {"rk4", &gsl_odeiv2_step_rk4,
       "Explicit 4th order (classical) Runge-Kutta. Error estimation is carried out by the "
       "step doubling method."},
      {"rkf45", &gsl_odeiv2_step_rkf45,
       "Explicit embedded Runge-Kutta-Fehlberg (4, 5) method. This method is a good "
       "general-purpose integrator."},
      {"rkck", &gsl_odeiv2_step_rkck, "Explicit embedded Runge-Kutta Cash-Karp (4, 5) method."},
      {"rk8pd", &gsl_odeiv2_step_rk8pd,
       "Explicit embedded Runge-Kutta Prince-Dormand (8, 9) method."},
      {"rk1imp", &gsl_odeiv2_step_rk1imp,
       "Implicit Gaussian first order Runge-Kutta. Also known as implicit Euler or backward "
       "Euler method. Error estimation is carried out by the step doubling method."},
      {"rk2imp", &gsl_odeiv2_step_rk2imp,
       "Implicit Gaussian second order Runge-Kutta. Also known as implicit mid-point rule. "
       "Error estimation is carried out by the step doubling method."},
      {"rk4imp", &gsl_odeiv2_step_rk4imp,
       "Implicit Gaussian 4th order Runge-Kutta. Error estimation is carried out by the step "
       "doubling method."},
  };
  return t;
}

/// GSL never aborts the process: every GSL error is a status code from here on.
void handler_off() {
  static const bool done = [] {
    gsl_set_error_handler_off();
    return true;
  }();
  static_cast<void>(done);
}

struct context {
  const type_info* info;
  ode_system ode;
  gsl_odeiv2_system sys;
  gsl_odeiv2_driver* driver = nullptr;
  std::vector<double> yerr;
  long long steps = 0;
};

int rhs(double t, const double y[], double dydt[], void* self) {
  auto* c = static_cast<context*>(self);
  return c->ode.rhs(t, y, dydt, c->ode.self) == 0 ? GSL_SUCCESS : GSL_EBADFUNC;
}

int jacobian(double t, const double y[], double* dfdy, double dfdt[], void* self) {
  auto* c = static_cast<context*>(self);
  for (int i = 0; i < c->ode.dimension; ++i) dfdt[i] = 0;  // autonomous problems
  return c->ode.jacobian(t, y, dfdy, c->ode.self) == 0 ? GSL_SUCCESS : GSL_EBADFUNC;
}

void step(double* y, double t, double h, void* ctx) {
  auto* c = static_cast<context*>(ctx);
  ++c->steps;
  const int status = gsl_odeiv2_step_apply(c->driver->s, t, h, y, c->yerr.data(), nullptr,
                                           nullptr, &c->sys);
  if (status != GSL_SUCCESS)
    throw convergence_error(std::string("gsl_odeiv2_step_apply (") + c->info->name +
                            ") returned " + std::to_string(status) + " (" +
                            gsl_strerror(status) + ") at step " + std::to_string(c->steps) +
                            ", t = " + to_text(t) + ", h = " + to_text(h));
}

/// rk2's embedded formula: rk2.c sets yerr = h (k2 - (k1 + 4 k2 + k3)/6), the midpoint
/// rule's step y + h k2 less the propagated one, so y + yerr is the midpoint rule's step.
void embedded_step(double* y, double t, double h, void* ctx) {
  step(y, t, h, ctx);
  const auto* c = static_cast<const context*>(ctx);
  for (int i = 0; i < c->ode.dimension; ++i) y[i] += c->yerr[std::size_t(i)];
}

black_box box_of(const type_info& info, double newton_tolerance, c_step stepper) {
  black_box b;
  const type_info* ti = &info;
  b.create = [ti, newton_tolerance](const ode_system& ode) -> void* {
    auto* c = new context{ti, ode, {}, nullptr, std::vector<double>(std::size_t(ode.dimension)), 0};
    c->sys = gsl_odeiv2_system{&rhs, &jacobian, static_cast<size_t>(ode.dimension), c};
    c->driver = gsl_odeiv2_driver_alloc_y_new(&c->sys, *ti->type, 1e-3, newton_tolerance,
                                              newton_tolerance);
    if (!c->driver) {
      delete c;
      throw error(std::string("gsl_odeiv2_driver_alloc_y_new (") + ti->name + ") failed");
    }
    return c;
  };
  b.step = stepper;
  b.destroy = [](void* ctx) {
    auto* c = static_cast<context*>(ctx);
    if (c->driver) gsl_odeiv2_driver_free(c->driver);
    delete c;
  };
  return b;
}
}  // namespace

std::string version() { return GSL_VERSION; }

std::vector<black_box> one_step_types(double newton_tolerance) {
  if (!(newton_tolerance > 0 && std::isfinite(newton_tolerance)))
    throw domain_error("gsl::one_step_types: the Newton tolerance must be positive and finite, got " +
                       to_text(newton_tolerance));
  handler_off();
  std::vector<black_box> out;
  for (const type_info& info : types()) {
    gsl_odeiv2_step* probe = gsl_odeiv2_step_alloc(*info.type, 2);
    if (!probe) throw error(std::string("gsl_odeiv2_step_alloc (") + info.name + ") failed");
    const unsigned order = gsl_odeiv2_step_order(probe);
    gsl_odeiv2_step_free(probe);
    black_box b;
    b.name = std::string("gsl::") + info.name;
    b.origin = "GSL " + version() + " gsl_odeiv2_step_" + info.name + " at fixed steps (" +
               "gsl_odeiv2_step_apply); order from gsl_odeiv2_step_order; manual: \"" +
               info.manual + "\"";
    if (std::string(info.name).find("imp") != std::string::npos)
      b.origin += "; Newton error level from a driver control with epsabs = epsrel = " +
                  to_text(newton_tolerance);
    b.declared.order = static_cast<int>(order);
    // gsl_odeiv2_step_order "returns the order of the stepping function on the previous
    // step": for an embedded pair the words admit the order of either formula. rk2 returns
    // the lower (2 of "(2, 3)") and propagates the higher; its companion gsl::rk2/embedding
    // propagates the lower, and measures that reading.
    const bool embedded_pair = std::string(info.manual).find("embedded") != std::string::npos;
    if (embedded_pair) b.declared.order_readings = {order_reading::embedded};
    const black_box made = box_of(info, newton_tolerance, &step);
    b.create = made.create;
    b.step = made.step;
    b.destroy = made.destroy;
    if (std::string(info.name) == "rk2") {
      black_box e = box_of(info, newton_tolerance, &embedded_step);
      e.name = b.name + "/embedding";
      e.origin = "GSL " + version() + " gsl_odeiv2_step_rk2's embedded formula, y + yerr (rk2.c: yerr = h (k2 - "
                 "(k1 + 4 k2 + k3)/6), the midpoint rule's step less the propagated one); its order is the lower "
                 "of the manual's \"(2, 3)\"";
      e.declared.order = 2;
      out.push_back(std::move(b));
      out.push_back(std::move(e));
      continue;
    }
    out.push_back(std::move(b));
  }
  return out;
}

namespace {
/// The GSL manual's words for the types audited only through the driver.
struct driver_type {
  const char* name;
  const gsl_odeiv2_step_type* const* type;
  const char* manual;
};

int driver_rhs(double t, const double y[], double dydt[], void* self) {
  const auto* ode = static_cast<const ode_system*>(self);
  return ode->rhs(t, y, dydt, ode->self) == 0 ? GSL_SUCCESS : GSL_EBADFUNC;
}
int driver_jacobian(double t, const double y[], double* dfdy, double dfdt[], void* self) {
  const auto* ode = static_cast<const ode_system*>(self);
  for (int i = 0; i < ode->dimension; ++i) dfdt[i] = 0;  // autonomous problems
  return ode->jacobian(t, y, dfdy, ode->self) == 0 ? GSL_SUCCESS : GSL_EBADFUNC;
}
}  // namespace

std::vector<adaptive_driver> drivers() {
  handler_off();
  static const std::vector<driver_type> types{
      {"rkf45", &gsl_odeiv2_step_rkf45, "Explicit embedded Runge-Kutta-Fehlberg (4, 5) method. This method is a good general-purpose integrator."},
      {"rkck", &gsl_odeiv2_step_rkck, "Explicit embedded Runge-Kutta Cash-Karp (4, 5) method."},
      {"rk8pd", &gsl_odeiv2_step_rk8pd, "Explicit embedded Runge-Kutta Prince-Dormand (8, 9) method."},
      {"msadams", &gsl_odeiv2_step_msadams, "A variable-coefficient linear multistep Adams method in Nordsieck form. This stepper uses explicit Adams-Bashforth (predictor) and implicit Adams-Moulton (corrector) methods in P(EC)^m functional iteration mode. Method order varies dynamically between 1 and 12."},
      {"msbdf", &gsl_odeiv2_step_msbdf, "A variable-coefficient linear multistep backward differentiation formula (BDF) method in Nordsieck form. This stepper uses the explicit BDF formula as predictor and implicit BDF formula as corrector. A modified Newton iteration method is used to solve the system of non-linear equations. Method order varies dynamically between 1 and 5."},
      {"bsimp", &gsl_odeiv2_step_bsimp, "Implicit Bulirsch-Stoer method of Bader and Deuflhard. The method is generally suitable for stiff problems."},
  };
  std::vector<adaptive_driver> out;
  for (const driver_type& t : types) {
    adaptive_driver d;
    d.name = std::string("gsl::driver_") + t.name;
    d.origin = "GSL " + version() + " gsl_odeiv2_driver_alloc_y_new(sys, gsl_odeiv2_step_" + t.name +
               ", hstart = 1e-3 (t1 - t0), tol, tol) and gsl_odeiv2_driver_apply, the Jacobian by AD; "
               "manual: \"" + t.manual + "\"";
    const driver_type* type = &t;
    d.integrate = [type, name = d.name](const ode_system& ode, double* y, double t0, double t1,
                                        double tol) -> driver_statistics {
      gsl_odeiv2_system sys{&driver_rhs, &driver_jacobian, static_cast<size_t>(ode.dimension),
                            const_cast<ode_system*>(&ode)};
      const std::unique_ptr<gsl_odeiv2_driver, decltype(&gsl_odeiv2_driver_free)> driver(
          gsl_odeiv2_driver_alloc_y_new(&sys, *type->type, 1e-3 * (t1 - t0), tol, tol),
          &gsl_odeiv2_driver_free);
      if (!driver) throw error(name + ": gsl_odeiv2_driver_alloc_y_new failed");
      constexpr unsigned long limit = 10000000;
      gsl_odeiv2_driver_set_nmax(driver.get(), limit);
      double t = t0;
      const int status = gsl_odeiv2_driver_apply(driver.get(), &t, t1, y);
      if (status != GSL_SUCCESS)
        throw convergence_error(name + ": gsl_odeiv2_driver_apply returned " + std::to_string(status) +
                                " (" + gsl_strerror(status) + ") at t = " + to_text(t) + " of " +
                                to_text(t1) + ", tol = " + to_text(tol) +
                                (status == GSL_EMAXITER ? " (" + std::to_string(limit) + " steps)" : ""));
      return {static_cast<long long>(driver->e->count) - static_cast<long long>(driver->e->failed_steps),
              static_cast<long long>(driver->e->failed_steps)};
    };
    out.push_back(std::move(d));
  }
  return out;
}

}  // namespace mechcheck::audit::gsl
