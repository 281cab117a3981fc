// jolt_pendulum.mjs -- the audit's pendulum_large in Jolt Physics (npm jolt-physics, single precision WASM): a
// bob with a 0.1 m sphere shape, mass properties overridden (EOverrideMassProperties_MassAndInertiaProvided, mass 1,
// inertia 1e-3 about each axis), whose centre is 1 m from a static body's origin, joined there by a
// HingeConstraint in world space (hinge axis y, normal axis x), gravity 9.81 along -z, damping 0 (Jolt's defaults
// are 0.05), sleeping off, one object layer whose pair is not enabled (nothing collides), released from rest at
// 2.5 rad from hanging straight down; 1e5 steps of JoltInterface.Step(0.01, 1) at PhysicsSettings'
// mNumPositionSteps 2 (its default) and 8. Each step: the pivot read back through the body, x - R (0, 0, -1), its
// distance from the origin (m); the energy E = |v|^2 / 2 + w . (R I R^T w) / 2 + 9.81 z, its change relative to
// the energy the pendulum can exchange, E0 - V_floor with V_floor = -9.81. Printed: the largest of each.
// Run: node jolt_pendulum.mjs PATH/TO/node_modules/jolt-physics/dist/jolt-physics.wasm-compat.js
// Output: lines "name value". Uses only Jolt and plain JavaScript.
import { readFileSync } from 'fs';
import { dirname } from 'path';
import { pathToFileURL } from 'url';
const entry = process.argv[2];
if (!entry) { console.error('usage: node jolt_pendulum.mjs PATH/TO/node_modules/jolt-physics/dist/jolt-physics.wasm-compat.js'); process.exit(1); }
const pkg = JSON.parse(readFileSync(dirname(dirname(entry)) + '/package.json', 'utf8'));
const Jolt = await (await import(pathToFileURL(entry).href)).default();
console.log('jolt_version', pkg.version);

const rotOf = (q) => {
  const [x, y, z, w] = [q.GetX(), q.GetY(), q.GetZ(), q.GetW()];
  return [[1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
    [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
    [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)]];
};
const xyz = (v) => [v.GetX(), v.GetY(), v.GetZ()];
const mul = (R, v) => R.map((r) => r[0] * v[0] + r[1] * v[1] + r[2] * v[2]);
const mulT = (R, v) => [0, 1, 2].map((j) => R[0][j] * v[0] + R[1][j] * v[1] + R[2][j] * v[2]);

function pendulum(positionSteps, n) {
  const a = 2.5, h = 0.01;
  const settings = new Jolt.JoltSettings();
  const pairs = new Jolt.ObjectLayerPairFilterTable(1); // no EnableCollision call: layer 0 vs 0 disabled
  const layers = new Jolt.BroadPhaseLayerInterfaceTable(1, 1);
  layers.MapObjectToBroadPhaseLayer(0, new Jolt.BroadPhaseLayer(0));
  settings.mObjectLayerPairFilter = pairs;
  settings.mBroadPhaseLayerInterface = layers;
  settings.mObjectVsBroadPhaseLayerFilter = new Jolt.ObjectVsBroadPhaseLayerFilterTable(layers, 1, pairs, 1);
  const jolt = new Jolt.JoltInterface(settings);
  const system = jolt.GetPhysicsSystem();
  system.SetGravity(new Jolt.Vec3(0, 0, -9.81));
  const physics = system.GetPhysicsSettings();
  physics.mNumPositionSteps = positionSteps;
  system.SetPhysicsSettings(physics);
  const bodies = system.GetBodyInterface();
  const ball = new Jolt.SphereShape(0.1, null);
  const groundSettings = new Jolt.BodyCreationSettings(ball, new Jolt.RVec3(0, 0, 0), new Jolt.Quat(0, 0, 0, 1), Jolt.EMotionType_Static, 0);
  const ground = bodies.CreateBody(groundSettings);
  bodies.AddBody(ground.GetID(), Jolt.EActivation_DontActivate);
  const c = new Jolt.BodyCreationSettings(ball, new Jolt.RVec3(-Math.sin(a), 0, -Math.cos(a)),
                                          new Jolt.Quat(0, Math.sin(a / 2), 0, Math.cos(a / 2)), Jolt.EMotionType_Dynamic, 0);
  c.mOverrideMassProperties = Jolt.EOverrideMassProperties_MassAndInertiaProvided;
  c.mMassPropertiesOverride.mMass = 1;
  c.mMassPropertiesOverride.mInertia = new Jolt.Mat44().sScaleVec3(new Jolt.Vec3(1e-3, 1e-3, 1e-3));
  c.mLinearDamping = 0;
  c.mAngularDamping = 0;
  c.mMaxAngularVelocity = 1e6;
  c.mAllowSleeping = false;
  const bob = bodies.CreateBody(c);
  bodies.AddBody(bob.GetID(), Jolt.EActivation_Activate);
  const hinge = new Jolt.HingeConstraintSettings();
  hinge.mSpace = Jolt.EConstraintSpace_WorldSpace;
  hinge.mPoint1 = hinge.mPoint2 = new Jolt.RVec3(0, 0, 0);
  hinge.mHingeAxis1 = hinge.mHingeAxis2 = new Jolt.Vec3(0, 1, 0);
  hinge.mNormalAxis1 = hinge.mNormalAxis2 = new Jolt.Vec3(1, 0, 0);
  system.AddConstraint(hinge.Create(ground, bob));
  const read = () => {
    const R = rotOf(bob.GetRotation()), x = xyz(bob.GetCenterOfMassPosition()), v = xyz(bob.GetLinearVelocity());
    const wb = mulT(R, xyz(bob.GetAngularVelocity())), arm = mul(R, [0, 0, -1]);
    const energy = (v[0] ** 2 + v[1] ** 2 + v[2] ** 2) / 2 + 1e-3 * (wb[0] ** 2 + wb[1] ** 2 + wb[2] ** 2) / 2 + 9.81 * x[2];
    return { energy, anchor: Math.hypot(x[0] - arm[0], x[1] - arm[1], x[2] - arm[2]) };
  };
  const e0 = read().energy, exchange = e0 + 9.81;
  let anchor = 0, energy = 0;
  for (let k = 0; k < n; k++) {
    jolt.Step(h, 1);
    const r = read();
    anchor = Math.max(anchor, r.anchor);
    energy = Math.max(energy, Math.abs(r.energy - e0) / exchange);
  }
  Jolt.destroy(jolt);
  return { anchor, energy };
}
for (const steps of [2, 8]) {
  const r = pendulum(steps, 100000);
  console.log(`pendulum_large_position_steps_${steps}_anchor_max`, r.anchor.toExponential(6));
  console.log(`pendulum_large_position_steps_${steps}_energy_max`, r.energy.toExponential(6));
}
