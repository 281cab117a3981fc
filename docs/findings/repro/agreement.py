#!/usr/bin/env python3
"""Holds each reproducer's numbers against the audit's: every published finding is measured
twice, by mechcheck's audit and by a program that uses only the library it is about, and
the two must agree within the tolerance stated here (derived from what each measures).

Usage: agreement.py REPRO_OUTPUT_DIR AUDIT_DIR   (ci/findings runs it)
Exits 1 when a pair disagrees or a number is missing, naming it."""
import json
import math
import os
import re
import sys

repro_dir, audit_dir = sys.argv[1], sys.argv[2]


def repro(program, key):
    path = os.path.join(repro_dir, program + ".txt")
    with open(path) as f:
        for line in f:
            name, _, value = line.strip().partition(" ")
            if name == key:
                return float(value)
    raise KeyError(f"{program}: no line '{key}' in {path}")


def load(name):
    with open(os.path.join(audit_dir, name)) as f:
        return json.load(f)


def engine(integrator, report="engines/engines.json"):
    for a in load(report)["integrators"]:
        if a["integrator"] == integrator:
            return a
    raise KeyError(f"engines.json: no integrator {integrator}")


def engine_scenario(integrator, scenario, report="engines/engines.json"):
    for s in engine(integrator, report)["scenarios"]:
        if s["scenario"] == scenario:
            return s
    raise KeyError(f"engines.json: {integrator} has no scenario {scenario}")


def class_fit(integrator, scenario, name, report="engines/engines.json"):
    return engine_scenario(integrator, scenario, report)["classes"][name]["fit"]["value"]


def class_error(integrator, scenario, name, h, report):
    """The error of a class's study at step h."""
    for p in engine_scenario(integrator, scenario, report)["classes"][name]["points"]:
        if p["h"] == h:
            return p["error"]
    raise KeyError(f"{report}: {integrator} on {scenario} has no {name} point at h = {h}")


def shape_row(engine_name, shape, report, mass_given=True):
    for s in load(report)["shapes"]:
        if s["engine"] == engine_name and s["shape"] == shape and s.get("mass_given", True) == mass_given:
            return s
    raise KeyError(f"{report}: no shape {engine_name} {shape}" + ("" if mass_given else " without a mass"))


def shape_error(engine_name, shape, report="engines/engines.json"):
    return shape_row(engine_name, shape, report)["relative_error"]


def alone(engine_name, report, key):
    """The box given without a mass: the engine's mass, or its largest moment."""
    row = shape_row(engine_name, "box", report, mass_given=False)
    return row["mass"] if key == "mass" else max(row["measured"])


def stepper(report, name, tier):
    for a in load(report)["audits"]:
        if a["stepper"] == name and a["tier"] == tier:
            return a
    raise KeyError(f"{report}: no stepper {name} [{tier}]")


def problem(report, name, tier, problem_name):
    for p in stepper(report, name, tier)["problems"]:
        if p["problem"] == problem_name:
            return p
    raise KeyError(f"{report}: {name} has no problem {problem_name}")


def verdict_number(report, name, tier, claim, words):
    """The number after `words` (a regular expression) in a verdict's evidence (printed to two digits)."""
    for v in stepper(report, name, tier)["verdicts"]:
        if v["claim"] == claim:
            found = re.search("(?:" + words + r") ([0-9.]+e[-+][0-9]+)", v["evidence"])
            if found:
                return float(found.group(1))
            raise KeyError(f"{report}: {name}'s {claim} evidence has no '{words}'")
    raise KeyError(f"{report}: {name} has no {claim} verdict")


def horizon(driver, multiple):
    for a in load("drivers/drivers.json"):
        if a["driver"] == driver:
            for m, r in a["horizon"]["ratio"]:
                if m == multiple:
                    return r
    raise KeyError(f"drivers.json: no horizon {multiple} for {driver}")


def contact_scenario(integrator, scenario, report):
    for a in load(report):
        if a["integrator"] == integrator:
            for s in a["scenarios"]:
                if s["scenario"] == scenario:
                    return s
    raise KeyError(f"{report}: {integrator} has no contact scenario {scenario}")


def contact_measure(integrator, scenario, name, report):
    """A contact measure at the report's first step (h = 1/60)."""
    for m in contact_scenario(integrator, scenario, report)["runs"][0]["measures"]:
        if m["name"] == name:
            return m["value"]
    raise KeyError(f"{report}: {integrator} on {scenario} has no measure '{name}'")


def contact_series(integrator, scenario, name, report):
    """A contact measure at each step of the report's runs (h = 1/60 and its halvings)."""
    out = []
    for r in contact_scenario(integrator, scenario, report)["runs"]:
        out += [m["value"] for m in r["measures"] if m["name"] == name]
    return out


def contact_measure_at(integrator, scenario, name, report, index):
    """A contact measure in the report's run `index` (0: h = 1/60, -1: the finest h)."""
    for m in contact_scenario(integrator, scenario, report)["runs"][index]["measures"]:
        if m["name"] == name:
            return m["value"]
    raise KeyError(f"{report}: {integrator} on {scenario} has no measure '{name}' in run {index}")


def contact_isotropy(integrator, report):
    """The stopping distance over v0^2/(2 mu g) at each theta and psi of the sweep, in its order."""
    return [p["over_exact"] for p in contact_scenario(integrator, "contact_slide", report)["isotropy"]]


def repro_isotropy(program, prefix):
    return [repro(program, f"{prefix}slide_theta{theta}_psi{psi}_over_exact") for psi in (0, 30)
            for theta in range(0, 91, 15)]


def slide_pairs(finding, label, program, prefix, integrator, report, spread_tolerance=1e-6, spread_relative=True):
    """The sliding box's two pairs: its stopping distance at each theta, psi of the sweep, and their spread."""
    return [
        (finding, f"{label}: the stopping distance over v0^2/(2 mu g) at each theta, psi",
         lambda: repro_isotropy(program, prefix), lambda: contact_isotropy(integrator, report), 1e-6, True),
        (finding, f"{label}: the spread of the stopping distance over theta and psi",
         lambda: repro(program, f"{prefix}slide_spread"),
         lambda: contact_scenario(integrator, "contact_slide", report)["anisotropy"], spread_tolerance, spread_relative),
    ]


def measure_pair(finding, what, program, key, integrator, scenario, name, report, tolerance=1e-6, relative=True):
    """A reproducer's number against a contact measure at the report's first step (h = 1/60)."""
    return (finding, what, lambda: repro(program, key),
            lambda: contact_measure(integrator, scenario, name, report), tolerance, relative)


def held_robot_mass_error(library, report="dynamics-mujoco/dynamics.json"):
    """max |M_held - M_given| of a dynamics campaign, from eps of the scale back to units."""
    for c in load(report):
        if c["library"].split(" on ")[0] == library:
            h = c["held_robot"]
            return h["largest_difference"] * 2.0**-52 * h["scale"]
    raise KeyError(f"{report}: no library {library}")


def long_run(integrator, scenario, report, field):
    """A scenario's long run: its largest energy error, angular momentum change, anchor or loop separation; for a run
    MuJoCo stopped with a warning, the step it stopped at (field "energy") and the warning's number (the others)."""
    s = engine_scenario(integrator, scenario, report)
    stop = re.match(r"step (\d+):.*MuJoCo warning (\d+)", s.get("long_run_failure", ""))
    if stop:
        return float(stop.group(1) if field == "energy" else stop.group(2))
    if field in ("energy", "momentum"):
        return s[field + "_max"]
    return s["constraint_max"]["position" if field == "anchor" else "loop"]


# The scenarios of <engine>_scenarios.mjs, and which each engine setting runs.
JOINTED = ["pendulum_small", "pendulum_large", "heavy_top", "double_pendulum", "chain5", "four_bar"]
SPINNING = ["free_top", "free_top_near_axis", "boxes", "free_symmetric_top"] + [f"body_1_{k}" for k in range(8)]
FREE = ["projectile", "kepler", "three_body"] + SPINNING


def repro_long_run(program, prefix, field):
    """The reproducer's side of long_run: its largest change, or where MuJoCo stopped the run."""
    try:
        return repro(program, f"{prefix}_stopped_at_step" if field == "energy" else f"{prefix}_stopped_by_warning")
    except KeyError:
        return repro(program, f"{prefix}_{field}_max")


def study_series(integrator, scenario, name, report, program, prefix):
    """Each point of a class's order study as (the reproducer's error, the audit's), n = 32 .. the audit's last."""
    points = engine_scenario(integrator, scenario, report)["classes"][name]["points"]
    t_end = 4 if scenario.startswith("body_") else {"free_top": 5, "free_top_near_axis": 10, "boxes": 10,
                                                      "free_symmetric_top": 5, "pendulum_small": 2,
                                                      "pendulum_large": 2, "projectile": 1, "kepler": 5,
                                                      "double_pendulum": 2, "chain5": 1, "four_bar": 2,
                                                      "three_body": 2}[scenario]
    return [(repro(program, f"{prefix}_{name.replace(' ', '_')}_error_n{round(t_end / p['h'])}"), p["error"])
            for p in points]


def study_classes(scenario):
    """The classes of a scenario's order study the reproducers compute (none: the heavy top)."""
    if scenario.startswith("pendulum_") or scenario in ("double_pendulum", "chain5", "four_bar"):
        return ["joint coordinates"]
    if scenario in ("projectile", "kepler", "three_body"):
        return ["position", "velocity"]
    if scenario not in FREE:
        return []
    return ["angular velocity"] + (["orientation"] if scenario == "free_symmetric_top" or scenario.startswith("body_") else [])


def measured(scenario):
    """What a long run of the scenario is held to: (field, words)."""
    if scenario == "projectile":  # no momentum law under gravity
        return [("energy", "energy error")]
    if scenario in FREE:
        return [("momentum", "angular momentum change"), ("energy", "energy error")]
    loop = [("loop", "loop separation")] if scenario == "four_bar" else []
    return [("anchor", "anchor separation"), *loop, ("energy", "energy error")]


# (engine, client, setting, scenarios, the audit's report): Jolt's solver steps act on the joints
# and its gyroscopic force on free bodies, so those settings are audited there alone, as the
# reproducer runs them (ci/findings: scenarios-jolt-joints, scenarios-jolt-free).
SCENARIO_RUNS = [("rapier", "rapier", "impulse_joints", JOINTED + FREE, "scenarios-rapier"),
                 ("rapier", "rapier", "impulse_joints_16_iterations", JOINTED + FREE, "scenarios-rapier"),
                 ("jolt", "jolt", "default", JOINTED + FREE, "scenarios-jolt"),
                 ("jolt", "jolt", "position_steps_8", JOINTED, "scenarios-jolt-joints"),
                 ("jolt", "jolt", "velocity_steps_40", JOINTED, "scenarios-jolt-joints"),
                 ("jolt", "jolt", "gyroscopic", FREE, "scenarios-jolt-free"),
                 ("havok", "havok", "step", JOINTED + FREE, "scenarios-havok"),
                 ("cannon", "cannon_es", "World.step", JOINTED + FREE, "scenarios-cannon"),
                 # MuJoCo's bindings take no force callback: no Kepler, no three bodies.
                 *[("mujoco_wasm", "mujoco_wasm", integrator, ["heavy_top", "projectile"] + SPINNING,
                    "scenarios-mujoco_wasm")
                   for integrator in ["Euler", "RK4", "implicit", "implicitfast"]]]


def largest_axis_error(program, shape):
    return max(abs(repro(program, f"{shape}_{axis}_bullet_over_exact") - 1) for axis in "xyz")


# (finding, what, reproducer's value, audit's value, tolerance, relative?)
# Orders: both fit log2 of error ratios in the asymptotic range; 0.05 is half the band a
# decisive fit may spread. Inertias: the same library function, printed to 6 digits: 1e-5.
# MuJoCo's compiled inertia: the same mass matrix, the audit's difference of two exact ones
# (each rounded once to double) against the reproducer's double difference: 1e-6 relative of
# a 2.5e-8 difference is 1e-14, a hundred ulps of M. Errors and ratios of identical setups: the same arithmetic up to summation order, 1e-3
# relative (cannon-es's, Havok's, Jolt's and Rapier's free top, read through the same quaternion and a reference
# good to 1e-13 against the audit's Jacobi elliptic one: 1e-6); the stall of CASH: 5 % (the audit's runs go to 2^16 steps, the reproducer's to
# 2^14, both on the plateau at 4.9e-11).
CHECKS = [
    ("mujoco-fullinertia", "MuJoCo 2.2.2: the mass matrix of the compiled one-link robot against I_zz",
     lambda: repro("mujoco_fullinertia", "mass_matrix_error"),
     lambda: held_robot_mass_error("mujoco"), 1e-6, True),
    # MuJoCo's contact: the same model, start and reading (mujoco_contact.c says why the reading
    # matters), the same arithmetic: 1e-6 relative. The elliptic cone's spread is rounding (4e-13
    # of the distance): held absolutely to 1e-9, a millionth of the isotropy verdict's 1e-3.
    *slide_pairs("mujoco-contact", "MuJoCo 2.2.2, pyramidal cone", "mujoco_contact", "pyramidal_", "mujoco::Euler",
                 "contact-mujoco/contact.json"),
    *slide_pairs("mujoco-contact", "MuJoCo 2.2.2, elliptic cone (its spread is rounding)", "mujoco_contact",
                 "elliptic_", "mujoco::Euler/elliptic", "contact-mujoco/contact.json", 1e-9, False),
    measure_pair("mujoco-contact", "MuJoCo 2.2.2, pyramidal cone: the creep rate down a slope below the friction angle",
                 "mujoco_contact", "pyramidal_slope_creep_rate", "mujoco::Euler", "contact_slope_stick",
                 "creep rate (second half)", "contact-mujoco/contact.json"),
    measure_pair("mujoco-contact", "MuJoCo 2.2.2, pyramidal cone: the creep down the slope in 3 s", "mujoco_contact",
                 "pyramidal_slope_creep", "mujoco::Euler", "contact_slope_stick", "creep down the slope",
                 "contact-mujoco/contact.json"),
    measure_pair("mujoco-contact", "MuJoCo 2.2.2, elliptic cone: the creep rate down the slope", "mujoco_contact",
                 "elliptic_slope_creep_rate", "mujoco::Euler/elliptic", "contact_slope_stick",
                 "creep rate (second half)", "contact-mujoco/contact.json"),
    ("mujoco-contact", "MuJoCo 2.2.2, e = 0.5 as solref's damping ratio: the ball's first apex at h = 1/60 and 1/960",
     lambda: [repro("mujoco_contact", f"bounce_apex1_n{n}") for n in (150, 2400)],
     lambda: [contact_measure_at("mujoco::Euler", "contact_bounce", "apex 1", "contact-mujoco/contact.json", i)
              for i in (0, -1)], 1e-6, True),
    # ODE's contact: the same world, start and arithmetic: 1e-6 relative; dWorldStep's creep rate
    # (6e-11 m/s: its LCP holds the box) absolutely to 1e-9 m/s, a thousandth of the verdict's 1e-6.
    *slide_pairs("ode-contact", "ODE 0.16.2, dWorldStep", "ode_contact", "step_", "ode::step",
                 "contact-ode/contact.json"),
    *slide_pairs("ode-contact", "ODE 0.16.2, dWorldQuickStep", "ode_contact", "quickstep_", "ode::quickstep",
                 "contact-ode/contact.json"),
    measure_pair("ode-contact", "ODE 0.16.2, dWorldStep: the creep rate down a slope below the friction angle",
                 "ode_contact", "step_slope_creep_rate", "ode::step", "contact_slope_stick", "creep rate (second half)",
                 "contact-ode/contact.json", 1e-9, False),
    measure_pair("ode-contact", "ODE 0.16.2, dWorldQuickStep (20 iterations): the creep rate down the slope",
                 "ode_contact", "quickstep_slope_creep_rate", "ode::quickstep", "contact_slope_stick",
                 "creep rate (second half)", "contact-ode/contact.json"),
    measure_pair("ode-contact", "ODE 0.16.2, dWorldQuickStep (20 iterations): the creep down the slope in 3 s",
                 "ode_contact", "quickstep_slope_creep", "ode::quickstep", "contact_slope_stick",
                 "creep down the slope", "contact-ode/contact.json"),
    # Bullet's contact: the same world, start and arithmetic: 1e-6 relative.
    *slide_pairs("bullet-contact", "Bullet 3.24", "bullet_contact", "", "bullet::gyroscopic_implicit_body",
                 "contact-bullet/contact.json"),
    ("bullet-contact", "Bullet 3.24: the stopping distance at h = 1/60 to 1/960 (m)",
     lambda: [repro("bullet_contact", f"slide_distance_n{n}") for n in (60, 120, 240, 480, 960)],
     lambda: contact_series("bullet::gyroscopic_implicit_body", "contact_slide", "stopping distance",
                            "contact-bullet/contact.json"), 1e-6, True),
    measure_pair("bullet-contact", "Bullet 3.24: the creep down a slope below the friction angle in 3 s",
                 "bullet_contact", "slope_creep", "bullet::gyroscopic_implicit_body", "contact_slope_stick",
                 "creep down the slope", "contact-bullet/contact.json"),
    measure_pair("bullet-contact", "Bullet 3.24: the creep rate over the second half", "bullet_contact",
                 "slope_creep_rate", "bullet::gyroscopic_implicit_body", "contact_slope_stick",
                 "creep rate (second half)", "contact-bullet/contact.json"),
    # cannon-es's contact: the same world, start and arithmetic: 1e-6 relative.
    ("cannon-contact", "cannon-es 0.20.0: the box's displacement in 1 s from the audit's start, at h = 1/60 to 1/960 (m)",
     lambda: [repro("cannon_contact", f"box_start_displacement_n{n}") for n in (60, 120, 240, 480, 960)],
     lambda: contact_series("exec::cannon_es::World.step", "contact_slide", "stopping distance",
                            "contact-cannon/contact.json"), 1e-6, True),
    # Simbody's compliant contact: the same system, start and error control (1e-6 relative; the
    # spread, 5.9e-8, to 1e-9).
    *slide_pairs("simbody-contact", "Simbody 3.7", "simbody_contact", "", "simbody::RungeKuttaMerson/contact",
                 "contact-simbody/contact.json", 1e-9, False),
    measure_pair("simbody-contact", "Simbody 3.7: the creep rate down a slope below the friction angle",
                 "simbody_contact", "slope_creep_rate", "simbody::RungeKuttaMerson/contact", "contact_slope_stick",
                 "creep rate (second half)", "contact-simbody/contact.json"),
    measure_pair("simbody-contact", "Simbody 3.7: the creep down the slope in 3 s", "simbody_contact", "slope_creep",
                 "simbody::RungeKuttaMerson/contact", "contact_slope_stick", "creep down the slope",
                 "contact-simbody/contact.json"),
    ("simbody-contact", "Simbody 3.7: the creep rate against its friction model's, vt step5^-1(tan a / mu)",
     lambda: repro("simbody_contact", "slope_creep_rate"), lambda: repro("simbody_contact", "slope_model_rate"), 1e-3, True),
    # Bullet's Featherstone world: the same world, start and arithmetic.
    *slide_pairs("bullet-multibody-contact", "Bullet 3.24 (btMultiBody)", "bullet_multibody_contact", "",
                 "bullet::multibody", "contact-bullet-multibody/contact.json"),
    ("bullet-multibody-contact", "Bullet 3.24 (btMultiBody): the stopping distance at h = 1/60 to 1/960 (m)",
     lambda: [repro("bullet_multibody_contact", f"slide_distance_n{n}") for n in (60, 120, 240, 480, 960)],
     lambda: contact_series("bullet::multibody", "contact_slide", "stopping distance",
                            "contact-bullet-multibody/contact.json"), 1e-6, True),
    # DART's contact: the same worlds, starts and arithmetic, at h = 1/60 and 1/960: 1e-6 relative.
] + [
    ("dart-contact", f"DART 6.12.1 ({which}): {what} at h = 1/60 and 1/960",
     lambda key=key, which=which: [
         repro("dart_contact", f"{'mesh' if which == 'dart::World' else 'primitive'}_{key}_n{n}") for n in (60, 960)],
     lambda scenario=scenario, name=name, which=which: [
         contact_measure_at(which, scenario, name, "contact-dart/contact.json", i) for i in (0, -1)], 1e-6, True)
    for which in ("dart::World", "dart::World/fcl_primitive")
    for key, scenario, name, what in (
        ("roll_distance", "contact_roll", "distance down the slope", "the ball's distance down the slope in 1 s"),
        ("billiard_final_speed", "contact_billiard", "final speed", "the billiard ball's speed at 1 s"),
        ("collision_v1_error", "contact_collision", "body 1's velocity after, error",
         "the head-on collision: the first ball's velocity after, its error"))
] + [
    ("mujoco-rk4", "RK4's order in the orientation (free symmetric top)",
     lambda: repro("mujoco_rk4_orientation", "rk4_axis_order"),
     lambda: class_fit("mujoco::RK4", "free_symmetric_top", "orientation"), 0.05, False),
    ("mujoco-rk4", "the dexp-corrected RK4's order in the orientation",
     lambda: repro("mujoco_rk4_orientation", "rk4_dexp_corrected_axis_order"),
     lambda: class_fit("mujoco::RK4/dexp_corrected", "free_symmetric_top", "orientation"), 0.05, False),
    ("mujoco-rk4", "MuJoCo 3.14.0 (WebAssembly): RK4's order in the orientation",
     lambda: repro("mujoco_wasm_rk4_orientation", "rk4_axis_order"),
     lambda: class_fit("exec::mujoco_wasm::RK4", "free_symmetric_top", "orientation", "engines-wasm/engines.json"),
     0.05, False),
    ("mujoco-rk4", "MuJoCo 3.14.0 (WebAssembly): the dexp-corrected RK4's order in the orientation",
     lambda: repro("mujoco_wasm_rk4_orientation", "rk4_dexp_corrected_axis_order"),
     lambda: class_fit("exec::mujoco_wasm::RK4/dexp_corrected", "free_symmetric_top", "orientation",
                       "engines-wasm/engines.json"), 0.05, False),
    ("cannon-free-body", "the free top's angular momentum, largest relative change over 10^4 steps",
     lambda: repro("cannon_free_body", "free_top_momentum_max"),
     lambda: engine_scenario("exec::cannon_es::World.step", "free_top", "engines-cannon/engines.json")["momentum_max"],
     1e-6, True),
    ("cannon-free-body", "the free top's body angular velocity error at t = 5, 16384 steps",
     lambda: repro("cannon_free_body", "free_top_error_n16384"),
     lambda: class_error("exec::cannon_es::World.step", "free_top", "angular velocity", 5 / 16384,
                         "engines-cannon/engines.json"), 1e-6, True),
    ("cannon-free-body", "a sphere's moment of inertia: relative error",
     lambda: repro("cannon_free_body", "sphere_over_exact") - 1,
     lambda: shape_error("exec::cannon_es", "sphere", "engines-cannon/engines.json"), 1e-5, True),
    ("havok-free-body", "Havok 1.3.14: the free top's angular momentum, largest relative change over 10^4 steps",
     lambda: repro("havok_free_body", "free_top_momentum_max"),
     lambda: engine_scenario("exec::havok::step", "free_top", "engines-havok/engines.json")["momentum_max"],
     1e-6, True),
    ("havok-free-body", "Havok 1.3.14: the free top's body angular velocity error at t = 5, 512 steps",
     lambda: repro("havok_free_body", "free_top_error_n512"),
     lambda: class_error("exec::havok::step", "free_top", "angular velocity", 5 / 512,
                         "engines-havok/engines.json"), 1e-6, True),
    ("jolt-gyroscopic", "Jolt 1.1.0, gyroscopic force on: the free top's energy, largest relative change over 10^4 steps",
     lambda: repro("jolt_gyroscopic", "gyroscopic_energy_max"),
     lambda: engine_scenario("exec::jolt::gyroscopic", "free_top", "engines-jolt/engines.json")["energy_max"],
     1e-6, True),
    ("jolt-gyroscopic", "Jolt 1.1.0, gyroscopic force on: the free top's angular momentum, largest relative change",
     lambda: repro("jolt_gyroscopic", "gyroscopic_momentum_max"),
     lambda: engine_scenario("exec::jolt::gyroscopic", "free_top", "engines-jolt/engines.json")["momentum_max"],
     1e-6, True),
    ("jolt-gyroscopic", "Jolt 1.1.0, its default: the free top's angular momentum, largest relative change",
     lambda: repro("jolt_gyroscopic", "default_momentum_max"),
     lambda: engine_scenario("exec::jolt::default", "free_top", "engines-jolt/engines.json")["momentum_max"],
     1e-6, True),
    ("rapier-free-body", "Rapier 0.21.0: the free top's body angular velocity error at t = 5, 512 steps (truncation)",
     lambda: repro("rapier_free_body", "free_top_error_n512"),
     lambda: class_error("exec::rapier::impulse_joints", "free_top", "angular velocity", 5 / 512,
                         "engines-rapier/engines.json"), 1e-6, True),
    ("rapier-free-body", "Rapier 0.21.0: the same at 16384 steps (its rounding)",
     lambda: repro("rapier_free_body", "free_top_error_n16384"),
     lambda: class_error("exec::rapier::impulse_joints", "free_top", "angular velocity", 5 / 16384,
                         "engines-rapier/engines.json"), 1e-6, True),
    ("rapier-free-body", "Rapier 0.21.0: the free top's energy, largest relative change over 10^4 steps",
     lambda: repro("rapier_free_body", "free_top_energy_max_1e4"),
     lambda: engine_scenario("exec::rapier::impulse_joints", "free_top", "engines-rapier/engines.json")["energy_max"],
     1e-6, True),
    ("simbody-feldberg", "RungeKuttaFeldberg's global order (pendulum)",
     lambda: repro("simbody_orders", "RungeKuttaFeldberg_global_order"),
     lambda: class_fit("simbody::RungeKuttaFeldberg", "pendulum_small", "joint coordinates"), 0.05, False),
    ("simbody-verlet", "Verlet's global order (pendulum)",
     lambda: repro("simbody_orders", "Verlet_global_order"),
     lambda: class_fit("simbody::Verlet", "pendulum_small", "joint coordinates"), 0.05, False),
    ("bullet-inertia", "capsule: largest relative error of the moments",
     lambda: largest_axis_error("bullet_inertia", "capsule"), lambda: shape_error("bullet", "capsule"), 1e-5, False),
    ("bullet-inertia", "cone: largest relative error of the moments",
     lambda: largest_axis_error("bullet_inertia", "cone"), lambda: shape_error("bullet", "cone"), 1e-5, False),
    ("bullet-inertia", "two spheres: largest relative error of the moments",
     lambda: largest_axis_error("bullet_inertia", "two_spheres"), lambda: shape_error("bullet", "two_spheres"), 1e-5, False),
    ("bullet-inertia", "convex hull: largest relative error of the moments",
     lambda: repro("bullet_inertia", "convex_hull_ascending_largest_relative_error"),
     lambda: shape_error("bullet", "convex_hull"), 1e-5, False),
    ("ode-quickstep", "QuickStep (20 iterations): the anchor after one step",
     lambda: repro("ode_quickstep_hinge", "quickstep_20_anchor_after_one_step"),
     lambda: engine_scenario("ode::quickstep", "pendulum_small")["constraint_first_step"]["position"], 1e-3, True),
    ("ode-quickstep", "QuickStep (160 iterations): the anchor after one step",
     lambda: repro("ode_quickstep_hinge", "quickstep_160_anchor_after_one_step"),
     lambda: engine_scenario("ode::quickstep/iterations_160", "pendulum_small")["constraint_first_step"]["position"], 1e-3, True),
    ("bullet-multibody-loop", "the four-bar's loop closure after one step (links with colliders)",
     lambda: repro("bullet_multibody_loop", "colliders_separation_after_one_step"),
     lambda: engine_scenario("bullet::multibody", "four_bar", "engines-loop/engines.json")["constraint_first_step"]["loop"],
     1e-3, True),
    ("arkode-cash", "CASH_5_2_4's error plateau on the oscillator",
     lambda: repro("arkode_dirk_weights", "cash_5_2_4_error_n4096"),
     lambda: problem("double/audit.json", "arkode::ARKODE_CASH_5_2_4", "double", "oscillator")["global_order"]["stall"]["error"], 0.05, True),
    # ARKODE's tables' order conditions, relative to the size of their terms (the one number
    # the audit states for a condition): the audit's exact arithmetic on the stored doubles,
    # printed to two digits, against the reproducer's long double sums: 5 % relative.
    ("arkode-cash", "CASH_5_2_4's embedding: |w . (A 1) - 1/2| / (2 sum |w| (|A| 1))",
     lambda: repro("arkode_dirk_weights", "cash_5_2_4_embedding_order2_relative"),
     lambda: verdict_number("double/audit.json", "arkode::ARKODE_CASH_5_2_4/embedding", "double", "order",
                            r"order 2 (?:only to|fails by)"), 0.05, True),
    ("arkode-billington", "BILLINGTON_3_3_2: |sum(b) - 1| / sum |b|",
     lambda: repro("arkode_dirk_weights", "billington_3_3_2_weight_sum_relative"),
     lambda: verdict_number("double/audit.json", "arkode::ARKODE_BILLINGTON_3_3_2", "double", "order",
                            r"order 1 (?:only to|fails by)|orders 1 to \d+ only to"), 0.05, True),
    ("gsl-rk2", "rk2's propagated order",
     lambda: repro("gsl_step_order", "rk2_propagated_order"),
     lambda: problem("double/audit.json", "gsl::rk2", "double", "oscillator")["global_order"]["fit"]["value"], 0.05, False),
    ("gsl-rk2", "rk2's embedded order",
     lambda: repro("gsl_step_order", "rk2_embedded_order"),
     lambda: problem("double/audit.json", "gsl::rk2/embedding", "double", "oscillator")["global_order"]["fit"]["value"], 0.05, False),
    ("gsl-rk2", "rk2's declared order",
     lambda: repro("gsl_step_order", "rk2_step_order"),
     lambda: stepper("double/audit.json", "gsl::rk2", "double")["declared"]["order"], 0, False),
    ("odeint-velocity-verlet", "velocity_verlet's order_value",
     lambda: repro("odeint_orders", "velocity_verlet_order_value"),
     lambda: stepper("double/audit.json", "odeint::velocity_verlet", "double")["declared"]["order"], 0, False),
    ("odeint-velocity-verlet", "velocity_verlet's global order",
     lambda: repro("odeint_orders", "velocity_verlet_global_order"),
     lambda: problem("double/audit.json", "odeint::velocity_verlet", "double", "oscillator")["global_order"]["fit"]["value"], 0.05, False),
    ("odeint-sb3a", "SB3A's one-step order beyond double",
     lambda: repro("odeint_orders", "sb3a_local_order_cpp_bin_float_50"),
     lambda: problem("mpfr50/audit.json", "odeint::symplectic_rkn_sb3a_mclachlan", "mpfr50", "oscillator")["local_order"]["fit"]["value"], 0.05, False),
    # A box given without a mass: the mass and largest moment each engine gives it, read by the
    # same calls in both (Rapier's and Jolt's in float, printed to 7 digits: 1e-6); Havok's
    # read-back held against its dynamics (a linear impulse of 1 changes v by 1/m).
    *[(f"shape-alone-{name}", f"{name}: the mass of a box given without one",
       (lambda program=program: repro(program, "box_alone_mass")),
       (lambda engine_name=engine_name, report=report: alone(engine_name, report, "mass")), tol, tol > 0)
      for name, program, engine_name, report, tol in [
          ("rapier", "rapier_free_body", "exec::rapier", "engines-rapier/engines.json", 1e-6),
          ("jolt", "jolt_gyroscopic", "exec::jolt", "engines-jolt/engines.json", 1e-6),
          ("havok", "havok_free_body", "exec::havok", "engines-havok/engines.json", 1e-6),
          ("mujoco_wasm", "mujoco_wasm_fullinertia", "exec::mujoco_wasm", "engines-wasm/engines.json", 1e-6),
          ("cannon_es", "cannon_free_body", "exec::cannon_es", "engines-cannon/engines.json", 0)]],
    *[(f"shape-alone-{name}", f"{name}: the largest moment of a box given without a mass",
       (lambda program=program: repro(program, "box_alone_moment_max")),
       (lambda engine_name=engine_name, report=report: alone(engine_name, report, "moment")), 1e-6, True)
      for name, program, engine_name, report in [
          ("rapier", "rapier_free_body", "exec::rapier", "engines-rapier/engines.json"),
          ("jolt", "jolt_gyroscopic", "exec::jolt", "engines-jolt/engines.json"),
          ("havok", "havok_free_body", "exec::havok", "engines-havok/engines.json"),
          ("mujoco_wasm", "mujoco_wasm_fullinertia", "exec::mujoco_wasm", "engines-wasm/engines.json")]],
    ("havok-pendulum", "Havok 1.3.14: pendulum_small's swing energy lost, at most, over 10^4 steps of 0.01",
     lambda: repro("havok_free_body", "pendulum_small_h0.01_swing_energy_lost_max"),
     lambda: engine_scenario("exec::havok::step", "pendulum_small", "engines-havok/engines.json")["energy_max"],
     1e-5, True),
    # The rigid-body scenarios in Rapier, Jolt, Havok and cannon-es (<engine>_scenarios.mjs): the same setup
    # stepped the same way in both, 10^5 steps, each solver setting the audit's integrator of that name; the
    # reproducer's numbers printed to 7 digits, the measures' double arithmetic in another order (1e-8 of the
    # smallest, Jolt's energy error of 7.9e-9): 1e-6.
    *[(f"{engine}-scenarios", f"{engine}: {scenario}'s largest {what} over 10^5 steps, {setting}" +
       (" (a run MuJoCo stops: the step it stops at for the energy's, its warning's number for the others')"
        if engine == "mujoco_wasm" else ""),
       (lambda program=f"{engine}_scenarios", prefix=f"{scenario}_{setting}", field=field:
        repro_long_run(program, prefix, field)),
       (lambda integrator=f"exec::{client}::{setting}", scenario=scenario, report=f"{report}/engines.json",
        field=field: long_run(integrator, scenario, report, field)), 1e-6, True)
      for engine, client, setting, names, report in SCENARIO_RUNS
      for scenario in names
      for field, what in measured(scenario)],
    # The free bodies', the pendulums', the chains', the projectile's, Kepler's and the three bodies' order studies:
    # each class's error at t_end at every n the audit ran, held point by point (the largest relative difference of
    # the series, its errors printed to 7 digits): 1e-6, beside the references' floor below.
    *[(f"{engine}-scenarios", f"{engine}: {scenario}'s {name} error at t_end, every n, {setting}",
       (lambda a=(f"exec::{client}::{setting}", scenario, name, f"{report}/engines.json", f"{engine}_scenarios",
                  f"{scenario}_{setting}"): [r for r, _ in study_series(*a)]),
       (lambda a=(f"exec::{client}::{setting}", scenario, name, f"{report}/engines.json", f"{engine}_scenarios",
                  f"{scenario}_{setting}"): [b for _, b in study_series(*a)]), 1e-6, True)
      for engine, client, setting, names, report in SCENARIO_RUNS
      for scenario in names
      for name in study_classes(scenario)],
    # The JavaScript engines' shapes of mass 2 (<engine>_scenarios.mjs' shape lines): the same calls, the largest
    # relative error of the moments against exact ones in double (the audit's in mpfr50), printed to 7 digits: 1e-6,
    # beside the 64 eps floor of the exact moments' rounding (cannon-es's box, 1.4e-16).
    *[(f"{engine}-shapes", f"{engine}: the {shape}'s moments, largest relative error",
       (lambda program=f"{engine}_scenarios", key=f"shape_{shape}_largest_relative_error": repro(program, key)),
       (lambda engine_name=f"exec::{client}", shape=shape, report=f"scenarios-{engine}/engines.json":
        shape_error(engine_name, shape, report)), 1e-6, True)
      for engine, client, offered in [
          ("rapier", "rapier", ["box", "sphere", "cylinder", "capsule", "cone", "two_spheres", "convex_hull"]),
          ("jolt", "jolt", ["box", "sphere", "cylinder", "capsule", "cone", "two_spheres", "convex_hull"]),
          ("havok", "havok", ["box", "sphere", "cylinder", "capsule", "two_spheres", "convex_hull"]),
          ("cannon", "cannon_es", ["box", "sphere", "cylinder", "two_spheres", "convex_hull"])]
      for shape in offered],
    *[("mujoco_wasm-shapes", f"MuJoCo 3.14.0 (WebAssembly): the {shape}'s moments, largest relative error",
       (lambda key=f"shape_{shape}_largest_relative_error": repro("mujoco_wasm_fullinertia", key)),
       (lambda shape=shape: shape_error("exec::mujoco_wasm", shape, "engines-wasm/engines.json")), 1e-6, True)
      for shape in ["box", "sphere", "cylinder", "capsule", "ellipsoid", "two_spheres", "convex_hull"]],
    ("havok-convex-hull", "Havok 1.3.14: a convex hull's moments (the tetrahedron), largest relative error",
     lambda: repro("havok_free_body", "convex_hull_x1_moment_largest_relative_error"),
     lambda: shape_error("exec::havok", "convex_hull", "engines-havok/engines.json"), 1e-5, True),
    ("cannon-free-body", "cannon-es: a ConvexPolyhedron's moments (the tetrahedron), largest relative error",
     lambda: repro("cannon_free_body", "convex_hull_largest_relative_error"),
     lambda: shape_error("exec::cannon_es", "convex_hull", "engines-cannon/engines.json"), 1e-5, True),
    ("shape-alone-havok", "Havok: the mass its dynamics show for a box given without one (1 / dv of a unit impulse)",
     lambda: 1 / repro("havok_free_body", "box_alone_impulse_dv"),
     lambda: alone("exec::havok", "engines-havok/engines.json", "mass"), 1e-6, True),
    ("drivers-horizon", "rk8pd: error/tol after one period",
     lambda: repro("gsl_driver_horizon", "rk8pd_error_over_tol_after_1_periods"),
     lambda: horizon("gsl::driver_rk8pd", 1), 1e-3, True),
    ("drivers-horizon", "rk8pd: error/tol after 64 periods",
     lambda: repro("gsl_driver_horizon", "rk8pd_error_over_tol_after_64_periods"),
     lambda: horizon("gsl::driver_rk8pd", 64), 1e-3, True),
]

failed = skipped = 0
for finding, what, ours, theirs, tolerance, relative in CHECKS:
    try:
        a = ours()
    except FileNotFoundError as e:
        # A library not found at configure time has no reproducer (and no audit): skipped.
        print(f"skipped   {finding:24s} {what}: {e}")
        skipped += 1
        continue
    except KeyError as e:
        print(f"MISSING   {finding:24s} {what}: {e}")
        failed += 1
        continue
    try:
        b = theirs()
    except (KeyError, OSError) as e:
        print(f"MISSING   {finding:24s} {what}: {e}")
        failed += 1
        continue
    # A series (an order study's points) is held point by point: its largest difference, at the point shown.
    series = list(zip(a, b)) if isinstance(a, list) else [(a, b)]
    if isinstance(a, list) and (len(a) != len(b) or not a):
        print(f"MISSING   {finding:24s} {what}: {len(a)} points against the audit's {len(b)}")
        failed += 1
        continue
    # An order study's errors are relative to the scenario's scale; the reproducer's RK4 reference is within 1e-11
    # of the audit's exact one (its change from h = 2e-4 to 1e-4, 15 times its own error, is 2.6e-11 at most:
    # chain5's), so a difference below 1e-11 is the references' (an engine in double at its rounding: the
    # projectile's velocity, 2.8e-16).
    # A long run's largest change is computed from the same frames by both, in double, the sums in another order: a
    # difference below 64 eps of the scale is that rounding's (cannon-es's three bodies' angular momentum, 2.6e-14).
    floor = 1e-11 if isinstance(a, list) else 64 * 2.0**-52 if finding.endswith(("-scenarios", "-shapes")) else 0
    diffs = [0 if abs(x - y) <= floor else abs(x - y) / (abs(y) if relative and y != 0 else 1) for x, y in series]
    worst = max(range(len(diffs)), key=lambda i: diffs[i] if math.isfinite(diffs[i]) else math.inf)
    (a, b), diff = series[worst], diffs[worst]
    ok = all(math.isfinite(x) and math.isfinite(y) for x, y in series) and diff <= tolerance
    failed += 0 if ok else 1
    points = f" ({len(series)} points, the worst)" if len(series) > 1 else ""
    print(f"{'agrees   ' if ok else 'DISAGREES'} {finding:24s} {what}: reproducer {a:.6g}, audit {b:.6g}{points} "
          f"({'relative ' if relative else ''}difference {diff:.2g}, tolerance {tolerance:g})")
print(f"agreement: {len(CHECKS) - failed - skipped} of {len(CHECKS)} pairs within their tolerance, "
      f"{failed} not, {skipped} skipped (library not found)")
sys.exit(1 if failed else 0)
