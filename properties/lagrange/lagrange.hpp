#pragma once
/// Lagrangian and Hamiltonian mechanics, Noether's theorem, Galilean and similarity laws
/// (notes lectures 1-8, 21). These are pointwise identities at random states: the
/// Euler-Lagrange accelerations, momenta and charges come from L by nested AD.
///
/// Tolerance model: each quantity is a short sum of products of AD derivatives, plus for
/// accelerations a linear solve with the kinetic matrix W (error ~ n eps cond(W)). Each
/// law names its scale (the magnitude of the terms that cancel) and a budget k counted
/// from those operations; residuals are reported in eps * scale.

#include <cmath>
#include "mechcheck/harness/generators.hpp"
#include "mechcheck/harness/law.hpp"

namespace mechcheck::laws::lagrange {

namespace mc = mechcheck;
namespace gen = mechcheck::generators;
namespace models = mechcheck::models;
using mc::dynamic_matrix;
using mc::dynamic_vector;
using mc::lift;
using mc::harness::check_close;
using mc::harness::check_zero;
using mc::harness::law_info;

template <class T>
T inf_norm(const dynamic_vector<T>& v) {
  return v.size() ? T(v.template lpNorm<Eigen::Infinity>()) : lift<T>(0);
}

template <class T>
T at_least_one(const T& x) {
  return x > 1 ? x : lift<T>(1);
}

template <class T>
void check_vectors(const std::string& what, const dynamic_vector<T>& computed,
                   const dynamic_vector<T>& expected, const T& scale, double budget) {
  for (Eigen::Index i = 0; i < computed.size(); ++i)
    check_close(what + "[" + std::to_string(i) + "]", computed(i), expected(i), scale, budget);
}

using closed_system = models::particle_system<double, gen::pair_potential>;
using gen::model_case;

/// The Noether charge of (L, G, F) as a function of (q, qdot, t), for d/dt by AD.
template <class L, class G, class F>
struct charge_function {
  const L& lag;
  const G& generator;
  const F& f;
  template <class S>
  S operator()(const dynamic_vector<S>& q, const dynamic_vector<S>& qdot, const S& t) const {
    return mc::noether_charge(lag, generator, f, q, qdot, t);
  }
};

/// d/dt of the charge on the solution through (q, qdot, t) as the sum of its terms
/// dQ/dz_i dz_i/dt, z = (q, qdot, t), dz/dt = (qdot, qddot, 1), and the sum of their
/// magnitudes as its scale.
template <class T, class L, class G, class F>
std::pair<T, T> charge_rate(const L& lag, const G& generator, const F& f,
                            const dynamic_vector<T>& q, const dynamic_vector<T>& qdot,
                            const T& t) {
  using std::abs;
  const Eigen::Index n = q.size();
  const dynamic_vector<T> a = mc::accelerations(lag, q, qdot, t);
  const charge_function<L, G, F> charge{lag, generator, f};
  const auto stacked = [&charge, n]<class S>(const dynamic_vector<S>& z) -> S {
    const dynamic_vector<S> qq = z.head(n), vv = z.segment(n, n);
    return charge(qq, vv, z(2 * n));
  };
  dynamic_vector<T> z(2 * n + 1), rate_of_z(2 * n + 1);
  z << q, qdot, t;
  rate_of_z << qdot, a, lift<T>(1);
  const dynamic_vector<T> g = mc::gradient(stacked, z);
  T rate = lift<T>(0), scale = lift<T>(0);
  for (Eigen::Index i = 0; i < z.size(); ++i) {
    const T term = g(i) * rate_of_z(i);
    rate += term;
    scale += abs(term);
  }
  return {rate, at_least_one(scale)};
}

/// Call body(lagrangian) with the case's model.
template <class Body>
void with_model(const model_case& c, Body&& body) {
  const auto& p = c.params;
  switch (c.which) {
    case 0:
      return body(models::spring_pendulum<double>{p[0], p[1], p[2], p[3]});
    case 1:
      return body(models::spherical_pendulum<double>(p[0], p[1], p[2]));
    case 2:
      return body(models::rotating_pivot_pendulum<double>{p[0], p[1], p[2], p[3], p[4]});
    default:
      return body(closed_system(c.particles.masses, c.pair));
  }
}

/// The symmetries of a closed N-particle system, one at a time.
enum class symmetry { translation, rotation, time_translation, boost };

template <class T, class Body>
void with_symmetry(symmetry which, const closed_system& sys, const std::vector<double>& n,
                   Body&& body) {
  const double d[3] = {n[0], n[1], n[2]};
  switch (which) {
    case symmetry::translation:
      return body(mc::translation_generator<double>{{d[0], d[1], d[2]}}, mc::zero_function{});
    case symmetry::rotation:
      return body(mc::rotation_generator<double>{{d[0], d[1], d[2]}}, mc::zero_function{});
    case symmetry::time_translation:
      return body(mc::time_translation_generator{}, sys);
    default:
      return body(mc::boost_generator<double>{{d[0], d[1], d[2]}},
                  mc::boost_gauge_function<double>{sys.masses, {d[0], d[1], d[2]}});
  }
}

}  // namespace mechcheck::laws::lagrange
