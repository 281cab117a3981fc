#!/usr/bin/env node
// Havok (npm @babylonjs/havok: the physics of Babylon.js, WebAssembly) served to mechcheck's
// audit as an engine (docs/protocol.md): HP_World_Step at a fixed step, on every scenario it
// can express: free bodies, a hinge or a ball to the world, the chains and the four-bar loop.
//
//   mechcheck-audit -o report --exec-engine -- node examples/exec/node/havok_engine.mjs
//
// The scenario's model: a DYNAMIC body per body with a sphere shape of radius 0.1 and its mass
// properties given by HP_Body_SetMassProperties -- the centre of mass at the body's origin,
// the mass, and the principal moments divided by the mass (HavokPhysics.d.ts: "Inertia for
// mass of 1") -- linear and angular damping set to 0, always active; gravity the world's.
// The ideal step time (HavokPhysics.d.ts: the solver parameters are "automatically adjusted"
// when a step differs from it, default 1/60) is set to each step's h. Havok takes no force
// from JavaScript, only impulses: the central force and the mutual gravitation are given as
// the impulse F h at each step's start (HP_Body_ApplyImpulse at the centre of mass). A hinge
// about y locks a constraint's three linear axes and its angular Y and Z, its X along world
// y; a ball its linear axes; each to a STATIC body at the origin or between links, their
// anchors in each body's frame at the start. Havok computes in single precision (float) in
// this build.
import HavokPhysics from '@babylonjs/havok';
import { readFileSync } from 'node:fs';
import { chainLinks, oneBodyStart, quaternionOf, rotate, sub } from './bodies.mjs';
import { Refused, frame, hullPoints, scenarioOf, serveEngine } from './protocol.mjs';

const root = new URL('./node_modules/@babylonjs/havok/', import.meta.url);
// Each run in a Havok instance of its own: a run's last digits depend on what its instance built before (the
// four-bar in an instance that has built the five other jointed scenarios' worlds leaves its anchors up to
// 6.489966e-3 m apart, in a fresh one 6.473416e-3), and a run's numbers should be those of its setup alone. The module is compiled once; an instance takes ~7 ms.
const compiled = await WebAssembly.compile(readFileSync(new URL('lib/esm/HavokPhysics.wasm', root)));
const instance = () =>
  HavokPhysics({
    instantiateWasm(imports, done) {
      WebAssembly.instantiate(compiled, imports).then((i) => done(i, compiled));
      return {};
    },
  });
/** The instance the shapes are built in. */
const HK = await instance();
const version = JSON.parse(readFileSync(new URL('package.json', root))).version;

/** The value of a Havok call that returns [result, value]; its result checked (by its number: each instance
 * has enum objects of its own). */
function ok(what, r) {
  const [result, ...value] = Array.isArray(r) ? r : [r];
  if (result?.value !== HK.Result.RESULT_OK.value) throw new Error(`Havok ${version}: ${what}: result ${result?.value}`);
  return value.length === 1 ? value[0] : value;
}
/** Row-major rotation of a quaternion [x, y, z, w]. */
function rotationOf([x, y, z, w]) {
  return [
    1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y),
    2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x),
    2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y),
  ];
}
/** R^T x, for R row-major: a world vector in the body's frame. */
const inBody = (r, x) => [0, 1, 2].map((j) => r[j] * x[0] + r[3 + j] * x[1] + r[6 + j] * x[2]);

const integrators = [
  {
    name: 'step',
    origin:
      'HP_World_Step with the ideal step time set to h; contact: a shape a body (box, sphere, cylinder), the ground a ' +
      'static box 200 m wide whose top face is the plane, every shape the material [mu, mu, e] combined by MINIMUM ' +
      '(every pair mu and e), damping 0, ALWAYS_ACTIVE, the solver at its defaults',
    // HavokPhysics.d.ts names a material's fields and nothing of how they act: no claim.
    contact: {
      words:
        'HavokPhysics.d.ts: PhysicsMaterial [static friction, dynamic friction, restitution, friction combine mode, ' +
        'restitution combine mode]; nothing of a cone, a restitution law or a soft contact',
    },
  },
];

class Run {
  constructor(HK, integrator, scenario) {
    this.HK = HK;
    if (!integrators.some((i) => i.name === integrator)) throw new Refused(`no integrator ${integrator}`);
    const s = scenarioOf(scenario);
    this.s = s;
    this.world = ok('HP_World_Create', HK.HP_World_Create());
    ok('HP_World_SetGravity', HK.HP_World_SetGravity(this.world, [0, 0, -s.gravity]));
    this.shape = ok('HP_Shape_CreateSphere', HK.HP_Shape_CreateSphere([0, 0, 0], 0.1));
    this.handles = [];
    const make = (motion, mass, inertia, rotation, position, velocity, omega, shape = this.shape) => {
      const b = ok('HP_Body_Create', HK.HP_Body_Create());
      this.handles.push(b);
      ok('HP_Body_SetShape', HK.HP_Body_SetShape(b, shape));
      ok('HP_Body_SetMotionType', HK.HP_Body_SetMotionType(b, motion));
      if (motion === HK.MotionType.DYNAMIC) {
        ok('HP_Body_SetMassProperties', HK.HP_Body_SetMassProperties(b, [[0, 0, 0], mass, inertia.map((i) => i / mass), [0, 0, 0, 1]]));
        ok('HP_Body_SetLinearDamping', HK.HP_Body_SetLinearDamping(b, 0));
        ok('HP_Body_SetAngularDamping', HK.HP_Body_SetAngularDamping(b, 0));
      }
      const q = quaternionOf(rotation);
      ok('HP_Body_SetQTransform', HK.HP_Body_SetQTransform(b, [position, [q.x, q.y, q.z, q.w]]));
      ok('HP_World_AddBody', HK.HP_World_AddBody(this.world, b, false));
      if (motion === HK.MotionType.DYNAMIC) {
        ok('HP_Body_SetActivationControl', HK.HP_Body_SetActivationControl(b, HK.ActivationControl.ALWAYS_ACTIVE));
        ok('HP_Body_SetLinearVelocity', HK.HP_Body_SetLinearVelocity(b, velocity));
        ok('HP_Body_SetAngularVelocity', HK.HP_Body_SetAngularVelocity(b, omega));
      }
      return { id: b, rotation, position };
    };
    const identity = [1, 0, 0, 0, 1, 0, 0, 0, 1];
    let ground = null;
    const fixed = () => (ground ??= make(HK.MotionType.STATIC, 0, [0, 0, 0], identity, [0, 0, 0], [0, 0, 0], [0, 0, 0]));
    // A joint at a world point between two bodies as they are at the start: a hinge about world
    // y (constraint X along y, Y along x) or a ball.
    const joint = (point, parent, child, hinge) => {
      const c = ok('HP_Constraint_Create', HK.HP_Constraint_Create());
      this.handles.push(null);
      ok('HP_Constraint_SetParentBody', HK.HP_Constraint_SetParentBody(c, parent.id));
      ok('HP_Constraint_SetChildBody', HK.HP_Constraint_SetChildBody(c, child.id));
      for (const [set, b] of [[HK.HP_Constraint_SetAnchorInParent, parent], [HK.HP_Constraint_SetAnchorInChild, child]])
        ok('HP_Constraint_SetAnchor', set(c, inBody(b.rotation, sub(point, b.position)), inBody(b.rotation, [0, 1, 0]), inBody(b.rotation, [1, 0, 0])));
      const locked = [HK.ConstraintAxis.LINEAR_X, HK.ConstraintAxis.LINEAR_Y, HK.ConstraintAxis.LINEAR_Z];
      if (hinge) locked.push(HK.ConstraintAxis.ANGULAR_Y, HK.ConstraintAxis.ANGULAR_Z);
      for (const axis of locked) ok('HP_Constraint_SetAxisMode', HK.HP_Constraint_SetAxisMode(c, axis, HK.ConstraintAxisLimitMode.LOCKED));
      ok('HP_Constraint_SetEnabled', HK.HP_Constraint_SetEnabled(c, 1));
    };
    this.bodies = [];
    if (s.structure === 'one_body') {
      const { com: x, velocity: v } = oneBodyStart(s);
      const b = make(HK.MotionType.DYNAMIC, s.mass, s.inertia, s.rotation0, x, v, s.omega0);
      this.bodies.push(b);
      if (s.joint !== 'free') joint([0, 0, 0], fixed(), b, s.joint === 'hinge_y');
    } else if (s.structure === 'chain') {
      let parent = null;
      chainLinks(s).forEach((start, k) => {
        const b = make(HK.MotionType.DYNAMIC, s.links[k].mass, s.links[k].inertia, start.rotation, start.com, start.velocity, start.omega);
        this.bodies.push(b);
        joint(sub(start.com, rotate(start.rotation, s.links[k].com)), parent ?? fixed(), b, true);
        parent = b;
      });
      if (s.loop) joint(s.loop.anchor, fixed(), parent, true);
    } else if (s.structure === 'contact') {
      // A shape a body (HP_Shape_CreateBox of the edges, a sphere, a cylinder along y), the
      // ground a static box 200 m wide and 2 m deep whose top face is the plane; every shape
      // the material [mu, mu, e] combined by MINIMUM (every pair: mu and e).
      const c = s.contact;
      const material = [c.mu, c.mu, c.restitution, HK.MaterialCombine.MINIMUM, HK.MaterialCombine.MINIMUM];
      const shaped = (sh) => {
        ok('HP_Shape_SetMaterial', HK.HP_Shape_SetMaterial(sh, material));
        return sh;
      };
      if (c.ground) {
        const plane = shaped(ok('HP_Shape_CreateBox', HK.HP_Shape_CreateBox([0, 0, -1], [0, 0, 0, 1], [200, 200, 2])));
        const turn = [Math.cos(c.slope), 0, Math.sin(c.slope), 0, 1, 0, -Math.sin(c.slope), 0, Math.cos(c.slope)];
        make(HK.MotionType.STATIC, 0, [0, 0, 0], turn, [0, 0, 0], [0, 0, 0], [0, 0, 0], plane);
      }
      for (const k of c.bodies) {
        const [r, y, z] = k.size;
        const sh = k.shape === 'box' ? ok('HP_Shape_CreateBox', HK.HP_Shape_CreateBox([0, 0, 0], [0, 0, 0, 1], [2 * r, 2 * y, 2 * z]))
          : k.shape === 'sphere' ? ok('HP_Shape_CreateSphere', HK.HP_Shape_CreateSphere([0, 0, 0], r))
          : k.shape === 'cylinder' ? ok('HP_Shape_CreateCylinder', HK.HP_Shape_CreateCylinder([0, -y, 0], [0, y, 0], r))
          : null;
        if (sh === null) throw new Refused(`this client builds no ${k.shape} in Havok ${version}`);
        this.bodies.push(make(HK.MotionType.DYNAMIC, k.mass, k.inertia, k.rotation0, k.position0, k.velocity0, k.omega0, shaped(sh)));
      }
    } else {
      for (const l of s.links) this.bodies.push(make(HK.MotionType.DYNAMIC, l.mass, l.inertia, identity, l.position0, l.velocity0, [0, 0, 0]));
    }
    this.masses = s.structure === 'one_body' ? [s.mass] : s.structure === 'contact' ? s.contact.bodies.map((b) => b.mass) : s.links.map((l) => l.mass);
    this.steps = 0;
  }

  position(k) {
    const HK = this.HK;
    return ok('HP_Body_GetQTransform', HK.HP_Body_GetQTransform(this.bodies[k].id))[0];
  }

  applyImpulses(h) {
    const HK = this.HK;
    const s = this.s;
    const impulse = (k, f) => ok('HP_Body_ApplyImpulse', HK.HP_Body_ApplyImpulse(this.bodies[k].id, this.position(k), f.map((x) => x * h)));
    if (s.central !== 0) {
      const x = this.position(0), r = Math.hypot(...x);
      impulse(0, x.map((xi) => (-s.mass * s.central * xi) / (r * r * r)));
    }
    if (s.gravitation !== 0)
      for (let a = 0; a < this.bodies.length; ++a)
        for (let c = a + 1; c < this.bodies.length; ++c) {
          const xa = this.position(a), r = sub(this.position(c), xa), d = Math.hypot(...r);
          const f = r.map((ri) => ((s.gravitation * this.masses[a] * this.masses[c]) / (d * d * d)) * ri);
          impulse(a, f);
          impulse(c, f.map((x) => -x));
        }
  }

  step(h) {
    const HK = this.HK;
    if (!(h > 0)) throw new Error(`Havok ${version}: HP_World_Step takes a positive step, got ${h}`);
    ++this.steps;
    ok('HP_World_SetIdealStepTime', HK.HP_World_SetIdealStepTime(this.world, h));
    this.applyImpulses(h);
    ok('HP_World_Step', HK.HP_World_Step(this.world, h));
    for (let k = 0; k < this.bodies.length; ++k)
      for (const x of [...this.position(k), ...ok('v', HK.HP_Body_GetLinearVelocity(this.bodies[k].id))])
        if (!Number.isFinite(x)) throw new Error(`Havok ${version}: step ${this.steps}: the state is not finite`);
  }

  reading() {
    const HK = this.HK;
    const frames = this.bodies.map((b) => {
      const [x, q] = ok('HP_Body_GetQTransform', HK.HP_Body_GetQTransform(b.id));
      return frame(rotationOf(q), x, ok('v', HK.HP_Body_GetLinearVelocity(b.id)), ok('w', HK.HP_Body_GetAngularVelocity(b.id)));
    });
    return this.s.structure === 'one_body' ? { frame: frames[0] } : { links: frames };
  }

  free() {
    const HK = this.HK;
    HK.HP_World_Release(this.world);
  }
}

/** A shape in Havok; the audit's axis (z) is the cylinder's and capsule's. */
function shapeOf(shape) {
  const [a, b, c] = shape.size;
  if (shape.name === 'box') return ok('box', HK.HP_Shape_CreateBox([0, 0, 0], [0, 0, 0, 1], [a, b, c]));
  if (shape.name === 'sphere') return ok('sphere', HK.HP_Shape_CreateSphere([0, 0, 0], a));
  if (shape.name === 'cylinder') return ok('cylinder', HK.HP_Shape_CreateCylinder([0, 0, -b / 2], [0, 0, b / 2], a));
  if (shape.name === 'capsule') return ok('capsule', HK.HP_Shape_CreateCapsule([0, 0, -b / 2], [0, 0, b / 2], a));
  if (shape.name === 'two_spheres') {
    const sh = ok('container', HK.HP_Shape_CreateContainer());
    for (const x of [b, -b]) {
      const ball = ok('sphere', HK.HP_Shape_CreateSphere([0, 0, 0], a));
      ok('HP_Shape_AddChild', HK.HP_Shape_AddChild(sh, ball, [[x, 0, 0], [0, 0, 0, 1], [1, 1, 1]]));
    }
    return sh;
  }
  if (shape.name === 'convex_hull') {
    // The points in the WebAssembly heap, as the declarations ask ("allocated using `_malloc`").
    const points = hullPoints(shape).flat(), at = HK._malloc(4 * points.length);
    try {
      new Float32Array(HK.HEAPU8.buffer, at, points.length).set(points);
      return ok('HP_Shape_CreateConvexHull', HK.HP_Shape_CreateConvexHull(at, points.length / 3));
    } finally {
      HK._free(at);
    }
  }
  throw new Refused(`this client builds no ${shape.name} in Havok ${version}`);
}

/** The principal moments Havok computes for a shape: HP_Shape_BuildMassProperties (at the
 * shape's default density; its inertia is "for mass of 1", so times the shape's mass). */
function moments(shape) {
  const [, , inertia] = ok('HP_Shape_BuildMassProperties', HK.HP_Shape_BuildMassProperties(shapeOf(shape)));
  return inertia.map((i) => i * shape.mass).sort((x, y) => x - y);
}

/** What Havok gives a dynamic body with the shape and no HP_Body_SetMassProperties:
 * HP_Body_GetMassProperties ("the mass properties currently used by the body"), its inertia
 * per unit mass times the mass. */
function withoutMass(shape) {
  const sh = shapeOf(shape);
  const b = ok('HP_Body_Create', HK.HP_Body_Create());
  try {
    ok('HP_Body_SetShape', HK.HP_Body_SetShape(b, sh));
    ok('HP_Body_SetMotionType', HK.HP_Body_SetMotionType(b, HK.MotionType.DYNAMIC));
    const [, mass, inertia] = ok('HP_Body_GetMassProperties', HK.HP_Body_GetMassProperties(b));
    const [, built] = ok('HP_Shape_BuildMassProperties', HK.HP_Shape_BuildMassProperties(sh));
    return {
      mass,
      moments: inertia.map((i) => i * mass),
      said:
        'HP_Body_GetMassProperties after HP_Body_SetShape and HP_Body_SetMotionType(DYNAMIC); ' +
        `HP_Shape_BuildMassProperties of the shape gives mass ${built} (its density, HP_Shape_SetDensity: ` +
        '"Used when calling `HP_Shape_BuildMassProperties()`"), not applied to the body',
    };
  } finally {
    HK.HP_Body_Release(b);
    HK.HP_Shape_Release(sh);
  }
}

await serveEngine(
  {
    name: 'havok',
    origin:
      `Havok ${version} (npm @babylonjs/havok, WebAssembly) in Node ${process.version}: HP_World_Step ` +
      '("Simulate the world and advance time by `timestep` seconds", HavokPhysics.d.ts); no order declared',
    integrators,
  },
  async (integrator, scenario) => new Run(await instance(), integrator, scenario),
  moments,
  withoutMass,
);
