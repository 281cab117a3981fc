// The classic problems without closed forms (problems/classic.hpp), in double and mpfr50:
// their systems, references and invariants compiled once.
#include "mechcheck/audit/problems/classic.hpp"

#include "mechcheck/core/format.hpp"
#include "mechcheck/integrators/systems.hpp"

namespace mechcheck::audit {

namespace {
/// Text of a list of values, for the cache key.
std::string joined(const std::vector<std::string>& v) {
  std::string out;
  for (const auto& s : v) out += (out.empty() ? "" : ",") + s;
  return out;
}

template <class P>
std::vector<P> values(const std::vector<std::string>& text, const std::string& what) {
  std::vector<P> out;
  for (std::size_t i = 0; i < text.size(); ++i) out.push_back(from_text<P>(text[i], what + "[" + std::to_string(i) + "]"));
  return out;
}

template <class P>
gravity_system<mpfr50> widened(const gravity_system<P>& s) {
  gravity_system<mpfr50> w;
  w.dim = s.dim;
  for (const P& m : s.masses) w.masses.push_back(mpfr50(m));
  w.g = mpfr50(s.g);
  return w;
}

/// The components of the total angular momentum sum q_i x p_i (planar: its z component).
template <class T>
std::vector<invariant<T>> angular_momentum(int dim, int bodies) {
  std::vector<invariant<T>> out;
  const int components = dim == 2 ? 1 : 3;
  for (int c = 0; c < components; ++c)
    out.push_back({dim == 2 ? std::string("angular momentum") : std::string("angular momentum L_") + char('x' + c),
                   [dim, bodies, c](const dynamic_vector<T>& q, const dynamic_vector<T>& p) -> T {
                     T l = 0;
                     for (int i = 0; i < bodies; ++i) {
                       const int a = dim == 2 ? 0 : (c + 1) % 3, b = dim == 2 ? 1 : (c + 2) % 3;
                       l += q(dim * i + a) * p(dim * i + b) - q(dim * i + b) * p(dim * i + a);
                     }
                     return l;
                   },
                   T(0)});
  return out;
}

template <class T, class System>
invariant<T> energy_invariant(const System& s) {
  return {"energy", [s](const dynamic_vector<T>& q, const dynamic_vector<T>& p) -> T { return s.energy(q, p); }};
}

/// Gravity problems: the masses and G as text; p = m v from the velocities as text.
template <class T>
problem<T> gravity_problem(problem_definition d, int dim, const std::vector<std::string>& masses,
                           const std::string& g, const std::vector<std::string>& velocities,
                           const reference_settings& settings) {
  gravity_system<T> s;
  s.dim = dim;
  s.masses = values<T>(masses, d.name + ": mass");
  s.g = from_text<T>(g, d.name + ": G");
  // p = m v, exact in 100 digits, as text.
  for (std::size_t i = 0; i < velocities.size(); ++i) {
    const mpfr100 p = read_coefficient(masses[i / std::size_t(dim)], "mass").value *
                      read_coefficient(velocities[i], "velocity").value;
    d.p0.push_back(scientific_text(p, 100));
  }
  d.parameters = "dim=" + std::to_string(dim) + "|masses=" + joined(masses) + "|G=" + g;
  d.separable = true;
  std::vector<invariant<T>> inv{energy_invariant<T>(s)};
  for (auto& l : angular_momentum<T>(dim, static_cast<int>(masses.size()))) inv.push_back(std::move(l));
  return reference_problem<T>(d, s, widened(s), std::move(inv), settings);
}

template <class T>
problem<T> pleiades(const reference_settings& settings) {
  problem_definition d;
  d.name = "pleiades";
  d.description = "seven stars in the plane, m_i = i, G = 1, t in [0, 3] (certified reference)";
  d.source = "Hairer, Norsett & Wanner, Solving Ordinary Differential Equations I (2nd ed., 1993), II.10, "
             "p. 245; the Bari IVP test set, problem PLEI";
  d.q0 = {"3", "3", "3", "-3", "-1", "2", "-3", "0", "2", "0", "-2", "-4", "2", "4"};
  d.t_end = "3";
  d.steps0 = 64;
  d.h_local = "0.01";
  d.h_long = "0.001";
  d.time_scale = 3;  // the span of the reference (no long run: see below)
  // The least distance of two stars in [0, 3], by Stormer-Verlet at h = 1e-5.
  d.long_run_refused = "two stars pass within 0.034 of each other near t = 1.68, where a fixed step of 0.001 "
                       "moves them ~0.03: a fixed step does not resolve the encounter, and its energy error says "
                       "nothing of a method's claim";
  return gravity_problem<T>(d, 2, {"1", "2", "3", "4", "5", "6", "7"}, "1",
                            {"0", "0", "0", "0", "0", "0", "0", "-1.25", "0", "1", "1.75", "0", "-1.5", "0"}, settings);
}

template <class T>
problem<T> outer_solar_system(const reference_settings& settings) {
  problem_definition d;
  d.name = "outer_solar_system";
  d.description = "the Sun (with the inner planets), Jupiter, Saturn, Uranus, Neptune, Pluto, 3D, AU and days, "
                  "over 20000 days (certified reference)";
  d.source = "Hairer, Lubich & Wanner, Geometric Numerical Integration (2nd ed., 2006), I.2.4, Table 2.1";
  d.q0 = {"0", "0", "0", "-3.5023653", "-3.8169847", "-1.5507963", "9.0755314", "-3.0458353", "-1.6483708",
          "8.3101420", "-16.2901086", "-7.2521278", "11.4707666", "-25.7294829", "-10.8169456", "-15.5387357",
          "-25.2225594", "-3.1902382"};
  d.t_end = "20000";
  d.steps0 = 64;
  d.h_local = "100";
  d.h_long = "10";
  // Pluto's period (248 years), the slowest of the system: the long run (10^6 days) spans 11 of it.
  d.time_scale = 90560;
  return gravity_problem<T>(
      d, 3, {"1.00000597682", "0.000954786104043", "0.000285583733151", "0.0000437273164546", "0.0000517759138449", "1/130000000"},
      "2.95912208286e-4",
      {"0", "0", "0", "0.00565429", "-0.00412490", "-0.00190589", "0.00168318", "0.00483525", "0.00192462", "0.00354178",
       "0.00137102", "0.00055029", "0.00288930", "0.00114527", "0.00039677", "0.00276725", "-0.00170702", "-0.00136504"},
      settings);
}

template <class T>
problem<T> arenstorf(const reference_settings& settings) {
  problem_definition d;
  d.name = "arenstorf";
  d.description = "the restricted three-body problem in the rotating frame, mu = 0.012277471, the Arenstorf orbit "
                  "over one period (certified reference)";
  d.source = "Hairer, Norsett & Wanner, Solving Ordinary Differential Equations I (2nd ed., 1993), II.0, p. 130: "
             "y1(0) = 0.994, y2'(0) = -2.00158510637908252240537862224, T = 17.0652165601579625588917206249; "
             "p = (y1' - y2, y2' + y1)";
  d.parameters = "mu=0.012277471";
  d.q0 = {"0.994", "0"};
  d.p0 = {"0", "-1.00758510637908252240537862224"};
  d.t_end = "17.0652165601579625588917206249";
  d.steps0 = 256;
  d.h_local = "0.01";
  d.h_long = "0.001";
  d.time_scale = 17.0652165601579625588917206249;  // the orbit's period
  arenstorf_system<T> s{from_text<T>("0.012277471", "arenstorf: mu")};
  return reference_problem<T>(d, s, arenstorf_system<mpfr50>{mpfr50(s.mu)}, {energy_invariant<T>(s)}, settings);
}

template <class T>
problem<T> henon_heiles(bool chaotic, const reference_settings& settings) {
  problem_definition d;
  d.name = chaotic ? "henon_heiles_chaotic" : "henon_heiles_regular";
  d.description = chaotic ? "Henon-Heiles at H = 0.1621 from q = (0, -0.1), p = (0.56, 0), over t = 1000: a "
                            "chaotic orbit, past the horizon of certification"
                          : "Henon-Heiles at H = 0.0807 from q = (0, 0.1), p = (0.39, 0), over t = 50: a regular "
                            "orbit (certified reference)";
  d.source = "Henon & Heiles, The applicability of the third integral of motion, Astron. J. 69 (1964); Hairer, "
             "Lubich & Wanner, Geometric Numerical Integration, I.3";
  d.parameters = "henon-heiles";
  d.q0 = chaotic ? std::vector<std::string>{"0", "-0.1"} : std::vector<std::string>{"0", "0.1"};
  d.p0 = chaotic ? std::vector<std::string>{"0.56", "0"} : std::vector<std::string>{"0.39", "0"};
  d.t_end = chaotic ? "1000" : "50";
  d.steps0 = chaotic ? 1024 : 32;
  d.h_local = "0.5";
  d.h_long = "0.05";
  d.time_scale = 2 * boost::math::constants::pi<double>();  // the small oscillations' period (omega = 1)
  d.separable = true;
  const henon_heiles_system s;
  return reference_problem<T>(d, s, s, {energy_invariant<T>(s)}, settings);
}

template <class T>
problem<T> double_pendulum(const reference_settings& settings) {
  problem_definition d;
  d.name = "double_pendulum";
  d.description = "the double pendulum of equal masses and lengths, m = l = g = 1, from 0.5 rad each at rest, over "
                  "t = 10 (certified reference)";
  d.source = "the Lagrangian L = (m1 + m2) l1^2 q1'^2/2 + m2 l2^2 q2'^2/2 + m2 l1 l2 q1' q2' cos(q1 - q2) + (m1 + m2) "
             "g l1 cos q1 + m2 g l2 cos q2 (Goldstein, Classical Mechanics, 1.6), its Legendre transform";
  d.parameters = "m=l=g=1";
  d.q0 = {"0.5", "0.5"};
  d.p0 = {"0", "0"};
  d.t_end = "10";
  d.steps0 = 32;
  d.h_local = "0.25";
  d.h_long = "0.01";
  // The slower normal mode's period, 2 pi / sqrt(2 - sqrt 2) = 8.2 for small swings (Goldstein, 6.4),
  // longer at 0.5 rad: t_end.
  d.time_scale = 10;
  const hamiltonian_system<double_pendulum_hamiltonian> s{{}};
  return reference_problem<T>(d, s, s, {energy_invariant<T>(s)}, settings);
}
}  // namespace

const std::vector<std::string>& classic_problem_names() {
  static const std::vector<std::string> names{"pleiades",           "arenstorf",           "outer_solar_system",
                                              "henon_heiles_regular", "henon_heiles_chaotic", "double_pendulum"};
  return names;
}

template <class T>
problem<T> classic_problem(const std::string& name, const reference_settings& settings) {
  if (name == "pleiades") return pleiades<T>(settings);
  if (name == "arenstorf") return arenstorf<T>(settings);
  if (name == "outer_solar_system") return outer_solar_system<T>(settings);
  if (name == "henon_heiles_regular") return henon_heiles<T>(false, settings);
  if (name == "henon_heiles_chaotic") return henon_heiles<T>(true, settings);
  if (name == "double_pendulum") return double_pendulum<T>(settings);
  std::string known;
  for (const auto& n : classic_problem_names()) known += " " + n;
  throw domain_error("classic_problem: no problem named '" + name + "' (known:" + known + ")");
}

template problem<double> classic_problem<double>(const std::string&, const reference_settings&);
template problem<mpfr50> classic_problem<mpfr50>(const std::string&, const reference_settings&);

}  // namespace mechcheck::audit
