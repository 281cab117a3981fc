#!/usr/bin/env node
// Jolt Physics (npm jolt-physics: the C++ engine compiled to WebAssembly) served to
// mechcheck's audit as an engine (docs/protocol.md): PhysicsSystem.Update through
// JoltInterface.Step at a fixed step, on every scenario it can express: free bodies (the
// tops, the box, a projectile, Kepler's orbit, three bodies), a hinge or a ball to the world
// (the pendulums, the heavy tops), the chains and the four-bar loop.
//
//   mechcheck-audit -o report --exec-engine -- node examples/exec/node/jolt_engine.mjs
//
// The scenario's model: a dynamic Body per body with a sphere shape of radius 0.1 (nothing
// collides: one object layer whose pairs are not enabled) and its mass and principal moments
// given (mOverrideMassProperties = MassAndInertiaProvided, the inertia diag(I) in the body's
// frame), linear and angular damping set to 0 (Jolt's defaults are 0.05 each,
// BodyCreationSettings.h), the angular velocity's clamp raised from its default 0.25 pi 60
// rad/s to 1e6, sleeping off; gravity the PhysicsSystem's; the central force and the mutual
// gravitation added by BodyInterface.AddForce before each step (Jolt clears a body's forces
// after each step). A hinge about y is a HingeConstraint, a ball a PointConstraint, each given
// in world space at the start, to a static body at the origin (the bindings expose no
// Body::sFixedToWorld) or between links; Jolt solves them iteratively (its PhysicsSettings:
// mNumVelocitySteps, mNumPositionSteps). Four integrators: Jolt's defaults
// (mApplyGyroscopicForce off, 10 velocity and 2 position steps), the gyroscopic force on, 40
// velocity steps, 8 position steps.
// Jolt computes in single precision (float) in this build.
import initJolt from 'jolt-physics/wasm-compat';
import { readFileSync } from 'node:fs';
import { chainLinks, oneBodyStart, quaternionOf, rotate, sub } from './bodies.mjs';
import { Refused, frame, hullPoints, scenarioOf, serveEngine } from './protocol.mjs';

const Jolt = await initJolt();
const version = JSON.parse(readFileSync(new URL('./node_modules/jolt-physics/package.json', import.meta.url))).version;

// Each integrator: the gyroscopic flag and the constraint solver's iterations (PhysicsSettings.h:
// mNumVelocitySteps = 10 and mNumPositionSteps = 2 by default; a free body's step reads
// neither).
const integrators = [
  {
    name: 'default',
    origin:
      "BodyCreationSettings.mApplyGyroscopicForce = false (Jolt's default); contact: BoxShape, SphereShape, CylinderShape " +
      '(convex radius 0) and a static PlaneShape ground, every body mFriction mu and mRestitution e (combined by the ' +
      "geometric mean and the maximum, Jolt's defaults: every pair mu and e), damping 0, sleeping off; PhysicsSettings at their defaults " +
      '(mMinVelocityForRestitution 1 m/s: "Minimal velocity needed before a collision can be elastic", ' +
      'mPenetrationSlop 0.02, mBaumgarte 0.2, mSpeculativeContactDistance 0.02)',
    // BodyCreationSettings.h's words: friction and restitution coefficients, their ends
    // described; nothing of a cone, a restitution law or a soft contact.
    contact: {
      words:
        'Jolt BodyCreationSettings.h: mFriction "Friction of the body (dimensionless number, usually between 0 and 1, ' +
        '0 = no friction, 1 = friction force equals force that presses the two bodies together)", mRestitution ' +
        '"Restitution of body (dimensionless number, usually between 0 and 1, 0 = completely inelastic collision ' +
        'response, 1 = completely elastic collision response)"; PhysicsSettings.h: mMinVelocityForRestitution ' +
        '"Minimal velocity needed before a collision can be elastic" (default 1 m/s)',
    },
  },
  {
    name: 'gyroscopic',
    origin:
      'BodyCreationSettings.mApplyGyroscopicForce = true (BodyCreationSettings.h: "Set to indicate that the ' +
      'gyroscopic force should be applied to this body (aka Dzhanibekov effect, see ' +
      'https://en.wikipedia.org/wiki/Tennis_racket_theorem)")',
  },
  {
    name: 'velocity_steps_40',
    origin: "Jolt's defaults but PhysicsSettings.mNumVelocitySteps = 40 (default 10: \"Number of solver velocity iterations to run\")",
  },
  {
    name: 'position_steps_8',
    origin: "Jolt's defaults but PhysicsSettings.mNumPositionSteps = 8 (default 2: \"Number of solver position iterations to run\")",
  },
];
const settingsOf = {
  default: { gyroscopic: false, velocitySteps: 10, positionSteps: 2 },
  gyroscopic: { gyroscopic: true, velocitySteps: 10, positionSteps: 2 },
  velocity_steps_40: { gyroscopic: false, velocitySteps: 40, positionSteps: 2 },
  position_steps_8: { gyroscopic: false, velocitySteps: 10, positionSteps: 8 },
};

const LAYER = 0;
const arr = (v) => [v.GetX(), v.GetY(), v.GetZ()];
/** The rotation (row-major) of a unit quaternion. */
function rotationOf(q) {
  const [x, y, z, w] = [q.GetX(), q.GetY(), q.GetZ(), q.GetW()];
  return [
    1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y),
    2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x),
    2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y),
  ];
}

/** A physics system of one object layer that collides with nothing, or (contact) of two: the
 * ground's (STATIC) and the bodies' (MOVING), the bodies colliding with the ground and with
 * each other. */
const STATIC = 0, MOVING = 1;
function makeSystem(gravity, contact = false) {
  const settings = new Jolt.JoltSettings();
  const n = contact ? 2 : 1;
  const pairs = new Jolt.ObjectLayerPairFilterTable(n);
  const layers = new Jolt.BroadPhaseLayerInterfaceTable(n, n);
  for (let k = 0; k < n; ++k) layers.MapObjectToBroadPhaseLayer(k, new Jolt.BroadPhaseLayer(k));
  if (contact) {
    pairs.EnableCollision(STATIC, MOVING);
    pairs.EnableCollision(MOVING, MOVING);
  }
  settings.mObjectLayerPairFilter = pairs;
  settings.mBroadPhaseLayerInterface = layers;
  settings.mObjectVsBroadPhaseLayerFilter = new Jolt.ObjectVsBroadPhaseLayerFilterTable(layers, n, pairs, n);
  const jolt = new Jolt.JoltInterface(settings);
  Jolt.destroy(settings);
  jolt.GetPhysicsSystem().SetGravity(new Jolt.Vec3(0, 0, -gravity));
  return jolt;
}

class Run {
  constructor(integrator, scenario) {
    if (!Object.hasOwn(settingsOf, integrator)) throw new Refused(`no integrator ${integrator}`);
    const chosen = settingsOf[integrator];
    const s = scenarioOf(scenario);
    this.s = s;
    if (s.structure === 'contact' && integrator !== 'default') throw new Refused(`${integrator} builds no contact scenario (default does)`);
    this.jolt = makeSystem(s.gravity, s.structure === 'contact');
    const physicsSettings = this.jolt.GetPhysicsSystem().GetPhysicsSettings();
    if (physicsSettings.mNumVelocitySteps !== 10 || physicsSettings.mNumPositionSteps !== 2)
      throw new Error(`Jolt's default solver steps read ${physicsSettings.mNumVelocitySteps} and ${physicsSettings.mNumPositionSteps}, not 10 and 2`);
    physicsSettings.mNumVelocitySteps = chosen.velocitySteps;
    physicsSettings.mNumPositionSteps = chosen.positionSteps;
    this.jolt.GetPhysicsSystem().SetPhysicsSettings(physicsSettings);
    const set = this.jolt.GetPhysicsSystem().GetPhysicsSettings();
    if (set.mNumVelocitySteps !== chosen.velocitySteps || set.mNumPositionSteps !== chosen.positionSteps)
      throw new Error('the solver steps were not set');
    const bodies = this.jolt.GetPhysicsSystem().GetBodyInterface();
    this.interface = bodies;
    this.shape = new Jolt.SphereShape(0.1, null);
    const body = (mass, inertia, rotation, position, velocity, omega, shape = this.shape, material = null) => {
      const q = quaternionOf(rotation);
      const c = new Jolt.BodyCreationSettings(shape, new Jolt.RVec3(...position), new Jolt.Quat(q.x, q.y, q.z, q.w),
                                              Jolt.EMotionType_Dynamic, material ? MOVING : LAYER);
      if (material) material(c);
      c.mOverrideMassProperties = Jolt.EOverrideMassProperties_MassAndInertiaProvided;
      c.mMassPropertiesOverride.mMass = mass;
      c.mMassPropertiesOverride.mInertia = new Jolt.Mat44().sScaleVec3(new Jolt.Vec3(...inertia));
      c.mLinearDamping = 0;
      c.mAngularDamping = 0;
      c.mMaxAngularVelocity = 1e6;
      c.mAllowSleeping = false;
      c.mApplyGyroscopicForce = chosen.gyroscopic;
      const b = bodies.CreateBody(c);
      Jolt.destroy(c);
      bodies.AddBody(b.GetID(), Jolt.EActivation_Activate);
      b.SetLinearVelocity(new Jolt.Vec3(...velocity));
      b.SetAngularVelocity(new Jolt.Vec3(...omega));
      return b;
    };
    const physics = this.jolt.GetPhysicsSystem();
    let ground = null;
    const fixed = () => {
      if (ground) return ground;
      const c = new Jolt.BodyCreationSettings(this.shape, new Jolt.RVec3(0, 0, 0), new Jolt.Quat(0, 0, 0, 1), Jolt.EMotionType_Static, LAYER);
      ground = bodies.CreateBody(c);
      Jolt.destroy(c);
      bodies.AddBody(ground.GetID(), Jolt.EActivation_DontActivate);
      return ground;
    };
    // A hinge about world y through a world point, or a ball at it, between two bodies.
    const hinge = (point, a, b) => {
      const c = new Jolt.HingeConstraintSettings();
      c.mSpace = Jolt.EConstraintSpace_WorldSpace;
      c.mPoint1 = c.mPoint2 = new Jolt.RVec3(...point);
      c.mHingeAxis1 = c.mHingeAxis2 = new Jolt.Vec3(0, 1, 0);
      c.mNormalAxis1 = c.mNormalAxis2 = new Jolt.Vec3(1, 0, 0);
      physics.AddConstraint(c.Create(a, b));
    };
    const ball = (point, a, b) => {
      const c = new Jolt.PointConstraintSettings();
      c.mSpace = Jolt.EConstraintSpace_WorldSpace;
      c.mPoint1 = c.mPoint2 = new Jolt.RVec3(...point);
      physics.AddConstraint(c.Create(a, b));
    };
    this.bodies = [];
    if (s.structure === 'one_body') {
      const { com: x, velocity: v } = oneBodyStart(s);
      const b = body(s.mass, s.inertia, s.rotation0, x, v, s.omega0);
      this.bodies.push(b);
      if (s.joint === 'hinge_y') hinge([0, 0, 0], fixed(), b);
      else if (s.joint === 'ball') ball([0, 0, 0], fixed(), b);
    } else if (s.structure === 'chain') {
      let parent = null;
      chainLinks(s).forEach((start, k) => {
        const b = body(s.links[k].mass, s.links[k].inertia, start.rotation, start.com, start.velocity, start.omega);
        this.bodies.push(b);
        hinge(sub(start.com, rotate(start.rotation, s.links[k].com)), parent ?? fixed(), b);
        parent = b;
      });
      if (s.loop) hinge(s.loop.anchor, parent, fixed());
    } else if (s.structure === 'contact') {
      ground = this.buildContact(s.contact, body);
    } else {
      for (const l of s.links) this.bodies.push(body(l.mass, l.inertia, [1, 0, 0, 0, 1, 0, 0, 0, 1], l.position0, l.velocity0, [0, 0, 0]));
    }
    this.ground = ground;
    this.masses = s.structure === 'one_body' ? [s.mass] : s.structure === 'contact' ? s.contact.bodies.map((b) => b.mass) : s.links.map((l) => l.mass);
    this.steps = 0;
  }

  /** A contact scenario: a body of each shape (BoxShape of the half-edges and SphereShape, a
   * CylinderShape along y, convex radius 0: no rounded corners), its mass and moments given;
   * the ground a static PlaneShape through the origin. Every body and the ground carry the
   * scenario's mFriction and mRestitution: Jolt combines two bodies' friction by the geometric
   * mean and their restitution by the maximum (PhysicsSystem's defaults), so every pair has
   * them. Returns the ground. */
  buildContact(c, body) {
    const material = (settings) => {
      settings.mFriction = c.mu;
      settings.mRestitution = c.restitution;
    };
    let ground = null;
    if (c.ground) {
      const plane = new Jolt.PlaneShape(new Jolt.Plane(new Jolt.Vec3(...c.normal), 0));
      const settings = new Jolt.BodyCreationSettings(plane, new Jolt.RVec3(0, 0, 0), new Jolt.Quat(0, 0, 0, 1), Jolt.EMotionType_Static, STATIC);
      material(settings);
      ground = this.interface.CreateBody(settings);
      Jolt.destroy(settings);
      this.interface.AddBody(ground.GetID(), Jolt.EActivation_DontActivate);
    }
    for (const k of c.bodies) {
      const [r, y, z] = k.size;
      const shape = k.shape === 'box' ? new Jolt.BoxShape(new Jolt.Vec3(r, y, z), 0)
        : k.shape === 'sphere' ? new Jolt.SphereShape(r)
        : k.shape === 'cylinder' ? new Jolt.CylinderShape(y, r, 0)
        : null;
      if (!shape) throw new Refused(`this client builds no ${k.shape} in Jolt ${version}`);
      this.bodies.push(body(k.mass, k.inertia, k.rotation0, k.position0, k.velocity0, k.omega0, shape, material));
    }
    return ground;
  }

  applyForces() {
    const s = this.s;
    // One Vec3 for every force of the run: a `new Jolt.Vec3` is allocated on the WebAssembly
    // heap until destroyed, and one a force a step ran the heap out (Aborted(OOM)) over the
    // audit's thousands of runs.
    this.forceVector ??= new Jolt.Vec3(0, 0, 0);
    const force = (k, f) => {
      this.forceVector.Set(f[0], f[1], f[2]);
      this.interface.AddForce(this.bodies[k].GetID(), this.forceVector, Jolt.EActivation_Activate);
    };
    if (s.central !== 0) {
      const x = arr(this.bodies[0].GetCenterOfMassPosition()), r = Math.hypot(...x);
      force(0, x.map((xi) => (-s.mass * s.central * xi) / (r * r * r)));
    }
    if (s.gravitation !== 0)
      for (let a = 0; a < this.bodies.length; ++a)
        for (let c = a + 1; c < this.bodies.length; ++c) {
          const xa = arr(this.bodies[a].GetCenterOfMassPosition()), xc = arr(this.bodies[c].GetCenterOfMassPosition());
          const r = xc.map((x, i) => x - xa[i]), d = Math.hypot(...r);
          const f = r.map((ri) => ((s.gravitation * this.masses[a] * this.masses[c]) / (d * d * d)) * ri);
          force(a, f);
          force(c, f.map((x) => -x));
        }
  }

  step(h) {
    ++this.steps;
    this.applyForces();
    this.jolt.Step(h, 1);
    for (const b of this.bodies)
      for (const x of [...arr(b.GetCenterOfMassPosition()), ...arr(b.GetLinearVelocity()), ...arr(b.GetAngularVelocity())])
        if (!Number.isFinite(x)) throw new Error(`Jolt ${version}: step ${this.steps}: the state is not finite`);
  }

  reading() {
    const frames = this.bodies.map((b) =>
      frame(rotationOf(b.GetRotation()), arr(b.GetCenterOfMassPosition()), arr(b.GetLinearVelocity()), arr(b.GetAngularVelocity())),
    );
    return this.s.structure === 'one_body' ? { frame: frames[0] } : { links: frames };
  }

  free() {
    for (const b of this.ground ? [...this.bodies, this.ground] : this.bodies) {
      this.interface.RemoveBody(b.GetID());
      this.interface.DestroyBody(b.GetID());
    }
    Jolt.destroy(this.jolt);
    if (this.forceVector) Jolt.destroy(this.forceVector);
  }
}

/** The shape of ShapeSettings, or Jolt's error. */
function created(settings) {
  const result = settings.Create();
  if (result.HasError()) throw new Error(`Jolt ${version}: ${result.GetError().c_str()}`);
  return result.Get();
}

/** A shape in Jolt: its axis (y) for the cylinder, the capsule and the cone (a tapered
 * cylinder) is the audit's z; convex radius 0 where a shape takes one (a hull's too: Jolt's
 * default rounds its corners). The shapes are reference-counted by Jolt and left to the
 * child's exit (a few per audit). */
function shapeOf(shape) {
  const [a, b, c] = shape.size;
  if (shape.name === 'box') return new Jolt.BoxShape(new Jolt.Vec3(a / 2, b / 2, c / 2), 0);
  if (shape.name === 'sphere') return new Jolt.SphereShape(a);
  if (shape.name === 'cylinder') return new Jolt.CylinderShape(b / 2, a, 0);
  if (shape.name === 'capsule') return new Jolt.CapsuleShape(b / 2, a);
  // A tapered cylinder of top radius 0: the cone, its centre of mass h/4 above the base.
  if (shape.name === 'cone') return created(new Jolt.TaperedCylinderShapeSettings(b / 2, 0, a, 0));
  if (shape.name === 'convex_hull') {
    const hull = new Jolt.ConvexHullShapeSettings();
    for (const p of hullPoints(shape)) hull.mPoints.push_back(new Jolt.Vec3(...p));
    hull.mMaxConvexRadius = 0;
    return created(hull);
  }
  if (shape.name === 'two_spheres') {
    const compound = new Jolt.StaticCompoundShapeSettings();
    const ball = new Jolt.SphereShapeSettings(a);
    compound.AddShape(new Jolt.Vec3(b, 0, 0), new Jolt.Quat(0, 0, 0, 1), ball, 0);
    compound.AddShape(new Jolt.Vec3(-b, 0, 0), new Jolt.Quat(0, 0, 0, 1), ball, 0);
    return created(compound);
  }
  throw new Refused(`this client builds no ${shape.name} in Jolt ${version}`);
}

/** The principal moments Jolt computes for a shape: Shape.GetMassProperties() (about the
 * centre of mass, at Jolt's density 1000) scaled to the shape's mass (MassProperties is linear
 * in the density); the moments reordered. */
function moments(shape) {
  const p = shapeOf(shape).GetMassProperties();
  const diagonal = arr(p.mInertia.GetDiagonal3()).map((x) => (x * shape.mass) / p.mMass);
  return diagonal.sort((x, y) => x - y);
}

let shapeSystem = null;
/** What Jolt gives a dynamic body created from the shape alone (BodyCreationSettings'
 * defaults): its MotionProperties' inverse mass and inverse principal inertia, inverted. */
function withoutMass(shape) {
  shapeSystem ??= makeSystem(0);
  const bodies = shapeSystem.GetPhysicsSystem().GetBodyInterface();
  const c = new Jolt.BodyCreationSettings(shapeOf(shape), new Jolt.RVec3(0, 0, 0), new Jolt.Quat(0, 0, 0, 1),
                                          Jolt.EMotionType_Dynamic, LAYER);
  const calculated = c.mOverrideMassProperties === Jolt.EOverrideMassProperties_CalculateMassAndInertia;
  const body = bodies.CreateBody(c);
  Jolt.destroy(c);
  try {
    const motion = body.GetMotionProperties();
    return {
      mass: 1 / motion.GetInverseMass(),
      moments: arr(motion.GetInverseInertiaDiagonal()).map((x) => 1 / x),
      said:
        `BodyCreationSettings.mOverrideMassProperties ${calculated ? 'CalculateMassAndInertia' : 'not CalculateMassAndInertia'} ` +
        '(its default: "Tells the system to calculate the mass and inertia based on density"), ConvexShape\'s mDensity ' +
        '1000 ("Uniform density of the interior of the convex object (kg / m^3)"); MotionProperties.GetInverseMass(), ' +
        'GetInverseInertiaDiagonal()',
    };
  } finally {
    bodies.DestroyBody(body.GetID());
  }
}

await serveEngine(
  {
    name: 'jolt',
    origin:
      `Jolt Physics ${version} (npm jolt-physics, WebAssembly) in Node ${process.version}: ` +
      'JoltInterface.Step(h, 1), one collision step of PhysicsSystem.Update; its documentation declares no order',
    integrators,
  },
  (integrator, scenario) => new Run(integrator, scenario),
  moments,
  withoutMass,
);
