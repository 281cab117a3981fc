// cannon_scenarios.mjs -- the audit's rigid-body scenarios (scenarios.mjs: the pendulums, the heavy top, the double
// pendulum, chain5, the four-bar loop, the free bodies) in cannon-es (double precision JavaScript): a Body a body, its
// mass and principal moments set directly (Body.inertia and invInertia, then updateInertiaWorld; no shape), damping 0
// (cannon-es's defaults are 0.01), at its centre of mass, started at its pose and velocity; a hinge a HingeConstraint
// (axis y), a ball a PointToPointConstraint, their pivots in each body's frame, to a static Body (mass 0) at the origin
// or between links; World.gravity the scenario's (9.81 along -z, or none). Kepler's central force set in Body.force
// before each step. 1e5 steps of World.step(h) (h 0.01; the heavy top's 0.002, the boxes' 0.0025, the projectile's
// 1e-4). Printed for each: the largest anchor and loop separations (m), or angular momentum change, and energy change
// (scenarios.mjs's longRun); a free body's or pendulum's order study besides (scenarios.mjs's orderStudy: each class's
// error at tEnd in n = steps0 .. 16384 steps).
// Run: node cannon_scenarios.mjs PATH/TO/node_modules/cannon-es/dist/cannon-es.js
// Output: lines "name value". Uses only cannon-es and plain JavaScript.
import { readFileSync } from 'fs';
import { dirname } from 'path';
import { pathToFileURL } from 'url';
import { SHAPE_MASS, bodiesAtStart, centralForce, gravitation, hullPoints, longRun, orderStudy, parts, shapeLines, quaternionOf, scenarios, sub } from './scenarios.mjs';
const entry = process.argv[2];
if (!entry) { console.error('usage: node cannon_scenarios.mjs PATH/TO/node_modules/cannon-es/dist/cannon-es.js'); process.exit(1); }
const pkg = JSON.parse(readFileSync(dirname(dirname(entry)) + '/package.json', 'utf8'));
const CANNON = await import(pathToFileURL(entry).href);
console.log('cannon_es_version', pkg.version);

const v3 = (a) => new CANNON.Vec3(a[0], a[1], a[2]);
const xyz = (v) => [v.x, v.y, v.z];
const Y = v3([0, 1, 0]);

function world(s, h = s.h) {
  const w = new CANNON.World();
  w.gravity.set(0, 0, -s.gravity);
  const ground = new CANNON.Body({ mass: 0 });
  w.addBody(ground);
  const of = parts(s);
  const made = bodiesAtStart(s).map((start, k) => {
    const b = new CANNON.Body({ mass: of[k].mass, linearDamping: 0, angularDamping: 0 });
    const [i1, i2, i3] = of[k].inertia;
    b.inertia.set(i1, i2, i3);
    b.invInertia.set(1 / i1, 1 / i2, 1 / i3);
    const q = quaternionOf(start.rotation);
    b.quaternion.copy(new CANNON.Quaternion(q.x, q.y, q.z, q.w));
    b.position.copy(v3(start.x));
    b.velocity.copy(v3(start.v));
    b.angularVelocity.copy(v3(start.w));
    b.updateInertiaWorld(true);
    w.addBody(b);
    return b;
  });
  if (s.joint !== 'free' && !s.links) {
    const pivot = v3(s.com.map((c) => -c)); // the pivot in the body's frame
    w.addConstraint(s.joint === 'ball' ? new CANNON.PointToPointConstraint(ground, v3([0, 0, 0]), made[0], pivot)
      : new CANNON.HingeConstraint(ground, made[0], { pivotA: v3([0, 0, 0]), axisA: Y, pivotB: pivot, axisB: Y }));
  } else if (s.links) {
    s.links.forEach((l, k) => {
      const parentCom = k === 0 ? [0, 0, 0] : s.links[k - 1].com;
      w.addConstraint(new CANNON.HingeConstraint(k === 0 ? ground : made[k - 1], made[k],
        { pivotA: v3(sub(l.hinge, parentCom)), axisA: Y, pivotB: v3(l.com.map((c) => -c)), axisB: Y }));
    });
    if (s.loop) {
      const last = s.links.length - 1;
      w.addConstraint(new CANNON.HingeConstraint(made[last], ground,
        { pivotA: v3(sub(s.loop.point, s.links[last].com)), axisA: Y, pivotB: v3(s.loop.anchor), axisB: Y }));
    }
  }
  const m = new CANNON.Mat3();
  return {
    step() {
      if (s.central) made[0].force.set(...centralForce(s, xyz(made[0].position)));
      for (const [a, c, f] of s.gravitation ? gravitation(s, made.map((b) => xyz(b.position))) : []) {
        made[a].force.vadd(v3(f), made[a].force);
        made[c].force.vsub(v3(f), made[c].force);
      }
      w.step(h);
    },
    frames: () => made.map((b) => {
      m.setRotationFromQuaternion(b.quaternion);
      return { rotation: Array.from(m.elements), x: xyz(b.position), v: xyz(b.velocity), w: xyz(b.angularVelocity) };
    }),
    free() {},
  };
}

for (const [name, s] of Object.entries(scenarios)) {
  longRun(`${name}_World.step`, s, world(s), 100000);
  await orderStudy(`${name}_World.step`, name, s, (h) => world(s, h));
}

// The shapes: a Body of mass 2 with the shape added (Body.addShape computes Body.inertia); the cylinder a Cylinder of
// 32 segments along its y; the hull a ConvexPolyhedron of the tetrahedron's faces. No capsule, no cone.
shapeLines((name, [a, b, c]) => {
  const body = new CANNON.Body({ mass: SHAPE_MASS });
  if (name === 'box') body.addShape(new CANNON.Box(v3([a / 2, b / 2, c / 2])));
  else if (name === 'sphere') body.addShape(new CANNON.Sphere(a));
  else if (name === 'cylinder') body.addShape(new CANNON.Cylinder(a, a, b, 32));
  else if (name === 'two_spheres') for (const x of [b, -b]) body.addShape(new CANNON.Sphere(a), v3([x, 0, 0]));
  else if (name === 'convex_hull')
    body.addShape(new CANNON.ConvexPolyhedron({ vertices: hullPoints([a, b, c]).map(v3), faces: [[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]] }));
  else return null;
  return xyz(body.inertia);
});
