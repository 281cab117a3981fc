#!/usr/bin/env node
// Rapier (npm @dimforge/rapier3d-compat: the Rust engine compiled to WebAssembly) served to
// mechcheck's audit as an engine (docs/protocol.md): World.step at a fixed step, its joints
// as impulse joints (constraints between bodies, solved iteratively), on every scenario it
// can express. Rapier's multibody joints (reduced coordinates) are not offered: its
// JavaScript API sets no multibody joint position or velocity (MultibodyJoint has
// setContactsEnabled only), and a link starts at its joint's zero, at rest, whatever the
// body's pose and velocity -- no scenario starts there.
//
//   mechcheck-audit -o report --exec-engine -- node examples/exec/node/rapier_engine.mjs
//
// The scenario's model: a dynamic RigidBody per body, its mass and principal moments given by
// setAdditionalMassProperties with the centre of mass at the body's origin (so translation()
// and linvel() are the centre of mass's), no collider (nothing collides and nothing adds mass;
// in a contact scenario a collider of the body's shape and density 0, and a HalfSpace ground),
// damping set to 0 (Rapier's defaults are 0 too) and sleeping off (setCanSleep(false): a slow
// body would otherwise be frozen); gravity as the World's; the central force and the mutual
// gravitation set by addForce before each step (Rapier applies a body's forces once a step).
// A hinge about y is a revolute joint, a ball a spherical one, to a fixed body at the origin
// or between links. Two integrators: the joints' solver at its default 4 iterations and at 16.
// Rapier computes in single precision (f32) in this build.
import RAPIER from '@dimforge/rapier3d-compat';
import { readFileSync } from 'node:fs';
import { chainLinks, oneBodyStart, quaternionOf, sub } from './bodies.mjs';
import { Refused, frame, hullPoints, scenarioOf, serveEngine } from './protocol.mjs';

await RAPIER.init();
const version = JSON.parse(readFileSync(new URL('./node_modules/@dimforge/rapier3d-compat/package.json', import.meta.url))).version;

const v3 = (a) => ({ x: a[0], y: a[1], z: a[2] });
const arr = (v) => [v.x, v.y, v.z];
/** The rotation (row-major) of a unit quaternion {x, y, z, w}. */
function rotationOf({ x, y, z, w }) {
  return [
    1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y),
    2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x),
    2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y),
  ];
}

// The integration parameter that changes the dynamics of what the scenarios hold: the
// joints' solver iterations (World.numSolverIterations, rapier's world.d.ts: "The number of
// solver iterations run by the constraints solver for calculating forces (default: `4`)",
// "The greater this value is, the most rigid and realistic the physics simulation will
// be"). It is also the number of substeps a step is cut into, free bodies' included
// (rapier's source: `params.dt /= num_solver_iterations`), which the free bodies' reports
// show. The others set nothing the scenarios use (contacts, continuous collision detection,
// soft bodies).
// Contact (the contact scenarios) in the default integrator: the claims are the user guide's
// words (rapier.rs, "Colliders", Friction and Restitution) and setRestitution's. The friction
// is bounded in magnitude by mu times the normal force (an isotropic cone); the restitution's
// documentation fixes its ends (0: no bounce; 1: the exit normal velocity of the entry's
// magnitude), not the law between them: no restitution law is claimed. Nothing calls the
// contact soft (its penetration is corrected over steps: contact_erp, "the proportion of the
// positional error to be corrected at each time step (default: 0.2)").
const contact = {
  friction_cone: 'elliptic',
  words:
    'rapier.rs user guide, Colliders, Friction: "Following the Coulomb friction model, the maximum magnitude of this ' +
    'force is the magnitude of the force along the contact normal multiplied by a friction coefficient", "Rapier does ' +
    'not make any distinction between the fixed and dynamic friction coefficients currently"; Restitution: "A ' +
    'restitution coefficient set to 1 (fully elastic contact) implies that the exit velocity at a contact has the same ' +
    'magnitude as the entry velocity along the contact normal"; ColliderDesc.setRestitution: "A value of 0 (the ' +
    'default) means no bouncing behavior while 1 means perfect bouncing (though energy may still be lost due to ' +
    'numerical errors of the constraints solver)"',
};
const integrators = [
  {
    name: 'impulse_joints',
    origin:
      'World.step with the joints as ImpulseJoints (world.createImpulseJoint), numSolverIterations = 4 (the default); ' +
      'contact: colliders of the body shapes and a HalfSpace ground, friction and restitution CoefficientCombineRule.Average ' +
      '(every collider the scenario\'s mu and e), its other IntegrationParameters at their defaults',
    contact,
  },
  { name: 'impulse_joints_16_iterations', origin: 'the same with World.numSolverIterations = 16' },
];
const solverIterations = { impulse_joints: 4, impulse_joints_16_iterations: 16 };

class Run {
  constructor(integrator, scenario) {
    if (!Object.hasOwn(solverIterations, integrator)) throw new Refused(`no integrator ${integrator}`);
    const iterations = solverIterations[integrator];
    const s = scenarioOf(scenario);
    if (s.structure === 'contact' && !integrators.find((i) => i.name === integrator).contact)
      throw new Refused(`${integrator} builds no contact scenario`);
    this.s = s;
    const world = new RAPIER.World(v3([0, 0, -s.gravity]));
    world.numSolverIterations = iterations;
    if (world.numSolverIterations !== iterations) throw new Error(`numSolverIterations reads ${world.numSolverIterations}, set ${iterations}`);
    this.world = world;
    const ground = world.createRigidBody(RAPIER.RigidBodyDesc.fixed());
    const body = (mass, inertia, rotation, position, velocity, omega) =>
      world.createRigidBody(
        RAPIER.RigidBodyDesc.dynamic()
          .setTranslation(...position)
          .setRotation(quaternionOf(rotation))
          .setLinvel(...velocity)
          .setAngvel(v3(omega))
          .setAdditionalMassProperties(mass, v3([0, 0, 0]), v3(inertia), { x: 0, y: 0, z: 0, w: 1 })
          .setLinearDamping(0)
          .setAngularDamping(0)
          .setCanSleep(false),
      );
    const joint = (data, a, b) => world.createImpulseJoint(data, a, b, true);
    this.bodies = [];
    if (s.structure === 'one_body') {
      const { com: x, velocity: v } = oneBodyStart(s);
      const b = body(s.mass, s.inertia, s.rotation0, x, v, s.omega0);
      this.bodies.push(b);
      const pivot = v3(s.com.map((c) => -c)); // the pivot in the body's frame (its origin at the centre of mass)
      if (s.joint === 'hinge_y') joint(RAPIER.JointData.revolute(v3([0, 0, 0]), pivot, v3([0, 1, 0])), ground, b);
      else if (s.joint === 'ball') joint(RAPIER.JointData.spherical(v3([0, 0, 0]), pivot), ground, b);
    } else if (s.structure === 'chain') {
      let parent = ground, parentCom = [0, 0, 0];
      chainLinks(s).forEach((start, k) => {
        const l = s.links[k];
        const b = body(l.mass, l.inertia, start.rotation, start.com, start.velocity, start.omega);
        this.bodies.push(b);
        joint(RAPIER.JointData.revolute(v3(sub(l.hinge, parentCom)), v3(l.com.map((c) => -c)), v3([0, 1, 0])), parent, b);
        parent = b;
        parentCom = l.com;
      });
      if (s.loop)
        joint(RAPIER.JointData.revolute(v3(sub(s.loop.point, parentCom)), v3(s.loop.anchor), v3([0, 1, 0])), parent, ground);
    } else if (s.structure === 'contact') {
      const c = s.contact;
      const material = (desc) =>
        desc
          .setFriction(c.mu)
          .setRestitution(c.restitution)
          .setFrictionCombineRule(RAPIER.CoefficientCombineRule.Average)
          .setRestitutionCombineRule(RAPIER.CoefficientCombineRule.Average);
      if (c.ground) world.createCollider(material(new RAPIER.ColliderDesc(new RAPIER.HalfSpace(v3(c.normal)))), ground);
      for (const b of c.bodies) {
        const rb = body(b.mass, b.inertia, b.rotation0, b.position0, b.velocity0, b.omega0);
        this.bodies.push(rb);
        const [r, y, z] = b.size;
        // A cylinder's axis is Rapier's y, the scenario's too; the colliders add no mass (density 0).
        const shape = b.shape === 'box' ? RAPIER.ColliderDesc.cuboid(r, y, z)
          : b.shape === 'sphere' ? RAPIER.ColliderDesc.ball(r)
          : b.shape === 'cylinder' ? RAPIER.ColliderDesc.cylinder(y, r)
          : null;
        if (!shape) throw new Refused(`Rapier ${version}: no ${b.shape} shape`);
        world.createCollider(material(shape).setDensity(0), rb);
      }
    } else {
      for (const l of s.links) this.bodies.push(body(l.mass, l.inertia, [1, 0, 0, 0, 1, 0, 0, 0, 1], l.position0, l.velocity0, [0, 0, 0]));
    }
    // An impulse joint is solved by numSolverIterations of a soft constraint: a compliant
    // joint, not the rigid one.
    if ((s.structure === 'one_body' && s.joint !== 'free') || s.structure === 'chain')
      this.modelDiffers =
        `Rapier ${version} solves an impulse joint as a soft constraint (integration parameters: ` +
        `${world.integrationParameters.numSolverIterations} solver iterations): a compliant joint, not the rigid one`;
    this.steps = 0;
  }

  applyForces() {
    const s = this.s;
    if (s.central === 0 && s.gravitation === 0) return;
    for (const b of this.bodies) b.resetForces(true);
    if (s.central !== 0) {
      const b = this.bodies[0];
      const x = arr(b.translation()), r = Math.hypot(...x);
      b.addForce(v3(x.map((xi) => (-s.mass * s.central * xi) / (r * r * r))), true);
    }
    if (s.gravitation !== 0)
      for (let a = 0; a < this.bodies.length; ++a)
        for (let c = a + 1; c < this.bodies.length; ++c) {
          const r = sub(arr(this.bodies[c].translation()), arr(this.bodies[a].translation())), d = Math.hypot(...r);
          const f = r.map((ri) => ((s.gravitation * s.links[a].mass * s.links[c].mass) / (d * d * d)) * ri);
          this.bodies[a].addForce(v3(f), true);
          this.bodies[c].addForce(v3(f.map((x) => -x)), true);
        }
  }

  step(h) {
    ++this.steps;
    this.applyForces();
    this.world.timestep = h;
    this.world.step();
    for (const b of this.bodies)
      for (const x of [...arr(b.translation()), ...arr(b.linvel()), ...arr(b.angvel())])
        if (!Number.isFinite(x)) throw new Error(`Rapier ${version}: step ${this.steps}: the state is not finite`);
  }

  reading() {
    const frames = this.bodies.map((b) => frame(rotationOf(b.rotation()), arr(b.translation()), arr(b.linvel()), arr(b.angvel())));
    return this.s.structure === 'one_body' ? { frame: frames[0] } : { links: frames };
  }

  free() {
    this.world.free();
  }
}

/** A body with the shape's colliders: of the shape's mass (ColliderDesc.setMass) or, without
 * one, as ColliderDesc makes them (its density, 1 unless set); f(body) reads it. The audit's
 * axis (z) is Rapier's y for the cylinder, capsule and cone, whose moments are then reordered. */
function withBody(shape, f) {
  const [a, b, c] = shape.size;
  const world = new RAPIER.World(v3([0, 0, 0]));
  try {
    const body = world.createRigidBody(RAPIER.RigidBodyDesc.dynamic());
    const collider = (desc, at) => {
      if (shape.mass !== undefined) desc.setMass(at ? shape.mass / 2 : shape.mass);
      world.createCollider(desc.setTranslation(...(at ?? [0, 0, 0])), body);
    };
    if (shape.name === 'box') collider(RAPIER.ColliderDesc.cuboid(a / 2, b / 2, c / 2));
    else if (shape.name === 'sphere') collider(RAPIER.ColliderDesc.ball(a));
    else if (shape.name === 'cylinder') collider(RAPIER.ColliderDesc.cylinder(b / 2, a));
    else if (shape.name === 'capsule') collider(RAPIER.ColliderDesc.capsule(b / 2, a));
    else if (shape.name === 'cone') collider(RAPIER.ColliderDesc.cone(b / 2, a));
    else if (shape.name === 'two_spheres') {
      collider(RAPIER.ColliderDesc.ball(a), [b, 0, 0]);
      collider(RAPIER.ColliderDesc.ball(a), [-b, 0, 0]);
    } else if (shape.name === 'convex_hull') collider(RAPIER.ColliderDesc.convexHull(new Float32Array(hullPoints(shape).flat())));
    else throw new Refused(`Rapier ${version} has no ${shape.name} shape`);
    return f(body);
  } finally {
    world.free();
  }
}

/** The principal moments Rapier computes for a shape of a given mass: principalInertia(). */
function moments(shape) {
  return withBody(shape, (body) => arr(body.principalInertia()).sort((x, y) => x - y));
}

/** What Rapier gives a body whose colliders carry no mass: RigidBody.mass() and principalInertia(). */
function withoutMass(shape) {
  const density = new RAPIER.ColliderDesc(new RAPIER.Ball(1)).density;
  return withBody(shape, (body) => ({
    mass: body.mass(),
    moments: arr(body.principalInertia()),
    said: `ColliderDesc's density ${density} unless set ("The mass and angular inertia tensor will be computed ` +
      "automatically based on this density and the collider's shape\", ColliderDesc.setDensity); RigidBody.mass(), principalInertia()",
  }));
}

await serveEngine(
  {
    name: 'rapier',
    origin:
      `Rapier ${version} (npm @dimforge/rapier3d-compat, WebAssembly) in Node ${process.version}: World.step(), ` +
      'one step of World.timestep; its documentation declares no order ("The timestep length", ' +
      'IntegrationParameters.dt)',
    integrators,
  },
  (integrator, scenario) => new Run(integrator, scenario),
  moments,
  withoutMass,
);
