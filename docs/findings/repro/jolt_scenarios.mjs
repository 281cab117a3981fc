// jolt_scenarios.mjs -- the audit's rigid-body scenarios (scenarios.mjs: the pendulums, the heavy top, the double
// pendulum, chain5, the four-bar loop, the free bodies) in Jolt Physics (npm jolt-physics, single precision WASM):
// every scenario at its defaults (mApplyGyroscopicForce false, PhysicsSettings' mNumVelocitySteps 10 and
// mNumPositionSteps 2), the jointed ones at 8 position steps and at 40 velocity steps, the free ones with the
// gyroscopic force on. A dynamic Body a body, a 0.1 m sphere shape with its mass properties overridden
// (EOverrideMassProperties_MassAndInertiaProvided: the mass, the principal moments as diag(I)), damping 0 (Jolt's
// defaults are 0.05), the angular velocity's clamp raised to 1e6, sleeping off, one object layer whose pair is not
// enabled (nothing collides), started at its pose and velocity; a hinge a HingeConstraint (axis y, normal axis x), a
// ball a PointConstraint, each in world space at the joint's point, to a static body at the origin or between links;
// the system's gravity the scenario's (9.81 along -z, or none). Kepler's central force by BodyInterface.AddForce before
// each step. 1e5 steps of JoltInterface.Step(h, 1) (h 0.01; the heavy top's 0.002, the boxes' 0.0025, the projectile's
// 1e-4). Printed for each: the largest anchor and loop separations (m), or angular momentum change, and energy change
// (scenarios.mjs's longRun); a free body's or pendulum's order study besides (scenarios.mjs's orderStudy: each class's
// error at tEnd in n = steps0 .. 16384 steps).
// Run: node jolt_scenarios.mjs PATH/TO/node_modules/jolt-physics/dist/jolt-physics.wasm-compat.js
// Output: lines "name value". Uses only Jolt and plain JavaScript.
import { readFileSync } from 'fs';
import { dirname } from 'path';
import { pathToFileURL } from 'url';
import { SHAPE_MASS, bodiesAtStart, centralForce, gravitation, hullPoints, longRun, orderStudy, parts, shapeLines, quaternionOf, rotationOf, scenarios } from './scenarios.mjs';
const entry = process.argv[2];
if (!entry) { console.error('usage: node jolt_scenarios.mjs PATH/TO/node_modules/jolt-physics/dist/jolt-physics.wasm-compat.js'); process.exit(1); }
const pkg = JSON.parse(readFileSync(dirname(dirname(entry)) + '/package.json', 'utf8'));
const Jolt = await (await import(pathToFileURL(entry).href)).default();
console.log('jolt_version', pkg.version);

const xyz = (v) => [v.GetX(), v.GetY(), v.GetZ()];
const quaternion = (q) => ({ x: q.GetX(), y: q.GetY(), z: q.GetZ(), w: q.GetW() });

function world(s, { velocitySteps, positionSteps, gyroscopic }, h = s.h) {
  const settings = new Jolt.JoltSettings();
  const pairs = new Jolt.ObjectLayerPairFilterTable(1); // no EnableCollision call: layer 0 vs 0 disabled
  const layers = new Jolt.BroadPhaseLayerInterfaceTable(1, 1);
  layers.MapObjectToBroadPhaseLayer(0, new Jolt.BroadPhaseLayer(0));
  settings.mObjectLayerPairFilter = pairs;
  settings.mBroadPhaseLayerInterface = layers;
  settings.mObjectVsBroadPhaseLayerFilter = new Jolt.ObjectVsBroadPhaseLayerFilterTable(layers, 1, pairs, 1);
  const jolt = new Jolt.JoltInterface(settings);
  const system = jolt.GetPhysicsSystem();
  system.SetGravity(new Jolt.Vec3(0, 0, -s.gravity));
  const physics = system.GetPhysicsSettings();
  physics.mNumVelocitySteps = velocitySteps;
  physics.mNumPositionSteps = positionSteps;
  system.SetPhysicsSettings(physics);
  const bodies = system.GetBodyInterface();
  const shape = new Jolt.SphereShape(0.1, null);
  let ground = null;
  const fixed = () => {
    if (ground) return ground;
    ground = bodies.CreateBody(new Jolt.BodyCreationSettings(shape, new Jolt.RVec3(0, 0, 0), new Jolt.Quat(0, 0, 0, 1), Jolt.EMotionType_Static, 0));
    bodies.AddBody(ground.GetID(), Jolt.EActivation_DontActivate);
    return ground;
  };
  const hinge = (point, a, b) => {
    const c = new Jolt.HingeConstraintSettings();
    c.mSpace = Jolt.EConstraintSpace_WorldSpace;
    c.mPoint1 = c.mPoint2 = new Jolt.RVec3(...point);
    c.mHingeAxis1 = c.mHingeAxis2 = new Jolt.Vec3(0, 1, 0);
    c.mNormalAxis1 = c.mNormalAxis2 = new Jolt.Vec3(1, 0, 0);
    system.AddConstraint(c.Create(a, b));
  };
  const ball = (point, a, b) => {
    const c = new Jolt.PointConstraintSettings();
    c.mSpace = Jolt.EConstraintSpace_WorldSpace;
    c.mPoint1 = c.mPoint2 = new Jolt.RVec3(...point);
    system.AddConstraint(c.Create(a, b));
  };
  const of = parts(s), made = [];
  // Each body made, then its joint to its parent (the static body made at the first joint, after the first body).
  bodiesAtStart(s).forEach((start, k) => {
    const q = quaternionOf(start.rotation);
    const c = new Jolt.BodyCreationSettings(shape, new Jolt.RVec3(...start.x), new Jolt.Quat(q.x, q.y, q.z, q.w), Jolt.EMotionType_Dynamic, 0);
    c.mOverrideMassProperties = Jolt.EOverrideMassProperties_MassAndInertiaProvided;
    c.mMassPropertiesOverride.mMass = of[k].mass;
    c.mMassPropertiesOverride.mInertia = new Jolt.Mat44().sScaleVec3(new Jolt.Vec3(...of[k].inertia));
    c.mLinearDamping = 0;
    c.mAngularDamping = 0;
    c.mMaxAngularVelocity = 1e6;
    c.mAllowSleeping = false;
    c.mApplyGyroscopicForce = gyroscopic;
    const b = bodies.CreateBody(c);
    bodies.AddBody(b.GetID(), Jolt.EActivation_Activate);
    b.SetLinearVelocity(new Jolt.Vec3(...start.v));
    b.SetAngularVelocity(new Jolt.Vec3(...start.w));
    made.push(b);
    if (s.joint !== 'free') (s.joint === 'ball' ? ball : hinge)(start.pivot, k === 0 ? fixed() : made[k - 1], b);
  });
  if (s.loop) hinge(s.loop.anchor, made[made.length - 1], fixed());
  const force = new Jolt.Vec3(0, 0, 0);
  return {
    step() {
      const push = (k, f) => {
        force.Set(...f);
        bodies.AddForce(made[k].GetID(), force, Jolt.EActivation_Activate);
      };
      if (s.central) push(0, centralForce(s, xyz(made[0].GetCenterOfMassPosition())));
      for (const [a, c, f] of s.gravitation ? gravitation(s, made.map((b) => xyz(b.GetCenterOfMassPosition()))) : []) {
        push(a, f);
        push(c, f.map((x) => -x));
      }
      jolt.Step(h, 1);
    },
    frames: () => made.map((b) => ({ rotation: rotationOf(quaternion(b.GetRotation())), x: xyz(b.GetCenterOfMassPosition()),
                                     v: xyz(b.GetLinearVelocity()), w: xyz(b.GetAngularVelocity()) })),
    free: () => Jolt.destroy(jolt),
  };
}

const settings = [
  ['default', { velocitySteps: 10, positionSteps: 2, gyroscopic: false }, () => true],
  ['position_steps_8', { velocitySteps: 10, positionSteps: 8, gyroscopic: false }, (s) => s.joint !== 'free'],
  ['velocity_steps_40', { velocitySteps: 40, positionSteps: 2, gyroscopic: false }, (s) => s.joint !== 'free'],
  ['gyroscopic', { velocitySteps: 10, positionSteps: 2, gyroscopic: true }, (s) => s.joint === 'free'],
];
for (const [setting, chosen, runs] of settings)
  for (const [name, s] of Object.entries(scenarios)) {
    if (!runs(s)) continue;
    const w = world(s, chosen);
    longRun(`${name}_${setting}`, s, w, 100000);
    w.free();
    await orderStudy(`${name}_${setting}`, name, s, (h) => world(s, chosen, h));
  }

// The shapes: Shape.GetMassProperties() (about the centre of mass, at Jolt's density) scaled to mass 2; the axis (z)
// Jolt's y for the cylinder, the capsule and the cone (a TaperedCylinderShape of top radius 0); convex radius 0 where
// a shape takes one.
const created = (settings) => {
  const result = settings.Create();
  if (result.HasError()) throw new Error(result.GetError().c_str());
  return result.Get();
};
shapeLines((name, [a, b, c]) => {
  let shape;
  if (name === 'box') shape = new Jolt.BoxShape(new Jolt.Vec3(a / 2, b / 2, c / 2), 0);
  else if (name === 'sphere') shape = new Jolt.SphereShape(a);
  else if (name === 'cylinder') shape = new Jolt.CylinderShape(b / 2, a, 0);
  else if (name === 'capsule') shape = new Jolt.CapsuleShape(b / 2, a);
  else if (name === 'cone') shape = created(new Jolt.TaperedCylinderShapeSettings(b / 2, 0, a, 0));
  else if (name === 'convex_hull') {
    const hull = new Jolt.ConvexHullShapeSettings();
    for (const p of hullPoints([a, b, c])) hull.mPoints.push_back(new Jolt.Vec3(...p));
    hull.mMaxConvexRadius = 0;
    shape = created(hull);
  } else if (name === 'two_spheres') {
    const compound = new Jolt.StaticCompoundShapeSettings(), ball = new Jolt.SphereShapeSettings(a);
    for (const x of [b, -b]) compound.AddShape(new Jolt.Vec3(x, 0, 0), new Jolt.Quat(0, 0, 0, 1), ball, 0);
    shape = created(compound);
  } else return null;
  const p = shape.GetMassProperties();
  return xyz(p.mInertia.GetDiagonal3()).map((x) => (x * SHAPE_MASS) / p.mMass);
});
