#include "poisson/poisson.hpp"

namespace {
using namespace mechcheck::laws::poisson;

template <class T>
T hessian_norm(const gen::smooth_function& f, const phase_point<T>& x) {
  return f.hessian_magnitude(x);
}

struct jacobi_identity {
  static law_info info() {
    return {"poisson.jacobi", "Jacobi identity {f,{g,h}} + {g,{h,f}} + {h,{f,g}} = 0",
            {"269", "279"}};
  }
  // Each term {a,{b,c}} sums 2n products of grad a with grad {b,c}, whose components
  // sum 4n products of a Hessian entry and a gradient entry: error <= 6n eps times
  // |grad a| (|H_b| |grad c| + |grad b| |H_c|). Three terms: k = 3 * 6n = 18n.
  template <class T>
  static void property() {
    const int n = *gen::degrees_of_freedom();
    const auto f = *gen::smooth_functions(n);
    const auto g = *gen::smooth_functions(n);
    const auto h = *gen::smooth_functions(n);
    const auto x = (*gen::phase_points(n)).template at<T>();
    RC_CLASSIFY(f.has_wave() || g.has_wave() || h.has_wave(), "trigonometric");
    const T df = grad_norm(f, x), dg = grad_norm(g, x), dh = grad_norm(h, x);
    const T hf = hessian_norm(f, x), hg = hessian_norm(g, x), hh = hessian_norm(h, x);
    const T scale = df * (hg * dh + dg * hh) + dg * (hh * df + dh * hf) + dh * (hf * dg + df * hg);
    const T sum = poisson_bracket(f, mc::bracket_function{g, h}, x) +
                  poisson_bracket(g, mc::bracket_function{h, f}, x) +
                  poisson_bracket(h, mc::bracket_function{f, g}, x);
    check_zero("{f,{g,h}} + {g,{h,f}} + {h,{f,g}}", sum, scale, 18.0 * n);
  }
};
MECHCHECK_LAW(jacobi_identity);

}  // namespace
