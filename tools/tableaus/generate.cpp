// Writes tableaus/*.json: the classical tableaus the tests and the tableau audit use, each
// derived here, not typed: exact rationals from Boost.Odeint's coefficient templates
// instantiated on GMP rationals (Cash-Karp 5(4), Fehlberg 7(8)); Gauss-Legendre, Radau IIA
// and Lobatto IIIA by collocation at their nodes in 100 digits; Crouzeix's SDIRK from its
// closed form. RK4, Kutta's third order and Dormand-Prince 5(4) are rationals of their
// definitions, checked by the order conditions (tests/tableau_test.cpp). Usage:
//   mechcheck_generate_tableaus DIR

#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <limits>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include <boost/math/special_functions/legendre.hpp>
#include <boost/multiprecision/gmp.hpp>
#include <boost/numeric/odeint/stepper/runge_kutta_cash_karp54.hpp>
#include <boost/numeric/odeint/stepper/runge_kutta_fehlberg78.hpp>

#include "mechcheck/core.hpp"
#include "mechcheck/integrators/steppers.hpp"
#ifdef MECHCHECK_HAVE_ARKODE
#include "mechcheck/audit/adapters/arkode.hpp"
#endif

namespace {
using mechcheck::mpfr100;
using rational = boost::multiprecision::mpq_rational;
namespace ode = boost::numeric::odeint;

/// A coefficient as the file writes it: an exact rational "p/q", or every digit of mpfr100.
struct entry {
  std::string text;
  static entry of(const rational& r) {
    std::ostringstream os;
    os << numerator(r);
    if (denominator(r) != 1) os << "/" << denominator(r);
    return {os.str()};
  }
  static entry of(const mpfr100& x) {
    std::ostringstream os;
    os.precision(std::numeric_limits<mpfr100>::digits10);
    os << x;
    return {os.str()};
  }
};

struct table {
  std::string name, source;
  std::vector<std::vector<entry>> a;
  std::vector<entry> b, c, bhat;
  int order = 0, embedding_order = 0;
  std::string symplectic, symmetric;  // "true", "false" or "" (not declared)
};

std::string quoted(const std::vector<entry>& v) {
  std::string s = "[";
  for (std::size_t i = 0; i < v.size(); ++i) s += (i ? ", \"" : "\"") + v[i].text + "\"";
  return s + "]";
}

void write(const std::filesystem::path& dir, const table& t) {
  std::ofstream out(dir / (t.name + ".json"));
  out << "{\n  \"name\": \"" << t.name << "\",\n  \"source\": \"" << t.source << "\",\n"
      << "  \"order\": " << t.order << ",\n";
  if (t.embedding_order) out << "  \"embedding_order\": " << t.embedding_order << ",\n";
  if (!t.symplectic.empty()) out << "  \"symplectic\": " << t.symplectic << ",\n";
  if (!t.symmetric.empty()) out << "  \"symmetric\": " << t.symmetric << ",\n";
  out << "  \"A\": [\n";
  for (std::size_t i = 0; i < t.a.size(); ++i)
    out << "    " << quoted(t.a[i]) << (i + 1 < t.a.size() ? ",\n" : "\n");
  out << "  ],\n  \"b\": " << quoted(t.b) << ",\n";
  if (!t.bhat.empty()) out << "  \"bhat\": " << quoted(t.bhat) << ",\n";
  out << "  \"c\": " << quoted(t.c) << "\n}\n";
}

/// An explicit table from rows of the strictly lower part.
template <class Row>
std::vector<std::vector<entry>> lower(const std::vector<Row>& rows, std::size_t s) {
  std::vector<std::vector<entry>> a(s, std::vector<entry>(s, entry{"0"}));
  for (std::size_t i = 1; i < s; ++i)
    for (std::size_t j = 0; j < rows[i - 1].size(); ++j) a[i][j] = entry::of(rational(rows[i - 1][j]));
  return a;
}

std::vector<entry> rationals(std::initializer_list<const char*> v) {
  std::vector<entry> out;
  for (const char* x : v) out.push_back(entry::of(rational(x)));
  return out;
}

/// The collocation tableau at nodes c (in 100 digits): a_ij = int_0^{c_i} l_j, b_j =
/// int_0^1 l_j, from the conditions sum_j a_ij c_j^(k-1) = c_i^k / k, sum_j b_j c_j^(k-1) = 1/k.
table collocation(const std::string& name, const std::vector<mpfr100>& c) {
  using namespace mechcheck;
  const int s = static_cast<int>(c.size());
  dynamic_matrix<mpfr100> v(s, s);
  for (int k = 0; k < s; ++k)
    for (int j = 0; j < s; ++j) v(k, j) = pow(c[std::size_t(j)], k);
  const Eigen::FullPivLU<dynamic_matrix<mpfr100>> lu(v);
  table t;
  t.name = name;
  dynamic_vector<mpfr100> rhs(s);
  for (int k = 0; k < s; ++k) rhs(k) = mpfr100(1) / (k + 1);
  const dynamic_vector<mpfr100> b = lu.solve(rhs);
  for (int i = 0; i < s; ++i) {
    for (int k = 0; k < s; ++k) rhs(k) = pow(c[std::size_t(i)], k + 1) / (k + 1);
    const dynamic_vector<mpfr100> row = lu.solve(rhs);
    std::vector<entry> r;
    for (int j = 0; j < s; ++j) r.push_back(entry::of(row(j)));
    t.a.push_back(r);
    t.b.push_back(entry::of(b(i)));
    t.c.push_back(entry::of(c[std::size_t(i)]));
  }
  return t;
}

/// The rational of smallest denominator (at most 10^9) that rounds to x in double, by the
/// convergents of x's continued fraction, or none. Published tables of rationals stored in
/// double come back exact this way; the order conditions then say whether they were.
std::optional<rational> rational_of(double x) {
  const rational target(x);  // exact value of the double
  rational rest = target;
  boost::multiprecision::mpz_int p0 = 0, p1 = 1, q0 = 1, q1 = 0;
  for (int k = 0; k < 64; ++k) {
    const boost::multiprecision::mpz_int a = numerator(rest) / denominator(rest) -
                                              (numerator(rest) < 0 && numerator(rest) % denominator(rest) != 0 ? 1 : 0);
    const boost::multiprecision::mpz_int p = a * p1 + p0, q = a * q1 + q0;
    if (q > 1000000000) return std::nullopt;
    const rational r(p, q);
    if (static_cast<double>(r) == x) return r;
    p0 = p1; p1 = p; q0 = q1; q1 = q;
    const rational frac = rest - rational(a);
    if (frac == 0) return std::nullopt;
    rest = 1 / frac;
  }
  return std::nullopt;
}

std::vector<mpfr100> gauss_nodes(int s) {
  const auto t = mechcheck::gauss_legendre_tableau<mpfr100>(s);
  return std::vector<mpfr100>(t.c.begin(), t.c.end());
}
}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::cerr << "usage: mechcheck_generate_tableaus DIR\n";
    return 2;
  }
  const std::filesystem::path dir = argv[1];
  std::filesystem::create_directories(dir);

  table rk4{"rk4", "Kutta (1901), the classical fourth-order method"};
  rk4.a = lower(std::vector<std::vector<rational>>{{rational(1, 2)}, {0, rational(1, 2)}, {0, 0, 1}}, 4);
  rk4.b = rationals({"1/6", "1/3", "1/3", "1/6"});
  rk4.c = rationals({"0", "1/2", "1/2", "1"});
  rk4.order = 4;
  rk4.symplectic = rk4.symmetric = "false";
  write(dir, rk4);

  table kutta3{"kutta3", "Kutta's third-order method"};
  kutta3.a = lower(std::vector<std::vector<rational>>{{rational(1, 2)}, {-1, 2}}, 3);
  kutta3.b = rationals({"1/6", "2/3", "1/6"});
  kutta3.c = rationals({"0", "1/2", "1"});
  kutta3.order = 3;
  write(dir, kutta3);

  table dopri5{"dopri5", "Dormand and Prince (1980), 5(4), FSAL"};
  dopri5.a = lower(std::vector<std::vector<rational>>{
                       {rational(1, 5)},
                       {rational(3, 40), rational(9, 40)},
                       {rational(44, 45), rational(-56, 15), rational(32, 9)},
                       {rational(19372, 6561), rational(-25360, 2187), rational(64448, 6561), rational(-212, 729)},
                       {rational(9017, 3168), rational(-355, 33), rational(46732, 5247), rational(49, 176), rational(-5103, 18656)},
                       {rational(35, 384), 0, rational(500, 1113), rational(125, 192), rational(-2187, 6784), rational(11, 84)}},
                   7);
  dopri5.b = rationals({"35/384", "0", "500/1113", "125/192", "-2187/6784", "11/84", "0"});
  dopri5.bhat = rationals({"5179/57600", "0", "7571/16695", "393/640", "-92097/339200", "187/2100", "1/40"});
  dopri5.c = rationals({"0", "1/5", "3/10", "4/5", "8/9", "1", "1"});
  dopri5.order = 5;
  dopri5.embedding_order = 4;
  write(dir, dopri5);

  {  // Cash-Karp 5(4) and Fehlberg 7(8): Boost.Odeint's coefficients on exact rationals.
    table ck{"cash_karp54", "Cash and Karp (1990), 5(4): Boost.Odeint's rk54_ck coefficients, exact"};
    std::vector<std::vector<rational>> rows;
    const auto add = [&rows](const auto& r) { rows.emplace_back(r.begin(), r.end()); };
    add(ode::rk54_ck_coefficients_a1<rational>());
    add(ode::rk54_ck_coefficients_a2<rational>());
    add(ode::rk54_ck_coefficients_a3<rational>());
    add(ode::rk54_ck_coefficients_a4<rational>());
    add(ode::rk54_ck_coefficients_a5<rational>());
    ck.a = lower(rows, 6);
    const auto b = ode::rk54_ck_coefficients_b<rational>();
    const auto db = ode::rk54_ck_coefficients_db<rational>();
    const auto c = ode::rk54_ck_coefficients_c<rational>();
    for (std::size_t i = 0; i < 6; ++i) {
      ck.b.push_back(entry::of(b[i]));
      ck.bhat.push_back(entry::of(rational(b[i] - db[i])));
      ck.c.push_back(entry::of(c[i]));
    }
    ck.order = 5;
    ck.embedding_order = 4;
    write(dir, ck);
  }
  {
    table f{"fehlberg78", "Fehlberg (1968), 7(8): Boost.Odeint's rk78 coefficients, exact; b the 8th-order weights, bhat = b - db the 7th-order ones"};
    std::vector<std::vector<rational>> rows;
    const auto add = [&rows](const auto& r) { rows.emplace_back(r.begin(), r.end()); };
    add(ode::rk78_coefficients_a1<rational>());
    add(ode::rk78_coefficients_a2<rational>());
    add(ode::rk78_coefficients_a3<rational>());
    add(ode::rk78_coefficients_a4<rational>());
    add(ode::rk78_coefficients_a5<rational>());
    add(ode::rk78_coefficients_a6<rational>());
    add(ode::rk78_coefficients_a7<rational>());
    add(ode::rk78_coefficients_a8<rational>());
    add(ode::rk78_coefficients_a9<rational>());
    add(ode::rk78_coefficients_a10<rational>());
    add(ode::rk78_coefficients_a11<rational>());
    add(ode::rk78_coefficients_a12<rational>());
    f.a = lower(rows, 13);
    const auto b = ode::rk78_coefficients_b<rational>();
    const auto db = ode::rk78_coefficients_db<rational>();
    const auto c = ode::rk78_coefficients_c<rational>();
    for (std::size_t i = 0; i < 13; ++i) {
      f.b.push_back(entry::of(b[i]));
      f.bhat.push_back(entry::of(rational(b[i] - db[i])));
      f.c.push_back(entry::of(c[i]));
    }
    f.order = 8;
    f.embedding_order = 7;
    write(dir, f);
  }
  for (const int s : {2, 3, 5}) {
    table g = collocation("gauss" + std::to_string(s), gauss_nodes(s));
    g.source = "Gauss-Legendre collocation, " + std::to_string(s) + " stages (nodes: zeros of P_s on [0, 1], 100 digits)";
    g.order = 2 * s;
    g.symplectic = g.symmetric = "true";
    write(dir, g);
  }
  {
    using std::sqrt;
    const mpfr100 r6 = sqrt(mpfr100(6));
    table r = collocation("radau_iia3", {(4 - r6) / 10, (4 + r6) / 10, mpfr100(1)});
    r.source = "Radau IIA, 3 stages: collocation at (4 -+ sqrt 6)/10 and 1 (100 digits)";
    r.order = 5;
    r.symplectic = r.symmetric = "false";
    write(dir, r);
    table l = collocation("lobatto_iiia3", {mpfr100(0), mpfr100(1) / 2, mpfr100(1)});
    l.source = "Lobatto IIIA, 3 stages: collocation at 0, 1/2, 1 (100 digits)";
    l.order = 4;
    l.symmetric = "true";
    write(dir, l);
    const mpfr100 gamma = (3 + sqrt(mpfr100(3))) / 6;
    table sd{"sdirk3", "Crouzeix (1975): 2-stage SDIRK of order 3, gamma = (3 + sqrt 3)/6 (100 digits)"};
    sd.a = {{entry::of(gamma), entry{"0"}}, {entry::of(mpfr100(1 - 2 * gamma)), entry::of(gamma)}};
    sd.b = rationals({"1/2", "1/2"});
    sd.c = {entry::of(gamma), entry::of(mpfr100(1 - gamma))};
    sd.order = 3;
    write(dir, sd);
  }
#ifdef MECHCHECK_HAVE_ARKODE
  // Verner's 6(5) as SUNDIALS ARKODE stores it, its doubles taken back to the rationals
  // they round from (rational_of; a double with no such rational is written with the 17
  // digits that reproduce it). tests/tableau_test.cpp checks the conditions hold exactly.
  for (const auto& t : mechcheck::audit::arkode::tables()) {
    if (t.name != "ARKODE_VERNER_8_5_6") continue;
    table v{"verner65", "Verner 6(5), 8 stages, as SUNDIALS " + mechcheck::audit::arkode::version() +
                            " ARKODE stores it (ARKODE_VERNER_8_5_6): its doubles taken back to the rationals of smallest denominator that round to them"};
    const auto d17 = [](double x) {
      if (const auto r = rational_of(x)) return entry::of(*r);
      std::ostringstream os;
      os.precision(17);
      os << x;
      return entry{os.str()};
    };
    for (const auto& row : t.a) {
      std::vector<entry> r;
      for (const double x : row) r.push_back(d17(x));
      v.a.push_back(r);
    }
    for (std::size_t i = 0; i < t.b.size(); ++i) {
      v.b.push_back(d17(t.b[i]));
      v.bhat.push_back(d17(t.d[i]));
      v.c.push_back(d17(t.c[i]));
    }
    v.order = t.q;
    v.embedding_order = t.p;
    write(dir, v);
  }
#endif
  std::cout << "wrote the tableaus to " << dir << "\n";
  return 0;
}
