#!/usr/bin/env node
// cannon-es (npm), a rigid-body engine in JavaScript, served to mechcheck's audit as an
// engine (docs/protocol.md): World.step(h) at a fixed step, on every scenario it can express.
//
//   mechcheck-audit -o report --exec-engine -- node examples/exec/node/cannon_engine.mjs
//
// The scenario's model: a Body of the scenario's mass with its principal moments set
// directly (Body.inertia and invInertia, then updateInertiaWorld; no shapes, so nothing
// recomputes them from a bounding box), no damping (cannon-es's default linear and angular
// damping of 0.01 set to 0), the body at its centre of mass (cannon-es's body origin);
// gravity as World.gravity; the central force and the mutual gravitation set in Body.force
// before each step (cannon-es evaluates forces once a step, at its start); a hinge about y a
// HingeConstraint, a ball a PointToPointConstraint, to a static body at the origin or between
// links. cannon-es solves each joint as SPOOK equations whose parameters its Equation
// constructor sets with a time step of 1/60 s, whatever the step: a compliant joint, not the
// rigid one (said to the audit as the run's model_differs). The engine declares no order.
import * as CANNON from 'cannon-es';
import { readFileSync } from 'node:fs';
import { chainLinks, oneBodyStart, quaternionOf, sub } from './bodies.mjs';
import { Refused, frame, hullPoints, scenarioOf, serveEngine } from './protocol.mjs';

const version = JSON.parse(readFileSync(new URL('./node_modules/cannon-es/package.json', import.meta.url))).version;

const v3 = (a) => new CANNON.Vec3(a[0], a[1], a[2]);
const arr = (v) => [v.x, v.y, v.z];

/** cannon-es's quaternion of a rotation matrix (row-major). */
function quaternion(r) {
  const { x, y, z, w } = quaternionOf(r);
  return new CANNON.Quaternion(x, y, z, w);
}

function rotationOf(q) {
  const m = new CANNON.Mat3();
  m.setRotationFromQuaternion(q);
  return Array.from(m.elements); // row-major
}

/** A body of mass m with principal moments `inertia` along its axes, at its centre of mass. */
function body(mass, inertia, rotation, position, velocity, omega) {
  const b = new CANNON.Body({ mass, linearDamping: 0, angularDamping: 0 });
  b.inertia.set(inertia[0], inertia[1], inertia[2]);
  b.invInertia.set(1 / inertia[0], 1 / inertia[1], 1 / inertia[2]);
  b.quaternion.copy(quaternion(rotation));
  b.position.copy(v3(position));
  b.velocity.copy(v3(velocity));
  b.angularVelocity.copy(v3(omega));
  b.updateInertiaWorld(true);
  return b;
}

const soft =
  "cannon-es solves each joint as SPOOK equations (stiffness 1e7, relaxation 4) whose parameters its Equation " +
  'constructor sets with a time step of 1/60 s whatever the step (its documentation: "note the hardcoded refresh ' +
  'rate"), with 10 Gauss-Seidel iterations: it integrates a compliant joint, not the rigid one';

class Run {
  constructor(integrator, scenario) {
    if (integrator !== 'World.step') throw new Refused(`no integrator ${integrator}`);
    const s = scenarioOf(scenario);
    this.s = s;
    const world = new CANNON.World();
    world.gravity.set(0, 0, -s.gravity);
    this.world = world;
    this.bodies = [];
    const ground = new CANNON.Body({ mass: 0 });
    world.addBody(ground);
    if (s.structure === 'one_body') {
      const { com: x, velocity: v } = oneBodyStart(s);
      const b = body(s.mass, s.inertia, s.rotation0, x, v, s.omega0);
      world.addBody(b);
      this.bodies.push(b);
      const pivot = v3(s.com.map((c) => -c)); // the pivot in the body's frame (its origin at the centre of mass)
      if (s.joint === 'hinge_y')
        world.addConstraint(new CANNON.HingeConstraint(ground, b, { pivotA: v3([0, 0, 0]), axisA: v3([0, 1, 0]), pivotB: pivot, axisB: v3([0, 1, 0]) }));
      else if (s.joint === 'ball') world.addConstraint(new CANNON.PointToPointConstraint(ground, v3([0, 0, 0]), b, pivot));
      if (s.joint !== 'free') this.modelDiffers = soft;
    } else if (s.structure === 'chain') {
      let parent = ground, parentCom = [0, 0, 0];
      chainLinks(s).forEach((start, k) => {
        const l = s.links[k];
        const b = body(l.mass, l.inertia, start.rotation, start.com, start.velocity, start.omega);
        world.addBody(b);
        this.bodies.push(b);
        world.addConstraint(
          new CANNON.HingeConstraint(parent, b, {
            pivotA: v3(sub(l.hinge, parentCom)),
            axisA: v3([0, 1, 0]),
            pivotB: v3(l.com.map((c) => -c)),
            axisB: v3([0, 1, 0]),
          }),
        );
        parent = b;
        parentCom = l.com;
      });
      if (s.loop)
        world.addConstraint(
          new CANNON.HingeConstraint(parent, ground, {
            pivotA: v3(sub(s.loop.point, parentCom)),
            axisA: v3([0, 1, 0]),
            pivotB: v3(s.loop.anchor),
            axisB: v3([0, 1, 0]),
          }),
        );
      this.modelDiffers = soft;
    } else if (s.structure === 'contact') {
      this.buildContact(s.contact, ground);
    } else {
      for (const l of s.links) {
        const b = body(l.mass, l.inertia, [1, 0, 0, 0, 1, 0, 0, 0, 1], l.position0, l.velocity0, [0, 0, 0]);
        world.addBody(b);
        this.bodies.push(b);
      }
    }
    // No contacts but a contact scenario's: the other scenarios' bodies have no shapes.
    this.steps = 0;
  }

  /** A contact scenario: a shape per body (Box of the half-edges, Sphere, Cylinder along y of
   * 64 segments: a prism), its moments set again after addShape (which recomputes them from the
   * shape's bounding box); the ground a Plane (its normal the local z) turned by the slope about
   * y; every pair the World's defaultContactMaterial, its friction and restitution the
   * scenario's (no body has a Material, so nothing combines them). */
  buildContact(c, ground) {
    this.world.defaultContactMaterial.friction = c.mu;
    this.world.defaultContactMaterial.restitution = c.restitution;
    if (c.ground) {
      ground.addShape(new CANNON.Plane());
      ground.quaternion.setFromAxisAngle(new CANNON.Vec3(0, 1, 0), c.slope);
    }
    for (const k of c.bodies) {
      const b = body(k.mass, k.inertia, k.rotation0, k.position0, k.velocity0, k.omega0);
      const [r, y, z] = k.size;
      if (k.shape === 'box') b.addShape(new CANNON.Box(v3([r, y, z])));
      else if (k.shape === 'sphere') b.addShape(new CANNON.Sphere(r));
      else if (k.shape === 'cylinder') b.addShape(new CANNON.Cylinder(r, r, 2 * y, 64));
      else throw new Refused(`cannon-es ${version}: no ${k.shape} shape`);
      b.inertia.set(k.inertia[0], k.inertia[1], k.inertia[2]);
      b.invInertia.set(1 / k.inertia[0], 1 / k.inertia[1], 1 / k.inertia[2]);
      b.updateInertiaWorld(true);
      this.world.addBody(b);
      this.bodies.push(b);
    }
  }

  /** The scenario's forces on the centres of mass, from the current state. */
  applyForces() {
    const s = this.s;
    if (s.central !== 0) {
      const b = this.bodies[0];
      const x = arr(b.position), r = Math.hypot(...x);
      b.force.set(...x.map((xi) => (-s.mass * s.central * xi) / (r * r * r)));
    }
    if (s.gravitation !== 0) {
      for (let a = 0; a < this.bodies.length; ++a)
        for (let c = a + 1; c < this.bodies.length; ++c) {
          const r = sub(arr(this.bodies[c].position), arr(this.bodies[a].position)), d = Math.hypot(...r);
          const f = r.map((ri) => ((s.gravitation * s.links[a].mass * s.links[c].mass) / (d * d * d)) * ri);
          this.bodies[a].force.vadd(v3(f), this.bodies[a].force);
          this.bodies[c].force.vsub(v3(f), this.bodies[c].force);
        }
    }
  }

  step(h) {
    ++this.steps;
    this.applyForces();
    this.world.step(h);
    for (const b of this.bodies)
      for (const x of [...arr(b.position), ...arr(b.velocity), ...arr(b.angularVelocity)])
        if (!Number.isFinite(x)) throw new Error(`cannon-es ${version}: step ${this.steps}: the state is not finite`);
  }

  reading() {
    const frames = this.bodies.map((b) => frame(rotationOf(b.quaternion), arr(b.position), arr(b.velocity), arr(b.angularVelocity)));
    return this.s.structure === 'one_body' ? { frame: frames[0] } : { links: frames };
  }
}

/** A Body with the shape added (Body.addShape calls updateMassProperties): of the shape's
 * mass, or of the Body's options without one. */
function bodyOf(shape) {
  const [a, b] = shape.size;
  const body = new CANNON.Body(shape.mass === undefined ? {} : { mass: shape.mass });
  if (shape.name === 'box') body.addShape(new CANNON.Box(v3(shape.size.map((x) => x / 2))));
  else if (shape.name === 'sphere') body.addShape(new CANNON.Sphere(a));
  else if (shape.name === 'cylinder') body.addShape(new CANNON.Cylinder(a, a, b, 32));
  else if (shape.name === 'two_spheres') {
    body.addShape(new CANNON.Sphere(a), v3([b, 0, 0]));
    body.addShape(new CANNON.Sphere(a), v3([-b, 0, 0]));
  } else if (shape.name === 'convex_hull')
    // The tetrahedron's faces, each counter-clockwise seen from outside.
    body.addShape(new CANNON.ConvexPolyhedron({ vertices: hullPoints(shape).map(v3), faces: [[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]] }));
  else if (shape.name === 'cone')
    // A Cylinder with radiusTop 0 is centred at its bounding box's centre, not at a cone's
    // centre of mass: not the audit's cone.
    throw new Refused(`cannon-es ${version} has no cone shape`);
  else throw new Refused(`cannon-es ${version} has no ${shape.name} shape`);
  return body;
}

/** The principal moments cannon-es computes for a shape of a given mass: Body.inertia. */
function moments(shape) {
  return arr(bodyOf(shape).inertia);
}

/** What cannon-es gives a Body with the shape and no mass option: Body.mass and inertia. */
function withoutMass(shape) {
  const body = bodyOf(shape);
  const type = Object.keys(CANNON.BODY_TYPES).find((k) => CANNON.BODY_TYPES[k] === body.type) ?? String(body.type);
  return {
    mass: body.mass,
    moments: arr(body.inertia),
    said:
      `new Body({}): Body.mass ${body.mass}, Body.type ${type} (its constructor: ` +
      "`const mass = typeof options.mass === 'number' ? options.mass : 0`, `this.type = mass <= 0.0 ? Body.STATIC : Body.DYNAMIC`), Body.inertia",
  };
}

await serveEngine(
  {
    name: 'cannon_es',
    origin: `cannon-es ${version} (npm) in Node ${process.version}: World.step(h), one internalStep of h; Body.integrate ("Use new velocity - leap frog", a code comment: velocity from the force, then position and quaternion from the new velocities)`,
    integrators: [
      {
        name: 'World.step',
        origin:
          'the only integrator; its documentation declares no order; contact: the default ContactMaterial with the ' +
          "scenario's friction and restitution, its equations' stiffness 1e7 and relaxation 3 (the defaults), 10 " +
          'Gauss-Seidel iterations (GSSolver, the default)',
        // The documentation (its comments): the friction's maximum force approximated by
        // mu m g, a fixed limit not scaled by the normal force (a "box"); the contact and
        // friction equations given a stiffness and a relaxation time: a compliant contact by
        // design; a restitution "coefficient", no law.
        contact: {
          friction_cone: 'box',
          soft: true,
          words:
            'cannon-es World.frictionGravity: "Gravity to use when approximating the friction max force (mu*mass*gravity). ' +
            'If undefined, global gravity will be used."; ContactMaterial: friction "Friction coefficient.", restitution ' +
            '"Restitution coefficient.", contactEquationStiffness "Stiffness of the produced contact equations." (default ' +
            '1e7), contactEquationRelaxation "Relaxation time of the produced contact equations." (default 3), the same ' +
            'two for the friction equations',
        },
      },
    ],
  },
  (integrator, scenario) => new Run(integrator, scenario),
  moments,
  withoutMass,
);
