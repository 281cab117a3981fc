#pragma once
/// Canonical maps (q, p) -> (Q, P) for n = 1 or 2, each generic in the scalar, shared by
/// the laws of canonical transformations (notes lecture 23).

#include "integrators/integrators.hpp"

namespace mechcheck::laws::canonical {

using namespace mechcheck::laws::integrators;

/// Maps (q, p) -> (Q, P) for n = 1 or 2, each generic in the scalar.
enum class canonical_map { swap, scaling, point, linear_point, kick_drift, oscillator_flow };

struct map_case {
  canonical_map kind;
  std::vector<double> values;  // parameters
};

inline void showValue(const map_case& c, std::ostream& os) {
  static const char* names[] = {"swap", "scaling (eq 311)", "point Q = q + e sin q",
                                "linear point Q = A q", "kick-drift of random potentials",
                                "exact oscillator flow"};
  os << names[static_cast<int>(c.kind)] << " params (";
  for (double v : c.values) os << v << " ";
  os << ")";
}

template <class S>
dynamic_vector<S> apply_map(const map_case& c, const dynamic_vector<S>& z) {
  using std::cos;
  using std::sin;
  using std::sqrt;
  const auto& v = c.values;
  dynamic_vector<S> out(z.size());
  switch (c.kind) {
    case canonical_map::swap:  // Q = p, P = -q (notes after eq 304)
      out << z(1), -z(0);
      break;
    case canonical_map::scaling: {  // Q = sqrt(m w) q, P = p / sqrt(m w) (eq 311)
      using R = mc::real_type_t<S>;
      const R root = sqrt(R(v[0]) * R(v[1]));
      out << lift<S>(root) * z(0), lift<S>(R(1) / root) * z(1);
      break;
    }
    case canonical_map::point: {  // Q = q + e sin q, P = p / (1 + e cos q), |e| < 1
      const S e = lift<S>(v[0]);
      const S s = sin(z(0)), co = cos(z(0));
      const S dq = lift<S>(1) + e * co;
      out << z(0) + e * s, z(1) * mc::inverse(dq);
      break;
    }
    case canonical_map::linear_point: {  // Q = A q, P = A^-T p on two dof
      using R = mc::real_type_t<S>;
      Eigen::Matrix<R, 2, 2> a;
      a << R(v[0]), R(v[1]), R(v[2]), R(v[3]);
      const Eigen::Matrix<R, 2, 2> ait = a.inverse().transpose();
      for (int i = 0; i < 2; ++i) {
        const S x = lift<S>(a(i, 0)) * z(0), y = lift<S>(a(i, 1)) * z(1);
        const S u = lift<S>(ait(i, 0)) * z(2), w = lift<S>(ait(i, 1)) * z(3);
        out(i) = x + y;
        out(2 + i) = u + w;
      }
      break;
    }
    case canonical_map::kick_drift: {
      // generating functions F2 = q P + e U(q) (kick) and F2 = q P + e K(P) (drift) with
      // U = a cos(q) + b q^3, K = c P^4 / 4 + d sin(P): explicit canonical maps.
      const S a = lift<S>(v[0]), b = lift<S>(v[1]), cc = lift<S>(v[2]), d = lift<S>(v[3]);
      const S s = sin(z(0));
      const S q2 = z(0) * z(0);
      const S du = b * lift<S>(3) * q2 - a * s;
      const S p_new = z(1) - du;
      const S p3 = p_new * p_new * p_new;
      const S c2 = cos(p_new);
      const S dk = cc * p3 + d * c2;
      out << z(0) + dk, p_new;
      break;
    }
    case canonical_map::oscillator_flow: {
      const mechcheck::reference::oscillator_flow<double> flow(v[0], v[1]);
      const dynamic_vector<S> q = z.head(1), p = z.tail(1);
      const auto x = flow(q, p, lift<S>(v[2]));
      out << x.q()(0), x.p()(0);
      break;
    }
  }
  return out;
}

inline rc::Gen<map_case> map_cases() {
  return rc::gen::exec([] {
    map_case c;
    c.kind = *rc::gen::element(canonical_map::swap, canonical_map::scaling, canonical_map::point,
                               canonical_map::linear_point, canonical_map::kick_drift,
                               canonical_map::oscillator_flow);
    switch (c.kind) {
      case canonical_map::swap:
        break;
      case canonical_map::scaling:
      case canonical_map::oscillator_flow:
        c.values = {*gen::positive(), *gen::positive(), *gen::coordinate()};
        break;
      case canonical_map::point:
        c.values = {*gen::dyadic_towards_zero(0.75)};
        break;
      case canonical_map::linear_point:
        c.values = *rc::gen::suchThat(rc::gen::container<std::vector<double>>(4, gen::coordinate()),
                                      [](const std::vector<double>& m) {
                                        return std::abs(m[0] * m[3] - m[1] * m[2]) >= 0.25;
                                      });
        break;
      default:
        c.values = *rc::gen::container<std::vector<double>>(4, gen::dyadic_towards_zero(1));
    }
    return c;
  });
}

/// The number of degrees of freedom a map acts on.
inline int map_dof(const map_case& c) { return c.kind == canonical_map::linear_point ? 2 : 1; }

}  // namespace mechcheck::laws::canonical
