#include "poisson/poisson.hpp"

namespace {
using namespace mechcheck::laws::poisson;

/// a f + b g with constant a, b.
template <class F, class G>
struct linear_combination {
  double a;
  F f;
  double b;
  G g;
  template <class S>
  S operator()(const dynamic_vector<S>& q, const dynamic_vector<S>& p) const {
    const S af = lift<S>(a) * f(q, p);
    const S bg = lift<S>(b) * g(q, p);
    return af + bg;
  }
};

struct bilinearity {
  static law_info info() {
    return {"poisson.bilinearity",
            "Bilinearity {af+bg,h} = a{f,h} + b{g,h}, in both slots", {"269"}};
  }
  // Three brackets of 2n products, plus the combinations a f' + b g' (2 roundings) and
  // a{f,h} + b{g,h} (2 roundings) per slot: k = 6n + 6.
  template <class T>
  static void property() {
    const int n = *gen::degrees_of_freedom();
    RC_TAG("n = " + std::to_string(n));
    const auto f = *gen::smooth_functions(n);
    const auto g = *gen::smooth_functions(n);
    const auto h = *gen::smooth_functions(n);
    const double a = *gen::coefficient(), b = *gen::coefficient();
    const auto x = (*gen::phase_points(n)).template at<T>();
    const linear_combination<gen::smooth_function, gen::smooth_function> afbg{a, f, b, g};
    const T ta = lift<T>(a), tb = lift<T>(b);
    using std::abs;
    const T scale = (abs(ta) * grad_norm(f, x) + abs(tb) * grad_norm(g, x)) * grad_norm(h, x);
    check_close("{af+bg,h}", poisson_bracket(afbg, h, x),
                T(ta * poisson_bracket(f, h, x) + tb * poisson_bracket(g, h, x)), scale,
                6.0 * n + 6);
    check_close("{h,af+bg}", poisson_bracket(h, afbg, x),
                T(ta * poisson_bracket(h, f, x) + tb * poisson_bracket(h, g, x)), scale,
                6.0 * n + 6);
  }
};
MECHCHECK_LAW(bilinearity);

}  // namespace
