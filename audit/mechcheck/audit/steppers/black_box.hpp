#pragma once
/// Black-box steppers: a double-only integrator with a C call, audited like any other.
///
/// The integrator is a function
///     void step(double* y, double t, double h, void* ctx);      (C++: throws on failure)
///     int step(double* y, double t, double h, void* ctx);       (C: returns 0, or a status)
/// that advances y = (q, p) (the problem's state, q first) from t by h in place. For each
/// run the audit calls `create` with the problem's first-order system y' = f(t, y) as C
/// callbacks (ode_system: the right-hand side and, for implicit methods, its Jacobian
/// df/dy by AD; on a separable problem its velocity and force apart, counted as the
/// library's steppers count them), and the context it returns goes to every step (and to
/// `destroy` at the end of the run).
///
/// What the audit measures is what it measures for any stepper (audit.hpp), in double. A
/// black box cannot run on AD scalars: the Jacobian of one step, for the symplectic
/// condition M J M^T = J (notes eqs 300-302), comes from finite differences
/// (finite_differences.hpp), whose error model gives the resolution of the check: a
/// defect below it is reported as "no defect above <resolution>", not as "preserved to
/// rounding".
///
/// Failures become results: a step that leaves a NaN or infinite state, a callback that
/// cannot evaluate, or an error the step reports by throwing a mechcheck::error ends that
/// run with a typed error naming the stepper, the step and the state (the audit records
/// it as a failed run); bad input to the adapter (no step function, a non-finite state, h
/// = 0) is a typed error.

#include <cstring>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "mechcheck/audit/audit.hpp"

namespace mechcheck::audit {

/// The problem's first-order system y' = f(t, y), y = (q, p), as C callbacks for a black
/// box. Both callbacks return 0 on success and -1 when they cannot evaluate (never throw).
struct ode_system {
  int dimension = 0;
  /// f(t, y): one evaluation of the whole vector field.
  int (*rhs)(double t, const double* y, double* dydt, void* self) = nullptr;
  /// df/dy, row-major dimension x dimension, by forward AD through the problem (not counted).
  int (*jacobian)(double t, const double* y, double* dfdy, void* self) = nullptr;
  void* self = nullptr;
  /// The size of q in y = (q, p).
  int nq = 0;
  /// A separable problem's halves (H = T(p) + V(q): q' = dT/dp, p' = -dV/dq), for a method
  /// that takes its velocity and its force apart (a splitting, an RKN method): each call of
  /// `force` is one evaluation, as the library's own steppers count one, and `velocity`
  /// none; calling `rhs` instead counts a whole evaluation for each half. Null on a problem
  /// that is not separable.
  int (*velocity)(double t, const double* p, double* dqdt, void* self) = nullptr;
  int (*force)(double t, const double* q, double* dpdt, void* self) = nullptr;
};

/// A step in place: y (size ode_system::dimension) from t to t + h. A failure is thrown as
/// a mechcheck::error (C++), or, for C code, returned by the c_step_status form: 0 for a
/// step taken, anything else a failed step (the run ends there, its status named).
using c_step = void (*)(double* y, double t, double h, void* ctx);
using c_step_status = int (*)(double* y, double t, double h, void* ctx);

/// A double-only stepper behind a C call.
struct black_box {
  std::string name;
  std::string origin;  ///< where it and its claims come from (shown in the report)
  claims declared;
  /// What the method needs of a problem: a splitting or symplectic Euler that takes its
  /// velocity and force from the q and p parts of the right-hand side needs a canonical,
  /// separable problem (structure.canonical = structure.separable = true), and is run on
  /// those only; the others are listed as skipped with the reason.
  method_structure structure;
  /// A context for the runs on one system (may be null for a stateless step).
  std::function<void*(const ode_system&)> create;
  c_step step = nullptr;                ///< the step (C++: throws on failure), or
  c_step_status step_status = nullptr;  ///< the step returning a status (C: 0 is success)
  std::function<void(void*)> destroy;  ///< frees a context (empty: nothing to free)
};

namespace detail {
/// The C view of an erased_system<double> with state y = (q, p): an ode_system whose
/// right-hand side counts as one evaluation and whose Jacobian is by forward AD (not
/// counted). A callback's exception is kept (`failure`) and reported as a nonzero status.
class c_view {
 public:
  c_view(const erased_system<double>& system, Eigen::Index nq, Eigen::Index np)
      : system_(system), nq_(nq), np_(np) {
    ode_.dimension = static_cast<int>(nq + np);
    ode_.rhs = &rhs;
    ode_.jacobian = &jacobian;
    ode_.self = this;
    ode_.nq = static_cast<int>(nq);
    if (system_.separable()) {
      ode_.velocity = &velocity;
      ode_.force = &force;
    }
  }
  c_view(const c_view&) = delete;
  c_view& operator=(const c_view&) = delete;

  const ode_system& ode() const { return ode_; }
  Eigen::Index nq() const { return nq_; }
  Eigen::Index np() const { return np_; }
  /// The message of the last callback that failed ("" if none); clear_failure() resets it.
  const std::string& failure() const { return error_; }
  void clear_failure() { error_.clear(); }
  /// Jacobian evaluations since construction.
  long long jacobians() const { return jacobians_; }

 private:
  static int rhs(double, const double* y, double* dydt, void* self) {
    auto* v = static_cast<c_view*>(self);
    try {
      dynamic_vector<double> q = Eigen::Map<const dynamic_vector<double>>(y, v->nq_);
      dynamic_vector<double> p = Eigen::Map<const dynamic_vector<double>>(y + v->nq_, v->np_);
      dynamic_vector<double> dq = q, dp = p;
      v->system_.vector_field(q, p, dq, dp);
      std::copy(dq.data(), dq.data() + v->nq_, dydt);
      std::copy(dp.data(), dp.data() + v->np_, dydt + v->nq_);
      return 0;
    } catch (const std::exception& e) {
      v->error_ = std::string("the right-hand side failed: ") + e.what();
      return -1;
    }
  }
  static int velocity(double, const double* p, double* dqdt, void* self) {
    auto* v = static_cast<c_view*>(self);
    try {
      const dynamic_vector<double> pv = Eigen::Map<const dynamic_vector<double>>(p, v->np_);
      dynamic_vector<double> dq(v->nq_);
      v->system_.velocity(pv, dq);
      std::copy(dq.data(), dq.data() + v->nq_, dqdt);
      return 0;
    } catch (const std::exception& e) {
      v->error_ = std::string("the velocity failed: ") + e.what();
      return -1;
    }
  }
  static int force(double, const double* q, double* dpdt, void* self) {
    auto* v = static_cast<c_view*>(self);
    try {
      const dynamic_vector<double> qv = Eigen::Map<const dynamic_vector<double>>(q, v->nq_);
      dynamic_vector<double> dp(v->np_);
      v->system_.force(qv, dp);
      std::copy(dp.data(), dp.data() + v->np_, dpdt);
      return 0;
    } catch (const std::exception& e) {
      v->error_ = std::string("the force failed: ") + e.what();
      return -1;
    }
  }
  static int jacobian(double, const double* y, double* dfdy, void* self) {
    auto* v = static_cast<c_view*>(self);
    try {
      ++v->jacobians_;
      const Eigen::Index n = v->nq_ + v->np_;
      const dynamic_vector<double> z = Eigen::Map<const dynamic_vector<double>>(y, n);
      const auto field = [v]<class S>(const dynamic_vector<S>& w) -> dynamic_vector<S> {
        dynamic_vector<S> q = w.head(v->nq_), p = w.tail(v->np_), dq = q, dp = p;
        v->system_.vector_field_uncounted(q, p, dq, dp);
        dynamic_vector<S> out(w.size());
        out << dq, dp;
        return out;
      };
      const dynamic_matrix<double> j = mechcheck::jacobian(field, z);
      for (Eigen::Index r = 0; r < n; ++r)
        for (Eigen::Index c = 0; c < n; ++c) dfdy[r * n + c] = j(r, c);
      return 0;
    } catch (const std::exception& e) {
      v->error_ = std::string("the Jacobian failed: ") + e.what();
      return -1;
    }
  }

  erased_system<double> system_;
  Eigen::Index nq_, np_;
  ode_system ode_;
  long long jacobians_ = 0;
  std::string error_;
};

/// One run of a black box on one problem: its C view of the system and its context.
class black_box_run {
 public:
  black_box_run(const black_box& box, const erased_system<double>& system, Eigen::Index nq,
                Eigen::Index np)
      : box_(box), view_(system, nq, np) {
    context_ = box_.create ? box_.create(view_.ode()) : nullptr;
    if (!view_.failure().empty()) throw error(box_.name + ": creating its context: " + view_.failure());
  }
  ~black_box_run() {
    if (box_.destroy) box_.destroy(context_);
  }
  black_box_run(const black_box_run&) = delete;
  black_box_run& operator=(const black_box_run&) = delete;

  void step(state<double>& x, const double& h) {
    if (!(std::isfinite(h) && h != 0))
      throw non_finite_error(box_.name + ": the step h must be finite and non-zero, got " +
                             to_text(h));
    require_finite_vector(x.q, box_.name, "q");
    require_finite_vector(x.p, box_.name, "p");
    const Eigen::Index nq = view_.nq(), np = view_.np();
    y_.resize(static_cast<std::size_t>(nq + np));
    std::copy(x.q.data(), x.q.data() + nq, y_.data());
    std::copy(x.p.data(), x.p.data() + np, y_.data() + nq);
    ++steps_;
    view_.clear_failure();
    if (box_.step_status) {
      const int status = box_.step_status(y_.data(), t_, h, context_);
      if (status != 0)
        throw convergence_error(box_.name + ": step " + std::to_string(steps_) + " at t = " + to_text(t_) +
                                ", h = " + to_text(h) + " returned status " + std::to_string(status) +
                                (view_.failure().empty() ? "" : " (" + view_.failure() + ")"));
    } else {
      try {
        box_.step(y_.data(), t_, h, context_);
      } catch (const non_finite_error& e) {  // a child's state that is not finite: where it went
        throw non_finite_error(box_.name + ": diverged at step " + std::to_string(steps_) + ": " + e.what());
      }
    }
    if (!view_.failure().empty())
      throw error(box_.name + ": step " + std::to_string(steps_) + " at t = " + to_text(t_) +
                  ", h = " + to_text(h) + ": " + view_.failure());
    for (std::size_t i = 0; i < y_.size(); ++i)
      if (!std::isfinite(y_[i]))
        throw non_finite_error(box_.name + ": diverged at step " + std::to_string(steps_) + " at t = " +
                               to_text(t_) + ", h = " + to_text(h) + ": it left y[" +
                               std::to_string(i) + "] = " + to_text(y_[i]) + " from q = " +
                               to_text(x.q) + ", p = " + to_text(x.p));
    std::copy(y_.data(), y_.data() + nq, x.q.data());
    std::copy(y_.data() + nq, y_.data() + nq + np, x.p.data());
    t_ += h;
  }

 private:
  const black_box& box_;
  c_view view_;
  void* context_ = nullptr;
  std::vector<double> y_;
  double t_ = 0;
  long long steps_ = 0;
};
}  // namespace detail

/// The audit's view of a black box: a stepper in double whose step Jacobian is taken by
/// finite differences. Throws domain_error for a box without a name or a step function.
inline stepper_under_audit<double> black_box_stepper(black_box box) {
  if (box.name.empty()) throw domain_error("black_box_stepper: the stepper needs a name");
  if (!box.step == !box.step_status)
    throw domain_error("black_box_stepper: " + box.name +
                       (box.step ? ": both step and step_status are set (one step function)" : ": the step function is null"));
  stepper_under_audit<double> s;
  s.name = box.name;
  s.origin = box.origin;
  s.declared = box.declared;
  s.structure = box.structure;
  s.finite_differences = true;
  auto shared = std::make_shared<const black_box>(std::move(box));
  s.make = [shared](const erased_system<double>& system) -> step_function<double> {
    // The state's split (q, p) is learnt from the first step.
    std::shared_ptr<detail::black_box_run> run;
    return [shared, system, run](state<double>& x, const double& h) mutable {
      if (!run) run = std::make_shared<detail::black_box_run>(*shared, system, x.q.size(), x.p.size());
      run->step(x, h);
    };
  };
  return s;
}

/// A library stepper Method<System, Vec> behind the C call: the system it sees is the
/// ode_system's callbacks (separable methods get velocity and force from the
/// right-hand side's q and p parts). For tests and as an example of the calling
/// convention.
template <template <class, class> class Method>
black_box library_stepper_as_black_box(std::string name, Eigen::Index nq_hint = -1) {
  struct c_system {
    ode_system ode;
    Eigen::Index nq;
    mutable dynamic_vector<double> q_last;
    void call(const dynamic_vector<double>& q, const dynamic_vector<double>& p,
              dynamic_vector<double>& dq, dynamic_vector<double>& dp) const {
      std::vector<double> y(static_cast<std::size_t>(q.size() + p.size())), f(y.size());
      std::copy(q.data(), q.data() + q.size(), y.data());
      std::copy(p.data(), p.data() + p.size(), y.data() + q.size());
      if (ode.rhs(0, y.data(), f.data(), ode.self) != 0)
        throw error("library_stepper_as_black_box: the right-hand side failed");
      dq = Eigen::Map<dynamic_vector<double>>(f.data(), q.size());
      dp = Eigen::Map<dynamic_vector<double>>(f.data() + q.size(), p.size());
    }
    void vector_field(const dynamic_vector<double>& q, const dynamic_vector<double>& p,
                      dynamic_vector<double>& dq, dynamic_vector<double>& dp) const {
      call(q, p, dq, dp);
    }
    // A separable problem's halves: its own callbacks (a force counted as one evaluation, a
    // velocity as none), else the whole right-hand side.
    void velocity(const dynamic_vector<double>& p, dynamic_vector<double>& dq) const {
      if (ode.velocity) {
        dq.resize(nq);
        if (ode.velocity(0, p.data(), dq.data(), ode.self) != 0)
          throw error("library_stepper_as_black_box: the velocity failed");
        return;
      }
      dynamic_vector<double> dp = p;
      call(q_last, p, dq, dp);  // separable: dq does not depend on q
    }
    void force(const dynamic_vector<double>& q, dynamic_vector<double>& dp) const {
      q_last = q;
      if (ode.force) {
        dp.resize(ode.dimension - nq);
        if (ode.force(0, q.data(), dp.data(), ode.self) != 0) throw error("library_stepper_as_black_box: the force failed");
        return;
      }
      dynamic_vector<double> dq = dp;
      dynamic_vector<double> p = dynamic_vector<double>::Zero(dp.size());
      call(q, p, dq, dp);  // separable: dp does not depend on p
    }
    double energy(const dynamic_vector<double>&, const dynamic_vector<double>&) const { return 0; }
  };
  struct context {
    c_system system;
    Method<c_system, dynamic_vector<double>> method;
    Eigen::Index nq;
  };
  black_box b;
  b.name = std::move(name);
  b.origin = "mechcheck stepper behind the black-box C call";
  using M = Method<c_system, dynamic_vector<double>>;
  b.declared = detail::claims_of<M>();
  b.structure = detail::structure_of<M>();
  b.create = [nq_hint](const ode_system& ode) -> void* {
    const Eigen::Index nq = nq_hint >= 0 ? nq_hint : ode.dimension / 2;
    c_system sys{ode, nq, dynamic_vector<double>::Zero(nq)};
    return new context{sys, M{sys}, nq};
  };
  b.step = [](double* y, double, double h, void* ctx) {
    auto* c = static_cast<context*>(ctx);
    const Eigen::Index n = c->system.ode.dimension;
    phase_state<dynamic_vector<double>> x{Eigen::Map<dynamic_vector<double>>(y, c->nq),
                                          Eigen::Map<dynamic_vector<double>>(y + c->nq, n - c->nq)};
    c->system.q_last = x.q;  // a method that drifts first takes its velocity at the start
    c->method(x, h);
    std::copy(x.q.data(), x.q.data() + c->nq, y);
    std::copy(x.p.data(), x.p.data() + (n - c->nq), y + c->nq);
  };
  b.destroy = [](void* ctx) { delete static_cast<context*>(ctx); };
  return b;
}

}  // namespace mechcheck::audit
