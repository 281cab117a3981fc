// rapier_scenarios.mjs -- the audit's rigid-body scenarios (scenarios.mjs: the pendulums, the heavy top, the double
// pendulum, chain5, the four-bar loop, the free bodies) in Rapier (@dimforge/rapier3d-compat, single precision WASM),
// each at World.numSolverIterations 4 (its default) and 16: a dynamic RigidBody a body, its mass and principal moments
// by setAdditionalMassProperties (centre of mass at the body's origin, no collider), damping 0, sleeping off, started
// at its pose and velocity; a hinge a JointData.revolute (axis y), a ball a JointData.spherical, each an impulse joint
// to a fixed body at the origin or between links, their anchors in each body's frame; the World's gravity the
// scenario's (9.81 along -z, or none). Kepler's central force by addForce before each step (its forces reset first).
// 1e5 steps of world.step() with world.timestep = h (0.01; the heavy top's 0.002, the boxes' 0.0025, the projectile's
// 1e-4). Printed for each: the largest anchor and loop separations (m), or angular momentum change, and energy change
// (scenarios.mjs's longRun); a free body's or pendulum's order study besides (scenarios.mjs's orderStudy: each class's
// error at tEnd in n = steps0 .. 16384 steps).
// Run: node rapier_scenarios.mjs PATH/TO/node_modules/@dimforge/rapier3d-compat
// Output: lines "name value". Uses only Rapier and plain JavaScript.
import { readFileSync } from 'fs';
import { pathToFileURL } from 'url';
import { SHAPE_MASS, bodiesAtStart, centralForce, gravitation, hullPoints, longRun, orderStudy, parts, shapeLines, quaternionOf, rotationOf, scenarios, sub } from './scenarios.mjs';
const dir = process.argv[2];
if (!dir) { console.error('usage: node rapier_scenarios.mjs PATH/TO/node_modules/@dimforge/rapier3d-compat'); process.exit(1); }
const pkg = JSON.parse(readFileSync(dir + '/package.json', 'utf8'));
const RAPIER = (await import(pathToFileURL(dir + '/dist/rapier.mjs').href)).default;
await RAPIER.init();
console.log('rapier_version', pkg.version);

const v3 = (a) => ({ x: a[0], y: a[1], z: a[2] });
const xyz = (v) => [v.x, v.y, v.z];
const Y = v3([0, 1, 0]);

function world(s, iterations, h = s.h) {
  const w = new RAPIER.World(v3([0, 0, -s.gravity]));
  w.numSolverIterations = iterations;
  const ground = w.createRigidBody(RAPIER.RigidBodyDesc.fixed());
  const bodies = parts(s);
  const made = bodiesAtStart(s).map((start, k) =>
    w.createRigidBody(
      RAPIER.RigidBodyDesc.dynamic()
        .setTranslation(...start.x)
        .setRotation(quaternionOf(start.rotation))
        .setLinvel(...start.v)
        .setAngvel(v3(start.w))
        .setAdditionalMassProperties(bodies[k].mass, v3([0, 0, 0]), v3(bodies[k].inertia), { x: 0, y: 0, z: 0, w: 1 })
        .setLinearDamping(0)
        .setAngularDamping(0)
        .setCanSleep(false),
    ));
  const joint = (data, a, b) => w.createImpulseJoint(data, a, b, true);
  if (s.joint !== 'free' && !s.links) {
    const pivot = v3(s.com.map((c) => -c)); // the pivot in the body's frame
    joint(s.joint === 'ball' ? RAPIER.JointData.spherical(v3([0, 0, 0]), pivot) : RAPIER.JointData.revolute(v3([0, 0, 0]), pivot, Y), ground, made[0]);
  } else if (s.links) {
    s.links.forEach((l, k) => {
      const parentCom = k === 0 ? [0, 0, 0] : s.links[k - 1].com;
      joint(RAPIER.JointData.revolute(v3(sub(l.hinge, parentCom)), v3(l.com.map((c) => -c)), Y), k === 0 ? ground : made[k - 1], made[k]);
    });
    if (s.loop) {
      const last = s.links.length - 1;
      joint(RAPIER.JointData.revolute(v3(sub(s.loop.point, s.links[last].com)), v3(s.loop.anchor), Y), made[last], ground);
    }
  }
  return {
    step() {
      if (s.central || s.gravitation) for (const b of made) b.resetForces(true);
      if (s.central) made[0].addForce(v3(centralForce(s, xyz(made[0].translation()))), true);
      for (const [a, c, f] of s.gravitation ? gravitation(s, made.map((b) => xyz(b.translation()))) : []) {
        made[a].addForce(v3(f), true);
        made[c].addForce(v3(f.map((x) => -x)), true);
      }
      w.timestep = h;
      w.step();
    },
    frames: () => made.map((b) => ({ rotation: rotationOf(b.rotation()), x: xyz(b.translation()), v: xyz(b.linvel()), w: xyz(b.angvel()) })),
    free: () => w.free(),
  };
}

for (const [setting, iterations] of [['impulse_joints', 4], ['impulse_joints_16_iterations', 16]])
  for (const [name, s] of Object.entries(scenarios)) {
    const w = world(s, iterations);
    longRun(`${name}_${setting}`, s, w, 100000);
    w.free();
    await orderStudy(`${name}_${setting}`, name, s, (h) => world(s, iterations, h));
  }

// The shapes, each a dynamic body with the shape's collider(s) of mass 2 (ColliderDesc.setMass; the two spheres 1
// each), its principal moments RigidBody.principalInertia(); the axis (z) Rapier's y for the cylinder, the capsule and
// the cone.
shapeLines((name, [a, b, c]) => {
  const w = new RAPIER.World(v3([0, 0, 0]));
  try {
    const body = w.createRigidBody(RAPIER.RigidBodyDesc.dynamic());
    const collider = (desc, at) => w.createCollider(desc.setMass(at ? SHAPE_MASS / 2 : SHAPE_MASS).setTranslation(...(at ?? [0, 0, 0])), body);
    if (name === 'box') collider(RAPIER.ColliderDesc.cuboid(a / 2, b / 2, c / 2));
    else if (name === 'sphere') collider(RAPIER.ColliderDesc.ball(a));
    else if (name === 'cylinder') collider(RAPIER.ColliderDesc.cylinder(b / 2, a));
    else if (name === 'capsule') collider(RAPIER.ColliderDesc.capsule(b / 2, a));
    else if (name === 'cone') collider(RAPIER.ColliderDesc.cone(b / 2, a));
    else if (name === 'two_spheres') for (const x of [b, -b]) collider(RAPIER.ColliderDesc.ball(a), [x, 0, 0]);
    else if (name === 'convex_hull') collider(RAPIER.ColliderDesc.convexHull(new Float32Array(hullPoints([a, b, c]).flat())));
    else return null;
    return xyz(body.principalInertia());
  } finally {
    w.free();
  }
});
