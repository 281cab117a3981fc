// havok_scenarios.mjs -- the audit's rigid-body scenarios (scenarios.mjs: the pendulums, the heavy top, the double
// pendulum, chain5, the four-bar loop, the free bodies) in Havok (@babylonjs/havok, single precision WASM): a DYNAMIC
// body a body with a 0.1 m sphere shape, its mass properties by HP_Body_SetMassProperties (centre of mass at its
// origin, the mass, the principal moments divided by the mass: "Inertia for mass of 1"), damping 0, ALWAYS_ACTIVE,
// started at its pose and velocity; a joint an HP_Constraint locking its three linear axes (a ball) and, for a hinge
// about world y, its angular Y and Z (its X along world y, its Y along world x), the anchors in each body's frame at
// the start, to a STATIC body at the origin or between links (the four-bar's loop: the ground the parent, the rocker
// the child); the world's gravity the scenario's (9.81 along -z, or none). Kepler's central force as the impulse F h at
// the centre of mass before each step (Havok takes no force). 1e5 steps of HP_World_Step(h), the ideal step time set to
// h before each (h 0.01; the heavy top's 0.002, the boxes' 0.0025, the projectile's 1e-4). Printed for each: the
// largest anchor and loop separations (m), or angular momentum change, and energy change (scenarios.mjs's longRun); a
// free body's or pendulum's order study besides (scenarios.mjs's orderStudy: each class's error at tEnd in n = steps0
// .. 16384 steps).
// Run: node havok_scenarios.mjs PATH/TO/node_modules/@babylonjs/havok
// Output: lines "name value". Uses only Havok and plain JavaScript.
import { readFileSync } from 'fs';
import { pathToFileURL } from 'url';
import { SHAPE_MASS, bodiesAtStart, centralForce, gravitation, hullPoints, longRun, orderStudy, parts, shapeLines, quaternionOf, rotateBack, rotationOf, scenarios, sub } from './scenarios.mjs';
const dir = process.argv[2];
if (!dir) { console.error('usage: node havok_scenarios.mjs PATH/TO/node_modules/@babylonjs/havok'); process.exit(1); }
const pkg = JSON.parse(readFileSync(dir + '/package.json', 'utf8'));
const HavokPhysics = (await import(pathToFileURL(dir + '/lib/esm/HavokPhysics_es.js').href)).default;
const wasmBinary = readFileSync(dir + '/lib/esm/HavokPhysics.wasm');
console.log('havok_version', pkg.version);
/** The value of a Havok call that returns [result, value], its result checked. */
let RESULT_OK;
const ck = (r) => {
  const result = Array.isArray(r) ? r[0] : r;
  if (result?.value !== RESULT_OK.value) throw new Error(`a Havok call returned ${result?.value}`); // enums: each instance's own
  return Array.isArray(r) ? r[1] : r;
};

// Each world in a Havok instance of its own: a run's last digits depend on what its instance ran before (the
// four-bar after the five other jointed scenarios' worlds were built in one instance: its largest anchor separation
// 6.489966e-3 m, 6.473416e-3 in a fresh one; the four_bar_after_five_worlds lines below).
async function world(s, h = s.h, instance = null) {
  const H = instance ?? (await HavokPhysics({ wasmBinary }));
  RESULT_OK = H.Result.RESULT_OK;
  const w = ck(H.HP_World_Create());
  ck(H.HP_World_SetGravity(w, [0, 0, -s.gravity]));
  const shape = ck(H.HP_Shape_CreateSphere([0, 0, 0], 0.1));
  const make = (dynamic, mass, inertia, rotation, x, v, omega) => {
    const b = ck(H.HP_Body_Create());
    ck(H.HP_Body_SetShape(b, shape));
    ck(H.HP_Body_SetMotionType(b, dynamic ? H.MotionType.DYNAMIC : H.MotionType.STATIC));
    if (dynamic) {
      ck(H.HP_Body_SetMassProperties(b, [[0, 0, 0], mass, inertia.map((i) => i / mass), [0, 0, 0, 1]]));
      ck(H.HP_Body_SetLinearDamping(b, 0));
      ck(H.HP_Body_SetAngularDamping(b, 0));
    }
    const q = quaternionOf(rotation);
    ck(H.HP_Body_SetQTransform(b, [x, [q.x, q.y, q.z, q.w]]));
    ck(H.HP_World_AddBody(w, b, false));
    if (dynamic) {
      ck(H.HP_Body_SetActivationControl(b, H.ActivationControl.ALWAYS_ACTIVE));
      ck(H.HP_Body_SetLinearVelocity(b, v));
      ck(H.HP_Body_SetAngularVelocity(b, omega));
    }
    return { id: b, rotation, x };
  };
  let ground = null;
  const fixed = () => (ground ??= make(false, 0, [0, 0, 0], [1, 0, 0, 0, 1, 0, 0, 0, 1], [0, 0, 0], [0, 0, 0], [0, 0, 0]));
  const joint = (point, parent, child, hinge) => {
    const c = ck(H.HP_Constraint_Create());
    ck(H.HP_Constraint_SetParentBody(c, parent.id));
    ck(H.HP_Constraint_SetChildBody(c, child.id));
    for (const [set, b] of [[H.HP_Constraint_SetAnchorInParent, parent], [H.HP_Constraint_SetAnchorInChild, child]])
      ck(set(c, rotateBack(b.rotation, sub(point, b.x)), rotateBack(b.rotation, [0, 1, 0]), rotateBack(b.rotation, [1, 0, 0])));
    const locked = [H.ConstraintAxis.LINEAR_X, H.ConstraintAxis.LINEAR_Y, H.ConstraintAxis.LINEAR_Z];
    if (hinge) locked.push(H.ConstraintAxis.ANGULAR_Y, H.ConstraintAxis.ANGULAR_Z);
    for (const axis of locked) ck(H.HP_Constraint_SetAxisMode(c, axis, H.ConstraintAxisLimitMode.LOCKED));
    ck(H.HP_Constraint_SetEnabled(c, 1));
  };
  const of = parts(s), made = [];
  // Each body made, then its joint to its parent (the static body made at the first joint, after the first body).
  bodiesAtStart(s).forEach((start, k) => {
    const b = make(true, of[k].mass, of[k].inertia, start.rotation, start.x, start.v, start.w);
    made.push(b);
    if (s.joint !== 'free') joint(start.pivot, k === 0 ? fixed() : made[k - 1], b, s.joint !== 'ball');
  });
  if (s.loop) joint(s.loop.anchor, fixed(), made[made.length - 1], true);
  return {
    step() {
      ck(H.HP_World_SetIdealStepTime(w, h));
      // Havok takes no force: the impulse F h at the centre of mass.
      const at = (k) => ck(H.HP_Body_GetQTransform(made[k].id))[0];
      const push = (k, f) => ck(H.HP_Body_ApplyImpulse(made[k].id, at(k), f.map((x) => x * h)));
      if (s.central) push(0, centralForce(s, at(0)));
      for (const [a, c, f] of s.gravitation ? gravitation(s, made.map((b, k) => at(k))) : []) {
        push(a, f);
        push(c, f.map((x) => -x));
      }
      ck(H.HP_World_Step(w, h));
    },
    frames: () => made.map((b) => {
      const [x, [qx, qy, qz, qw]] = ck(H.HP_Body_GetQTransform(b.id));
      return { rotation: rotationOf({ x: qx, y: qy, z: qz, w: qw }), x, v: ck(H.HP_Body_GetLinearVelocity(b.id)),
               w: ck(H.HP_Body_GetAngularVelocity(b.id)) };
    }),
    free: () => ck(H.HP_World_Release(w)),
  };
}

for (const [name, s] of Object.entries(scenarios)) {
  const w = await world(s);
  longRun(`${name}_step`, s, w, 100000);
  w.free();
  await orderStudy(`${name}_step`, name, s, (h) => world(s, h));
}
// The history: the four-bar in an instance that has built the five other jointed scenarios' worlds before it
// (built and released, not stepped).
{
  const H = await HavokPhysics({ wasmBinary });
  for (const name of ['pendulum_small', 'pendulum_large', 'heavy_top', 'double_pendulum', 'chain5']) (await world(scenarios[name], 0.01, H)).free();
  const w = await world(scenarios.four_bar, 0.01, H);
  longRun('four_bar_after_five_worlds_step', scenarios.four_bar, w, 100000);
  w.free();
}

// The shapes: HP_Shape_BuildMassProperties (its inertia "for mass of 1") times 2; the axis (z) the cylinder's and the
// capsule's; the hull's points in the WebAssembly heap (_malloc), as its declarations ask. No cone.
{
  const H = await HavokPhysics({ wasmBinary });
  RESULT_OK = H.Result.RESULT_OK;
  shapeLines((name, [a, b, c]) => {
    let shape;
    if (name === 'box') shape = ck(H.HP_Shape_CreateBox([0, 0, 0], [0, 0, 0, 1], [a, b, c]));
    else if (name === 'sphere') shape = ck(H.HP_Shape_CreateSphere([0, 0, 0], a));
    else if (name === 'cylinder') shape = ck(H.HP_Shape_CreateCylinder([0, 0, -b / 2], [0, 0, b / 2], a));
    else if (name === 'capsule') shape = ck(H.HP_Shape_CreateCapsule([0, 0, -b / 2], [0, 0, b / 2], a));
    else if (name === 'two_spheres') {
      shape = ck(H.HP_Shape_CreateContainer());
      for (const x of [b, -b]) ck(H.HP_Shape_AddChild(shape, ck(H.HP_Shape_CreateSphere([0, 0, 0], a)), [[x, 0, 0], [0, 0, 0, 1], [1, 1, 1]]));
    } else if (name === 'convex_hull') {
      const points = hullPoints([a, b, c]).flat(), at = H._malloc(4 * points.length);
      new Float32Array(H.HEAPU8.buffer, at, points.length).set(points);
      shape = ck(H.HP_Shape_CreateConvexHull(at, points.length / 3));
      H._free(at);
    } else return null;
    return ck(H.HP_Shape_BuildMassProperties(shape))[2].map((i) => i * SHAPE_MASS);
  });
}
