// The contact audit against engines whose answers are known: the test engine of
// contact_engine.hpp (an isotropic Coulomb cone, no creep, Newton's restitution) is
// confirmed on every claim, and its variants -- a pyramid cone, a creeping stick, a
// restitution applied twice -- are caught as anisotropy, creep and energy gained.

#include <gtest/gtest.h>

#include <algorithm>
#include <sstream>

#include "contact_engine.hpp"
#include "mechcheck/audit/engines/contact.hpp"

namespace contact_test {
using outcome = audit::verdict::outcome;

const audit::verdict& verdict_of(const audit::contact_audit& a, const std::string& claim) {
  for (const auto& v : a.verdicts)
    if (v.claim == claim) return v;
  throw std::runtime_error("no verdict " + claim);
}

std::string all_of(const audit::contact_audit& a) {
  std::ostringstream s;
  audit::print_contact(s, {a});
  return s.str();
}

TEST(contact, the_exact_engine_is_confirmed_on_every_claim) {
  const audit::contact_audit a = audit::audit_contact(exact_contact_engine(variant::exact));
  ASSERT_EQ(a.scenarios.size(), audit::contact_scenarios().size());
  for (const auto& s : a.scenarios) EXPECT_EQ(s.refused, "") << s.scenario;
  for (const char* claim : {"friction cone", "static friction", "at rest", "restitution", "energy", "exact motions"})
    EXPECT_EQ(verdict_of(a, claim).result, outcome::confirmed) << claim << ": " << verdict_of(a, claim).measured << " -- "
                                                              << verdict_of(a, claim).evidence << "\n" << all_of(a);
  // The sliding box's stopping distance converges to v0^2 / (2 mu g); the billiard ball's
  // final speed is 5/7 v0 at every h (the impulse that ends the slip is exact).
  for (const auto& s : a.scenarios)
    for (const auto& t : s.trends) {
      if (s.scenario == "contact_slide" && t.measure == "stopping distance") EXPECT_TRUE(t.order) << t.words;
      if (s.scenario == "contact_billiard" && t.measure == "final speed") EXPECT_LT(t.at_default, 1e-12) << t.words;
    }
  // Its impacts are found inside the step: the collisions' outgoing velocities are exact at
  // every h, and the stack does not move.
  for (const auto& s : a.scenarios)
    for (const auto& r : s.runs)
      for (const auto& m : r.measures) {
        if (s.scenario.rfind("contact_collision", 0) == 0) EXPECT_LT(std::abs(m.error()), 1e-12) << s.scenario << " " << m.name;
        if (s.scenario == "contact_stack" && m.name.rfind("drift", 0) == 0) EXPECT_EQ(m.value, 0) << m.name;
      }
  EXPECT_LT(std::find_if(a.scenarios.begin(), a.scenarios.end(), [](const auto& s) { return s.scenario == "contact_slide"; })
                ->anisotropy,
            1e-9);
}

TEST(contact, a_pyramid_cone_is_caught_as_anisotropy) {
  // Declared elliptic, clamped per world axis: along x it stops where Coulomb's does, on the
  // diagonal its friction is sqrt 2 mu N and it stops at 1/sqrt 2 of the distance.
  const audit::contact_audit a = audit::audit_contact(exact_contact_engine(variant::pyramid), {{"contact_slide"}});
  const audit::verdict& v = verdict_of(a, "friction cone");
  EXPECT_EQ(v.result, outcome::contradicted) << v.measured << " -- " << v.evidence;
  EXPECT_NEAR(a.scenarios.front().anisotropy, 1 - 1 / std::sqrt(2.0), 0.05);
}

TEST(contact, a_creeping_stick_is_caught_as_creep) {
  const audit::contact_audit a = audit::audit_contact(exact_contact_engine(variant::creep), {{"contact_slope_stick"}});
  const audit::verdict& v = verdict_of(a, "static friction");
  EXPECT_EQ(v.result, outcome::measured) << v.measured << " -- " << v.evidence;
  EXPECT_NE(v.measured.find("creeps at"), std::string::npos) << v.measured;
}

TEST(contact, a_restitution_applied_twice_is_caught_as_energy_gained) {
  const audit::contact_audit a =
      audit::audit_contact(exact_contact_engine(variant::restitution_twice), {{"contact_bounce", "contact_collision"}});
  const audit::verdict& v = verdict_of(a, "energy");
  EXPECT_EQ(v.result, outcome::contradicted) << v.measured << " -- " << v.evidence;
  EXPECT_FALSE(a.claims_hold());
}

TEST(contact, a_sinking_stack_is_caught_as_moving_at_rest) {
  const audit::contact_audit a = audit::audit_contact(exact_contact_engine(variant::sinking), {{"contact_stack"}});
  const audit::verdict& v = verdict_of(a, "at rest");
  EXPECT_EQ(v.result, outcome::measured) << v.measured << " -- " << v.evidence;
  EXPECT_NE(v.measured.find("moves"), std::string::npos) << v.measured;
}

TEST(contact, an_engine_without_contact_refuses_every_scenario_by_name) {
  audit::engine_integrator none;
  none.name = "test::no_contact";
  none.start = [](const audit::scenario&) -> std::unique_ptr<audit::engine_run> { return nullptr; };
  const audit::contact_audit a = audit::audit_contact(none);
  for (const auto& s : a.scenarios) EXPECT_NE(s.refused.find("builds no contact scenario"), std::string::npos) << s.scenario;
}

}  // namespace contact_test
