// jolt_gyroscopic.mjs -- torque-free asymmetric rigid body in Jolt Physics (npm jolt-physics, single precision WASM),
// with and without BodyCreationSettings.mApplyGyroscopicForce.
// A body with a 0.1 m sphere shape, mass properties overridden (EOverrideMassProperties_MassAndInertiaProvided,
// mass 1, inertia diag(1, 2, 3)), no gravity (system gravity 0 and gravity factor 0), linear/angular damping 0
// (Jolt's defaults are 0.05), max angular velocity clamp raised to 1e6, sleeping off, identity orientation, world
// angular velocity (1, 0.2, 0.5) rad/s, one object layer whose pair is not enabled (nothing collides), stepped with
// JoltInterface.Step(0.01, 1). Each step the world angular velocity w and rotation R are read back;
// w_body = R^T w, E = 1/2 w_body . I w_body, L = R I w_body (world).
// A second body, spun near its major axis (0.2, 0.2, 1), over 1e5 steps: E/(|L|^2/(2 I2)) at t = 0 and 1000.
// Printed: energy and angular momentum drift over 1e4 steps with the gyroscopic force on and off, E(t)/(|L|^2/(2 I2))
// at t = 0, 100 and (1e5-step run) 1000 against the initial |L| (and at t = 1000 against |L(t)| too), and the same ratios from a double precision JavaScript replica of Jolt's
// update (ApplyGyroscopicForceInternal, then q <- exp(h w) q), to separate float32 effects from the method.
// Run: node jolt_gyroscopic.mjs PATH/TO/node_modules/jolt-physics/dist/jolt-physics.wasm-compat.js
// Output: lines "name value". Uses only Jolt and plain JavaScript.
import { readFileSync } from 'fs';
import { dirname } from 'path';
import { pathToFileURL } from 'url';
const entry = process.argv[2];
if (!entry) { console.error('usage: node jolt_gyroscopic.mjs PATH/TO/node_modules/jolt-physics/dist/jolt-physics.wasm-compat.js'); process.exit(1); }
const pkg = JSON.parse(readFileSync(dirname(dirname(entry)) + '/package.json', 'utf8'));
const Jolt = await (await import(pathToFileURL(entry).href)).default();

const I = [1, 2, 3], H = 0.01;
// The audit's free_top, spun nearer its minor axis; and a body spun near its major axis, a
// stable rotation whose energy Euler's equations keep below L^2 / (2 I2).
const TOP = [1, 0.2, 0.5], MAJOR = [0.2, 0.2, 1];
let W0 = TOP;
const norm = (v) => Math.hypot(v[0], v[1], v[2]);
const sub = (a, b) => [a[0] - b[0], a[1] - b[1], a[2] - b[2]];
const cross = (a, b) => [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
function rotOf([x, y, z, w]) { // rotation matrix (rows) of unit quaternion [x, y, z, w]
  return [[1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
          [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
          [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)]];
}
const mul = (R, v) => R.map((r) => r[0] * v[0] + r[1] * v[1] + r[2] * v[2]);
const mulT = (R, v) => [0, 1, 2].map((j) => R[0][j] * v[0] + R[1][j] * v[1] + R[2][j] * v[2]);
function energyMomentum(q, w) { // q [x,y,z,w], w world angular velocity -> {E, L (world)}
  const R = rotOf(q), wb = mulT(R, w), Lb = [I[0] * wb[0], I[1] * wb[1], I[2] * wb[2]];
  return { E: 0.5 * (wb[0] * Lb[0] + wb[1] * Lb[1] + wb[2] * Lb[2]), L: mul(R, Lb) };
}

// One Jolt world per run; one object layer, its pair with itself not enabled.
function makeWorld(gyro) {
  const settings = new Jolt.JoltSettings();
  const olpf = new Jolt.ObjectLayerPairFilterTable(1); // no EnableCollision call: layer 0 vs 0 disabled
  const bpi = new Jolt.BroadPhaseLayerInterfaceTable(1, 1);
  bpi.MapObjectToBroadPhaseLayer(0, new Jolt.BroadPhaseLayer(0));
  settings.mObjectLayerPairFilter = olpf;
  settings.mBroadPhaseLayerInterface = bpi;
  settings.mObjectVsBroadPhaseLayerFilter = new Jolt.ObjectVsBroadPhaseLayerFilterTable(bpi, 1, olpf, 1);
  const jolt = new Jolt.JoltInterface(settings);
  const sys = jolt.GetPhysicsSystem();
  sys.SetGravity(new Jolt.Vec3(0, 0, 0));
  const bcs = new Jolt.BodyCreationSettings(new Jolt.SphereShape(0.1), new Jolt.RVec3(0, 0, 0),
    new Jolt.Quat(0, 0, 0, 1), Jolt.EMotionType_Dynamic, 0);
  const mp = new Jolt.MassProperties();
  mp.mMass = 1;
  mp.mInertia = Jolt.Mat44.prototype.sScaleVec3(new Jolt.Vec3(I[0], I[1], I[2]));
  bcs.mOverrideMassProperties = Jolt.EOverrideMassProperties_MassAndInertiaProvided;
  bcs.mMassPropertiesOverride = mp;
  bcs.mApplyGyroscopicForce = gyro;
  bcs.mLinearDamping = 0; bcs.mAngularDamping = 0;
  bcs.mMaxAngularVelocity = 1e6; bcs.mGravityFactor = 0; bcs.mAllowSleeping = false;
  bcs.mAngularVelocity = new Jolt.Vec3(W0[0], W0[1], W0[2]);
  const bi = sys.GetBodyInterface();
  const body = bi.CreateBody(bcs);
  bi.AddBody(body.GetID(), Jolt.EActivation_Activate);
  return { jolt, body };
}
const readState = (body) => {
  const q = body.GetRotation(), w = body.GetAngularVelocity();
  return { q: [q.GetX(), q.GetY(), q.GetZ(), q.GetW()], w: [w.GetX(), w.GetY(), w.GetZ()] };
};

// Run n steps; record drift maxima and E at chosen step counts.
function run(gyro, n, marks = []) {
  const { jolt, body } = makeWorld(gyro);
  const s0 = readState(body), m0 = energyMomentum(s0.q, s0.w), L0n = norm(m0.L);
  const r = { E0: m0.E, L0: L0n, eMax: 0, lMax: 0, lMagMax: 0, wMax: 0, Eat: {}, Lat: {}, body };
  for (let k = 1; k <= n; k++) {
    jolt.Step(H, 1);
    const s = readState(body), m = energyMomentum(s.q, s.w);
    r.eMax = Math.max(r.eMax, Math.abs(m.E - m0.E) / m0.E);
    r.lMax = Math.max(r.lMax, norm(sub(m.L, m0.L)) / L0n);
    r.lMagMax = Math.max(r.lMagMax, Math.abs(norm(m.L) - L0n) / L0n);
    r.wMax = Math.max(r.wMax, norm(sub(s.w, s0.w)) / norm(s0.w));
    if (marks.includes(k)) {
      r.Eat[k] = m.E;
      r.Lat[k] = norm(m.L);
    }
  }
  return r;
}

// Double precision replica of Jolt's per-step update for this body (mInertiaRotation taken as identity).
function replica(n, marks) {
  let q = [0, 0, 0, 1], w = W0.slice(); const out = { eMax: 0, lMax: 0, lMagMax: 0 }, m0 = energyMomentum(q, w);
  for (let k = 1; k <= n; k++) {
    const R = rotOf(q), wb = mulT(R, w), Lb = [I[0] * wb[0], I[1] * wb[1], I[2] * wb[2]];
    let Ln = sub(Lb, cross(wb, Lb).map((c) => H * c));
    const s = Math.sqrt((Lb[0] ** 2 + Lb[1] ** 2 + Lb[2] ** 2) / (Ln[0] ** 2 + Ln[1] ** 2 + Ln[2] ** 2));
    Ln = Ln.map((c) => c * s);
    w = mul(R, [Ln[0] / I[0], Ln[1] / I[1], Ln[2] / I[2]]);
    const th = norm(w) * H, a = w.map((c) => c / norm(w)), sn = Math.sin(th / 2), cs = Math.cos(th / 2);
    const d = [a[0] * sn, a[1] * sn, a[2] * sn, cs]; // q <- d * q  (Hamilton product, [x,y,z,w])
    q = [d[3] * q[0] + d[0] * q[3] + d[1] * q[2] - d[2] * q[1], d[3] * q[1] - d[0] * q[2] + d[1] * q[3] + d[2] * q[0],
         d[3] * q[2] + d[0] * q[1] - d[1] * q[0] + d[2] * q[3], d[3] * q[3] - d[0] * q[0] - d[1] * q[1] - d[2] * q[2]];
    const ql = Math.hypot(...q); q = q.map((c) => c / ql);
    const m = energyMomentum(q, w);
    if (k <= 10000) { // drift maxima over the first 1e4 steps, as for the Jolt run
      out.eMax = Math.max(out.eMax, Math.abs(m.E - m0.E) / m0.E);
      out.lMax = Math.max(out.lMax, norm(sub(m.L, m0.L)) / norm(m0.L));
    }
    out.lMagMax = Math.max(out.lMagMax, Math.abs(norm(m.L) - norm(m0.L)) / norm(m0.L));
    if (marks.includes(k)) out[k] = m.E;
  }
  return out;
}

const f = (x) => x.toExponential(6);
const g = run(true, 10000, [1000, 10000]);
const invI = g.body.GetMotionProperties().GetInverseInertiaDiagonal();
const ref = g.L0 ** 2 / (2 * I[1]);
console.log('jolt_version', pkg.version);
console.log('check_inverse_inertia_diagonal', [invI.GetX(), invI.GetY(), invI.GetZ()].map(f).join(','));
console.log('check_E0', f(g.E0));
console.log('check_L0', f(g.L0));
console.log('gyroscopic_energy_max', f(g.eMax));
console.log('gyroscopic_momentum_max', f(g.lMax));
console.log('gyroscopic_momentum_magnitude_max', f(g.lMagMax));
console.log('gyroscopic_energy_t0_over_L2_2I2', f(g.E0 / ref));
console.log('gyroscopic_energy_t10_over_L2_2I2', f(g.Eat[1000] / ref));
console.log('gyroscopic_energy_t100_over_L2_2I2', f(g.Eat[10000] / ref));
const d = run(false, 10000);
console.log('default_world_omega_change_max', f(d.wMax));
console.log('default_momentum_max', f(d.lMax));
console.log('default_energy_max', f(d.eMax));
const gl = run(true, 100000, [100000]);
console.log('gyroscopic_long_energy_max_1e5_steps', f(gl.eMax));
console.log('gyroscopic_long_momentum_magnitude_max_1e5_steps', f(gl.lMagMax));
console.log('gyroscopic_long_energy_t1000_over_L2_2I2', f(gl.Eat[100000] / ref));
const rp = replica(100000, [1000, 10000, 100000]);
console.log('replica_f64_energy_max', f(rp.eMax));
console.log('replica_f64_momentum_max', f(rp.lMax));
console.log('replica_f64_energy_t10_over_L2_2I2', f(rp[1000] / ref));
console.log('replica_f64_energy_t100_over_L2_2I2', f(rp[10000] / ref));
console.log('replica_f64_energy_t1000_over_L2_2I2', f(rp[100000] / ref));
// Spun near the major axis: 10^5 steps of 0.01.
W0 = MAJOR;
const mj = run(true, 100000, [100000]), refMajor = mj.L0 ** 2 / (2 * I[1]);
console.log('major_axis_energy_t0_over_L2_2I2', f(mj.E0 / refMajor));
console.log('major_axis_energy_t1000_over_L2_2I2', f(mj.Eat[100000] / refMajor));
// The same ratio against |L| at t = 1000 (single precision's rounding changes |L| by up to
// 3.8e-3 over 1e5 steps): where the motion is against the separatrix of its own |L|.
console.log('major_axis_L_t1000_over_L0', f(mj.Lat[100000] / mj.L0));
console.log('major_axis_energy_t1000_over_current_L2_2I2', f(mj.Eat[100000] / (mj.Lat[100000] ** 2 / (2 * I[1]))));
console.log('gyroscopic_long_energy_t1000_over_current_L2_2I2', f(gl.Eat[100000] / (gl.Lat[100000] ** 2 / (2 * I[1]))));
// The double precision replica of the update on the same body (it keeps |L| to double's rounding).
const rm = replica(100000, [100000]);
console.log('major_axis_replica_f64_energy_t1000_over_L2_2I2', f(rm[100000] / refMajor));
console.log('major_axis_replica_f64_momentum_magnitude_max_1e5_steps', f(rm.lMagMax));
console.log('major_axis_energy_max_1e5_steps', f(mj.eMax));
console.log('major_axis_momentum_magnitude_max_1e5_steps', f(mj.lMagMax));
// A body given a shape and no mass properties: a box 0.3 x 0.5 x 0.7 (BoxShape takes half-extents;
// convex radius 0), BodyCreationSettings' defaults. Exact for ConvexShape's density of 1000: mass 105,
// largest moment 105 (0.5^2 + 0.7^2) / 12 = 6.475.
{
  const { jolt } = makeWorld(false);
  const bcs = new Jolt.BodyCreationSettings(new Jolt.BoxShape(new Jolt.Vec3(0.15, 0.25, 0.35), 0), new Jolt.RVec3(0, 0, 0),
    new Jolt.Quat(0, 0, 0, 1), Jolt.EMotionType_Dynamic, 0);
  const body = jolt.GetPhysicsSystem().GetBodyInterface().CreateBody(bcs);
  const motion = body.GetMotionProperties(), inv = motion.GetInverseInertiaDiagonal();
  console.log('box_alone_mass', (1 / motion.GetInverseMass()).toExponential(6));
  console.log('box_alone_moment_max', (1 / Math.min(inv.GetX(), inv.GetY(), inv.GetZ())).toExponential(6));
}
