#pragma once
/// Symmetric compositions of Stormer-Verlet of order 4, 6 and 8 (triple jump).

#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "mechcheck/integrators/splitting.hpp"

namespace mechcheck {

/// Triple-jump weights (Yoshida 1990; Suzuki 1990) of a symmetric composition of
/// Stormer-Verlet of the given even order: S_{2k+2}(h) = S_{2k}(w1 h) S_{2k}(w0 h)
/// S_{2k}(w1 h) with w1 = 1 / (2 - 2^(1/(2k+1))), w0 = 1 - 2 w1, computed in S.
template <class S>
std::vector<S> triple_jump_weights(int order) {
  if (order < 2 || order % 2 != 0)
    throw domain_error("triple_jump_weights: order must be even and >= 2, got " +
                       std::to_string(order));
  using std::pow;
  std::vector<S> w{lift<S>(1)};
  for (int k = 1; 2 * k < order; ++k) {
    const S root = pow(lift<S>(2), lift<S>(1) / lift<S>(2 * k + 1));
    const S w1 = lift<S>(1) / (lift<S>(2) - root);
    const S w0 = lift<S>(1) - lift<S>(2) * w1;
    std::vector<S> next;
    for (const S& f : {w1, w0, w1})
      for (const S& x : w) next.push_back(f * x);
    w = std::move(next);
  }
  return w;
}

/// Symmetric composition of Stormer-Verlet of order 4, 6 or 8 (3, 9 or 27 Verlet steps,
/// one force evaluation each). Symplectic for any weights; the order needs them exact.
template <class System, class Vec, int Order>
class composition {
 public:
  static constexpr int order = Order;
  static constexpr bool symplectic = true;
  static constexpr bool symmetric = true;
  /// The energy error stays bounded over long runs (a symplectic map at small h).
  static constexpr bool bounded_energy = true;
  static constexpr bool separable = true;  ///< Stormer-Verlet's: needs H = |p|^2/2 + V(q)
  using scalar = typename Vec::Scalar;

  explicit composition(System system)
      : verlet_(std::move(system)), weights_(triple_jump_weights<real_type_t<scalar>>(Order)) {}

  void operator()(phase_state<Vec>& x, const scalar& h) {
    scratch_.use([&](workspace& w) {
      detail::guarded_step<System>(x, h, "composition", w.start, [&](phase_state<Vec>& y) {
        for (const auto& weight : weights_) {
          detail::scale(w.hw, weight, h);
          verlet_.substep(y, w.hw, w.verlet);
        }
      });
    });
  }

  const std::vector<real_type_t<scalar>>& weights() const { return weights_; }

 private:
  struct workspace {
    phase_state<Vec> start;
    typename stormer_verlet<System, Vec>::workspace verlet;
    scalar hw;
  };
  stormer_verlet<System, Vec> verlet_;
  std::vector<real_type_t<scalar>> weights_;
  detail::scratch<workspace, scalar> scratch_;
};

}  // namespace mechcheck
