// cannon-es (npm) -- the friction limit of a contact, on a box and a ball sent sliding on a
// plane. Uses cannon-es only.
//
// A box of half-edges (0.1, 0.1, 0.05) m and a ball of radius 0.1 m (I = 2/5 m r^2), each
// 1 kg, on a Plane; World.defaultContactMaterial friction mu = 0.5, restitution 0; gravity
// 9.81 m/s^2; World.step(h), no damping. Each body is left 1 s to settle, then sent at
// v0 = 2 m/s along x (the box also along the diagonal).
//
// Coulomb: the box decelerates at mu g (a velocity loss of mu g h a step) and stops after
// v0^2 / (2 mu g) = 0.4077 m; the ball slides until t = 2 v0 / (7 mu g) = 0.1165 s, then
// rolls at 5/7 v0.
//
// cannon-es makes two friction equations a contact point (Narrowphase.
// createFrictionEquationsFromContact), each with maxForce = mu |g| times the pair's reduced
// mass: World.frictionGravity, "Gravity to use when approximating the friction max force
// (mu*mass*gravity)"; Equation.maxForce, "Maximum (read: positive max) force to be applied by
// the constraint". GSSolver.solve clamps each equation's lambda to [minForce, maxForce] and
// sets its force, Equation.multiplier, to lambda / h: the force is then bounded by
// maxForce / h.
//
// Printed (name value):
//   multiplier_over_max_force   the largest |multiplier| / maxForce of the friction
//                               equations in the box's first step after it is sent
//   box_loss_over_mu_g_h        the box's velocity lost in that step over mu g h
//   box_distance                its stopping distance over v0^2 / (2 mu g), along x ...
//   box_distance_diagonal       ... and along (1, 1) / sqrt 2
//   box_points                  its contact points in that step
//   ball_loss_over_mu_g_h       the ball's velocity lost in its first step over mu g h
//   ball_rolling_at             the time from the send at which its contact point's slip
//                               falls under 1e-3 v0, and ball_rolling_exact, Coulomb's
//                               v0 k / ((1 + k) mu g) for the moment k m r^2 cannon-es gives
//                               the body (its bounding box's: k = 2/3, Body.inertia)
//   box_fixed_rotation_loss_over_mu_g_h  the box's first-step loss with its rotation fixed
//   box_loss_mu_0.05, box_loss_mu_1  the box's first-step loss (m/s) at mu = 0.05 and 1
//   bound_multiplier_over_max_force  the box, its rotation fixed (Body.fixedRotation), sent
//                               at 50 m/s: the largest |multiplier| / maxForce of its friction
//                               equations in the first step (1 if the force is bounded by
//                               maxForce; 1/h = 60 if the impulse is)
// each at h = 1/60, and box_distance_240 at h = 1/240; and as the audit's contact_slide
// starts (the box's lowest face exactly on the plane, sent at t = 0, no settling):
//   box_start_displacement_nN   its horizontal displacement (m) after 1 s in N steps,
//                               N = 60, 120, 240, 480, 960
//
// Run: node cannon_contact.mjs PATH/TO/node_modules/cannon-es/dist/cannon-es.js
import { readFileSync } from 'node:fs';
import { dirname, join } from 'node:path';
import { pathToFileURL } from 'node:url';

const CANNON = await import(pathToFileURL(process.argv[2]).href);
const version = JSON.parse(readFileSync(join(dirname(process.argv[2]), '..', 'package.json'))).version;
const g = 9.81, v0 = 2;
let mu = 0.5;

/** The body (box or ball) settled for `settle` s at step h, then sent along (cos t, sin t). */
function sent(ball, theta, h, settle = 1) {
  const w = new CANNON.World();
  w.gravity.set(0, 0, -g);
  w.defaultContactMaterial.friction = mu;
  w.defaultContactMaterial.restitution = 0;
  const ground = new CANNON.Body({ mass: 0 });
  ground.addShape(new CANNON.Plane());
  w.addBody(ground);
  const b = new CANNON.Body({ mass: 1, linearDamping: 0, angularDamping: 0 });
  b.addShape(ball ? new CANNON.Sphere(0.1) : new CANNON.Box(new CANNON.Vec3(0.1, 0.1, 0.05)));
  b.position.set(0, 0, ball ? 0.1 : 0.05);
  w.addBody(b);
  for (let k = 0; k < Math.round(settle / h); ++k) w.step(h);
  const x0 = [b.position.x, b.position.y];
  b.velocity.set(v0 * Math.cos(theta), v0 * Math.sin(theta), 0);
  return { w, b, x0 };
}

function box(theta, h) {
  const { w, b, x0 } = sent(false, theta, h);
  w.step(h);
  const first = {
    loss: v0 - Math.hypot(b.velocity.x, b.velocity.y),
    multiplier: Math.max(...w.frictionEquations.map((e) => Math.abs(e.multiplier) / e.maxForce)),
    points: w.contacts.length,
  };
  for (let k = 1; k < Math.round(2 / h); ++k) w.step(h);
  return { ...first, distance: Math.hypot(b.position.x - x0[0], b.position.y - x0[1]) / ((v0 * v0) / (2 * mu * g)) };
}

function ball(h) {
  const { w, b } = sent(true, 0, h);
  const k = b.inertia.y / (b.mass * 0.1 * 0.1);
  let loss = 0, at = null;
  for (let k = 1; k <= Math.round(2 / h) && at === null; ++k) {
    w.step(h);
    if (k === 1) loss = v0 - b.velocity.x;
    const slip = Math.hypot(b.velocity.x - b.angularVelocity.y * 0.1, b.velocity.y + b.angularVelocity.x * 0.1);
    if (slip < 1e-3 * v0) at = k * h;
  }
  return { loss, at, exact: (v0 * k) / ((1 + k) * mu * g) };
}

/** The box, its rotation fixed, sent at `speed`: the largest |multiplier| / maxForce of its
 * friction equations in its first step, and its speed lost. */
function bound(speed, h) {
  const { w, b } = sent(false, 0, h);
  b.fixedRotation = true;
  b.updateMassProperties();
  b.velocity.set(speed, 0, 0);
  w.step(h);
  return {
    ratio: Math.max(...w.frictionEquations.map((e) => Math.abs(e.multiplier) / e.maxForce)),
    loss: speed - Math.hypot(b.velocity.x, b.velocity.y),
  };
}

const h = 1 / 60;
const axis = box(0, h), diagonal = box(Math.PI / 4, h), rolling = ball(h);
console.log(`# cannon-es ${version}, h = 1/60`);
console.log(`multiplier_over_max_force ${axis.multiplier}`);
console.log(`box_loss_over_mu_g_h ${axis.loss / (mu * g * h)}`);
console.log(`box_distance ${axis.distance}`);
console.log(`box_distance_diagonal ${diagonal.distance}`);
console.log(`box_points ${axis.points}`);
console.log(`ball_loss_over_mu_g_h ${rolling.loss / (mu * g * h)}`);
console.log(`ball_rolling_at ${rolling.at}`);
console.log(`ball_rolling_exact ${rolling.exact}`);
console.log(`box_fixed_rotation_loss_over_mu_g_h ${bound(v0, h).loss / (mu * g * h)}`);
for (const m of [0.05, 1]) {
  mu = m;
  console.log(`box_loss_mu_${m} ${box(0, h).loss}`);
}
mu = 0.5;
console.log(`bound_multiplier_over_max_force ${bound(50, h).ratio}`);
console.log(`box_distance_240 ${box(0, 1 / 240).distance}`);
for (const n of [60, 120, 240, 480, 960]) {
  const start = sent(false, 0, 1 / n, 0);
  for (let k = 0; k < n; ++k) start.w.step(1 / n);
  console.log(`box_start_displacement_n${n} ${Math.hypot(start.b.position.x, start.b.position.y)}`);
}
