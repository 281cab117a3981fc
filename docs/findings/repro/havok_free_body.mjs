// havok_free_body.mjs -- torque-free rigid body in Havok (@babylonjs/havok), checked against Euler's equations.
// A body with principal moments I = (1, 2, 3), mass 1, no gravity, zero damping, ALWAYS_ACTIVE, identity
// orientation, angular velocity (1, 0.2, 0.5) rad/s (Havok's angular velocity is world-frame), is stepped
// with HP_World_Step. Printed: world angular momentum drift L = R diag(I) R^T w over 1e4 steps of 0.01,
// world angular velocity drift, body angular velocity error at t = 5 after 512 steps vs an RK4 reference,
// an impulse check of whether the inertia argument of HP_Body_SetMassProperties is scaled by mass, and
// what a body given a box shape and no HP_Body_SetMassProperties gets (read back, and by impulses).
// Run: node havok_free_body.mjs PATH/TO/node_modules/@babylonjs/havok
// Output: lines "name value". Uses only Havok and plain JavaScript.
import { readFileSync } from 'fs';
import { pathToFileURL } from 'url';
const dir = process.argv[2];
if (!dir) { console.error('usage: node havok_free_body.mjs PATH/TO/node_modules/@babylonjs/havok'); process.exit(1); }
const pkg = JSON.parse(readFileSync(dir + '/package.json', 'utf8'));
const HavokPhysics = (await import(pathToFileURL(dir + '/lib/esm/HavokPhysics_es.js').href)).default;
const H = await HavokPhysics({ wasmBinary: readFileSync(dir + '/lib/esm/HavokPhysics.wasm') });
const OK = H.Result.RESULT_OK;
const ck = (r) => { const res = Array.isArray(r) ? r[0] : r; if (res !== OK) throw new Error('Havok call failed'); return Array.isArray(r) ? r[1] : r; };

const I = [1, 2, 3], W0 = [1, 0.2, 0.5];
const norm = (v) => Math.hypot(v[0], v[1], v[2]);
const sub = (a, b) => [a[0] - b[0], a[1] - b[1], a[2] - b[2]];
function rotOf([x, y, z, w]) { // rotation matrix (rows) of unit quaternion [x, y, z, w]
  return [[1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
          [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
          [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)]];
}
const mul = (R, v) => R.map((r) => r[0] * v[0] + r[1] * v[1] + r[2] * v[2]);
const mulT = (R, v) => [0, 1, 2].map((j) => R[0][j] * v[0] + R[1][j] * v[1] + R[2][j] * v[2]);

// One world per body, so bodies never touch each other.
// Its ideal step time set to the step taken (the default is 1/60 s), as the audit's client does.
function makeFreeBody(mass, inertia, omega, q = [0, 0, 0, 1], h = 0.01) {
  const world = ck(H.HP_World_Create());
  ck(H.HP_World_SetIdealStepTime(world, h));
  ck(H.HP_World_SetGravity(world, [0, 0, 0]));
  const body = ck(H.HP_Body_Create());
  ck(H.HP_Body_SetShape(body, ck(H.HP_Shape_CreateSphere([0, 0, 0], 0.1))));
  ck(H.HP_Body_SetMotionType(body, H.MotionType.DYNAMIC));
  ck(H.HP_Body_SetMassProperties(body, [[0, 0, 0], mass, inertia, [0, 0, 0, 1]]));
  ck(H.HP_Body_SetLinearDamping(body, 0));
  ck(H.HP_Body_SetAngularDamping(body, 0)); // default is 0.1
  ck(H.HP_Body_SetQTransform(body, [[0, 0, 0], q]));
  ck(H.HP_World_AddBody(world, body, false));
  ck(H.HP_Body_SetActivationControl(body, H.ActivationControl.ALWAYS_ACTIVE));
  ck(H.HP_Body_SetLinearVelocity(body, [0, 0, 0]));
  ck(H.HP_Body_SetAngularVelocity(body, omega));
  return { world, body };
}
const state = (body) => {
  const R = rotOf(ck(H.HP_Body_GetQTransform(body))[1]);
  const w = ck(H.HP_Body_GetAngularVelocity(body)); // world frame
  const Wb = mulT(R, w); // body frame
  return { w, Wb, L: mul(R, Wb.map((x, i) => I[i] * x)) };
};

console.log('havok_version', pkg.version);

// Run 1: 1e4 steps of h = 0.01 (t = 0.01 .. 100).
{
  const { world, body } = makeFreeBody(1, I, W0);
  const mp = ck(H.HP_Body_GetMassProperties(body));
  console.log('mass_readback', mp[1]);
  console.log('inertia_readback', mp[2].join(','));
  console.log('inertia_orientation_readback', mp[3].join(','));
  console.log('angular_damping_readback', ck(H.HP_Body_GetAngularDamping(body)));
  const s0 = state(body);
  let dL = 0, dw = 0;
  for (let n = 1; n <= 10000; n++) {
    ck(H.HP_World_Step(world, 0.01));
    const s = state(body);
    dL = Math.max(dL, norm(sub(s.L, s0.L)) / norm(s0.L));
    dw = Math.max(dw, norm(sub(s.w, s0.w)) / norm(s0.w));
  }
  console.log('free_top_momentum_max', dL.toExponential(6));
  console.log('free_top_world_omega_change_max', dw.toExponential(6));
  console.log('free_top_omega_body_t100', state(body).Wb.map((x) => x.toFixed(6)).join(','));
}

// Reference: classical RK4 on Euler's equations I W' = (I W) x W, body frame.
function eulerRK4(W, T, n) {
  const h = T / n;
  const f = ([a, b, c]) => [(I[1] - I[2]) * b * c / I[0], (I[2] - I[0]) * c * a / I[1], (I[0] - I[1]) * a * b / I[2]];
  const ax = (u, k, s) => u.map((x, i) => x + s * k[i]);
  for (let i = 0; i < n; i++) {
    const k1 = f(W), k2 = f(ax(W, k1, h / 2)), k3 = f(ax(W, k2, h / 2)), k4 = f(ax(W, k3, h));
    W = W.map((x, j) => x + (h / 6) * (k1[j] + 2 * k2[j] + 2 * k3[j] + k4[j]));
  }
  return W;
}

// Run 2: 512 steps of 5/512, body angular velocity at t = 5 vs reference.
{
  const exact = eulerRK4(W0, 5, 50000), check = eulerRK4(W0, 5, 25000);
  console.log('reference_h1e-4_vs_h2e-4', (norm(sub(exact, check)) / norm(W0)).toExponential(6));
  console.log('reference_omega_body_t5', exact.map((x) => x.toFixed(6)).join(','));
  const { world, body } = makeFreeBody(1, I, W0, [0, 0, 0, 1], 5 / 512);
  for (let n = 0; n < 512; n++) ck(H.HP_World_Step(world, 5 / 512));
  const Wb = state(body).Wb;
  console.log('havok_omega_body_t5', Wb.map((x) => x.toFixed(6)).join(','));
  console.log('free_top_error_n512', (norm(sub(Wb, exact)) / norm(W0)).toExponential(6));
}

// Inertia-argument check: mass 2, inertia argument (1,2,3), body at rest, angular impulse (1,1,1).
// dw_i * I_i = 1 if the argument is the inertia itself, = 1/mass = 0.5 if it is inertia per unit mass.
{
  const { body } = makeFreeBody(2, I, [0, 0, 0]);
  ck(H.HP_Body_ApplyAngularImpulse(body, [1, 1, 1]));
  const w = ck(H.HP_Body_GetAngularVelocity(body));
  console.log('mass2_impulse_dw_times_inertia_arg', w.map((x, i) => (x * I[i]).toFixed(6)).join(','));
}

// Frame check: orientation 90 deg about z, angular velocity (1,0,0), one step of 0.01. The rotation
// q1 * conj(q0) has axis (1,0,0) if the velocity is world-frame, (0,-1,0) if it were body-frame.
{
  const c = Math.SQRT1_2, { world, body } = makeFreeBody(1, I, [1, 0, 0], [0, 0, c, c]);
  const q0 = ck(H.HP_Body_GetQTransform(body))[1];
  ck(H.HP_World_Step(world, 0.01));
  const [x, y, z, w] = ck(H.HP_Body_GetQTransform(body))[1], [a, b, d, e] = [-q0[0], -q0[1], -q0[2], q0[3]];
  const v = [w * a + x * e + y * d - z * b, w * b - x * d + y * e + z * a, w * d + x * b - y * a + z * e];
  console.log('frame_check_step_axis', v.map((t) => (t / norm(v)).toFixed(6)).join(','));
}

// A body given a shape and no mass properties: a box 0.3 x 0.5 x 0.7 (HP_Shape_BuildMassProperties
// gives the box's mass at its density), a DYNAMIC body with that shape, added to a world. Read back
// with HP_Body_GetMassProperties, and measured: a linear impulse of 1 changes v by 1/m, an angular
// impulse (1, 1, 1) changes omega_i by 1/I_i (at the identity orientation).
{
  const world = ck(H.HP_World_Create());
  ck(H.HP_World_SetGravity(world, [0, 0, 0]));
  const box = ck(H.HP_Shape_CreateBox([0, 0, 0], [0, 0, 0, 1], [0.3, 0.5, 0.7]));
  const body = ck(H.HP_Body_Create());
  ck(H.HP_Body_SetShape(body, box));
  ck(H.HP_Body_SetMotionType(body, H.MotionType.DYNAMIC));
  ck(H.HP_World_AddBody(world, body, false));
  const mp = ck(H.HP_Body_GetMassProperties(body));
  console.log('box_alone_mass', mp[1]);
  console.log('box_alone_inertia', mp[2].join(','));
  console.log('box_alone_moment_max', mp[1] * Math.max(...mp[2])); // the inertia is per unit mass
  console.log('box_built_mass', ck(H.HP_Shape_BuildMassProperties(box))[1].toFixed(6));
  ck(H.HP_Body_ApplyImpulse(body, [0, 0, 0], [1, 0, 0]));
  console.log('box_alone_impulse_dv', ck(H.HP_Body_GetLinearVelocity(body))[0]);
  ck(H.HP_Body_ApplyAngularImpulse(body, [1, 1, 1]));
  console.log('box_alone_angular_impulse_dw', ck(H.HP_Body_GetAngularVelocity(body)).join(','));
}

// A convex hull: the tetrahedron (+-a, 0, c), (0, +-b, -c), a = 0.3, b = 0.4, c = 0.25 (its centroid
// the origin, its principal axes x, y, z: I = m diag(b^2/10 + c^2/5, a^2/10 + c^2/5, (a^2 + b^2)/10),
// volume 4abc/3), the points in the WebAssembly heap as the declarations ask, scaled by k: what
// HP_Shape_BuildMassProperties gives against the exact moments (per unit mass) and against the mass
// of the shape's density (HP_Shape_GetDensity) times the volume.
for (const k of [1, 10, 100]) {
  const [a, b, c] = [0.3 * k, 0.4 * k, 0.25 * k];
  const points = [a, 0, c, -a, 0, c, 0, b, -c, 0, -b, -c];
  const at = H._malloc(4 * points.length);
  new Float32Array(H.HEAPU8.buffer, at, points.length).set(points);
  const hull = ck(H.HP_Shape_CreateConvexHull(at, 4));
  H._free(at);
  const [, mass, inertia] = ck(H.HP_Shape_BuildMassProperties(hull));
  const exact = [b * b / 10 + c * c / 5, a * a / 10 + c * c / 5, (a * a + b * b) / 10];
  const up = (v) => [...v].sort((x, y) => x - y), [g, e] = [up(inertia), up(exact)]; // ascending, as the audit
  const error = Math.max(...g.map((x, i) => Math.abs(x / e[i] - 1)));
  console.log(`convex_hull_x${k}_moment_largest_relative_error`, error.toExponential(6));
  console.log(`convex_hull_x${k}_mass_over_density_volume_minus_1`,
              (mass / (ck(H.HP_Shape_GetDensity(hull)) * (4 * a * b * c) / 3) - 1).toExponential(6));
}

// A pendulum, the audit's pendulum_small: a bob of mass 1 (inertia 1e-3 about its centre, a sphere
// shape of radius 0.1) whose centre is 1 m from a static body's origin, turned about y by a from
// hanging straight down (centre at (-sin a, 0, -cos a)), joined at the origin by a constraint whose
// linear axes and ANGULAR_Y, ANGULAR_Z are LOCKED (a hinge about world y), gravity 9.81 along -z,
// damping 0, released from rest; the ideal step time the step. Printed: the largest loss of the
// swing's energy (E0 - E) / (E0 - V_floor), V_floor = -m g l the bob hanging below the pivot, over
// n steps; the friction its free axis reads (HP_Constraint_GetAxisFriction); the angle at the
// end and the time after the last step that changed the angle by more than 1e-7 rad; and
// for a swing of 0.3 rad the period (from the downward zero crossings over 20 s, linear
// interpolation) against the exact 4 K(sin(a/2)) sqrt(I / (m g l)), I = 1.001 (K by the
// arithmetic-geometric mean), and the swing's energy lost over 20 s at 0.3 and 1 rad.
function pendulum(a, h, n) {
  const world = ck(H.HP_World_Create());
  ck(H.HP_World_SetGravity(world, [0, 0, -9.81]));
  ck(H.HP_World_SetIdealStepTime(world, h));
  const ball = ck(H.HP_Shape_CreateSphere([0, 0, 0], 0.1));
  const ground = ck(H.HP_Body_Create());
  ck(H.HP_Body_SetShape(ground, ball));
  ck(H.HP_Body_SetMotionType(ground, H.MotionType.STATIC));
  ck(H.HP_World_AddBody(world, ground, false));
  const bob = ck(H.HP_Body_Create());
  ck(H.HP_Body_SetShape(bob, ball));
  ck(H.HP_Body_SetMotionType(bob, H.MotionType.DYNAMIC));
  ck(H.HP_Body_SetMassProperties(bob, [[0, 0, 0], 1, [1e-3, 1e-3, 1e-3], [0, 0, 0, 1]]));
  ck(H.HP_Body_SetLinearDamping(bob, 0));
  ck(H.HP_Body_SetAngularDamping(bob, 0));
  const c = Math.cos(a), s = Math.sin(a);
  ck(H.HP_Body_SetQTransform(bob, [[-s, 0, -c], [0, Math.sin(a / 2), 0, Math.cos(a / 2)]]));
  ck(H.HP_World_AddBody(world, bob, false));
  ck(H.HP_Body_SetActivationControl(bob, H.ActivationControl.ALWAYS_ACTIVE));
  const joint = ck(H.HP_Constraint_Create());
  ck(H.HP_Constraint_SetParentBody(joint, ground));
  ck(H.HP_Constraint_SetChildBody(joint, bob));
  ck(H.HP_Constraint_SetAnchorInParent(joint, [0, 0, 0], [0, 1, 0], [1, 0, 0]));
  // The pivot (0, 0, 1) and the axes y, x in the bob's frame (turned by a about y).
  ck(H.HP_Constraint_SetAnchorInChild(joint, [0, 0, 1], [0, 1, 0], [c, 0, s]));
  const A = H.ConstraintAxis;
  for (const axis of [A.LINEAR_X, A.LINEAR_Y, A.LINEAR_Z, A.ANGULAR_Y, A.ANGULAR_Z])
    ck(H.HP_Constraint_SetAxisMode(joint, axis, H.ConstraintAxisLimitMode.LOCKED));
  ck(H.HP_Constraint_SetEnabled(joint, 1));
  const friction = ck(H.HP_Constraint_GetAxisFriction(joint, A.ANGULAR_X)); // the hinge's free axis
  const energy = () => {
    const x = ck(H.HP_Body_GetQTransform(bob))[0], v = ck(H.HP_Body_GetLinearVelocity(bob));
    const w = ck(H.HP_Body_GetAngularVelocity(bob));
    return (v[0] ** 2 + v[1] ** 2 + v[2] ** 2) / 2 + 1e-3 * (w[0] ** 2 + w[1] ** 2 + w[2] ** 2) / 2 + 9.81 * x[2];
  };
  const angle = () => { const x = ck(H.HP_Body_GetQTransform(bob))[0]; return Math.atan2(-x[0], -x[2]); };
  const e0 = energy(), swing = e0 + 9.81;
  const crossings = [];
  let lost = 0, previous = angle(), still = 0;
  for (let k = 1; k <= n; k++) {
    ck(H.HP_World_Step(world, h));
    lost = Math.max(lost, (e0 - energy()) / swing);
    const now = angle();
    if (previous > 0 && now <= 0) crossings.push(k * h - (h * now) / (now - previous));
    if (Math.abs(now - previous) > 1e-7) still = k;
    previous = now;
  }
  return { lost, angle: previous, stillFrom: still * h, crossings, friction };
}
for (const h of [0.01, 0.002]) {
  const r = pendulum(0.1, h, Math.round(100 / h));
  console.log(`pendulum_small_h${h}_swing_energy_lost_max`, r.lost.toExponential(6));
  console.log(`pendulum_small_h${h}_angle_at_t100`, r.angle.toExponential(4));
  console.log(`pendulum_small_h${h}_still_from_t`, r.stillFrom.toFixed(2));
  console.log(`pendulum_small_h${h}_free_axis_friction`, r.friction);
}
{
  const a = 0.3, r = pendulum(a, 0.001, 20000);
  let m = 1, g = Math.cos(a / 2);
  for (let i = 0; i < 40; i++) [m, g] = [(m + g) / 2, Math.sqrt(m * g)];
  const exact = 4 * (Math.PI / (2 * m)) * Math.sqrt(1.001 / 9.81), x = r.crossings;
  console.log('pendulum_0.3rad_h0.001_period_relative_error', (((x[x.length - 1] - x[0]) / (x.length - 1)) / exact - 1).toExponential(3));
  // The swing's energy it loses meanwhile, and at 1 rad and at h = 0.01: the loss is not slow
  // motion's alone.
  console.log('pendulum_0.3rad_h0.001_swing_energy_lost_max_20s', r.lost.toExponential(6));
  for (const [amplitude, h] of [[0.3, 0.01], [1, 0.001], [1, 0.01]])
    console.log(`pendulum_${amplitude}rad_h${h}_swing_energy_lost_max_20s`,
                pendulum(amplitude, h, Math.round(20 / h)).lost.toExponential(6));
}
