#!/usr/bin/env bash
# The command's behaviour towards a newcomer (ctest: cli.command): names are checked and the
# valid ones listed, the report goes where -o says, a batch goes on past a bad input and the
# exit status says so, --list lists every kind, --help names the installed tableaus.
# Usage: command_test.sh MECHCHECK_AUDIT SOURCE_DIR EXEC_CHILD EXEC_DYNAMICS_CHILD
set -uo pipefail
audit=$1
source_dir=$2
child=$3
dynamics_child=$4
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failed=0
# expect STATUS REGEX ARGS...: the command exits with STATUS and its output matches REGEX.
expect() {
  local status=$1 regex=$2
  shift 2
  local out got begin=$SECONDS
  out=$("$audit" "$@" 2>&1)
  got=$?
  if [ "$got" != "$status" ] || ! grep -Eq -- "$regex" <<< "$out"; then
    echo "FAILED: mechcheck-audit $*"
    echo "  expected status $status and /$regex/; got status $got and:"
    sed 's/^/    /' <<< "$out" | tail -n 8
    failed=1
  else
    echo "ok: mechcheck-audit $* (status $got, $(( SECONDS - begin )) s)"
  fi
}

# Names: a misspelt stepper, driver, engine, problem or scenario is an error naming what there is.
expect 1 "'odient::\*' matches no stepper; this build has [0-9]+ of them, named mechcheck::\*, odeint::\*" \
  -s 'odient::*' -o "$work/a"
expect 1 "matches no adaptive driver.*odeint::\*" --driver 'gls::*' -o "$work/a"
expect 1 "matches no engine integrator" --engine 'mujuco::*' -o "$work/a"
expect 1 "scenario free_tpo names no scenario \(known: free_top" --engine '*' --scenario free_tpo -o "$work/a"
expect 105 "kepler_e05 not in .*kepler_e0.5" -p kepler_e05 -o "$work/a"
[ -e "$work/a" ] && { echo "FAILED: a refused command wrote $work/a"; failed=1; }
# The report goes where -o says; without -o nothing is written anywhere.
(cd "$work" && expect 1 "say where the report goes: -o DIR" -t double -s mechcheck::rk4 -p oscillator)
[ -z "$(ls -A "$work")" ] || { echo "FAILED: a command without -o wrote into the current directory"; failed=1; }
# A batch goes on: a bad tableau file among good ones is a row of the report, the others are
# audited, and the status says that something failed.
printf '{"A": [["0"]], "b": ["1"], "c": ["0"]}' > "$work/euler.json"
printf '{"A": [["0", "0"]], "b": ["1"], "c": ["0"]}' > "$work/wrong.json"
expect 1 "wrote .*tableaus.md" --tableau "$work/euler.json" --tableau "$work/wrong.json" \
  --tableau "$work/missing.json" -t double -p oscillator --long-run-steps 0 -q -o "$work/batch"
grep -q "| euler | 1 | explicit" "$work/batch/tableaus.md" && grep -q "| wrong | - | FAILED: .*A\[0\] has 2 entries" \
  "$work/batch/tableaus.md" && grep -q "| missing | - | FAILED: .*cannot be read" "$work/batch/tableaus.md" &&
  grep -q "tableau::euler" "$work/batch/audit.md" || { echo "FAILED: the batch's report lacks a row"; failed=1; }
# --require sees a tableau file's algebraic claims: Heun's method declaring stage order 2
# (its C(2) fails: a_21 c_1 = 0, not c_2^2/2) exits 2 naming the claim; declaring 1, 0. A
# misspelt claim is an error naming the field.
printf '{"A": [["0","0"],["1","0"]], "b": ["1/2","1/2"], "c": ["0","1"], "order": 2, "stage_order": 2}' > "$work/heun.json"
expect 2 "tableau::heun .*stage order declared 2 is contradicted" --tableau "$work/heun.json" --require '*' \
  -t double -p oscillator --long-run-steps 0 -q -o "$work/heun"
printf '{"A": [["0","0"],["1","0"]], "b": ["1/2","1/2"], "c": ["0","1"], "order": 2, "stage_order": 1}' > "$work/heun.json"
expect 0 "audited 1 stepper-tier pairs" --tableau "$work/heun.json" --require '*' \
  -t double -p oscillator --long-run-steps 0 -q -o "$work/heun"
printf '{"A": [["1/2"]], "b": ["1"], "c": ["1/2"], "symplectc": true}' > "$work/typo.json"
expect 1 "has the field \"symplectc\", which a tableau file does not have .*symplectic" --tableau "$work/typo.json" \
  -t double -p oscillator --long-run-steps 0 -q -o "$work/typo"
# Random robots as engine scenarios: each one's URDF goes with the report, for the engines'
# own loaders.
expect 0 "audited [0-9]+ engine integrators" --engine '*' --engine-robots 1 --engine-robot-links 1 \
  --scenario 'robot_*' --engine-long-run-steps 100 -q -o "$work/robots"
grep -q '<robot name="robot_1_0">' "$work/robots/robots/robot_1_0.urdf" ||
  { echo "FAILED: --engine-robots wrote no robots/robot_1_0.urdf"; failed=1; }
# Random robots on a floating base: their URDF (a floating joint from "world") with the report.
expect 0 "audited [0-9]+ engine integrators" --engine '*' --engine-floating-robots 1 --engine-robot-links 1 \
  --scenario 'floating_*' --engine-long-run-steps 100 -q -o "$work/floating"
grep -q 'type="floating"' "$work/floating/robots/floating_1_0.urdf" ||
  { echo "FAILED: --engine-floating-robots wrote no floating robots/floating_1_0.urdf"; failed=1; }
# Random free bodies: named by their seed, described in the report (principal axes turned,
# the body angular velocity drawn).
expect 0 "audited [0-9]+ engine integrators" --engine '*' --engine-bodies 2 --seed 3 --scenario 'body_*' \
  --engine-long-run-steps 100 -q -o "$work/bodies"
grep -q '"scenario": "body_3_1"' "$work/bodies/engines.json" ||
  { echo "FAILED: --engine-bodies 2 --seed 3 audited no body_3_1"; failed=1; }
expect 1 "names no scenario" --engine '*' --engine-bodies 1 --scenario 'body_2_*' -q -o "$work/bodies"
# --require-measured: a child that refuses the scenario asked for (the test engine builds hinge
# pendulums only) measured nothing and fails the gate, naming the scenario and its words; on a
# pendulum it passes. Without the flag the refusal is a row of the report, status 0.
expect 2 "exec::test_engine/engine::euler: not measured: free_top: refused: this engine builds hinge pendulums only" \
  --exec-engine --scenario free_top --engine-long-run-steps 0 --require-measured '*' -q -o "$work/refuses" -- "$child" engine
expect 0 "audited 3 engine integrators" --exec-engine --scenario free_top --engine-long-run-steps 0 -q \
  -o "$work/refuses" -- "$child" engine
expect 0 "audited 3 engine integrators" --exec-engine --scenario pendulum_small --engine-long-run-steps 1000 \
  --require-measured '*' -q -o "$work/measures" -- "$child" engine
grep -q '"scenario": "pendulum_small"' "$work/measures/engines.json" ||
  { echo "FAILED: the measured run's report lacks its scenario"; failed=1; }
# The equations of motion: random robots, a user's URDF, a file that is not one.
expect 1 "--dynamics matches no dynamics library" --dynamics 'kld' -o "$work/d"
expect 0 "mass matrix .* within" --dynamics '*' --robots 20 -q --require '*' -o "$work/d"
expect 0 "on arm .*forward dynamics .* within" --dynamics '*' --urdf "$source_dir/examples/robots/arm.urdf" --robots 20 -q \
  -o "$work/d"
printf '<robot name="r"><link name="a"/><joint name="j" type="planar"/></robot>' > "$work/bad.urdf"
expect 1 "bad.urdf: robot r: joint j: type planar is not modelled" --dynamics '*' --urdf "$work/bad.urdf" -o "$work/d"
# A floating base (a floating joint from the world): MuJoCo holds it through its freejoint, KDL refuses it by name.
printf '<robot name="r"><link name="world"/><link name="a"><inertial><origin xyz="0.1 0 0"/><mass value="2"/><inertia ixx="0.1" ixy="0" ixz="0" iyy="0.2" iyz="0" izz="0.25"/></inertial></link><link name="b"><inertial><mass value="1"/><inertia ixx="0.1" ixy="0" ixz="0" iyy="0.1" iyz="0" izz="0.1"/></inertial></link><joint name="free" type="floating"><parent link="world"/><child link="a"/></joint><joint name="j" type="continuous"><parent link="a"/><child link="b"/><origin xyz="0 0 -0.5"/><axis xyz="0 1 0"/></joint></robot>' > "$work/floating.urdf"
expect 0 "kdl on r refused 10 of 10 .*KDL has no floating base" --dynamics '*' --urdf "$work/floating.urdf" --robots 10 -q -o "$work/d"
# A user's file as ROS reads it: a moving joint that carries no mass is refused by name
# before any library runs; a joint without <axis> takes URDF's default, and the report says so.
printf '<robot name="r"><link name="a"/><link name="b"/><joint name="j" type="continuous"><parent link="a"/><child link="b"/><axis xyz="0 0 1"/></joint></robot>' > "$work/massless.urdf"
expect 1 "massless.urdf: robot r: joint j moves link b, which carries no mass" --dynamics '*' --urdf "$work/massless.urdf" -o "$work/d"
inertial='<inertial><mass value="1"/><inertia ixx="0.1" ixy="0" ixz="0" iyy="0.2" iyz="0" izz="0.25"/></inertial>'
printf '<robot name="r"><link name="a"/><link name="b">%s</link><link name="c">%s</link><link name="d">%s</link>
<joint name="j" type="continuous"><parent link="a"/><child link="b"/><origin xyz="0 0 0.5"/></joint>
<joint name="k" type="continuous"><parent link="b"/><child link="c"/><origin xyz="0.5 0 0"/><axis xyz="0 1 0"/></joint>
<joint name="l" type="continuous"><parent link="b"/><child link="d"/><origin xyz="0 0.5 0"/><axis xyz="0 0 1"/></joint>
</robot>' "$inertial" "$inertial" "$inertial" > "$work/tree.urdf"
expect 0 "reading: .*tree.urdf: robot r: joint j: no axis given: URDF's default \(1, 0, 0\)" --dynamics '*' \
  --urdf "$work/tree.urdf" --robots 5 -q -o "$work/d"
grep -q "Reading: .*joint j: no axis given" "$work/d/dynamics.md" ||
  { echo "FAILED: dynamics.md does not say the default axis it took"; failed=1; }
# --require on a library that checked nothing (it refused every state of the robot) fails.
expect 2 "checked nothing \(it refused 5 of 5 states; the first: .*a tree" --urdf "$work/tree.urdf" --robots 5 -q \
  --require 'exec::*' -o "$work/d" --exec-dynamics -- "$dynamics_child" refuse_trees
# --list names every kind; --help names the tableaus.
for section in "steppers \([0-9]+;" "adaptive drivers \([0-9]+;" "engine integrators \([0-9]+;" \
               "engine scenarios \(25;" "problems \([0-9]+;" "dynamics libraries \([0-9]+;"; do
  expect 0 "^$section" --list
done
expect 0 "The classical tableaus \(--tableau\): .*tableaus" --help
# --help names every claim a tableau file may declare -- the fields the reader knows (its
# error for an unknown one lists them), less those that are not claims -- in --require's
# words and the exit status's.
fields=$("$audit" --tableau "$work/typo.json" -t double -p oscillator --long-run-steps 0 -q -o "$work/typo" 2>&1 |
         sed -n 's/.*(its fields: \([^)]*\)).*/\1/p' | head -n 1 | tr -d ',')
[ -n "$fields" ] || { echo "FAILED: the tableau reader's error lists no fields"; failed=1; }
help=$("$audit" --help | tr -s ' \n' ' ')
for field in $fields; do
  case $field in name|source|A|b|c|bhat|precision) continue ;; esac
  [ "$(grep -o "($field)" <<< "$help" | wc -l)" -ge 2 ] ||
    { echo "FAILED: --help does not name the claim $field in --require and the exit status"; failed=1; }
done
# A declared "no" states absence: Radau IIA 3 declared not L-stable (it is) is contradicted,
# and --require fails on it.
sed 's/^{/{"L_stable": false, /' "$source_dir/tableaus/radau_iia3.json" > "$work/radau.json"
expect 2 "tableau::radau_iia3 .*L-stable declared no is contradicted" --tableau "$work/radau.json" --require '*' \
  -t double -p oscillator --long-run-steps 0 -q -o "$work/radau"
exit $failed
