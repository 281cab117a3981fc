#include "canonical/maps.hpp"

namespace {
using namespace mechcheck::laws::canonical;

/// Lecture 23, eqs 306-314: for H = p^2 / (2m) + m w^2 q^2 / 2 Hamilton's equations are
/// pdot = -m w^2 q, qdot = p / m (eqs 306-307), so qddot = -w^2 q (eq 308), solved by
/// q = A sin(w (t - t0)), p = m w A cos(w (t - t0)) (eqs 309-310); in the scaled
/// variables Q = sqrt(m w) q, P = p / sqrt(m w) of eq 311 the solution is a circle
/// (eqs 312-313) and d(P^2 + Q^2)/dt = 0 (eq 314). The rates come from the library's H by
/// AD (hamiltonian_vector_field), the solution is checked against the exact flow.
struct oscillator_solution {
  static law_info info() {
    return {"canonical.oscillator_solution",
            "Oscillator: pdot = -m w^2 q, qdot = p/m, qddot = -w^2 q, solved by q = A sin(w(t - "
            "t0)), p = m w A cos(w(t - t0)); in Q, P a circle, d(P^2 + Q^2)/dt = 0",
            {"306", "307", "308", "309", "310", "312", "313", "314"}};
  }
  // Each rate is one or two AD products against a closed form of three or four roundings
  // (sin, cos, products): scale of the terms, budget 16; the flow reference likewise.
  template <class T>
  static void property() {
    using std::abs;
    using std::cos;
    using std::sin;
    using std::sqrt;
    const double m = *gen::positive(), k = *gen::positive();
    const T tm = T(m), w = sqrt(T(T(k) / tm));
    const T amp = T(*gen::dyadic(-2, 2)), t0 = T(*gen::coordinate()), t = T(*gen::coordinate());
    const T phase = w * (t - t0), s = sin(phase), c = cos(phase);
    const T q = amp * s, p = tm * w * amp * c;  // eqs 309, 310
    const T qdot = amp * w * c, pdot = -(tm * w * w * amp * s);
    const mc::harmonic_oscillator<double> h(m, k);
    dynamic_vector<T> qs(1), ps(1);
    qs << q;
    ps << p;
    const dynamic_vector<T> rate = mc::hamiltonian_vector_field(h, mc::phase_point<T>(qs, ps));
    const T size = abs(amp) * w * (1 + tm * w);
    check_close("qdot = dH/dp = p/m (eq 307)", rate(0), qdot, size, 16);
    check_close("pdot = -dH/dq = -m w^2 q (eq 306)", rate(1), pdot, size, 16);
    check_close("qddot = pdot/m = -w^2 q (eq 308)", T(rate(1) / tm), T(-(w * w * q)),
                T(abs(amp) * w * w), 16);
    // The same state by the exact flow from (q, p)(t0) = (0, m w A) over t - t0.
    dynamic_vector<T> q0(1), p0(1);
    q0 << lift<T>(0);
    p0 << tm * w * amp;
    const auto flowed = mc::reference::oscillator_flow<double>(m, k)(q0, p0, T(t - t0));
    check_close("q(t) (eq 309) against the exact flow", flowed.q()(0), q, abs(amp), 16);
    check_close("p(t) (eq 310) against the exact flow", flowed.p()(0), p, T(tm * w * abs(amp)), 16);
    // Scaled variables: Q = A' sin, P = A' cos with A' = sqrt(m w) A, and P^2 + Q^2 constant.
    const T root = sqrt(T(tm * w));
    const T big_q = root * q, big_p = p / root;
    check_close("Q(t) = A' sin(w(t - t0)) (eq 312)", big_q, T(root * amp * s), T(root * abs(amp)), 16);
    check_close("P(t) = A' cos(w(t - t0)) (eq 313)", big_p, T(root * amp * c), T(root * abs(amp)), 16);
    const T circle_rate = 2 * (big_q * (root * rate(0)) + big_p * (rate(1) / root));
    check_zero("d(P^2 + Q^2)/dt (eq 314)", circle_rate, T(2 * tm * w * amp * amp * w), 16);
  }
};
MECHCHECK_LAW(oscillator_solution);

}  // namespace
