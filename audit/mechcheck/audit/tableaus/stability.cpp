#include "mechcheck/audit/tableaus/stability.hpp"

#include "mechcheck/core.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

namespace mechcheck::audit {

namespace {
using boost::multiprecision::abs;
using poly = std::vector<rational>;  // coefficients of x^0, x^1, ...
using matrix = std::vector<std::vector<rational>>;

void trim(poly& p) {
  while (!p.empty() && p.back() == 0) p.pop_back();
}
int degree(const poly& p) { return static_cast<int>(p.size()) - 1; }  // -1: the zero polynomial

rational eval(const poly& p, const rational& x) {
  rational v = 0;
  for (auto it = p.rbegin(); it != p.rend(); ++it) v = v * x + *it;
  return v;
}
int sign(const rational& x) { return x > 0 ? 1 : x < 0 ? -1 : 0; }
double to_double(const rational& x) { return static_cast<double>(x); }
double magnitude(const rational& x) { return std::abs(to_double(x)); }

poly multiply(const poly& a, const poly& b) {
  if (a.empty() || b.empty()) return {};
  poly out(a.size() + b.size() - 1, rational(0));
  for (std::size_t i = 0; i < a.size(); ++i)
    for (std::size_t j = 0; j < b.size(); ++j) out[i + j] += a[i] * b[j];
  return out;
}
poly subtract(poly a, const poly& b) {
  if (a.size() < b.size()) a.resize(b.size(), rational(0));
  for (std::size_t i = 0; i < b.size(); ++i) a[i] -= b[i];
  trim(a);
  return a;
}
/// The remainder of a by b (b non-zero).
poly remainder(poly a, const poly& b) {
  trim(a);
  while (degree(a) >= degree(b)) {
    const rational f = a.back() / b.back();
    const int shift = degree(a) - degree(b);
    for (std::size_t i = 0; i < b.size(); ++i) a[i + std::size_t(shift)] -= f * b[i];
    a.pop_back();
    trim(a);
  }
  return a;
}
poly derivative(const poly& p) {
  poly d;
  for (std::size_t i = 1; i < p.size(); ++i) d.push_back(p[i] * static_cast<long long>(i));
  return d;
}
poly gcd(poly a, poly b) {
  trim(a);
  trim(b);
  while (!b.empty()) {
    poly r = remainder(a, b);
    a = std::move(b);
    b = std::move(r);
  }
  return a;
}
/// a / b for b dividing a.
poly divide(poly a, const poly& b) {
  trim(a);
  poly out(std::size_t(std::max(0, degree(a) - degree(b) + 1)), rational(0));
  while (degree(a) >= degree(b) && !a.empty()) {
    const rational f = a.back() / b.back();
    const int shift = degree(a) - degree(b);
    out[std::size_t(shift)] = f;
    for (std::size_t i = 0; i < b.size(); ++i) a[i + std::size_t(shift)] -= f * b[i];
    a.pop_back();
    trim(a);
  }
  return out;
}

/// det(I - z M) = 1 + c_1 z + ... + c_n z^n, with det(lambda I - M) = lambda^n + c_1
/// lambda^(n-1) + ... + c_n (Faddeev-LeVerrier).
poly det_one_minus_z(const matrix& m) {
  const std::size_t n = m.size();
  poly c{rational(1)};
  matrix mk(n, std::vector<rational>(n, rational(0)));  // M_0 = 0
  rational ck = 1;
  for (std::size_t k = 1; k <= n; ++k) {
    // M_k = M M_(k-1) + c_(k-1) I; c_k = -tr(M M_k) / k.
    matrix next(n, std::vector<rational>(n, rational(0)));
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t j = 0; j < n; ++j) {
        rational v = i == j ? ck : rational(0);
        for (std::size_t l = 0; l < n; ++l)
          if (m[i][l] != 0) v += m[i][l] * mk[l][j];
        next[i][j] = v;
      }
    rational trace = 0;
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t l = 0; l < n; ++l)
        if (m[i][l] != 0) trace += m[i][l] * next[l][i];
    ck = -trace / static_cast<long long>(k);
    c.push_back(ck);
    mk = std::move(next);
  }
  trim(c);
  return c;
}

/// The real and imaginary parts of p(iy) as polynomials in y.
std::pair<poly, poly> on_imaginary_axis(const poly& p) {
  poly re(p.size(), rational(0)), im(p.size(), rational(0));
  for (std::size_t k = 0; k < p.size(); ++k) {
    const int phase = static_cast<int>(k % 4);  // i^k = 1, i, -1, -i
    if (phase == 0) re[k] = p[k];
    if (phase == 1) im[k] = p[k];
    if (phase == 2) re[k] = -p[k];
    if (phase == 3) im[k] = -p[k];
  }
  trim(re);
  trim(im);
  return {re, im};
}
poly squared_modulus(const poly& p) {  // |p(iy)|^2 as a polynomial in y
  const auto [re, im] = on_imaginary_axis(p);
  poly a = multiply(re, re), b = multiply(im, im);
  if (a.size() < b.size()) a.resize(b.size(), rational(0));
  for (std::size_t i = 0; i < b.size(); ++i) a[i] += b[i];
  trim(a);
  return a;
}

/// Routh's criterion: every zero of f in the open left half-plane (f of degree >= 1, real
/// coefficients). A zero in the first column means a zero on or right of the axis, or a
/// pair symmetric about it: not all in the open half-plane.
bool hurwitz(const poly& f) {
  const int n = degree(f);
  if (n <= 0) return true;
  // Rows of coefficients from the highest power down.
  std::vector<rational> r0, r1;
  for (int k = n; k >= 0; k -= 2) r0.push_back(f[std::size_t(k)]);
  for (int k = n - 1; k >= 0; k -= 2) r1.push_back(f[std::size_t(k)]);
  const int s0 = sign(r0[0]);
  for (int row = 1; row <= n; ++row) {
    if (r1.empty() || sign(r1[0]) != s0) return false;
    std::vector<rational> r2;
    for (std::size_t j = 0; j + 1 < r0.size(); ++j) {
      const rational b = j + 1 < r1.size() ? r1[j + 1] : rational(0);
      r2.push_back((r1[0] * r0[j + 1] - r0[0] * b) / r1[0]);
    }
    r0 = std::move(r1);
    r1 = std::move(r2);
  }
  return true;
}

/// Sign variations of a Sturm sequence at x (nullopt: at +infinity).
int variations(const std::vector<poly>& seq, const std::optional<rational>& x) {
  int count = 0, last = 0;
  for (const auto& p : seq) {
    const int s = x ? sign(eval(p, *x)) : sign(p.back());
    if (s == 0) continue;
    if (last != 0 && s != last) ++count;
    last = s;
  }
  return count;
}
std::vector<poly> sturm(const poly& f) {
  std::vector<poly> seq{f, derivative(f)};
  while (!seq.back().empty() && degree(seq.back()) > 0) {
    poly r = remainder(seq[seq.size() - 2], seq.back());
    for (auto& c : r) c = -c;
    if (r.empty()) break;
    seq.push_back(std::move(r));
  }
  return seq;
}

/// Whether e(x) >= 0 for every x > 0, with a witness x where it is not.
std::pair<bool, std::optional<rational>> nonnegative_on_positive_axis(poly e) {
  trim(e);
  if (e.empty()) return {true, std::nullopt};
  std::size_t zeros = 0;  // x^m e~(x): the factor is positive for x > 0
  while (zeros < e.size() && e[zeros] == 0) ++zeros;
  e.erase(e.begin(), e.begin() + long(zeros));
  if (sign(e.back()) < 0) {  // negative at infinity: a witness past the roots
    rational bound = 1;
    for (const auto& c : e) bound += abs(c / e.back());
    return {false, bound};
  }
  // The square-free part holds every root once; isolate them in (0, B] and take e's sign at
  // every isolating interval's ends, which lie in the gaps between roots.
  const poly f = divide(e, gcd(e, derivative(e)));
  if (degree(f) <= 0) return {sign(e[0]) >= 0, sign(e[0]) >= 0 ? std::nullopt : std::optional<rational>(1)};
  const std::vector<poly> seq = sturm(f);
  rational bound = 1;
  for (const auto& c : f) bound += abs(c / f.back());
  std::vector<std::pair<rational, rational>> work{{rational(0), bound}}, isolated;
  const auto count = [&](const rational& lo, const rational& hi) { return variations(seq, lo) - variations(seq, hi); };
  int guard = 0;
  for (; !work.empty() && guard < 4096; ++guard) {
    const auto [lo, hi] = work.back();
    work.pop_back();
    const int n = count(lo, hi);
    if (n == 0) continue;
    if (n == 1) {
      isolated.push_back({lo, hi});
      continue;
    }
    rational mid = lo + (hi - lo) * 3 / 7;  // a rational split; moved off a root of f
    if (eval(f, mid) == 0) mid = lo + (hi - lo) * 2 / 7;
    work.push_back({lo, mid});
    work.push_back({mid, hi});
  }
  if (!work.empty()) throw domain_error("stability: the roots of E were not isolated in 4096 bisections");
  std::vector<rational> samples{bound};
  for (const auto& [lo, hi] : isolated) {
    if (lo > 0) samples.push_back(lo);
    samples.push_back(hi);
  }
  // Between 0 and the first root: e(0+) has the sign of e(0) (e(0) != 0 once x^m is out);
  // a witness by halving towards 0.
  if (sign(e[0]) < 0) {
    rational x = bound;
    for (int k = 0; k < 4096 && sign(eval(e, x)) >= 0; ++k) x /= 2;
    return {false, x};
  }
  for (const auto& x : samples)
    if (eval(f, x) != 0 && sign(eval(e, x)) < 0) return {false, x};
  return {true, std::nullopt};
}

std::string number_text(const rational& x) {
  std::ostringstream os;
  if (boost::multiprecision::denominator(x) < 100000 && abs(boost::multiprecision::numerator(x)) < 100000000)
    os << x;
  else {
    char buf[40];
    std::snprintf(buf, sizeof buf, "%.17g", to_double(x));
    os << buf;
  }
  return os.str();
}
/// The polynomial whole; a coefficient within its bound (bound[k] > 0) named so.
std::string poly_text(const poly& p, const std::vector<double>& bound = {}) {
  if (p.empty()) return "0";
  std::string out;
  for (std::size_t k = 0; k < p.size(); ++k) {
    if (p[k] == 0) continue;
    const bool negative = p[k] < 0;
    const rational a = negative ? rational(-p[k]) : p[k];
    out += out.empty() ? (negative ? "-" : "") : (negative ? " - " : " + ");
    const std::string power = k == 0 ? "" : k == 1 ? "z" : "z^" + std::to_string(k);
    if (k == 0 || a != 1) out += number_text(a) + (k ? " " : "");
    out += power;
    if (k < bound.size() && bound[k] > 0 && magnitude(p[k]) <= bound[k]) out += " (within the precision given)";
  }
  return out;
}
std::string sci(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g", x);
  return buf;
}
}  // namespace

std::complex<double> stability_report::r(std::complex<double> z) const {
  std::complex<double> num = 0, den = 0;
  for (auto it = p.rbegin(); it != p.rend(); ++it) num = num * z + to_double(*it);
  for (auto it = q.rbegin(); it != q.rend(); ++it) den = den * z + to_double(*it);
  return num / den;
}

std::string stability_report::r_text() const {
  if (p_written.empty() && q_written.empty()) return "(" + poly_text(p) + ") / (" + poly_text(q) + ")";
  return "(" + poly_text(p_written, p_bound) + ") / (" + poly_text(q_written, q_bound) + ")";
}

stability_report stability(const butcher_tableau<rational>& t, double precision) {
  stability_report out;
  const std::size_t s = t.b.size();
  const bool implicit = !t.is_explicit();
  if (implicit && s > 16) {
    out.not_analysed = "an implicit tableau of " + std::to_string(s) + " stages (at most 16 are analysed)";
    return out;
  }
  // The rationals' sizes bound the work: 100-digit decimals are 333 bits each.
  std::size_t bits = 0, largest_bits = 0;
  const auto size_of = [](const rational& x) {
    const auto n = boost::multiprecision::numerator(x), d = boost::multiprecision::denominator(x);
    return std::size_t((n == 0 ? 0 : boost::multiprecision::msb(abs(n)) + 1) + boost::multiprecision::msb(d) + 1);
  };
  for (std::size_t i = 0; i < s; ++i) {
    bits += size_of(t.b[i]);
    largest_bits = std::max(largest_bits, size_of(t.b[i]));
    for (std::size_t j = 0; j < s; ++j) {
      bits += size_of(t.a[i][j]);
      largest_bits = std::max(largest_bits, size_of(t.a[i][j]));
    }
  }
  if (implicit && (bits > max_stability_bits || largest_bits > max_stability_coefficient_bits)) {
    out.not_analysed = "coefficients of " + std::to_string(bits) + " bits in all, the largest " +
                       std::to_string(largest_bits) + " (an implicit tableau is analysed in exact rationals up to " +
                       std::to_string(max_stability_bits) + " bits, " + std::to_string(max_stability_coefficient_bits) +
                       " a coefficient)";
    return out;
  }
  matrix a = t.a, m = t.a;
  for (std::size_t i = 0; i < s; ++i)
    for (std::size_t j = 0; j < s; ++j) m[i][j] -= t.b[j];  // A - 1 b^T
  if (implicit) {
    out.q = det_one_minus_z(a);
    out.p = det_one_minus_z(m);
  } else {  // Q = 1 and P(z) = 1 + sum_k b^T A^(k-1) 1 z^k: s products of A with a vector
    out.q = {rational(1)};
    out.p = {rational(1)};
    std::vector<rational> v(s, rational(1));
    for (std::size_t k = 1; k <= s; ++k) {
      rational c = 0;
      for (std::size_t i = 0; i < s; ++i) c += t.b[i] * v[i];
      out.p.push_back(c);
      std::vector<rational> next(s, rational(0));
      for (std::size_t i = 0; i < s; ++i)
        for (std::size_t j = 0; j < i; ++j)
          if (t.a[i][j] != 0) next[i] += t.a[i][j] * v[j];
      v = std::move(next);
    }
    trim(out.p);
  }
  // What coefficients off by a relative `precision` can move: q_k is a sum of products of k
  // entries of A (principal minors), each moved by at most k precision times its size, and
  // the sum of their sizes is at most e_k(r), the elementary symmetric function of the row
  // sums r_i = sum_j |a_ij| (a permanent of |A|'s minor is at most the product of its row
  // sums); p_k likewise with |a_ij| + |b_j|. Where a coefficient lies within its bound it is
  // zero to the precision given.
  std::vector<double> ra(s, 0.0), rm(s, 0.0);
  for (std::size_t i = 0; i < s; ++i)
    for (std::size_t j = 0; j < s; ++j) {
      ra[i] += magnitude(t.a[i][j]);
      rm[i] += magnitude(t.a[i][j]) + magnitude(t.b[j]);
    }
  const auto moved = [&](const std::vector<double>& r) {
    std::vector<double> e(s + 1, 0.0);  // e_k(r), then k precision e_k
    e[0] = 1;
    for (std::size_t i = 0; i < s; ++i)
      for (std::size_t k = i + 1; k >= 1; --k) e[k] += e[k - 1] * r[i];
    for (std::size_t k = 0; k <= s; ++k) e[k] *= double(k) * precision;
    return e;
  };
  std::vector<double> dq = moved(ra), dp = moved(rm);
  if (!implicit) {  // p_k = b^T A^(k-1) 1: k precision |b|^T |A|^(k-1) 1, the sizes it sums
    dq.assign(1, 0.0);
    dp.assign(s + 1, 0.0);
    std::vector<double> v(s, 1.0);
    for (std::size_t k = 1; k <= s; ++k) {
      double sum = 0;
      for (std::size_t i = 0; i < s; ++i) sum += magnitude(t.b[i]) * v[i];
      dp[k] = double(k) * precision * sum;
      std::vector<double> next(s, 0.0);
      for (std::size_t i = 0; i < s; ++i)
        for (std::size_t j = 0; j < i; ++j) next[i] += magnitude(t.a[i][j]) * v[j];
      v = std::move(next);
    }
  }
  out.p_written = out.p;
  out.q_written = out.q;
  out.p_bound = dp;
  out.q_bound = dq;
  const auto clean_by = [&](poly& c, const std::vector<double>& d) {
    bool changed = false;
    for (std::size_t k = 0; k < c.size() && k < d.size(); ++k)
      if (c[k] != 0 && magnitude(c[k]) <= d[k]) {
        c[k] = 0;
        changed = true;
      }
    trim(c);
    return changed;
  };
  if (precision > 0) out.to_precision = clean_by(out.p, dp) | clean_by(out.q, dq);
  const double tolerance = 4.0 * double(s) * precision;  // M's entries, below
  // |R(iy)| <= 1 is decided on P and Q as they are (a common factor g multiplies E by
  // |g(iy)|^2 >= 0, and the bounds dp, dq are theirs); R = P/Q in lowest terms for its
  // poles and degrees: a common factor is no pole.
  const poly p_full = out.p, q_full = out.q;
  {
    const poly g = gcd(out.p, out.q);
    if (degree(g) > 0) {
      out.p = divide(out.p, g);
      out.q = divide(out.q, g);
      const rational q0 = out.q[0];
      for (auto& c : out.p) c /= q0;
      for (auto& c : out.q) c /= q0;
    }
  }
  // A-stability.
  if (degree(out.p) > degree(out.q)) {
    out.a_words = "R is unbounded at infinity (deg P = " + std::to_string(degree(out.p)) + " > deg Q = " +
                  std::to_string(degree(out.q)) + ")";
  } else {
    poly q_minus(out.q.size());  // Q(-z): its zeros are those of Q reflected
    for (std::size_t k = 0; k < out.q.size(); ++k) q_minus[k] = k % 2 ? rational(-out.q[k]) : out.q[k];
    if (!hurwitz(q_minus)) {
      out.a_words = "R has a pole with Re z <= 0 (Routh's array of Q(-z))";
    } else {
      const poly qq = squared_modulus(q_full), pp = squared_modulus(p_full);
      poly e = subtract(qq, pp);
      // Only even powers of y: e(x), x = y^2. A coefficient within the tolerance of the
      // same coefficient of |Q(iy)|^2 + |P(iy)|^2 (its scale: e is their difference) is zero.
      poly ex;
      for (std::size_t k = 0; k < e.size(); k += 2) ex.push_back(e[k]);
      if (precision > 0) {
        // The bound of each coefficient of |Q(iy)|^2 - |P(iy)|^2 when q_k, p_k move by dq_k,
        // dp_k: sum over j + l = n of (|q_j| + dq_j)(|q_l| + dq_l) - |q_j||q_l|, and the same
        // for P.
        const auto bound = [](const poly& c, const std::vector<double>& d, std::size_t n) {
          double out_n = 0;
          for (std::size_t j = 0; j <= n; ++j) {
            const std::size_t l = n - j;
            const double cj = j < c.size() ? magnitude(c[j]) : 0, cl = l < c.size() ? magnitude(c[l]) : 0;
            const double dj = j < d.size() ? d[j] : 0, dl = l < d.size() ? d[l] : 0;
            out_n += dj * cl + cj * dl + dj * dl;  // (cj + dj)(cl + dl) - cj cl, without cancelling
          }
          return out_n;
        };
        for (std::size_t k = 0; k < ex.size(); ++k)
          if (ex[k] != 0 && magnitude(ex[k]) <= bound(q_full, dq, 2 * k) + bound(p_full, dp, 2 * k)) {
            ex[k] = 0;
            out.to_precision = true;
          }
      }
      trim(ex);
      std::pair<bool, std::optional<rational>> decided;
      try {
        decided = nonnegative_on_positive_axis(ex);
      } catch (const domain_error& e) {
        out.not_analysed = e.what();
        return out;
      }
      const auto [holds, witness] = decided;
      out.a_stable = holds;
      if (holds) {
        out.a_words = ex.empty() ? "no pole with Re z <= 0; |R(iy)| = 1 for every y"
                                 : "no pole with Re z <= 0; |R(iy)| <= 1 for every y (Sturm)";
      } else {
        const double y = std::sqrt(to_double(*witness));
        out.a_words = "|R(iy)| = " + sci(std::abs(out.r({0, y}))) + " > 1 at y = " + sci(y);
      }
    }
  }
  // L-stability.
  out.l_stable = out.a_stable && degree(out.p) < degree(out.q);
  out.l_words = !out.a_stable ? "not A-stable"
                : out.l_stable ? "A-stable and R(infinity) = 0 (deg P < deg Q)"
                               : "A-stable, R(infinity) = " + sci(out.p.empty() ? 0.0 : std::abs(to_double(out.p.back() / out.q.back())));
  // Algebraic stability.
  {
    double largest_b = 0;
    for (const auto& bi : t.b) largest_b = std::max(largest_b, magnitude(bi));
    std::string why;
    for (std::size_t i = 0; i < s && why.empty(); ++i)
      if (t.b[i] < 0 && magnitude(t.b[i]) > tolerance * largest_b) why = "b_" + std::to_string(i + 1) + " < 0";
    matrix mm(s, std::vector<rational>(s));
    double largest = 0;
    for (std::size_t i = 0; i < s; ++i)
      for (std::size_t j = 0; j < s; ++j) {
        mm[i][j] = t.b[i] * t.a[i][j] + t.b[j] * t.a[j][i] - t.b[i] * t.b[j];
        largest = std::max(largest, magnitude(t.b[i] * t.b[j]));
      }
    // Symmetric elimination: a negative pivot, or a zero pivot with a non-zero row, is not
    // positive semidefinite. Entries of the trailing block within the tolerance of M's
    // scale are zero at each step (a rank-deficient M of rounded coefficients leaves noise of
    // either sign there).
    for (std::size_t k = 0; k < s && why.empty(); ++k) {
      for (std::size_t i = k; i < s; ++i)
        for (std::size_t j = k; j < s; ++j)
          if (mm[i][j] != 0 && tolerance > 0 && magnitude(mm[i][j]) <= tolerance * largest) {
            mm[i][j] = 0;
            out.to_precision = true;
          }
      if (mm[k][k] < 0) {
        why = "M = BA + A^T B - b b^T has a negative pivot at " + std::to_string(k + 1);
        break;
      }
      if (mm[k][k] == 0) {
        for (std::size_t j = k + 1; j < s; ++j)
          if (mm[k][j] != 0) why = "M = BA + A^T B - b b^T is indefinite (zero pivot " + std::to_string(k + 1) +
                                   " with a non-zero row)";
        continue;
      }
      for (std::size_t i = k + 1; i < s; ++i) {
        const rational f = mm[i][k] / mm[k][k];
        for (std::size_t j = k; j < s; ++j) mm[i][j] -= f * mm[k][j];
      }
    }
    out.algebraically_stable = why.empty();
    out.algebraic_words = why.empty() ? "b >= 0 and M = BA + A^T B - b b^T positive semidefinite" : why;
  }
  return out;
}

std::string stability_svg(const stability_report& s, const std::string& title) {
  // The box: x in [-12, 6], y in [-9, 9]; cells of 0.1, each inside the region filled, runs
  // of a row merged into one rectangle.
  const double x0 = -12, x1 = 6, y0 = -9, y1 = 9, cell = 0.1, scale = 25;
  const int nx = static_cast<int>((x1 - x0) / cell + 0.5), ny = static_cast<int>((y1 - y0) / cell + 0.5);
  std::ostringstream svg;
  svg << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << nx * cell * scale << "\" height=\""
      << ny * cell * scale + 30 << "\">\n<title>" << title << "</title>\n"
      << "<text x=\"5\" y=\"20\" font-family=\"sans-serif\" font-size=\"14\">" << title
      << ": |R(z)| &lt;= 1 (filled), Re z in [-12, 6], Im z in [-9, 9]</text>\n<g transform=\"translate(0,30)\">\n";
  if (s.not_analysed.empty())
    for (int j = 0; j < ny; ++j) {
      const double y = y1 - (j + 0.5) * cell;
      int start = -1;
      for (int i = 0; i <= nx; ++i) {
        const bool inside = i < nx && std::abs(s.r({x0 + (i + 0.5) * cell, y})) <= 1;
        if (inside && start < 0) start = i;
        if (!inside && start >= 0) {
          svg << "<rect x=\"" << start * cell * scale << "\" y=\"" << j * cell * scale << "\" width=\""
              << (i - start) * cell * scale << "\" height=\"" << cell * scale << "\" fill=\"#9ecae1\"/>\n";
          start = -1;
        }
      }
    }
  const double ox = -x0 * scale, oy = y1 * scale;
  svg << "<line x1=\"0\" y1=\"" << oy << "\" x2=\"" << nx * cell * scale << "\" y2=\"" << oy
      << "\" stroke=\"black\"/>\n<line x1=\"" << ox << "\" y1=\"0\" x2=\"" << ox << "\" y2=\"" << ny * cell * scale
      << "\" stroke=\"black\"/>\n</g>\n</svg>\n";
  return svg.str();
}

}  // namespace mechcheck::audit
