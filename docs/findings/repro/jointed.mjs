// jointed.mjs -- the audit's jointed scenarios in plain JavaScript, for the engines' reproducers
// (rapier_joints.mjs, jolt_joints.mjs, havok_joints.mjs, cannon_joints.mjs): what each body is and where it
// starts, and what is measured of a run. Uses nothing but JavaScript.
//
// The scenarios (gravity 9.81 along -z, every hinge about the world's y axis, all released from rest but the
// heavy top), their numbers as the audit states them (decimal, 17 digits):
// - pendulum_small, pendulum_large: a bob of mass 1 (principal moments 1e-3) whose centre is 1 m from a pivot
//   at the origin, on a hinge, at 0.1 and 2.5 rad from hanging straight down.
// - heavy_top: a body of mass 1, moments (0.05, 0.05, 0.1), its centre 0.5 m up its axis from a ball joint at
//   the origin, the axis tilted 0.5 rad about y, spinning (world angular velocity omega0); its step 0.002, the
//   others' 0.01 (h below).
// - double_pendulum, chain5: bars end to end from a hinge at the origin (2 bars of 1 kg and 1 m; 5 of 0.5 kg and
//   0.5 m), moments (m l^2 / 12, m l^2 / 12, 1e-3 m), each turned from its parent by angle0 about y.
// - four_bar: bars of 1 kg along their x axes (crank 1 m, coupler 2 m, rocker 1.5 m), moments (1e-3, l^2 / 12,
//   l^2 / 12), the crank at 1 rad and the others where the loop closes (angle0 below: the closure to double),
//   the rocker's end hinged to the ground at (2, 0, 0).
// A link's frame is its parent's turned by angle0 about y at its hinge (hinge: in the parent's frame, link 0's
// in the world's); com: its centre of mass in its own frame (a one-body scenario's: from its pivot).
export const GRAVITY = 9.8100000000000005;

const identity = [1, 0, 0, 0, 1, 0, 0, 0, 1];
const bar = (mass, length, angle0, first) => ({
  mass, angle0, inertia: [mass * length * length / 12, mass * length * length / 12, 1e-3 * mass],
  com: [0, 0, -length / 2], hinge: first ? [0, 0, 0] : [0, 0, -length],
});
const crankBar = (length, hinge, angle0) => ({
  mass: 1, angle0, inertia: [1e-3, length * length / 12, length * length / 12], com: [length / 2, 0, 0], hinge,
});

export const scenarios = {
  pendulum_small: {
    h: 0.01, joint: 'hinge_y', mass: 1, inertia: [0.001, 0.001, 0.001], com: [0, 0, -1], omega0: [0, 0, 0],
    rotation0: [0.99500416527802582, 0, 0.099833416646828155, 0, 1, 0, -0.099833416646828155, 0, 0.99500416527802582],
  },
  pendulum_large: {
    h: 0.01, joint: 'hinge_y', mass: 1, inertia: [0.001, 0.001, 0.001], com: [0, 0, -1], omega0: [0, 0, 0],
    rotation0: [-0.8011436155469337, 0, 0.59847214410395655, 0, 0.99999999999999989, 0, -0.59847214410395655, 0, -0.8011436155469337],
  },
  heavy_top: {
    h: 0.002, joint: 'ball', mass: 1, inertia: [0.05, 0.05, 0.1], com: [0, 0, 0.5], omega0: [18.610969897084864, 0, 35.412537899796675],
    rotation0: [0.87758256189037276, 0, 0.47942553860420301, 0, 1, 0, -0.47942553860420301, 0, 0.87758256189037276],
  },
  double_pendulum: { h: 0.01, links: [bar(1, 1, 0.5, true), bar(1, 1, 0.5, false)] },
  chain5: { h: 0.01, links: [0, 1, 2, 3, 4].map((k) => bar(0.5, 0.5, 0.25, k === 0)) },
  four_bar: {
    h: 0.01,
    links: [crankBar(1, [0, 0, 0], 1), crankBar(2, [1, 0, 0], -2.3447685306996595), crankBar(1.5, [2, 0, 0], 2.1755201159650825)],
    loop: { point: [1.5, 0, 0], anchor: [2, 0, 0] },
  },
};

/** R x, R row-major. */
export const rotate = (r, x) => [0, 1, 2].map((i) => r[3 * i] * x[0] + r[3 * i + 1] * x[1] + r[3 * i + 2] * x[2]);
/** R^T x, R row-major. */
export const rotateBack = (r, x) => [0, 1, 2].map((j) => r[j] * x[0] + r[3 + j] * x[1] + r[6 + j] * x[2]);
export const cross = (a, b) => [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
export const add = (a, b) => a.map((x, i) => x + b[i]);
export const sub = (a, b) => a.map((x, i) => x - b[i]);
const aboutY = (t) => [Math.cos(t), 0, Math.sin(t), 0, 1, 0, -Math.sin(t), 0, Math.cos(t)];
function times(a, b) {
  const out = new Array(9).fill(0);
  for (let i = 0; i < 3; ++i) for (let j = 0; j < 3; ++j) for (let k = 0; k < 3; ++k) out[3 * i + j] += a[3 * i + k] * b[3 * k + j];
  return out;
}

/** The unit quaternion {x, y, z, w} of a rotation (row-major), Shepperd's method. */
export function quaternionOf(r) {
  const [m00, m01, m02, m10, m11, m12, m20, m21, m22] = r;
  const trace = m00 + m11 + m22;
  if (trace > 0) {
    const s = 2 * Math.sqrt(1 + trace);
    return { w: s / 4, x: (m21 - m12) / s, y: (m02 - m20) / s, z: (m10 - m01) / s };
  }
  if (m00 > m11 && m00 > m22) {
    const s = 2 * Math.sqrt(1 + m00 - m11 - m22);
    return { w: (m21 - m12) / s, x: s / 4, y: (m01 + m10) / s, z: (m02 + m20) / s };
  }
  if (m11 > m22) {
    const s = 2 * Math.sqrt(1 + m11 - m00 - m22);
    return { w: (m02 - m20) / s, x: (m01 + m10) / s, y: s / 4, z: (m12 + m21) / s };
  }
  const s = 2 * Math.sqrt(1 + m22 - m00 - m11);
  return { w: (m10 - m01) / s, x: (m02 + m20) / s, y: (m12 + m21) / s, z: s / 4 };
}

/** The rotation (row-major) of a unit quaternion {x, y, z, w}. */
export function rotationOf({ x, y, z, w }) {
  return [
    1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y),
    2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x),
    2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y),
  ];
}

/** Each body at the start, in the world: {rotation, x (its centre of mass), v (that point's velocity), w (the
 * world angular velocity), pivot (its joint's point in the world)}. */
export function bodiesAtStart(s) {
  if (!s.links) {
    const x = rotate(s.rotation0, s.com);
    return [{ rotation: s.rotation0, x, v: cross(s.omega0, x), w: s.omega0, pivot: [0, 0, 0] }];
  }
  const out = [];
  let rotation = identity, origin = [0, 0, 0], omega = [0, 0, 0], velocity = [0, 0, 0];
  for (const l of s.links) {
    const hinge = add(origin, rotate(rotation, l.hinge));
    velocity = add(velocity, cross(omega, sub(hinge, origin)));
    rotation = times(rotation, aboutY(l.angle0));
    origin = hinge;
    const x = add(origin, rotate(rotation, l.com));
    out.push({ rotation, x, v: add(velocity, cross(omega, sub(x, origin))), w: omega, pivot: sub(x, rotate(rotation, l.com)) });
  }
  return out;
}

/** The potential's floor: a pendulum's bob or top's centre straight below its pivot; a chain's links each
 * hanging straight down below the one above (a lower bound where a loop keeps them from it). */
export function potentialFloor(s) {
  if (!s.links) return -s.mass * GRAVITY * Math.hypot(...s.com);
  let floor = 0, hingeZ = s.links[0].hinge[2];
  s.links.forEach((l, k) => {
    if (k > 0) hingeZ -= Math.hypot(...l.hinge);
    floor += l.mass * GRAVITY * (hingeZ - Math.hypot(...l.com));
  });
  return floor;
}

/** What a state shows: frames [{rotation (row-major), x, v, w}] of the bodies. The energy (kinetic and m g z);
 * the largest distance between a joint's point seen from its two sides (the pivot at the origin, or the hinge on
 * the parent's frame); the loop's (the rocker's end against its ground point). */
export function measure(s, frames) {
  const bodies = s.links ?? [s];
  let energy = 0, anchor = 0, loop = 0;
  frames.forEach((f, k) => {
    const b = bodies[k], wb = rotateBack(f.rotation, f.w);
    energy += (b.mass * (f.v[0] ** 2 + f.v[1] ** 2 + f.v[2] ** 2)) / 2 +
      (wb[0] * b.inertia[0] * wb[0] + wb[1] * b.inertia[1] * wb[1] + wb[2] * b.inertia[2] * wb[2]) / 2 + b.mass * GRAVITY * f.x[2];
    const origin = sub(f.x, rotate(f.rotation, b.com));
    const expected = !s.links || k === 0 ? [0, 0, 0] : add(frames[k - 1].x, rotate(frames[k - 1].rotation, sub(b.hinge, bodies[k - 1].com)));
    anchor = Math.max(anchor, Math.hypot(...sub(origin, expected)));
  });
  if (s.loop) {
    const f = frames[frames.length - 1];
    loop = Math.hypot(...sub(add(f.x, rotate(f.rotation, sub(s.loop.point, bodies[bodies.length - 1].com))), s.loop.anchor));
  }
  return { energy, anchor, loop };
}

/** n steps of a world ({step(), frames()}) from its start: the largest anchor and loop separations (m) and the
 * largest energy change relative to the energy the motion can exchange (E0 above the potential's floor);
 * printed as lines "<prefix>_anchor_max", "<prefix>_loop_max" (a loop's), "<prefix>_energy_max". */
export function longRun(prefix, s, world, n) {
  const m0 = measure(s, world.frames()), exchange = m0.energy - potentialFloor(s);
  let anchor = 0, loop = 0, energy = 0;
  for (let k = 1; k <= n; ++k) {
    world.step();
    const m = measure(s, world.frames());
    if (!Number.isFinite(m.energy)) throw new Error(`${prefix}: the state is not finite at step ${k}`);
    anchor = Math.max(anchor, m.anchor);
    loop = Math.max(loop, m.loop);
    energy = Math.max(energy, Math.abs(m.energy - m0.energy) / exchange);
  }
  console.log(`${prefix}_anchor_max`, anchor.toExponential(6));
  if (s.loop) console.log(`${prefix}_loop_max`, loop.toExponential(6));
  console.log(`${prefix}_energy_max`, energy.toExponential(6));
}
