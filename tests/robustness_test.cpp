// Bad input, systematically: every public entry point of lib/ and reference/ that takes
// physical parameters or states is fed invalid values (NaN, +-inf, zero, negative,
// subnormal and huge values, mismatched sizes, non-physical tensors, unbound energies,
// impossible eccentricities, singular Legendre maps, steps that cannot converge). Each
// must throw a typed mechcheck::error whose message starts with the function's name and
// names the argument and the offending value; a stepper that throws leaves the state as
// it was. The random invalid values come from RapidCheck generators with a fixed seed,
// so the count printed at the end is the same on every run.
#include <array>
#include <cmath>
#include <cstring>
#include <functional>
#include <iostream>
#include <limits>
#include <set>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <rapidcheck.h>

#include "mechcheck/mechcheck.hpp"
#include "mechcheck/reference/harmonic_oscillator.hpp"
#include "mechcheck/reference/pendulum.hpp"
#include "mechcheck/reference/solids.hpp"
#include "mechcheck/reference/tops.hpp"
#include "mechcheck/reference/twist.hpp"

namespace {
namespace mc = mechcheck;
namespace models = mechcheck::models;
namespace ref = mechcheck::reference;
using V3 = mc::vector3<double>;
using M3 = mc::matrix3<double>;
using DV = mc::dynamic_vector<double>;
using args = std::vector<double>;

constexpr double nan_value = std::numeric_limits<double>::quiet_NaN();
constexpr double inf = std::numeric_limits<double>::infinity();
constexpr double huge = 1e300;

/// What an argument must be; its invalid values follow from it.
enum class must_be { positive, non_negative, finite };

struct argument {
  std::string name;  ///< as the error message must name it
  must_be rule;
};

/// Every probe: one call with one bad input, and what came back.
class tally {
 public:
  explicit tally(std::uint64_t seed) : random_(seed) {}

  /// `call` must throw a mechcheck::error whose message starts with "function" (then ':'
  /// or "::") and contains `argument` and `value`.
  void refuse(const std::string& function, const std::string& argument, const std::string& value,
              const std::function<void()>& call) {
    ++tried_;
    functions_.insert(function);
    inputs_.insert(function + "|" + argument + "|" + value);
    const std::string probe = function + " with " + argument + " = " + value;
    try {
      call();
      failures_.push_back(probe + ": accepted (no error)");
    } catch (const mc::error& e) {
      const std::string m = e.what();
      const bool named = m.rfind(function + ":", 0) == 0;
      if (!named)
        failures_.push_back(probe + ": message does not start with the function: " + m);
      else if (m.find(argument) == std::string::npos)
        failures_.push_back(probe + ": message does not name the argument: " + m);
      else if (m.find(value) == std::string::npos)
        failures_.push_back(probe + ": message does not name the value: " + m);
      else
        ++typed_;
    } catch (const std::exception& e) {
      failures_.push_back(probe + ": foreign exception: " + e.what());
    }
  }

  /// One argument at a time replaced by each invalid value of its rule, the others kept
  /// at `good` (which the call must accept: a probe of a call that always throws proves
  /// nothing).
  void sweep(const std::string& function, const std::vector<argument>& arguments, const args& good,
             const std::function<void(const args&)>& call) {
    try {
      call(good);
    } catch (const std::exception& e) {
      failures_.push_back(function + ": the valid baseline is refused: " + e.what());
      return;
    }
    for (std::size_t i = 0; i < arguments.size(); ++i)
      for (double v : invalid(arguments[i].rule)) {
        args a = good;
        a[i] = v;
        refuse(function, arguments[i].name, mc::to_text(v), [&] { call(a); });
      }
  }

  /// NaN, +-inf; for positive arguments also zero, -0, negatives (tiny, unit, huge and
  /// random ones) and subnormals; for non-negative ones the negatives.
  std::vector<double> invalid(must_be rule) {
    std::vector<double> v{nan_value, inf, -inf};
    if (rule == must_be::finite) return v;
    const double tiny = std::numeric_limits<double>::denorm_min();
    for (double x : {-tiny, -1e-310, -1.0, -huge}) v.push_back(x);
    for (int k = 0; k < 3; ++k) v.push_back(-random_magnitude());
    if (rule == must_be::positive)
      for (double x : {0.0, -0.0, tiny, 1e-310}) v.push_back(x);
    return v;
  }

  /// A random magnitude 2^e m / 2^20 with m in [1, 2^20) and e in [-40, 40].
  double random_magnitude() {
    const auto mantissa = rc::gen::inRange(1, 1 << 20)(random_.split()).value();
    const auto exponent = rc::gen::inRange(-40, 41)(random_.split()).value();
    return std::ldexp(mantissa, exponent - 20);
  }

  int tried() const { return tried_; }
  int typed() const { return typed_; }
  std::size_t distinct_inputs() const { return inputs_.size(); }
  std::size_t entry_points() const { return functions_.size(); }
  const std::vector<std::string>& failures() const { return failures_; }
  void fail(const std::string& what) { failures_.push_back(what); }

 private:
  rc::Random random_;
  int tried_ = 0, typed_ = 0;
  std::set<std::string> functions_, inputs_;
  std::vector<std::string> failures_;
};

constexpr auto pos = must_be::positive;
constexpr auto fin = must_be::finite;
constexpr auto nonneg = must_be::non_negative;

DV vec(std::initializer_list<double> x) {
  DV v(static_cast<Eigen::Index>(x.size()));
  Eigen::Index i = 0;
  for (double e : x) v(i++) = e;
  return v;
}

/// Model constructors and their Lagrangians' states.
void models_and_lagrangians(tally& t) {
  t.sweep("free_particle", {{"mass", pos}}, {1}, [](const args& a) { static_cast<void>(models::free_particle(a[0])); });
  t.sweep("oscillator", {{"mass", pos}, {"stiffness", pos}}, {1, 2},
          [](const args& a) { models::oscillator(a[0], a[1]); });
  const std::vector<argument> mlg{{"mass", pos}, {"length", pos}, {"gravity", pos}};
  t.sweep("simple_pendulum", mlg, {1, 2, 3},
          [](const args& a) { models::simple_pendulum(a[0], a[1], a[2]); });
  t.sweep("spherical_pendulum", mlg, {1, 2, 3},
          [](const args& a) { models::spherical_pendulum(a[0], a[1], a[2]); });
  const std::vector<argument> mklg{
      {"mass", pos}, {"stiffness", pos}, {"length", pos}, {"gravity", pos}};
  t.sweep("spring_pendulum", mklg, {1, 2, 3, 4},
          [](const args& a) { models::spring_pendulum(a[0], a[1], a[2], a[3]); });
  t.sweep("spring_pendulum_cartesian", mklg, {1, 2, 3, 4},
          [](const args& a) { models::spring_pendulum_cartesian(a[0], a[1], a[2], a[3]); });
  t.sweep("rotating_pivot_pendulum",
          {{"mass", pos}, {"length", pos}, {"gravity", pos}, {"radius", nonneg}, {"omega", fin}},
          {1, 2, 3, 0.5, -1},
          [](const args& a) { models::rotating_pivot_pendulum(a[0], a[1], a[2], a[3], a[4]); });
  // The spring pendulum's arm l + x through or beyond the pivot.
  const models::spring_pendulum<double> spring(1, 1, 1, 1);
  for (double x : {-1.0, -1.5, -1e3, -huge})
    t.refuse("spring_pendulum", "l + x", mc::to_text(1 + x),
             [&] { spring(vec({x, 0.1}), vec({0, 0}), 0.0); });
  t.refuse("spring_pendulum", "q", "needs 2",
           [&] { spring(vec({0.1}), vec({0}), 0.0); });
  t.sweep("particle_system", {{"mass 0", pos}, {"mass 1", pos}}, {1, 2}, [](const args& a) {
    models::particle_system<double, models::power_law_pair<double>>({a[0], a[1]}, {1.0, -1});
  });
  t.sweep("velocity_coupled_system",
          {{"mass 0", pos}, {"mass 1", pos}, {"beta", nonneg}, {"kappa", fin}}, {1, 2, 0.5, 0.1},
          [](const args& a) {
            models::velocity_coupled_system<double, models::power_law_pair<double>>(
                {a[0], a[1]}, {1.0, -1}, models::kinetic_form::quartic, a[2], a[3]);
          });
  {
    const models::velocity_coupled_system<double, models::power_law_pair<double>> light(
        {1.0}, {1.0, -1}, models::kinetic_form::relativistic, 0.0, 0.0);
    for (double v : {1.0, -1.5, 1e3})
      t.refuse("velocity_coupled_system", "|v|^2", mc::to_text(v * v),
               [&] { light(vec({0, 0, 0}), vec({v, 0, 0}), 0.0); });
    t.refuse("velocity_coupled_system", "coordinates", "got 2",
             [&] { light(vec({0, 0}), vec({0, 0}), 0.0); });
  }
  t.sweep("power_law_pair", {{"c", fin}}, {-1}, [](const args& a) { models::power_law_pair(a[0], 2); });
  t.refuse("power_law_pair", "exponent k", "0", [] { models::power_law_pair(1.0, 0); });
  t.sweep("lennard_jones_pair", {{"depth", pos}, {"size", pos}}, {1, 1},
          [](const args& a) { models::lennard_jones_pair(a[0], a[1]); });
  t.sweep("morse_pair", {{"depth", pos}, {"width", pos}, {"r0", pos}}, {1, 2, 1},
          [](const args& a) { models::morse_pair(a[0], a[1], a[2]); });
  t.sweep("vertical_field", {{"a", fin}, {"b", fin}}, {1, -1},
          [](const args& a) { models::vertical_field(a[0], a[1]); });

  // The Lagrangian machinery at bad states: (q, qdot, t) and, for paths, qddot.
  const models::oscillator<double> osc(1, 2);
  const std::vector<argument> state{{"q[0]", fin}, {"q[1]", fin}, {"qdot[0]", fin},
                                    {"qdot[1]", fin}, {"t", fin}};
  const args good{0.5, -0.25, 1, 2, 0.125};
  const auto q = [](const args& a) { return vec({a[0], a[1]}); };
  const auto v = [](const args& a) { return vec({a[2], a[3]}); };
  t.sweep("generalized_momenta", state, good,
          [&](const args& a) { mc::generalized_momenta(osc, q(a), v(a), a[4]); });
  t.sweep("accelerations", state, good,
          [&](const args& a) { mc::accelerations(osc, q(a), v(a), a[4]); });
  t.sweep("energy_function", state, good,
          [&](const args& a) { mc::energy_function(osc, q(a), v(a), a[4]); });
  t.sweep("noether_charge", state, good, [&](const args& a) {
    mc::noether_charge(osc, mc::time_translation_generator{}, osc, q(a), v(a), a[4]);
  });
  std::vector<argument> path = state;
  path.push_back({"qddot[0]", fin});
  args good_path = good;
  good_path.push_back(0.75);
  const auto acc = [](const args& a) { return vec({a[5], 0.0}); };
  t.sweep("euler_lagrange_residual", path, good_path,
          [&](const args& a) { mc::euler_lagrange_residual(osc, q(a), v(a), acc(a), a[4]); });
  t.sweep("symmetry_defect", path, good_path, [&](const args& a) {
    mc::symmetry_defect(osc, mc::time_translation_generator{}, osc, q(a), v(a), acc(a), a[4]);
  });
  const std::vector<argument> qp{{"q", fin}, {"q", fin}, {"p", fin}, {"p", fin}, {"t", fin}};
  t.sweep("velocities_from_momenta", qp, good,
          [&](const args& a) { mc::velocities_from_momenta(osc, q(a), v(a), a[4]); });
  const mc::legendre_hamiltonian<models::oscillator<double>> h{osc};
  t.sweep("hamilton_equations", {{"q[0]", fin}, {"q[1]", fin}, {"p[0]", fin}, {"p[1]", fin},
                                 {"t", fin}},
          good, [&](const args& a) { mc::hamilton_equations(h, q(a), v(a), a[4]); });
  t.refuse("generalized_momenta", "qdot", "3",
           [&] { mc::generalized_momenta(osc, vec({1, 2}), vec({1, 2, 3}), 0.0); });
  t.refuse("euler_lagrange_residual", "qddot", "1",
           [&] { mc::euler_lagrange_residual(osc, vec({1, 2}), vec({1, 2}), vec({1}), 0.0); });
  t.refuse("velocities_from_momenta", "p", "3",
           [&] { mc::velocities_from_momenta(osc, vec({1, 2}), vec({1, 2, 3}), 0.0); });
  // Singular Legendre maps: L = (qdot_0 + qdot_1)^2 / 2 and L = qdot_0 (linear).
  const auto degenerate = []<class S>(const mc::dynamic_vector<S>&, const mc::dynamic_vector<S>& w,
                                      const S&) -> S {
    const S s = w(0) + w(1);
    return s * s * mc::half<S>();
  };
  const auto linear = []<class S>(const mc::dynamic_vector<S>&, const mc::dynamic_vector<S>& w,
                                  const S&) -> S { return w(0); };
  t.refuse("accelerations", "kinetic matrix", "rank 1",
           [&] { mc::accelerations(degenerate, vec({1, 2}), vec({0.5, 1}), 0.0); });
  t.refuse("accelerations", "kinetic matrix", "rank 0",
           [&] { mc::accelerations(linear, vec({1}), vec({0.5}), 0.0); });
  t.refuse("velocities_from_momenta", "kinetic matrix", "rank 1",
           [&] { mc::velocities_from_momenta(degenerate, vec({1, 2}), vec({0.5, 1}), 0.0); });
  t.refuse("velocities_from_momenta", "kinetic matrix", "rank 0",
           [&] { mc::velocities_from_momenta(linear, vec({1}), vec({0.5}), 0.0); });
}

/// Phase space, Poisson brackets and the phase-space functions.
void phase_space_and_poisson(tally& t) {
  t.refuse("phase_point", "p", "3", [] { mc::phase_point<double>(vec({1, 2}), vec({1, 2, 3})); });
  t.refuse("phase_point::from_stacked", "length", "3",
           [] { mc::phase_point<double>::from_stacked(vec({1, 2, 3})); });
  const mc::harmonic_oscillator<double> h(1, 1);
  const std::vector<argument> point{{"q[0]", fin}, {"q[1]", fin}, {"p[0]", fin}, {"p[1]", fin}};
  const auto x = [](const args& a) { return mc::phase_point<double>(vec({a[0], a[1]}), vec({a[2], a[3]})); };
  t.sweep("poisson_bracket", point, {1, 2, 3, 4},
          [&](const args& a) { mc::poisson_bracket(h, mc::q_component{0}, x(a)); });
  t.sweep("hamiltonian_vector_field", point, {1, 2, 3, 4},
          [&](const args& a) { mc::hamiltonian_vector_field(h, x(a)); });
  t.sweep("harmonic_oscillator", {{"mass", pos}, {"stiffness", pos}}, {1, 2},
          [](const args& a) { mc::harmonic_oscillator(a[0], a[1]); });
  t.sweep("power_law_potential", {{"k", fin}}, {-1},
          [](const args& a) { mc::power_law_potential(a[0], -1); });
  t.refuse("power_law_potential", "exponent n", "0", [] { mc::power_law_potential(1.0, 0); });
  t.sweep("central_force_hamiltonian", {{"mass", pos}}, {1}, [](const args& a) {
    mc::central_force_hamiltonian(a[0], mc::power_law_potential(-1.0, -1));
  });
  t.refuse("angular_momentum", "q", "got 2",
           [] { mc::angular_momentum{0}(vec({1, 2}), vec({3, 4})); });
  t.refuse("lrl_vector", "degrees of freedom", "got 2",
           [] { mc::lrl_vector(vec({1, 2}), vec({3, 4}), 1.0, 1.0); });
}

/// Two bodies, Kepler orbits, radial quadratures.
void central_forces(tally& t) {
  const std::vector<argument> masses{{"m1", pos}, {"m2", pos}};
  t.sweep("reduced_mass", masses, {1, 2}, [](const args& a) { mc::reduced_mass(a[0], a[1]); });
  t.sweep("to_relative", {{"m1", pos}, {"m2", pos}, {"r1", fin}, {"v2", fin}}, {1, 2, 0.5, -1},
          [](const args& a) {
            mc::to_relative(a[0], a[1], V3(a[2], 0, 0), V3(1, 1, 1), V3(0, 1, 0), V3(0, 0, a[3]));
          });
  t.sweep("from_relative", {{"m1", pos}, {"m2", pos}, {"centre", fin}, {"r", fin}},
          {1, 2, 0.5, -1},
          [](const args& a) { mc::from_relative(a[0], a[1], V3(a[2], 0, 0), V3(0, a[3], 1)); });
  t.sweep("kepler_constants", {{"mu", pos}, {"k", pos}}, {1, 2},
          [](const args& a) { mc::kepler_constants(a[0], a[1]); });
  const mc::kepler_constants<double> c(1, 1);
  for (double m : {0.0, -0.0, nan_value, inf, -inf})
    t.refuse("kepler_constants::circular_radius", "angular momentum", mc::to_text(m),
             [&] { c.circular_radius(m); });
  for (double e : {0.0, -0.0, 0.5, 1e300, nan_value, inf, -inf})
    t.refuse("semi_major_axis", "energy", mc::to_text(e), [&] { mc::semi_major_axis(c, e); });
  // Unbound states: E = p^2/2 - 1/r >= 0.
  for (double speed : {std::sqrt(2.0), 1.5, 10.0, huge})
    t.refuse("orbital_period", "energy", mc::to_text(speed),
             [&] { mc::orbital_period(c, V3(1, 0, 0), V3(0, speed, 0)); });
  t.sweep("orbital_period", {{"r", fin}, {"p", fin}}, {1, 0.5},
          [&](const args& a) { mc::orbital_period(c, V3(a[0], 0, 0), V3(0, a[1], 0)); });
  const std::vector<double> not_elliptic{nan_value, inf, -inf, 1, 1.5, -0.25, -1e-300, huge, -huge};
  for (double e : not_elliptic) {
    t.refuse("solve_kepler", "eccentricity", mc::to_text(e), [&] { mc::solve_kepler(e, 1.0); });
    t.refuse("mean_anomaly_from_eccentric", "eccentricity", mc::to_text(e),
             [&] { mc::mean_anomaly_from_eccentric(e, 1.0); });
  }
  for (double e : {nan_value, inf, -inf, 1.0, 0.5, 0.0, -1.0})
    t.refuse("solve_hyperbolic_kepler", "eccentricity", mc::to_text(e),
             [&] { mc::solve_hyperbolic_kepler(e, 1.0); });
  for (double e : {nan_value, inf, -inf, -0.5, -huge}) {
    t.refuse("mean_anomaly_from_true", "eccentricity", mc::to_text(e),
             [&] { mc::mean_anomaly_from_true(e, 1.0); });
    t.refuse("true_anomaly_from_mean", "eccentricity", mc::to_text(e),
             [&] { mc::true_anomaly_from_mean(e, 1.0); });
  }
  t.sweep("solve_kepler", {{"mean anomaly", fin}}, {1}, [](const args& a) { mc::solve_kepler(0.5, a[0]); });
  t.sweep("solve_hyperbolic_kepler", {{"mean anomaly", fin}}, {1},
          [](const args& a) { mc::solve_hyperbolic_kepler(1.5, a[0]); });
  t.sweep("mean_anomaly_from_eccentric", {{"eccentric anomaly", fin}}, {1},
          [](const args& a) { mc::mean_anomaly_from_eccentric(0.5, a[0]); });
  t.sweep("mean_anomaly_from_true", {{"true anomaly", fin}}, {1},
          [](const args& a) { mc::mean_anomaly_from_true(0.5, a[0]); });
  t.sweep("true_anomaly_from_mean", {{"mean anomaly", fin}}, {1},
          [](const args& a) { mc::true_anomaly_from_mean(0.5, a[0]); });
  // Beyond the asymptotes of a hyperbola (e = 2: |nu| < 2 pi / 3).
  for (double nu : {2.1, -2.5, 3.0})
    t.refuse("mean_anomaly_from_true", "true anomaly", mc::to_text(nu),
             [&] { mc::mean_anomaly_from_true(2.0, nu); });
  const std::vector<argument> rv{{"r", fin}, {"r", fin}, {"v", fin}, {"v", fin}};
  t.sweep("elements_from_state", rv, {1, 0.5, 0.25, 1}, [&](const args& a) {
    mc::elements_from_state(c, V3(a[0], a[1], 0), V3(a[2], a[3], 0));
  });
  t.refuse("elements_from_state", "angular momentum", "r = (1, 0, 0)",
           [&] { mc::elements_from_state(c, V3(1, 0, 0), V3(2, 0, 0)); });
  t.sweep("kepler_orbit", {{"r0", fin}, {"r0", fin}, {"v0", fin}, {"v0", fin}}, {1, 0.5, 0.25, 1}, [&](const args& a) {
    mc::kepler_orbit<double>(c, V3(a[0], a[1], 0), V3(a[2], a[3], 0));
  });
  for (double p : {0.0, -1.0, nan_value}) {
    mc::orbit_elements<double> el{p, 0.5, 0, 0, 0, 0};
    t.refuse("state_from_elements", "semi-latus rectum", mc::to_text(p),
             [&] { mc::state_from_elements(c, el); });
  }
  t.sweep("radial_orbit", {{"mu", pos}, {"r1", pos}, {"r2", fin}}, {1, 1, 2},
          [](const args& a) { mc::radial_orbit<double>(a[0], 1, 2, a[1], a[2]); });
  for (double r2 : {1.0, 0.5, -1.0})
    t.refuse("radial_orbit", "r2", mc::to_text(r2),
             [&] { mc::radial_orbit<double>(1, 1, 2, 1, r2); });
  for (double cn : {0.0, -1.0, nan_value, inf})
    t.refuse("radial_orbit", "c", mc::to_text(cn), [&] { mc::radial_orbit<double>(1, cn, 2, 1, 2); });
}

/// Inertia, rigid bodies, Euler angles, tops.
void rigid_bodies(tally& t) {
  const auto cloud = [](const args& a) {
    return mc::point_cloud<double>{{a[0], 1.0}, {V3(a[1], 0, 0), V3(0, 1, 0)}};
  };
  const std::vector<argument> cloud_args{{"mass 0", pos}, {"position 0", fin}};
  t.sweep("centre_of_mass", cloud_args, {1, 1},
          [&](const args& a) { mc::centre_of_mass(cloud(a)); });
  std::vector<argument> with_origin = cloud_args;
  with_origin.push_back({"origin", fin});
  t.sweep("inertia_tensor", with_origin, {1, 1, 0.5}, [&](const args& a) {
    mc::inertia_tensor(cloud(a), V3(0, a[2], 0));
  });
  t.refuse("centre_of_mass", "masses", "3 positions", [] {
    mc::centre_of_mass(mc::point_cloud<double>{{1.0}, {V3(0, 0, 0), V3(1, 0, 0), V3(0, 1, 0)}});
  });
  t.refuse("inertia_tensor", "masses", "0 positions", [] {
    mc::inertia_tensor(mc::point_cloud<double>{}, V3(0, 0, 0));
  });
  const M3 box = ref::box_inertia(1.0, 1.0, 2.0, 3.0);
  const std::vector<argument> shift{{"total mass", pos}, {"offset b", fin}};
  t.sweep("parallel_axis_term", shift, {2, 1},
          [](const args& a) { mc::parallel_axis_term(a[0], V3(0, a[1], 0)); });
  t.sweep("shift_from_centre", shift, {2, 1},
          [&](const args& a) { mc::shift_from_centre(box, a[0], V3(0, a[1], 0)); });
  t.sweep("shift_to_centre", shift, {2, 1},
          [&](const args& a) { mc::shift_to_centre(box, a[0], V3(0, a[1], 0)); });
  const auto with_entry = [&](double x, int i, int j) {
    M3 m = box;
    m(i, j) = x;
    return m;
  };
  for (double x : {nan_value, inf, -inf})
    for (const auto& f : {"principal_axes", "classify", "validate_inertia", "rotate"}) {
      const std::string name = f;
      t.refuse(name, "inertia tensor", mc::to_text(x), [&] {
        const M3 m = with_entry(x, 0, 1);
        if (name == "principal_axes") mc::principal_axes(m);
        if (name == "classify") mc::classify(m);
        if (name == "validate_inertia") mc::validate_inertia(m, "validate_inertia");
        if (name == "rotate") mc::rotate(m, M3::Identity().eval());
      });
    }
  // Not symmetric, not positive semi-definite, violating the triangle inequality.
  for (double x : {0.5, -0.5, 1e-6})
    for (const auto& f : {"principal_axes", "classify", "validate_inertia"}) {
      const std::string name = f;
      t.refuse(name, "not symmetric", mc::to_text(x), [&] {
        const M3 m = with_entry(x, 0, 1);
        if (name == "principal_axes") mc::principal_axes(m);
        if (name == "classify") mc::classify(m);
        if (name == "validate_inertia") mc::validate_inertia(m, "validate_inertia");
      });
    }
  for (double x : {-1.0, -1e-3, -huge}) {
    const M3 m = V3(x, 1, 1).asDiagonal();
    t.refuse("validate_inertia", "positive semi-definite", mc::to_text(x),
             [&] { mc::validate_inertia(m, "validate_inertia"); });
  }
  for (double x : {2.5, 3.0, 100.0}) {
    const M3 m = V3(1, 1, x).asDiagonal();
    t.refuse("validate_inertia", "triangle inequality", mc::to_text(x),
             [&] { mc::validate_inertia(m, "validate_inertia"); });
    t.refuse("free_rigid_body", "triangle inequality", mc::to_text(x),
             [&] { mc::free_rigid_body<double>(V3(1, 1, x)); });
  }
  for (double x : {0.5, 2.0, -1.0, 1.001})
    t.refuse("rotate", "rotation", "det R = " + mc::to_text(x), [&] {
      M3 r = M3::Identity();
      r(0, 0) = x;
      mc::rotate(box, r);
    });
  t.sweep("rotate", {{"rotation", fin}}, {0}, [&](const args& a) {
    M3 r = M3::Identity();
    r(1, 0) = a[0];
    mc::rotate(box, r);
  });
  t.sweep("free_rigid_body", {{"I1", pos}, {"I2", pos}, {"I3", pos}}, {1, 1.5, 2},
          [](const args& a) { mc::free_rigid_body<double>(V3(a[0], a[1], a[2])); });
  t.sweep("heavy_top", {{"I1", pos}, {"I3", pos}, {"mgl", fin}}, {1, 0.5, 2},
          [](const args& a) { mc::heavy_top<double>(a[0], a[1], a[2]); });
  const mc::heavy_top<double> top(1, 0.5, 2);
  t.sweep("heavy_top::steady_precession_rates", {{"theta", fin}, {"Omega_3", fin}}, {0.5, 20},
          [&](const args& a) { top.steady_precession_rates(a[0], a[1]); });
  for (double w : {0.0, 1.0, -1.0})
    t.refuse("heavy_top::steady_precession_rates", "Omega_3", mc::to_text(w),
             [&] { top.steady_precession_rates(0.5, w); });
  for (double theta : {nan_value, inf, 2.0, 3.0})
    t.refuse("heavy_top::minimum_spin", "theta", mc::to_text(theta), [&] { top.minimum_spin(theta); });
  const std::vector<argument> angles{{"phi", fin}, {"theta", fin}, {"psi", fin}};
  t.sweep("euler_rotation", angles, {0.1, 0.2, 0.3},
          [](const args& a) { mc::euler_rotation(a[0], a[1], a[2]); });
  t.sweep("body_angular_velocity",
          {{"phi", fin}, {"theta", fin}, {"psi", fin}, {"phi_dot", fin}, {"theta_dot", fin},
           {"psi_dot", fin}},
          {0.1, 0.2, 0.3, 1, 2, 3},
          [](const args& a) { mc::body_angular_velocity(a[0], a[1], a[2], a[3], a[4], a[5]); });
  t.sweep("rotation_1", {{"angle a", fin}}, {1}, [](const args& a) { mc::rotation_1(a[0]); });
  t.sweep("rotation_3", {{"angle a", fin}}, {1}, [](const args& a) { mc::rotation_3(a[0]); });
}

/// Systems, steppers and integration.
template <class Stepper>
void stepper_refuses(tally& t, const std::string& name, Stepper step) {
  using state = mc::phase_state<DV>;
  const auto unchanged = [&](const state& before, const state& after, const std::string& probe) {
    const auto same = [](const DV& a, const DV& b) {
      return a.size() == b.size() &&
             std::memcmp(a.data(), b.data(), sizeof(double) * std::size_t(a.size())) == 0;
    };
    if (!same(before.q, after.q) || !same(before.p, after.p))
      t.fail(name + " with " + probe + ": the state changed although the step threw");
  };
  const auto probe = [&](const std::string& argument, const std::string& value, state x, double h) {
    const state before = x;
    t.refuse(name, argument, value, [&] { step(x, h); });
    unchanged(before, x, argument + " = " + value);
  };
  for (double h : {0.0, -0.0, nan_value, inf, -inf}) probe("h", mc::to_text(h), {vec({1, 0}), vec({0, 1})}, h);
  for (int i = 0; i < 2; ++i)
    for (double v : {nan_value, inf, -inf}) {
      state x{vec({1, 0.5}), vec({0.25, 1})};
      x.q(i) = v;
      probe("q[" + std::to_string(i) + "]", mc::to_text(v), x, 0.1);
      x.q(i) = 0.5;
      x.p(i) = v;
      probe("p[" + std::to_string(i) + "]", mc::to_text(v), x, 0.1);
    }
  probe("p", "has 3", {vec({1, 0}), vec({0, 1, 2})}, 0.1);
  // Huge states whose step overflows: the step says so and restores the state.
  for (double q : {huge, -huge, 1e200}) probe("h", "q = (" + mc::to_text(q), {vec({q, 0}), vec({0, 1})}, 1e300);
}

void integrators(tally& t) {
  const std::vector<argument> mk{{"mass", pos}, {"k", pos}};
  t.sweep("kepler_system", mk, {1, 2}, [](const args& a) { mc::kepler_system(a[0], a[1]); });
  t.sweep("harmonic_oscillator_system", {{"mass", pos}, {"stiffness", pos}}, {1, 2},
          [](const args& a) { mc::harmonic_oscillator_system(a[0], a[1]); });
  t.sweep("pendulum_system", {{"mass", pos}, {"length", pos}, {"gravity", pos}}, {1, 2, 3},
          [](const args& a) { mc::pendulum_system(a[0], a[1], a[2]); });
  t.sweep("pair_force_system", {{"mass 0", pos}, {"mass 1", pos}}, {1, 2}, [](const args& a) {
    mc::pair_force_system<double, models::power_law_pair<double>>({a[0], a[1]}, {1.0, -1});
  });
  using sys = mc::harmonic_oscillator_system<double>;
  const sys osc(1, 1);
  stepper_refuses(t, "explicit_euler", mc::explicit_euler<sys, DV>(osc));
  stepper_refuses(t, "rk4", mc::rk4<sys, DV>(osc));
  stepper_refuses(t, "symplectic_euler", mc::symplectic_euler<sys, DV>(osc));
  stepper_refuses(t, "stormer_verlet", mc::stormer_verlet<sys, DV>(osc));
  stepper_refuses(t, "composition", mc::composition<sys, DV, 4>(osc));
  stepper_refuses(t, "mclachlan4", mc::mclachlan4<sys, DV>(osc));
  stepper_refuses(t, "gauss_legendre", mc::gauss_legendre<sys, DV, 2>(osc));
  // An implicit step that cannot converge: a stiff pendulum (w = 1000) with h = 1.
  for (double h : {1.0, 0.5, -1.0}) {
    const mc::pendulum_system<double> stiff(1, 1, 1e6);
    mc::gauss_legendre<mc::pendulum_system<double>, DV, 3> gl(stiff);
    mc::phase_state<DV> x{vec({0.5}), vec({0})};
    const auto before = x;
    t.refuse("gauss_legendre", "h", mc::to_text(h), [&] { gl(x, h); });
    if (x.q != before.q || x.p != before.p) t.fail("gauss_legendre: state changed on divergence");
  }
  for (int order : {0, 1, 3, -2, 5})
    t.refuse("triple_jump_weights", "order", std::to_string(order),
             [&] { mc::triple_jump_weights<double>(order); });
  for (int s : {0, -1, 13})
    t.refuse("gauss_legendre_tableau", "stages", std::to_string(s),
             [&] { static_cast<void>(mc::gauss_legendre_tableau<double>(s)); });
  for (long steps : {-1L, -1000L}) {
    mc::stormer_verlet<sys, DV> verlet(osc);
    mc::phase_state<DV> x{vec({1}), vec({0})};
    t.refuse("integrate", "steps", std::to_string(steps), [&] { mc::integrate(verlet, x, 0.1, steps); });
  }
}

/// The analytic references.
void references(tally& t) {
  t.sweep("oscillator_flow", {{"mass", pos}, {"stiffness", pos}}, {1, 2},
          [](const args& a) { ref::oscillator_flow(a[0], a[1]); });
  const ref::oscillator_flow<double> flow(1, 2);
  t.refuse("oscillator_flow", "p", "3", [&] { flow(vec({1, 2}), vec({1, 2, 3}), 0.5); });
  t.sweep("pendulum_motion",
          {{"mass", pos}, {"length", pos}, {"gravity", pos}, {"theta0", fin}, {"p0", fin}},
          {1, 2, 3, 0.5, 0.25},
          [](const args& a) { ref::pendulum_motion<double>(a[0], a[1], a[2], a[3], a[4]); });
  for (double p0 : {10.0, -10.0, 1e10})  // rotations, not oscillations
    t.refuse("pendulum_motion", "p0", mc::to_text(p0),
             [&] { ref::pendulum_motion<double>(1, 1, 1, 0.5, p0); });
  const ref::pendulum_motion<double> pendulum(1, 1, 1, 0.5, 0);
  t.sweep("pendulum_motion::state_at", {{"t", fin}}, {1}, [&](const args& a) { pendulum.state_at(a[0]); });
  t.sweep("box_inertia", {{"mass", pos}, {"edge a", pos}, {"edge b", pos}, {"edge c", pos}},
          {1, 2, 3, 4}, [](const args& a) { ref::box_inertia(a[0], a[1], a[2], a[3]); });
  t.sweep("box_points", {{"mass", pos}, {"edge a", pos}, {"edge b", pos}, {"edge c", pos}},
          {1, 2, 3, 4}, [](const args& a) { ref::box_points(a[0], a[1], a[2], a[3]); });
  t.sweep("cube_inertia", {{"mass", pos}, {"edge l", pos}}, {1, 2},
          [](const args& a) { ref::cube_inertia(a[0], a[1]); });
  t.sweep("solid_sphere_inertia", {{"mass", pos}, {"radius", pos}}, {1, 2},
          [](const args& a) { ref::solid_sphere_inertia(a[0], a[1]); });
  t.sweep("spherical_shell_inertia", {{"mass", pos}, {"radius", pos}}, {1, 2},
          [](const args& a) { ref::spherical_shell_inertia(a[0], a[1]); });
  t.sweep("solid_cylinder_inertia", {{"mass", pos}, {"radius", pos}, {"height", pos}}, {1, 2, 3},
          [](const args& a) { ref::solid_cylinder_inertia(a[0], a[1], a[2]); });
  t.sweep("thin_rod_inertia", {{"mass", pos}, {"length", pos}}, {1, 2},
          [](const args& a) { ref::thin_rod_inertia(a[0], a[1]); });
  t.sweep("solid_capsule_inertia", {{"mass", pos}, {"radius", pos}, {"cylinder length", pos}}, {1, 2, 3},
          [](const args& a) { ref::solid_capsule_inertia(a[0], a[1], a[2]); });
  t.sweep("solid_cone_inertia", {{"mass", pos}, {"radius", pos}, {"height", pos}}, {1, 2, 3},
          [](const args& a) { ref::solid_cone_inertia(a[0], a[1], a[2]); });
  t.sweep("solid_ellipsoid_inertia", {{"mass", pos}, {"semi-axis a", pos}, {"semi-axis b", pos}, {"semi-axis c", pos}},
          {1, 2, 3, 4}, [](const args& a) { ref::solid_ellipsoid_inertia(a[0], a[1], a[2], a[3]); });
  const auto vertices = [](double x) {
    return std::array<V3, 4>{V3(x, 0, 0), V3(1, 0, 0), V3(0, 1, 0), V3(0, 0, 1)};
  };
  t.sweep("tetrahedron_inertia", {{"mass", pos}, {"vertex 0", fin}}, {1, -1},
          [&](const args& a) { ref::tetrahedron_inertia(a[0], vertices(a[1])); });
  t.sweep("tetrahedron_points", {{"mass", pos}, {"vertex 0", fin}}, {1, -1},
          [&](const args& a) { ref::tetrahedron_points(a[0], vertices(a[1])); });
  t.sweep("free_symmetric_top",
          {{"I1", pos}, {"I3", pos}, {"|M|", pos}, {"phi0", fin}, {"theta0", fin}, {"psi0", fin}},
          {1, 1.5, 2, 0.1, 0.2, 0.3}, [](const args& a) {
            ref::free_symmetric_top<double>(a[0], a[1], a[2], a[3], a[4], a[5]);
          });
  for (double i3 : {2.5, 3.0, 1e10})
    t.refuse("free_symmetric_top", "I3", mc::to_text(i3),
             [&] { ref::free_symmetric_top<double>(1, i3, 1, 0, 0.5, 0); });
  t.sweep("asymmetric_top_angular_velocity",
          {{"I1", fin}, {"Omega(0)", fin}, {"t", fin}}, {1, 0.5, 2}, [](const args& a) {
            ref::asymmetric_top_angular_velocity(V3(a[0], 2, 3), V3(a[1], 0.25, 1), a[2]);
          });
  for (const V3& moments : {V3(2, 1, 3), V3(1, 1, 2), V3(0, 1, 2), V3(-1, 1, 2)})
    t.refuse("asymmetric_top_angular_velocity", "I1 < I2 < I3", mc::to_text(moments),
             [&] { ref::asymmetric_top_angular_velocity(moments, V3(1, 1, 1), 1.0); });
  t.sweep("twist_flow", {{"q0", fin}, {"p0", fin}, {"t", fin}}, {1, 2, 3},
          [](const args& a) { ref::twist_flow(a[0], a[1], a[2]); });
}

TEST(robustness, every_entry_point_refuses_bad_input_with_a_typed_error) {
  tally t(20261123);
  models_and_lagrangians(t);
  phase_space_and_poisson(t);
  central_forces(t);
  rigid_bodies(t);
  integrators(t);
  references(t);
  for (const auto& f : t.failures()) ADD_FAILURE() << f;
  std::cout << "robustness: " << t.distinct_inputs() << " distinct bad inputs (" << t.tried()
            << " probes) over " << t.entry_points() << " entry points; " << t.typed()
            << " typed errors naming function, argument and value; "
            << t.tried() - t.typed() << " accepted, untyped or unnamed\n";
  EXPECT_GE(t.distinct_inputs(), 300u);
  EXPECT_GE(t.entry_points(), 40u);
  EXPECT_EQ(t.typed(), t.tried());
}

}  // namespace
