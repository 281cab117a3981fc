// cannon-es (npm) -- a torque-free asymmetric body, and the inertia of a sphere. Uses
// cannon-es only.
//
// The body: principal moments I = (1, 2, 3), mass 1, angular velocity (1, 0.2, 0.5) at the
// identity orientation (body and world components agree at t = 0), no gravity, no damping
// (cannon-es's default linear and angular damping of 0.01 set to 0), stepped by
// World.step(h). Euler's equations I w' = (I w) x w move its body angular velocity and keep
// its angular momentum L = R I R^T w fixed in the world; the reference here is the classical
// RK4 on Euler's equations at h = 1e-4 (error below 1e-13 at t = 5, checked against h = 2e-4).
//
// Run: node cannon_free_body.mjs PATH/TO/node_modules/cannon-es/dist/cannon-es.js
// Prints: lines "name value" (see ci/findings).
import { readFileSync } from 'node:fs';
import { dirname, join } from 'node:path';
import { pathToFileURL } from 'node:url';

const CANNON = await import(pathToFileURL(process.argv[2]).href);
const version = JSON.parse(readFileSync(join(dirname(process.argv[2]), '..', 'package.json'))).version;
const I = [1, 2, 3], w0 = [1, 0.2, 0.5];

function body() {
  const world = new CANNON.World();
  world.gravity.set(0, 0, 0);
  const b = new CANNON.Body({ mass: 1, linearDamping: 0, angularDamping: 0 });
  b.inertia.set(...I);
  b.invInertia.set(1 / I[0], 1 / I[1], 1 / I[2]);
  b.angularVelocity.set(...w0);
  b.updateInertiaWorld(true);
  world.addBody(b);
  return { world, b };
}

/** The rotation (row-major) of a cannon-es quaternion. */
function rotation(q) {
  const m = new CANNON.Mat3();
  m.setRotationFromQuaternion(q);
  return m.elements;
}
const times = (r, x) => [0, 1, 2].map((i) => r[3 * i] * x[0] + r[3 * i + 1] * x[1] + r[3 * i + 2] * x[2]);
const timesT = (r, x) => [0, 1, 2].map((i) => r[i] * x[0] + r[3 + i] * x[1] + r[6 + i] * x[2]);
const norm = (x) => Math.hypot(...x);

/** The world angular momentum R I R^T w of the body. */
function momentum(b) {
  const r = rotation(b.quaternion), w = [b.angularVelocity.x, b.angularVelocity.y, b.angularVelocity.z];
  const body = timesT(r, w);
  return times(r, body.map((x, i) => I[i] * x));
}

/** The body angular velocity at t by RK4 on Euler's equations, step h. */
function euler(t, h) {
  const f = (w) => [((I[1] - I[2]) * w[1] * w[2]) / I[0], ((I[2] - I[0]) * w[2] * w[0]) / I[1], ((I[0] - I[1]) * w[0] * w[1]) / I[2]];
  let w = w0.slice();
  const n = Math.round(t / h);
  for (let i = 0; i < n; ++i) {
    const k1 = f(w), k2 = f(w.map((x, j) => x + (h / 2) * k1[j])), k3 = f(w.map((x, j) => x + (h / 2) * k2[j]));
    const k4 = f(w.map((x, j) => x + h * k3[j]));
    w = w.map((x, j) => x + (h / 6) * (k1[j] + 2 * k2[j] + 2 * k3[j] + k4[j]));
  }
  return w;
}

console.log(`cannon_version ${version}`);
// The long run: 10^4 steps of 0.01; the largest relative change of L.
{
  const { world, b } = body();
  const l0 = momentum(b);
  let worst = 0, magnitude = 0, angle = 0;
  for (let n = 1; n <= 10000; ++n) {
    world.step(0.01);
    const l = momentum(b);
    worst = Math.max(worst, norm(l.map((x, i) => x - l0[i])) / norm(l0));
    // The vector's change split: its length, and the angle it turns through.
    magnitude = Math.max(magnitude, Math.abs(norm(l) - norm(l0)) / norm(l0));
    const cross = [l[1] * l0[2] - l[2] * l0[1], l[2] * l0[0] - l[0] * l0[2], l[0] * l0[1] - l[1] * l0[0]];
    angle = Math.max(angle, Math.atan2(norm(cross), l.reduce((s, x, i) => s + x * l0[i], 0)));
  }
  // |L(t) - L(0)| / |L(0)|, the largest over t = 0.01 .. 100.
  console.log(`free_top_momentum_max ${worst.toExponential(6)}`);
  console.log(`free_top_momentum_magnitude_max ${magnitude.toExponential(2)}`);
  console.log(`free_top_momentum_angle_max_rad ${angle.toFixed(4)}`);
  console.log(`free_top_world_omega_after_10000 ${[b.angularVelocity.x, b.angularVelocity.y, b.angularVelocity.z].join(' ')}`);
}
// The body angular velocity at t = 5 against Euler's equations, as the step halves: the
// relative error |w - w_exact| / |w0|, the body components.
const exact = euler(5, 1e-4), check = euler(5, 2e-4);
console.log(`reference_check ${norm(exact.map((x, i) => x - check[i])).toExponential(2)}`);
for (const n of [1024, 4096, 16384]) {
  const { world, b } = body();
  for (let i = 0; i < n; ++i) world.step(5 / n);
  const w = timesT(rotation(b.quaternion), [b.angularVelocity.x, b.angularVelocity.y, b.angularVelocity.z]);
  console.log(`free_top_error_n${n} ${(norm(w.map((x, i) => x - exact[i])) / norm(w0)).toExponential(6)}`);
}
// A sphere of radius 0.4 and mass 2 (the audit's shape): Body.addShape's inertia against 2/5 m r^2.
{
  const b = new CANNON.Body({ mass: 2 });
  b.addShape(new CANNON.Sphere(0.4));
  console.log(`sphere_over_exact ${(b.inertia.x / (0.4 * 2 * 0.16)).toFixed(6)}`);
}
// A Body given a box shape and no mass option: its mass and type.
{
  const b = new CANNON.Body();
  b.addShape(new CANNON.Box(new CANNON.Vec3(0.15, 0.25, 0.35)));
  console.log(`box_alone_mass ${b.mass}`);
  console.log(`box_alone_static ${b.type === CANNON.Body.STATIC ? 1 : 0}`);
}
// A ConvexPolyhedron: the tetrahedron (+-a, 0, c), (0, +-b, -c), a = 0.3, b = 0.4, c = 0.25, mass 2
// (I = m diag(b^2/10 + c^2/5, a^2/10 + c^2/5, (a^2 + b^2)/10)), and the box that bounds it.
{
  const [a, b, c, m] = [0.3, 0.4, 0.25, 2];
  const vertices = [[a, 0, c], [-a, 0, c], [0, b, -c], [0, -b, -c]].map(([x, y, z]) => new CANNON.Vec3(x, y, z));
  const body = new CANNON.Body({ mass: m });
  body.addShape(new CANNON.ConvexPolyhedron({ vertices, faces: [[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]] }));
  const exact = [m * (b * b / 10 + c * c / 5), m * (a * a / 10 + c * c / 5), m * (a * a + b * b) / 10];
  const box = [(4 * b * b + 4 * c * c) * m / 12, (4 * a * a + 4 * c * c) * m / 12, (4 * a * a + 4 * b * b) * m / 12];
  const got = [body.inertia.x, body.inertia.y, body.inertia.z];
  // The moments compared in ascending order, each engine's axes being its own.
  const up = (v) => [...v].sort((x, y) => x - y), [g, e] = [up(got), up(exact)];
  console.log(`convex_hull_largest_relative_error ${Math.max(...g.map((x, i) => Math.abs(x / e[i] - 1))).toFixed(6)}`);
  console.log(`convex_hull_over_bounding_box_largest ${Math.max(...got.map((x, i) => Math.abs(x / box[i] - 1))).toExponential(3)}`);
}
