#pragma once
/// Exact flow of the isotropic harmonic oscillator H = |p|^2 / (2m) + k |q|^2 / 2
/// (notes eqs 315-318 in action-angle form; here in Cartesian form):
///   q(t) = q0 cos(w t) + p0 / (m w) sin(w t),
///   p(t) = p0 cos(w t) - m w q0 sin(w t),      w = sqrt(k / m).
/// Templated on the parameter tier P and the evaluation scalar S (a tier, or AD over one,
/// so that d/dt of the flow is available by automatic differentiation).

#include "mechcheck/core.hpp"
#include "mechcheck/phase_space.hpp"
#include "mechcheck/poisson/functions.hpp"

namespace mechcheck::reference {

template <class P>
struct oscillator_flow {
  P mass, stiffness;

  oscillator_flow(P m, P k) : mass(std::move(m)), stiffness(std::move(k)) {
    require_positive(mass, "oscillator_flow", "mass");
    require_positive(stiffness, "oscillator_flow", "stiffness");
  }

  /// Angular frequency w = sqrt(k / m).
  P frequency() const {
    using std::sqrt;
    return sqrt(stiffness / mass);
  }

  /// The state at time t of the trajectory through (q0, p0) at t = 0.
  template <class S>
  phase_point<S> operator()(const dynamic_vector<S>& q0, const dynamic_vector<S>& p0,
                            const S& t) const {
    using std::cos;
    using std::sin;
    if (q0.size() != p0.size())
      throw dimension_error("oscillator_flow: q has " + std::to_string(q0.size()) +
                            " components but p has " + std::to_string(p0.size()));
    using R = real_type_t<S>;  // derived constants in the evaluation tier, never in P
    using std::sqrt;
    const R m = R(mass), wr = sqrt(R(stiffness) / m);
    const S w = lift<S>(wr);
    const S mw = lift<S>(R(m * wr));
    const S inv_mw = lift<S>(R(1 / (m * wr)));
    const S wt = w * t;
    const S c = cos(wt), s = sin(wt);
    dynamic_vector<S> q(q0.size()), p(p0.size());
    for (Eigen::Index i = 0; i < q0.size(); ++i) {
      // Named terms (see mechcheck/core/autodiff.hpp on combining AD values).
      const S qc = q0(i) * c, pc = p0(i) * c;
      const S velocity = p0(i) * inv_mw, force = mw * q0(i);
      const S vs = velocity * s, fs = force * s;
      q(i) = qc + vs;
      p(i) = pc - fs;
    }
    return phase_point<S>(q, p);
  }
};

}  // namespace mechcheck::reference
