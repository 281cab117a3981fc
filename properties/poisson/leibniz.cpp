#include "poisson/poisson.hpp"

namespace {
using namespace mechcheck::laws::poisson;

template <class T>
T value_norm(const gen::smooth_function& f, const phase_point<T>& x) {
  return f.magnitude(x);
}

/// f g.
template <class F, class G>
struct product {
  F f;
  G g;
  template <class S>
  S operator()(const dynamic_vector<S>& q, const dynamic_vector<S>& p) const {
    const S fs = f(q, p), gs = g(q, p);
    return fs * gs;
  }
};

struct leibniz_rule {
  static law_info info() {
    return {"poisson.leibniz", "Leibniz rule {fg,h} = f{g,h} + {f,h}g", {"269"}};
  }
  // Three brackets of 2n products; the product rule f g' + g f' (2 roundings) and the
  // right-hand side (3 roundings): k = 6n + 6.
  template <class T>
  static void property() {
    const int n = *gen::degrees_of_freedom();
    RC_TAG("n = " + std::to_string(n));
    const auto f = *gen::smooth_functions(n);
    const auto g = *gen::smooth_functions(n);
    const auto h = *gen::smooth_functions(n);
    const auto x = (*gen::phase_points(n)).template at<T>();
    const T fv = f(x.q(), x.p()), gv = g(x.q(), x.p());
    const T scale =
        (value_norm(f, x) * grad_norm(g, x) + value_norm(g, x) * grad_norm(f, x)) * grad_norm(h, x);
    const product<gen::smooth_function, gen::smooth_function> fg{f, g};
    check_close("{fg,h}", poisson_bracket(fg, h, x),
                T(fv * poisson_bracket(g, h, x) + poisson_bracket(f, h, x) * gv), scale,
                6.0 * n + 6);
  }
};
MECHCHECK_LAW(leibniz_rule);

}  // namespace
