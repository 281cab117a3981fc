#include "canonical/maps.hpp"

namespace {
using namespace mechcheck::laws::canonical;

/// Lecture 23, eqs 294-298: the Poisson bracket is the same in any canonical coordinates,
/// {f o Phi, g o Phi}_(q,p) = {f, g}_(Q,P) o Phi, because the Jacobian of Phi satisfies
/// M J M^T = J. Random smooth f, g (sums of polynomial and trigonometric terms) and the
/// canonical maps of canonical.symplectic_condition; the left side differentiates the
/// compositions by AD (through the map), the right side only f and g.
struct bracket_invariance {
  static law_info info() {
    return {"canonical.bracket_invariance",
            "Poisson brackets are invariant under canonical maps: {f o Phi, g o Phi} = {f, g} "
            "o Phi",
            {"294", "295", "296", "297", "298"}};
  }
  // Both sides are sums of 2n products of gradients; the left side's gradients are
  // M^T grad f, M^T grad g (2n more products each): error ~ 8n eps |M|^2 |grad f||grad g|,
  // budget 32n on that scale.
  template <class T>
  static void property() {
    const auto c = *map_cases();
    RC_TAG(static_cast<int>(c.kind));
    const int n = map_dof(c);
    const auto f = *gen::smooth_functions(n);
    const auto g = *gen::smooth_functions(n);
    const dynamic_vector<T> z = gen::to_tier<T>(*gen::coordinates(2 * n));
    const auto map = [&c]<class S>(const dynamic_vector<S>& w) -> dynamic_vector<S> {
      return apply_map(c, w);
    };
    const auto composed = [&map, n](const auto& h) {
      return [&map, &h, n]<class S>(const dynamic_vector<S>& q, const dynamic_vector<S>& p) -> S {
        dynamic_vector<S> w(2 * n);
        w << q, p;
        const dynamic_vector<S> image = map(w);
        return h(dynamic_vector<S>(image.head(n)), dynamic_vector<S>(image.tail(n)));
      };
    };
    const mc::phase_point<T> x = mc::phase_point<T>::from_stacked(z);
    const mc::phase_point<T> image = mc::phase_point<T>::from_stacked(map(z));
    const T left = mc::poisson_bracket(composed(f), composed(g), x);
    const T right = mc::poisson_bracket(f, g, image);
    const dynamic_matrix<T> m = mc::jacobian(map, z);
    // Term-wise gradient bounds of f and g (a generated sum may cancel: its rounding is
    // that of its terms, not of its small gradient).
    const T scale = m.squaredNorm() * f.gradient_magnitude(image) * g.gradient_magnitude(image);
    check_close("{f o Phi, g o Phi} against {f, g} o Phi (eqs 294-298)", left, right,
                scale > 0 ? scale : lift<T>(1), 32.0 * n);
  }
};
MECHCHECK_LAW(bracket_invariance);

}  // namespace
