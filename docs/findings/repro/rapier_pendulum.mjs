// rapier_pendulum.mjs -- the audit's pendulum_large in Rapier (@dimforge/rapier3d-compat, single precision WASM):
// a bob of mass 1 (principal inertia 1e-3 about its centre, by RigidBodyDesc.setAdditionalMassProperties, no
// collider) whose centre is 1 m from a fixed body's origin, joined there by an impulse joint
// (JointData.revolute, the axis world y), gravity 9.81 along -z, damping 0, sleeping off, released from rest at
// 2.5 rad from hanging straight down (the centre at (-sin 2.5, 0, -cos 2.5), the body turned by 2.5 about y);
// 1e5 steps of world.step() with world.timestep = 0.01, at World.numSolverIterations 4 (its default) and 16.
// Each step: the pivot read back through the body, x - R (0, 0, -1), its distance from the origin (m); the energy
// E = |v|^2 / 2 + w . (R I R^T w) / 2 + 9.81 z, its change relative to the energy the pendulum can exchange,
// E0 - V_floor with V_floor = -9.81 (the bob hanging below the pivot). Printed: the largest of each.
// Run: node rapier_pendulum.mjs PATH/TO/node_modules/@dimforge/rapier3d-compat
// Output: lines "name value". Uses only Rapier and plain JavaScript.
import { readFileSync } from 'fs';
import { pathToFileURL } from 'url';
const dir = process.argv[2];
if (!dir) { console.error('usage: node rapier_pendulum.mjs PATH/TO/node_modules/@dimforge/rapier3d-compat'); process.exit(1); }
const pkg = JSON.parse(readFileSync(dir + '/package.json', 'utf8'));
const RAPIER = (await import(pathToFileURL(dir + '/dist/rapier.mjs').href)).default;
await RAPIER.init();
console.log('rapier_version', pkg.version);

const rotOf = ({ x, y, z, w }) => [[1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
  [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
  [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)]];
const mul = (R, v) => R.map((r) => r[0] * v[0] + r[1] * v[1] + r[2] * v[2]);
const mulT = (R, v) => [0, 1, 2].map((j) => R[0][j] * v[0] + R[1][j] * v[1] + R[2][j] * v[2]);

function pendulum(iterations, n) {
  const a = 2.5, h = 0.01;
  const world = new RAPIER.World({ x: 0, y: 0, z: -9.81 });
  world.numSolverIterations = iterations;
  const ground = world.createRigidBody(RAPIER.RigidBodyDesc.fixed());
  const bob = world.createRigidBody(
    RAPIER.RigidBodyDesc.dynamic()
      .setTranslation(-Math.sin(a), 0, -Math.cos(a))
      .setRotation({ x: 0, y: Math.sin(a / 2), z: 0, w: Math.cos(a / 2) })
      .setAdditionalMassProperties(1, { x: 0, y: 0, z: 0 }, { x: 1e-3, y: 1e-3, z: 1e-3 }, { x: 0, y: 0, z: 0, w: 1 })
      .setLinearDamping(0)
      .setAngularDamping(0)
      .setCanSleep(false),
  );
  world.createImpulseJoint(RAPIER.JointData.revolute({ x: 0, y: 0, z: 0 }, { x: 0, y: 0, z: 1 }, { x: 0, y: 1, z: 0 }), ground, bob, true);
  const read = () => {
    const R = rotOf(bob.rotation()), t = bob.translation(), v = bob.linvel(), w = bob.angvel();
    const x = [t.x, t.y, t.z], wv = [w.x, w.y, w.z], arm = mul(R, [0, 0, -1]);
    const wb = mulT(R, wv);
    const energy = (v.x * v.x + v.y * v.y + v.z * v.z) / 2 + 1e-3 * (wb[0] ** 2 + wb[1] ** 2 + wb[2] ** 2) / 2 + 9.81 * x[2];
    return { energy, anchor: Math.hypot(x[0] - arm[0], x[1] - arm[1], x[2] - arm[2]) };
  };
  const e0 = read().energy, exchange = e0 + 9.81;
  let anchor = 0, energy = 0;
  for (let k = 0; k < n; k++) {
    world.timestep = h;
    world.step();
    const r = read();
    anchor = Math.max(anchor, r.anchor);
    energy = Math.max(energy, Math.abs(r.energy - e0) / exchange);
  }
  world.free();
  return { anchor, energy };
}
for (const iterations of [4, 16]) {
  const r = pendulum(iterations, 100000);
  console.log(`pendulum_large_iterations_${iterations}_anchor_max`, r.anchor.toExponential(6));
  console.log(`pendulum_large_iterations_${iterations}_energy_max`, r.energy.toExponential(6));
}
