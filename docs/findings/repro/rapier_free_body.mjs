// rapier_free_body.mjs -- torque-free asymmetric rigid body in Rapier (@dimforge/rapier3d-compat), checked against
// Euler's equations. A dynamic body with no collider, mass properties from RigidBodyDesc.setAdditionalMassProperties
// (mass 1, centre of mass 0, principal inertia (1, 2, 3), identity inertia frame), World gravity 0, linear and
// angular damping 0, setCanSleep(false), identity orientation, angular velocity (1, 0.2, 0.5) rad/s, stepped with
// world.step() and world.timestep = h. Each step: w = body.angvel() (taken as world frame; checked below by a
// rotated isotropic body), R from body.rotation(), W = R^T w (body frame), E = 1/2 W.I W, L = R I W (world).
// Printed: a frame check of angvel(); |W - W_exact|/|W0| at t = 5 for n = 32 .. 32768 steps of 5/n, with log2 ratios,
// against classical RK4 at h = 1e-4 (checked against 2e-4); the largest relative changes of E, |L| and vector L over
// 1e4 and 1e5 steps of 0.01; E/(|L|^2/(2 I2)) at t = 0, 100, 1000; the same ratio for W0 = (0.2, 0.2, 1); the mass
// and largest principal moment of a body given a box collider and no mass.
// Run: node rapier_free_body.mjs PATH/TO/node_modules/@dimforge/rapier3d-compat
// Output: lines "name value". Uses only Rapier and plain JavaScript.
import { readFileSync } from 'fs';
import { pathToFileURL } from 'url';
const dir = process.argv[2];
if (!dir) { console.error('usage: node rapier_free_body.mjs PATH/TO/node_modules/@dimforge/rapier3d-compat'); process.exit(1); }
const pkg = JSON.parse(readFileSync(dir + '/package.json', 'utf8'));
const RAPIER = (await import(pathToFileURL(dir + '/dist/rapier.mjs').href)).default;
await RAPIER.init();

const I = [1, 2, 3], W0 = [1, 0.2, 0.5];
const norm = (v) => Math.hypot(v[0], v[1], v[2]);
const sub = (a, b) => [a[0] - b[0], a[1] - b[1], a[2] - b[2]];
const cross = (a, b) => [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
const rotOf = ({ x, y, z, w }) => [[1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
  [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
  [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)]];
const mul = (R, v) => R.map((r) => r[0] * v[0] + r[1] * v[1] + r[2] * v[2]);
const mulT = (R, v) => [0, 1, 2].map((j) => R[0][j] * v[0] + R[1][j] * v[1] + R[2][j] * v[2]);
const v3 = (a) => ({ x: a[0], y: a[1], z: a[2] });
const arr = (v) => [v.x, v.y, v.z];

// One world per body.
function makeBody(W, h, inertia = I, q = { x: 0, y: 0, z: 0, w: 1 }) {
  const world = new RAPIER.World({ x: 0, y: 0, z: 0 });
  world.timestep = h;
  const desc = RAPIER.RigidBodyDesc.dynamic()
    .setAdditionalMassProperties(1, { x: 0, y: 0, z: 0 }, v3(inertia), { x: 0, y: 0, z: 0, w: 1 })
    .setLinearDamping(0).setAngularDamping(0).setCanSleep(false).setRotation(q).setAngvel(v3(W));
  return { world, body: world.createRigidBody(desc) };
}
const state = (body) => {
  const R = rotOf(body.rotation()), w = arr(body.angvel()), Wb = mulT(R, w);
  const IW = Wb.map((x, i) => I[i] * x);
  return { w, Wb, E: 0.5 * (Wb[0] * IW[0] + Wb[1] * IW[1] + Wb[2] * IW[2]), L: mul(R, IW) };
};

console.log('rapier_version', pkg.version);
console.log('rapier_wasm_version', RAPIER.version());

// Frame check: isotropic body (no gyroscopic term) turned 90 deg about world z, angvel set to (1, 0, 0).
// After one step of 1e-3, the rotation increment dq = q1 q0^-1 has its axis along w if w is world frame.
{
  const s = Math.SQRT1_2, q0 = { x: 0, y: 0, z: s, w: s };
  const { world, body } = makeBody([1, 0, 0], 1e-3, [1, 1, 1], q0);
  world.step();
  const q1 = body.rotation(), c = [-q0.x, -q0.y, -q0.z]; // q0^-1 = (c, w)
  const v = [q1.w * c[0] + q0.w * q1.x + q1.y * c[2] - q1.z * c[1], q1.w * c[1] + q0.w * q1.y + q1.z * c[0] - q1.x * c[2],
    q1.w * c[2] + q0.w * q1.z + q1.x * c[1] - q1.y * c[0]];
  console.log('frame_check_world_increment_axis', v.map((x) => (x / norm(v)).toFixed(4)).join(','));
  console.log('frame_check_angvel_after_step', arr(body.angvel()).map((x) => x.toFixed(6)).join(','));
  const b = makeBody(W0, 0.01); // mass properties are filled in by the first step
  console.log('mass_readback_before_step', b.body.mass(), arr(b.body.principalInertia()).join(','));
  b.world.step();
  console.log('mass_readback_after_step', b.body.mass(), arr(b.body.principalInertia()).join(','));
}

// Reference: classical RK4 on I W' = (I W) x W.
function eulerRK4(W, T, n) {
  const h = T / n, f = (X) => cross(X.map((x, i) => I[i] * x), X).map((x, i) => x / I[i]);
  for (let k = 0; k < n; k++) {
    const k1 = f(W), k2 = f(W.map((x, i) => x + 0.5 * h * k1[i]));
    const k3 = f(W.map((x, i) => x + 0.5 * h * k2[i])), k4 = f(W.map((x, i) => x + h * k3[i]));
    W = W.map((x, i) => x + (h / 6) * (k1[i] + 2 * k2[i] + 2 * k3[i] + k4[i]));
  }
  return W;
}
const Wex = eulerRK4(W0, 5, 50000), Wex2 = eulerRK4(W0, 5, 25000);
console.log('reference_W_t5', Wex.map((x) => x.toFixed(12)).join(','));
console.log('reference_h1e-4_vs_h2e-4', (norm(sub(Wex, Wex2)) / norm(W0)).toExponential(3));

// Claim 1: body angular velocity error at t = 5, n steps of 5/n.
let prev = null;
for (let n = 32; n <= 32768; n *= 2) {
  const { world, body } = makeBody(W0, 5 / n);
  for (let k = 0; k < n; k++) world.step();
  const s = state(body), e = norm(sub(s.Wb, Wex)) / norm(W0);
  console.log(`free_top_error_n${n}`, e.toExponential(6));
  if (prev !== null) console.log(`free_top_log2_ratio_n${n / 2}_n${n}`, Math.log2(prev / e).toFixed(3));
  prev = e;
  if (n === 512) {
    console.log('free_top_W_body_t5_n512', s.Wb.map((x) => x.toFixed(6)).join(','));
    console.log('free_top_W_body_change_t5_n512', (norm(sub(s.Wb, W0)) / norm(W0)).toExponential(6));
    console.log('free_top_w_world_change_t5_n512', (norm(sub(s.w, W0)) / norm(W0)).toExponential(6));
  }
}

// Claims 2 and 3: long runs at h = 0.01, t = 0 .. 1000.
function longRun(W, tag) {
  const { world, body } = makeBody(W, 0.01);
  const s0 = state(body), L0 = norm(s0.L), sep = (s) => s.E / (norm(s.L) ** 2 / (2 * I[1]));
  let dE = 0, dLn = 0, dL = 0, Emin = s0.E, Emax = s0.E;
  console.log(`${tag}_energy_t0_over_L2_2I2`, sep(s0).toFixed(6));
  for (let n = 1; n <= 100000; n++) {
    world.step();
    const s = state(body);
    dE = Math.max(dE, Math.abs(s.E - s0.E) / s0.E);
    dLn = Math.max(dLn, Math.abs(norm(s.L) - L0) / L0);
    dL = Math.max(dL, norm(sub(s.L, s0.L)) / L0);
    Emin = Math.min(Emin, s.E); Emax = Math.max(Emax, s.E);
    if (n === 10000 || n === 100000) {
      const k = n === 10000 ? '1e4' : '1e5', t = n === 10000 ? 't100' : 't1000';
      console.log(`${tag}_energy_max_${k}`, dE.toExponential(6));
      console.log(`${tag}_momentum_norm_max_${k}`, dLn.toExponential(6));
      console.log(`${tag}_momentum_max_${k}`, dL.toExponential(6));
      console.log(`${tag}_energy_${t}_over_L2_2I2`, sep(s).toFixed(6));
      console.log(`${tag}_energy_rel_change_${t}`, ((s.E - s0.E) / s0.E).toExponential(6));
      console.log(`${tag}_momentum_norm_rel_change_${t}`, ((norm(s.L) - L0) / L0).toExponential(6));
      console.log(`${tag}_energy_min_max_over_E0_${k}`, (Emin / s0.E).toFixed(6) + ',' + (Emax / s0.E).toFixed(6));
    }
  }
}
longRun(W0, 'free_top');
for (const h of [0.02, 0.01, 0.005]) { // does the energy drift at t = 100 scale with h?
  const { world, body } = makeBody(W0, h), E0 = state(body).E;
  for (let k = 0, n = Math.round(100 / h); k < n; k++) world.step();
  console.log(`free_top_energy_rel_change_t100_h${h}`, ((state(body).E - E0) / E0).toExponential(6));
}
longRun([0.2, 0.2, 1], 'major_axis');

// A body given a collider and no mass: a box 0.3 x 0.5 x 0.7 (ColliderDesc.cuboid takes half-extents,
// its density left as ColliderDesc makes it). Exact for a density of 1: mass 0.105, largest moment
// 0.105 (0.5^2 + 0.7^2) / 12 = 6.475e-3.
{
  const world = new RAPIER.World({ x: 0, y: 0, z: 0 });
  const body = world.createRigidBody(RAPIER.RigidBodyDesc.dynamic());
  world.createCollider(RAPIER.ColliderDesc.cuboid(0.15, 0.25, 0.35), body);
  const m = body.principalInertia();
  console.log('box_alone_mass', body.mass().toExponential(6));
  console.log('box_alone_moment_max', Math.max(m.x, m.y, m.z).toExponential(6));
  world.free();
}
