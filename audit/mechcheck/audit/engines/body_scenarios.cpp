// Free rigid bodies as engine scenarios (engines/scenarios.hpp): a body of any principal
// moments, its principal axes turned anywhere, spun about no axis of its own, against the
// elliptic solution of Euler's equations; and random bodies drawn as scenarios.
#include <algorithm>
#include <cmath>
#include <limits>

#include <Eigen/Geometry>

#include "mechcheck/audit/problems/certified.hpp"
#include "mechcheck/audit/engines/scenarios.hpp"
#include "mechcheck/harness/generators.hpp"
#include "mechcheck/reference/tops.hpp"

namespace mechcheck::audit {

namespace {
using detail::exact_text;

std::string numbers(const Eigen::Vector3d& v) {
  return "(" + exact_text(v(0)) + ", " + exact_text(v(1)) + ", " + exact_text(v(2)) + ")";
}

vector3<mpfr50> to_mp(const Eigen::Vector3d& v) { return {mpfr50(v(0)), mpfr50(v(1)), mpfr50(v(2))}; }
}  // namespace

scenario free_body_scenario(std::string name, double mass, const Eigen::Vector3d& inertia,
                            const Eigen::Matrix3d& rotation0, const Eigen::Vector3d& position0,
                            const Eigen::Vector3d& velocity0, const Eigen::Vector3d& omega0, double t_end) {
  const std::string where = "free_body_scenario " + name + ": ";
  if (!std::isfinite(mass) || !std::isfinite(t_end))
    throw non_finite_error(where + "mass = " + to_text(mass) + ", t_end = " + to_text(t_end));
  for (const auto& [field, value] : {std::pair{"inertia", inertia}, std::pair{"position0", position0},
                                     std::pair{"velocity0", velocity0}, std::pair{"omega0", omega0}})
    if (!value.allFinite()) throw non_finite_error(where + field + " = " + to_text(value));
  if (!rotation0.allFinite()) throw non_finite_error(where + "rotation0 has a number that is not finite");
  if (!(mass > 0)) throw domain_error(where + "the mass must be positive, got " + to_text(mass));
  if (!(inertia(0) > 0 && inertia(0) < inertia(1) && inertia(1) < inertia(2)))
    throw domain_error(where + "need 0 < I1 < I2 < I3 (an asymmetric body; turn its axes with rotation0), got " +
                       to_text(inertia));
  if (!(inertia(2) < inertia(0) + inertia(1)))
    throw domain_error(where + "the moments " + to_text(inertia) + " break the triangle inequality I3 < I1 + I2");
  // A rotation to double's rounding: R^T R = 1 and det R = 1 within 16 eps.
  constexpr double eps = std::numeric_limits<double>::epsilon();
  if ((rotation0.transpose() * rotation0 - Eigen::Matrix3d::Identity()).norm() > 16 * eps ||
      std::abs(rotation0.determinant() - 1) > 16 * eps)
    throw domain_error(where + "rotation0 is not a rotation");
  if (!(t_end > 0)) throw domain_error(where + "t_end must be positive, got " + to_text(t_end));

  scenario s;
  s.kind = scenario_kind::free_body;
  s.name = std::move(name);
  s.mass = mass;
  s.inertia = inertia;
  s.rotation0 = rotation0;
  s.position0 = position0;
  s.velocity0 = velocity0;
  s.omega0 = omega0;
  s.t_end = t_end;
  s.steps0 = 32;
  s.h_long = 0.01;
  s.momentum = scenario::momentum_law::vector;
  // The body angular velocity the engine starts from, R0^T omega0, in mpfr50 from the
  // doubles it is given; the reference throws on the separatrix (M^2 = 2 E I2).
  const matrix3<mpfr50> r_mp = rotation0.cast<mpfr50>();
  const vector3<mpfr50> in_mp = to_mp(inertia), w_mp = r_mp.transpose() * to_mp(omega0);
  const mpfr50 l_norm = in_mp.cwiseProduct(w_mp).norm();
  if (l_norm == 0) throw domain_error(where + "the body does not turn (omega0 = 0)");
  s.time_scale = static_cast<double>(reference::asymmetric_top_period(in_mp, w_mp));
  const Eigen::Vector3d body_omega(static_cast<double>(w_mp(0)), static_cast<double>(w_mp(1)),
                                   static_cast<double>(w_mp(2)));
  s.scale = std::max({1.0, body_omega.norm(), position0.norm(), velocity0.norm()});
  s.classes = {{"angular velocity", 0, 3}, {"orientation", 3, 3}, {"position", 6, 3}, {"velocity", 9, 3}};
  s.description = "free body, m = " + exact_text(mass) + ", principal moments " + numbers(inertia) +
                  " along the columns of rotation0 (the principal axes in the world), body angular velocity " +
                  numbers(body_omega) + ", centre of mass from " + numbers(position0) + " at " +
                  numbers(velocity0) +
                  ", no gravity: body angular velocity against the Jacobi elliptic solution (Landau & "
                  "Lifshitz section 37), orientation as the fixed angular momentum's direction in the body "
                  "(R^T M / |M| = I Omega / |M|: the turn about M is not compared), centre of mass in uniform motion";
  s.exact = [in_mp, w_mp, l_norm, position0, velocity0](double t) -> Eigen::VectorXd {
    const vector3<mpfr50> w = t == 0 ? w_mp : reference::asymmetric_top_angular_velocity(in_mp, w_mp, mpfr50(t));
    const vector3<mpfr50> m = in_mp.cwiseProduct(w) / l_norm;
    Eigen::VectorXd out(12);
    for (int i = 0; i < 3; ++i) {
      out(i) = static_cast<double>(w(i));
      out(3 + i) = static_cast<double>(m(i));
      out(6 + i) = static_cast<double>(mpfr50(position0(i)) + mpfr50(velocity0(i)) * mpfr50(t));
      out(9 + i) = velocity0(i);
    }
    return out;
  };
  return s;
}

std::vector<scenario> random_body_scenarios(int count, std::uint64_t seed) {
  if (count < 0) throw domain_error("random_body_scenarios: count must be >= 0, got " + std::to_string(count));
  struct drawn {
    double mass;
    Eigen::Vector3d inertia, angles, omega, position, velocity;
  };
  std::vector<scenario> out;
  for (int k = 0; k < count; ++k) {
    const auto draw = rc::gen::exec([] {
      drawn d;
      d.mass = *generators::dyadic(0.25, 4);
      // I1 < I2 < I3 < I1 + I2, the gaps at least 1/16 of I1: products of dyadics, exact.
      const double i1 = *generators::dyadic(0.25, 2);
      const double i2 = i1 * (1 + *generators::dyadic(1.0 / 16, 1));
      const double i3 = i2 + i1 * *generators::dyadic(1.0 / 16, 15.0 / 16);
      d.inertia = {i1, i2, i3};
      for (int i = 0; i < 3; ++i) {
        d.angles(i) = *generators::dyadic_towards_zero(3.14);
        d.omega(i) = *generators::dyadic_towards_zero(2);
        d.position(i) = *generators::dyadic_towards_zero(1);
        d.velocity(i) = *generators::dyadic_towards_zero(1);
      }
      return d;
    });
    // Off every principal axis (two components at least), turning at 1/4 or more, and away
    // from the separatrix: |M^2 - 2 E I2| >= M^2 / 8, so that the period stays within a few
    // turns.
    const auto kept = rc::gen::suchThat(draw, [](const drawn& d) {
      const Eigen::Vector3d m = d.inertia.cwiseProduct(d.omega);
      const int turning = int(d.omega(0) != 0) + int(d.omega(1) != 0) + int(d.omega(2) != 0);
      const double pivot = m.squaredNorm() - d.omega.dot(m) * d.inertia(1);
      return turning >= 2 && d.omega.norm() >= 0.25 && std::abs(pivot) >= m.squaredNorm() / 8;
    });
    // One stream per body: body k is the same whatever count is asked for.
    const drawn d = kept(rc::Random(seed * 1000003u + std::uint64_t(k)), rc::kNominalSize).value();
    // The principal axes turned by roll, pitch and yaw; the world angular velocity from the
    // body's, both rounded to double.
    const Eigen::Matrix3d r = (Eigen::AngleAxisd(d.angles(2), Eigen::Vector3d::UnitZ()) *
                               Eigen::AngleAxisd(d.angles(1), Eigen::Vector3d::UnitY()) *
                               Eigen::AngleAxisd(d.angles(0), Eigen::Vector3d::UnitX()))
                                  .toRotationMatrix();
    out.push_back(free_body_scenario("body_" + std::to_string(seed) + "_" + std::to_string(k), d.mass, d.inertia, r,
                                     d.position, d.velocity, r * d.omega));
  }
  return out;
}

}  // namespace mechcheck::audit
