// scenarios.mjs -- the audit's rigid-body scenarios in plain JavaScript, for the engines' reproducers
// (rapier_scenarios.mjs, jolt_scenarios.mjs, havok_scenarios.mjs, cannon_scenarios.mjs): what each body is and
// where it starts, and what is measured of a long run and of an order study; the audit's shapes and their exact
// moments of inertia. Uses nothing but JavaScript.
//
// The scenarios, their numbers as the audit states them (decimal, 17 digits). Jointed, under gravity 9.81 along
// -z, every hinge about the world's y axis, all released from rest but the heavy top:
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
// Free, without gravity, each body's principal axes its frame's, turned by rotation0 (row-major), its world
// angular velocity omega0, its centre of mass at position0 moving at velocity0:
// - three_body: three bodies of 1 kg (moments 1e-3) under their mutual gravitation G = 1 (set before each step), on
//   the figure-eight choreography.
// - projectile: a body of 1 kg thrown from the origin at (1, 0.5, 3) under gravity 9.81 (its step 1e-4);
//   kepler: a point mass of 1 kg under the force -x / |x|^3 (set before each step), from (0.5, 0, 0) at
//   (0, sqrt 3, 0): an ellipse of a = 1, e = 0.5.
// - free_top (moments (1, 2, 3), omega0 (1, 0.2, 0.5)), free_top_near_axis (omega0 (0.01, 1, 0.01)), boxes (the
//   moments of a 10 kg box, spun near its middle axis; its step 0.0025), free_symmetric_top (moments (1, 1, 2)).
// - body_1_0 .. body_1_7: the audit's random free bodies of seed 1 (--engine-bodies 8 --seed 1).
// Their order studies run to tEnd in n = steps0, 2 steps0, .. 16384 steps, as the pendulums' (to 2 s, released at
// theta0) and the chains' (to 2 s; chain5's to 1 s).
export const GRAVITY = 9.8100000000000005;

const free = (h, tEnd, mass, inertia, omega0, rotation0 = [1, 0, 0, 0, 1, 0, 0, 0, 1], position0 = [0, 0, 0], velocity0 = [0, 0, 0]) =>
  ({ h, tEnd, steps0: 32, gravity: 0, central: 0, gravitation: 0, joint: 'free', mass, inertia, omega0, rotation0, position0, velocity0, com: [0, 0, 0] });

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
    gravity: GRAVITY, h: 0.01, tEnd: 2, steps0: 32, theta0: 0.1, joint: 'hinge_y', mass: 1, inertia: [0.001, 0.001, 0.001], com: [0, 0, -1], omega0: [0, 0, 0],
    rotation0: [0.99500416527802582, 0, 0.099833416646828155, 0, 1, 0, -0.099833416646828155, 0, 0.99500416527802582],
  },
  pendulum_large: {
    gravity: GRAVITY, h: 0.01, tEnd: 2, steps0: 32, theta0: 2.5, joint: 'hinge_y', mass: 1, inertia: [0.001, 0.001, 0.001], com: [0, 0, -1], omega0: [0, 0, 0],
    rotation0: [-0.8011436155469337, 0, 0.59847214410395655, 0, 0.99999999999999989, 0, -0.59847214410395655, 0, -0.8011436155469337],
  },
  heavy_top: {
    gravity: GRAVITY, h: 0.002, joint: 'ball', mass: 1, inertia: [0.05, 0.05, 0.1], com: [0, 0, 0.5], omega0: [18.610969897084864, 0, 35.412537899796675],
    rotation0: [0.87758256189037276, 0, 0.47942553860420301, 0, 1, 0, -0.47942553860420301, 0, 0.87758256189037276],
  },
  double_pendulum: { h: 0.01, tEnd: 2, steps0: 32, gravity: GRAVITY, links: [bar(1, 1, 0.5, true), bar(1, 1, 0.5, false)] },
  chain5: { h: 0.01, tEnd: 1, steps0: 32, gravity: GRAVITY, links: [0, 1, 2, 3, 4].map((k) => bar(0.5, 0.5, 0.25, k === 0)) },
  four_bar: {
    h: 0.01, tEnd: 2, steps0: 32, gravity: GRAVITY,
    links: [crankBar(1, [0, 0, 0], 1), crankBar(2, [1, 0, 0], -2.3447685306996595), crankBar(1.5, [2, 0, 0], 2.1755201159650825)],
    loop: { point: [1.5, 0, 0], anchor: [2, 0, 0] },
  },
  three_body: {
    h: 0.01, tEnd: 2, steps0: 32, gravity: 0, central: 0, gravitation: 1, joint: 'free', bodies: [
      [[0.97000436000000001, -0.24308753, 0], [0.46620368499999998, 0.43236573, -0]],
      [[-0.97000436000000001, 0.24308753, -0], [0.46620368499999998, 0.43236573, -0]],
      [[0, 0, 0], [-0.93240736999999996, -0.86473146000000001, 0]],
    ].map(([position0, velocity0]) => ({ mass: 1, inertia: [0.001, 0.001, 0.001], com: [0, 0, 0], position0, velocity0 })),
  },
  projectile: { ...free(1e-4, 1, 1, [1, 1, 1], [0, 0, 0], undefined, [0, 0, 0], [1, 0.5, 3]), gravity: GRAVITY, steps0: 16, momentum: false },
  kepler: { ...free(0.01, 5, 1, [1e-3, 1e-3, 1e-3], [0, 0, 0], undefined, [0.5, 0, 0], [0, Math.sqrt(3), 0]), central: 1, steps0: 64 },
  free_top: free(0.01, 5, 1, [1, 2, 3], [1, 0.20000000000000001, 0.5]),
  free_top_near_axis: free(0.01, 10, 1, [1, 2, 3], [0.01, 1, 0.01]),
  boxes: { ...free(0.0025, 10, 10, [0.80833333333333335, 0.68333333333333335, 0.14166666666666669], [0.001, 1.5, 0.014999999999999999]), steps0: 64 },
  free_symmetric_top: free(0.01, 5, 1, [1, 1, 2], [0.59999999999999998, 0, 1]),
  body_1_0: free(0.01, 4, 0.64453125, [1.1171875, 1.18701171875, 1.94635009765625],
    [-1.8199544532042635, -0.56133824056811288, -0.69877107314515363],
    [0.17758364312752972, -0.060164186919576479, -0.98226489314535759, -0.81570879321517831, 0.54937615550360186,
     -0.18112151842207991, 0.55052993957185647, 0.8334063296954185, 0.048483762834785615],
    [0.91796875, 0.33203125, -0.75], [-0.0234375, 0.1015625, -0.41015625]),
  body_1_1: free(0.01, 4, 3.76171875, [2, 3.078125, 4.71875], [0.24219045930955863, -1.2507076589096309, 1.1545260744593002],
    [0.76087095334868771, 0.47684461134783096, 0.44010749707178937, 0.41276715434326894, -0.87898760891638039,
     0.23875522961146611, 0.50069818118864684, 0, -0.86562193326785608],
    [-0.35546875, 0.35546875, 0.12109375], [-0.94140625, -0.3359375, 0.89453125]),
  body_1_2: free(0.01, 4, 1.98828125, [0.92578125, 1.699676513671875, 1.757537841796875],
    [1.0669276487882449, -0.0037336343455187659, 1.8783425186224219],
    [0.20686674080567879, 0.94527369214263623, 0.25231686129045078, 0.60669854435600057, -0.32626352334279196,
     0.72489239864427968, 0.76754350223602708, 0.0031241445190384742, -0.64098924475866048],
    [-0.5, 0.1484375, 0.08203125], [-0.8671875, 0.30078125, 0.3046875]),
  body_1_3: free(0.01, 4, 2.59375, [1.46875, 2.7825927734375, 4.0218505859375],
    [0.014253165654857021, 0.38162886144915498, 1.3489972077098926],
    [0.99884389467618473, -0.02931686794403382, -0.038097182600067121, 0.047823836316282467, 0.68636602220966436,
     0.72568213718960739, 0.0048738842932713536, -0.72666512563218189, 0.6869745558911633],
    [1, 0.37890625, -0.03125], [-0.31640625, -0.7109375, -0.7421875]),
  body_1_4: free(0.01, 4, 0.25, [1.19140625, 1.5590667724609375, 2.308349609375],
    [2.0913383611796803, 1.2868478389693023, 0.32422621882946012],
    [-0.36182921822112823, 0.84141764516693085, -0.40136761608682836, 0.10798634740599161, -0.38981190010224109,
     -0.91454121356699525, -0.92596898739396194, -0.37424995516421489, 0.050183716922759247],
    [-0.25, -0.62109375, -0.7734375], [-0.703125, -0.09375, -0.01953125]),
  body_1_5: free(0.01, 4, 1.76171875, [1.6328125, 2.1175537109375, 3.55902099609375],
    [-2.456509248603143, 0.83424854027290418, 0.46096995119842488],
    [0.48453044767655917, -0.80749217713994514, 0.33643220584858524, -0.71255126553647197, -0.58741788488339153,
     -0.38368075596971973, 0.50744550373091846, -0.053820185589747133, -0.86000142346763631],
    [-0.39453125, 0.90625, -0.63671875], [1, 0.97265625, 0.90625]),
  body_1_6: free(0.01, 4, 1.9765625, [0.3046875, 0.405853271484375, 0.66888427734375],
    [-1.128684874394039, 0.37738657961938599, 1.6671730155794735],
    [0.46522159605115232, 0.55748955087312901, -0.6875858253592021, 0.0022674631615524077, -0.77751060717406473,
     -0.62886573634014142, -0.88519134947107869, 0.29100284603263615, -0.36297881263577403],
    [-0.47265625, -0.06640625, -0.15625], [0.5546875, 0, -0.25390625]),
  body_1_7: free(0.01, 4, 3.1875, [1.5390625, 2.068115234375, 3.510986328125],
    [-0.37241805131003392, -0.87586903447462394, -0.33376737579870236],
    [-0.44382502565086646, -0.77693731407117317, 0.44652856191948032, -0.79663581073988621, 0.57026556796461914,
     0.20042097455305088, -0.41035439762821135, -0.26676879877126125, -0.87203421741886178],
    [-0.8359375, 0.54296875, 0.26171875], [-0.4296875, 0.0703125, -1]),
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

/** The scenario's bodies: a chain's links, the free bodies, or the one body. */
export const parts = (s) => s.links ?? s.bodies ?? [s];

/** The mutual gravitation of free bodies at positions x, pair by pair as [a, c, f]: f on a, -f on c. */
export function gravitation(s, x) {
  const out = [], m = parts(s).map((b) => b.mass);
  for (let a = 0; a < x.length; ++a)
    for (let c = a + 1; c < x.length; ++c) {
      const r = sub(x[c], x[a]), d = Math.hypot(...r);
      out.push([a, c, r.map((ri) => ((s.gravitation * m[a] * m[c]) / (d * d * d)) * ri)]);
    }
  return out;
}

/** Each body at the start, in the world: {rotation, x (its centre of mass), v (that point's velocity), w (the
 * world angular velocity), pivot (its joint's point in the world)}. */
export function bodiesAtStart(s) {
  if (s.bodies) return s.bodies.map((b) => ({ rotation: identity, x: b.position0, v: b.velocity0, w: [0, 0, 0] }));
  if (s.joint === 'free') return [{ rotation: s.rotation0, x: s.position0, v: s.velocity0, w: s.omega0 }];
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
  if (!s.links) return -s.mass * s.gravity * Math.hypot(...s.com);
  let floor = 0, hingeZ = s.links[0].hinge[2];
  s.links.forEach((l, k) => {
    if (k > 0) hingeZ -= Math.hypot(...l.hinge);
    floor += l.mass * s.gravity * (hingeZ - Math.hypot(...l.com));
  });
  return floor;
}

/** What a state shows: frames [{rotation (row-major), x, v, w}] of the bodies. The energy (kinetic and m g z);
 * the angular momentum about the origin, m x × v + R I R^T w; the largest distance between a joint's point seen
 * from its two sides (the pivot at the origin, or the hinge on the parent's frame); the loop's (the rocker's end
 * against its ground point). */
export function measure(s, frames) {
  const bodies = parts(s);
  let energy = 0, anchor = 0, loop = 0, momentum = [0, 0, 0];
  for (const [a, c] of s.gravitation ? gravitation(s, frames.map((f) => f.x)) : [])
    energy -= (s.gravitation * bodies[a].mass * bodies[c].mass) / Math.hypot(...sub(frames[c].x, frames[a].x));
  frames.forEach((f, k) => {
    const b = bodies[k], wb = rotateBack(f.rotation, f.w);
    energy += (b.mass * (f.v[0] ** 2 + f.v[1] ** 2 + f.v[2] ** 2)) / 2 +
      (wb[0] * b.inertia[0] * wb[0] + wb[1] * b.inertia[1] * wb[1] + wb[2] * b.inertia[2] * wb[2]) / 2 + b.mass * s.gravity * f.x[2]
      - (s.central ? (b.mass * s.central) / Math.hypot(...f.x) : 0);
    momentum = add(momentum, add(cross(f.x, f.v).map((c) => b.mass * c), rotate(f.rotation, wb.map((c, i) => b.inertia[i] * c))));
    if (s.joint === 'free') return;
    const origin = sub(f.x, rotate(f.rotation, b.com));
    const expected = !s.links || k === 0 ? [0, 0, 0] : add(frames[k - 1].x, rotate(frames[k - 1].rotation, sub(b.hinge, bodies[k - 1].com)));
    anchor = Math.max(anchor, Math.hypot(...sub(origin, expected)));
  });
  if (s.loop) {
    const f = frames[frames.length - 1];
    loop = Math.hypot(...sub(add(f.x, rotate(f.rotation, sub(s.loop.point, bodies[bodies.length - 1].com))), s.loop.anchor));
  }
  return { energy, momentum, anchor, loop };
}

/** n steps of a world ({step(), frames()}) from its start, printed as lines "<prefix>_<name>_max" of the largest
 * of each over the run: a free body's energy change relative to |E0| ("energy") and its angular momentum's,
 * |L - L0| / |L0| ("momentum"); a jointed one's anchor and loop separations (m, "anchor", "loop": a loop's) and
 * its energy change relative to the energy it can exchange, E0 above the potential's floor ("energy"). */
export function longRun(prefix, s, world, n) {
  const m0 = measure(s, world.frames());
  // (1 where |E0| or |L0| is 0, as the audit: the figure-eight's angular momentum)
  const scale = s.joint === 'free' ? Math.abs(m0.energy) || 1 : m0.energy - potentialFloor(s), l0 = Math.hypot(...m0.momentum) || 1;
  let anchor = 0, loop = 0, energy = 0, momentum = 0;
  for (let k = 1; k <= n; ++k) {
    world.step();
    const m = measure(s, world.frames());
    if (!Number.isFinite(m.energy)) throw new Error(`${prefix}: the state is not finite at step ${k}`);
    anchor = Math.max(anchor, m.anchor);
    loop = Math.max(loop, m.loop);
    energy = Math.max(energy, Math.abs(m.energy - m0.energy) / scale);
    momentum = Math.max(momentum, Math.hypot(...sub(m.momentum, m0.momentum)) / l0);
  }
  const line = (name, value) => console.log(`${prefix}_${name}_max`, value.toExponential(6));
  if (s.joint !== 'free') line('anchor', anchor);
  else if (s.momentum !== false) line('momentum', momentum); // the projectile's: none under gravity
  if (s.loop) line('loop', loop);
  line('energy', energy);
}

/** The body angular velocity Omega and the rotation R of a free body at t, by the classical RK4 on Euler's
 * equations I Omega' = (I Omega) x Omega and q' = q (0, Omega) / 2 (q the unit quaternion of R) in steps of at
 * most h: the reference of its order study (at h = 1e-4 within 1e-13 of the Jacobi elliptic solution here; the
 * reproducers print its change from h = 2e-4). */
export function freeReference(s, t, h) {
  const I = s.inertia, n = Math.ceil(t / h), dt = t / n;
  const rate = ([w0, w1, w2, qx, qy, qz, qw]) => [
    ((I[1] - I[2]) * w1 * w2) / I[0], ((I[2] - I[0]) * w2 * w0) / I[1], ((I[0] - I[1]) * w0 * w1) / I[2],
    (qw * w0 + qy * w2 - qz * w1) / 2, (qw * w1 + qz * w0 - qx * w2) / 2, (qw * w2 + qx * w1 - qy * w0) / 2,
    (-qx * w0 - qy * w1 - qz * w2) / 2,
  ];
  const q0 = quaternionOf(s.rotation0);
  let y = [...rotateBack(s.rotation0, s.omega0), q0.x, q0.y, q0.z, q0.w];
  const at = (z, k, c) => z.map((v, i) => v + c * k[i]);
  for (let k = 0; k < n; ++k) {
    const k1 = rate(y), k2 = rate(at(y, k1, dt / 2)), k3 = rate(at(y, k2, dt / 2)), k4 = rate(at(y, k3, dt));
    y = y.map((v, i) => v + (dt / 6) * (k1[i] + 2 * k2[i] + 2 * k3[i] + k4[i]));
  }
  const norm = Math.hypot(y[3], y[4], y[5], y[6]);
  return { omega: y.slice(0, 3), rotation: rotationOf({ x: y[3] / norm, y: y[4] / norm, z: y[5] / norm, w: y[6] / norm }) };
}

/** The central force -m k x / |x|^3 on a body at x (kepler's, k = s.central), set before each step. */
export function centralForce(s, x) {
  const r = Math.hypot(...x);
  return x.map((xi) => (-s.mass * s.central * xi) / (r * r * r));
}

/** Kepler's ellipse of a = 1, e = 0.5 (mu = 1, the period 2 pi) from its pericentre (0.5, 0, 0) at t = 0: the
 * position and velocity at t, the eccentric anomaly E from Kepler's equation E - e sin E = t by Newton's method. */
function keplerOrbit(t) {
  const e = 0.5, b = Math.sqrt(1 - e * e);
  let E = t;
  for (let k = 0; k < 50; ++k) E -= (E - e * Math.sin(E) - t) / (1 - e * Math.cos(E));
  const rate = 1 / (1 - e * Math.cos(E));
  return { position: [Math.cos(E) - e, b * Math.sin(E), 0], velocity: [-Math.sin(E) * rate, b * Math.cos(E) * rate, 0] };
}

/** Gaussian elimination with partial pivoting: x with A x = b. */
function solve(A, b) {
  const n = b.length, M = A.map((row, i) => [...row, b[i]]);
  for (let c = 0; c < n; ++c) {
    let p = c;
    for (let r = c + 1; r < n; ++r) if (Math.abs(M[r][c]) > Math.abs(M[p][c])) p = r;
    [M[c], M[p]] = [M[p], M[c]];
    for (let r = c + 1; r < n; ++r) {
      const f = M[r][c] / M[c][c];
      for (let k = c; k <= n; ++k) M[r][k] -= f * M[c][k];
    }
  }
  const x = new Array(n).fill(0);
  for (let r = n - 1; r >= 0; --r) {
    let v = M[r][n];
    for (let k = r + 1; k < n; ++k) v -= M[r][k] * x[k];
    x[r] = v / M[r][r];
  }
  return x;
}

/** A planar chain's motion (the links' absolute angles phi about y and their rates) at t, by the classical RK4 in
 * steps of at most h on d'Alembert's equations: link k's centre of mass c_k = sum_{j<k} R(phi_j) hinge_{j+1} +
 * R(phi_k) com_k in the (x, z) plane, a_kj = dc_k/dphi_j = R'(phi_j) d_kj, so M phi'' = Q with M_ij = sum_k m_k
 * a_ki . a_kj + delta_ij I_i and Q_i = sum_k m_k a_ki . (sum_j R(phi_j) d_kj phi_j'^2 - g e_z) (R'' = -R); a loop
 * (the four-bar's rocker end held at its anchor) adds J phi'' = sum_j R(phi_j) e_j phi_j'^2 with its multipliers. */
function chainReference(s, t, h) {
  const L = s.links, n = L.length;
  const turn = (phi, [x, , z]) => [Math.cos(phi) * x + Math.sin(phi) * z, -Math.sin(phi) * x + Math.cos(phi) * z];
  const dturn = (phi, [x, , z]) => [-Math.sin(phi) * x + Math.cos(phi) * z, -Math.cos(phi) * x - Math.sin(phi) * z];
  const arm = (k, j) => (j < k ? L[j + 1].hinge : j === k ? L[k].com : null); // d_kj
  const loopArm = (j) => (j < n - 1 ? L[j + 1].hinge : s.loop.point);
  const acceleration = (phi, rate) => {
    const size = n + (s.loop ? 2 : 0), A = [...Array(size)].map(() => new Array(size).fill(0)), b = new Array(size).fill(0);
    for (let k = 0; k < n; ++k) {
      const a = [...Array(n)].map((_, j) => (arm(k, j) ? dturn(phi[j], arm(k, j)) : [0, 0]));
      const centripetal = [0, 0];
      for (let j = 0; j <= k; ++j) {
        const r = turn(phi[j], arm(k, j));
        centripetal[0] += r[0] * rate[j] ** 2;
        centripetal[1] += r[1] * rate[j] ** 2;
      }
      for (let i = 0; i <= k; ++i) {
        for (let j = 0; j <= k; ++j) A[i][j] += L[k].mass * (a[i][0] * a[j][0] + a[i][1] * a[j][1]);
        b[i] += L[k].mass * (a[i][0] * centripetal[0] + a[i][1] * (centripetal[1] - s.gravity));
      }
    }
    for (let i = 0; i < n; ++i) A[i][i] += L[i].inertia[1];
    if (s.loop)
      for (let j = 0; j < n; ++j) {
        const d = dturn(phi[j], loopArm(j)), r = turn(phi[j], loopArm(j));
        for (let c = 0; c < 2; ++c) {
          A[n + c][j] = A[j][n + c] = d[c];
          b[n + c] += r[c] * rate[j] ** 2;
        }
      }
    return solve(A, b).slice(0, n);
  };
  let phi = 0;
  let y = [...L.map((l) => (phi += l.angle0)), ...new Array(n).fill(0)];
  const rate = (z) => [...z.slice(n), ...acceleration(z.slice(0, n), z.slice(n))];
  const steps = Math.ceil(t / h), dt = t / steps, at = (z, k, c) => z.map((v, i) => v + c * k[i]);
  for (let k = 0; k < steps; ++k) {
    const k1 = rate(y), k2 = rate(at(y, k1, dt / 2)), k3 = rate(at(y, k2, dt / 2)), k4 = rate(at(y, k3, dt));
    y = y.map((v, i) => v + (dt / 6) * (k1[i] + 2 * k2[i] + 2 * k3[i] + k4[i]));
  }
  return y;
}

/** An angle in [-pi, pi]. */
const wrap = (a) => a - 2 * Math.PI * Math.round(a / (2 * Math.PI));

/** What a scenario's order study compares, as the audit observes it from a frame, and its scale: a free body's
 * body angular velocity R^T w ("angular_velocity"); the symmetric top's axis R e3 and a random body's fixed angular
 * momentum's direction in the body, R^T M0 / |M0| ("orientation"), relative to |w0| for the tops and the boxes, 1
 * for the symmetric top, a random body's max(1, |Omega0|, |x0|, |v0|); a pendulum's angle about y and its rate,
 * (atan2(R_02, R_00), w_y) ("joint_coordinates"), relative to |theta0| sqrt(1 + w0^2); the projectile's and
 * Kepler's orbit's position and velocity, relative to |v0| and 1. Null for the others. */
function studyOf(name, s) {
  if (s.theta0 !== undefined) {
    const w02 = (s.mass * s.gravity * Math.hypot(...s.com)) / (s.mass * (s.com[0] ** 2 + s.com[1] ** 2 + s.com[2] ** 2) + s.inertia[1]);
    return {
      scale: Math.abs(s.theta0) * Math.sqrt(1 + w02),
      observe: (rotation, omega) => ({ joint_coordinates: [Math.atan2(rotation[2], rotation[0]), omega[1]] }),
      // theta'' = -w0^2 sin theta from (theta0, 0), by the classical RK4 in steps of at most h.
      exact(h) {
        const n = Math.ceil(s.tEnd / h), dt = s.tEnd / n, rate = ([q, p]) => [p, -w02 * Math.sin(q)];
        let y = [s.theta0, 0];
        for (let k = 0; k < n; ++k) {
          const k1 = rate(y), k2 = rate(y.map((v, i) => v + (dt / 2) * k1[i])), k3 = rate(y.map((v, i) => v + (dt / 2) * k2[i]));
          const k4 = rate(y.map((v, i) => v + dt * k3[i]));
          y = y.map((v, i) => v + (dt / 6) * (k1[i] + 2 * k2[i] + 2 * k3[i] + k4[i]));
        }
        return { joint_coordinates: y };
      },
    };
  }
  if (s.bodies) {
    // Every body's position and velocity, relative to 1; the reference the classical RK4 on Newton's equations.
    const n = s.bodies.length, m = s.bodies.map((b) => b.mass);
    const split = (y) => ({ position: y.slice(0, 3 * n), velocity: y.slice(3 * n) });
    return {
      scale: 1,
      observeLinks: (frames) => split([...frames.flatMap((f) => f.x), ...frames.flatMap((f) => f.v)]),
      exact(h) {
        const rate = (y) => {
          const a = new Array(3 * n).fill(0);
          for (let i = 0; i < n; ++i)
            for (let j = 0; j < n; ++j) {
              if (i === j) continue;
              const r = [0, 1, 2].map((c) => y[3 * j + c] - y[3 * i + c]), d = Math.hypot(...r);
              for (let c = 0; c < 3; ++c) a[3 * i + c] += (s.gravitation * m[j] * r[c]) / (d * d * d);
            }
          return [...y.slice(3 * n), ...a];
        };
        const steps = Math.ceil(s.tEnd / h), dt = s.tEnd / steps, at = (z, k, c) => z.map((v, i) => v + c * k[i]);
        let y = [...s.bodies.flatMap((b) => b.position0), ...s.bodies.flatMap((b) => b.velocity0)];
        for (let k = 0; k < steps; ++k) {
          const k1 = rate(y), k2 = rate(at(y, k1, dt / 2)), k3 = rate(at(y, k2, dt / 2)), k4 = rate(at(y, k3, dt));
          y = y.map((v, i) => v + (dt / 6) * (k1[i] + 2 * k2[i] + 2 * k3[i] + k4[i]));
        }
        return split(y);
      },
    };
  }
  if (s.links) {
    // The joints' angles and rates, each relative to its parent's (link 0's to the world's), from each link's angle
    // about y and its rate; relative to |angle0| sqrt(1 + g / l) (l the first bar's length; the four-bar's 1).
    const relative = (phi, rate) => [...phi.map((p, k) => wrap(p - (k ? phi[k - 1] : 0))), ...rate.map((r, k) => r - (k ? rate[k - 1] : 0))];
    const length = s.loop ? 1 : 2 * Math.hypot(...s.links[0].com);
    return {
      scale: Math.hypot(...s.links.map((l) => l.angle0)) * Math.sqrt(1 + s.gravity / length),
      observeLinks: (frames) => ({ joint_coordinates: relative(frames.map((f) => Math.atan2(f.rotation[2], f.rotation[0])), frames.map((f) => f.w[1])) }),
      exact(h) {
        const y = chainReference(s, s.tEnd, h), n = s.links.length;
        return { joint_coordinates: relative(y.slice(0, n), y.slice(n)) };
      },
    };
  }
  if (s.joint !== 'free') return null;
  if (name === 'projectile' || name === 'kepler') {
    const motion = (rotation, omega, x, v) => ({ position: x, velocity: v });
    return {
      scale: name === 'kepler' ? 1 : Math.hypot(...s.velocity0), observe: motion,
      exact: () => (name === 'kepler' ? keplerOrbit(s.tEnd)
        : { position: s.velocity0.map((v, i) => v * s.tEnd - (i === 2 ? (s.gravity * s.tEnd * s.tEnd) / 2 : 0)),
            velocity: s.velocity0.map((v, i) => v - (i === 2 ? s.gravity * s.tEnd : 0)) }),
    };
  }
  const body = name.startsWith('body_'), symmetric = name === 'free_symmetric_top';
  const m0 = rotate(s.rotation0, rotateBack(s.rotation0, s.omega0).map((w, i) => s.inertia[i] * w)), l0 = Math.hypot(...m0);
  const observe = (rotation, omega) => {
    const wb = rotateBack(rotation, omega);
    if (symmetric) return { angular_velocity: wb, orientation: [rotation[2], rotation[5], rotation[8]] };
    return body ? { angular_velocity: wb, orientation: rotateBack(rotation, m0.map((m) => m / l0)) } : { angular_velocity: wb };
  };
  const scale = symmetric ? 1 : !body ? Math.hypot(...s.omega0)
    : Math.max(1, Math.hypot(...rotateBack(s.rotation0, s.omega0)), Math.hypot(...s.position0), Math.hypot(...s.velocity0));
  return {
    scale, observe,
    exact(h) {
      const r = freeReference(s, s.tEnd, h);
      return observe(r.rotation, rotate(r.rotation, r.omega));
    },
  };
}

// The references of the order studies, computed once per scenario and step (a reproducer studies each scenario at
// several settings or integrators; the references are the same numbers each time).
const references = new WeakMap();
function reference(name, s, study, h) {
  if (!references.has(s)) references.set(s, new Map());
  const known = references.get(s), key = `${name} ${h}`;
  if (!known.has(key)) known.set(key, study.exact(h));
  return known.get(key);
}

/** A scenario's order study (studyOf; none for the others): n = steps0, 2 steps0, .. 16384 steps of tEnd / n from its
 * start in a new world each (makeWorld(h) gives {step(), frames()}, or a promise of it), each class's error at tEnd
 * relative to the scale, printed as lines "<prefix>_<class>_error_n<n>"; and the reference's change from h = 2e-4
 * to 1e-4 ("<prefix>_reference_change"). */
export async function orderStudy(prefix, name, s, makeWorld) {
  const study = studyOf(name, s);
  if (!study) return;
  const want = reference(name, s, study, 1e-4), rough = reference(name, s, study, 2e-4);
  let change = 0;
  for (const c of Object.keys(want)) change = Math.max(change, Math.hypot(...sub(want[c], rough[c])) / study.scale);
  console.log(`${prefix}_reference_change`, change.toExponential(2));
  for (let n = s.steps0; n <= 16384; n *= 2) {
    const world = await makeWorld(s.tEnd / n);
    for (let k = 0; k < n; ++k) world.step();
    const frames = world.frames(), [f] = frames;
    world.free?.();
    const got = study.observeLinks ? study.observeLinks(frames) : study.observe(f.rotation, f.w, f.x, f.v);
    for (const c of Object.keys(want)) console.log(`${prefix}_${c}_error_n${n}`, (Math.hypot(...sub(got[c], want[c])) / study.scale).toExponential(6));
  }
}

/** The audit's shapes, each of mass 2 (box: edges; sphere: radius; cylinder, capsule, cone: radius and height or
 * cylinder length, axis z; ellipsoid: semi-axes; two_spheres: radius and the centres' distance from the origin along x; convex_hull: the
 * tetrahedron (+-a, 0, c), (0, +-b, -c)), and their principal moments about the centre of mass, ascending. */
export const SHAPE_MASS = 2;
export const shapes = {
  box: [0.3, 0.5, 0.7], sphere: [0.4, 0, 0], cylinder: [0.2, 0.9, 0], capsule: [0.2, 0.6, 0], cone: [0.3, 0.8, 0],
  ellipsoid: [0.2, 0.3, 0.5], two_spheres: [0.1, 0.4, 0], convex_hull: [0.3, 0.4, 0.25],
};
export const hullPoints = ([a, b, c]) => [[a, 0, c], [-a, 0, c], [0, b, -c], [0, -b, -c]];
export function exactMoments(name, [a, b, c], m = SHAPE_MASS) {
  const ascending = (x) => x.sort((p, q) => p - q);
  if (name === 'box') return ascending([m * (b * b + c * c) / 12, m * (a * a + c * c) / 12, m * (a * a + b * b) / 12]);
  if (name === 'sphere') return [1, 2, 3].map(() => (2 * m * a * a) / 5);
  if (name === 'cylinder') return ascending([m * (3 * a * a + b * b) / 12, m * (3 * a * a + b * b) / 12, (m * a * a) / 2]);
  if (name === 'capsule') { // a cylinder of length b and two half balls of radius a
    const mc = (m * b) / (b + (4 * a) / 3), mh = (m - mc) / 2;
    const side = (mc * (3 * a * a + b * b)) / 12 + 2 * mh * ((2 * a * a) / 5 + (b * b) / 4 + (3 * b * a) / 8);
    return ascending([side, side, (mc * a * a) / 2 + (4 * mh * a * a) / 5]);
  }
  if (name === 'cone') return ascending([(3 * m * a * a) / 20 + (3 * m * b * b) / 80, (3 * m * a * a) / 20 + (3 * m * b * b) / 80, (3 * m * a * a) / 10]);
  if (name === 'ellipsoid') return ascending([(m * (b * b + c * c)) / 5, (m * (a * a + c * c)) / 5, (m * (a * a + b * b)) / 5]);
  if (name === 'two_spheres') { // each ball about its centre, and the parallel axes' m/2 b^2 each
    const ball = (2 * (m / 2) * a * a) / 5;
    return ascending([2 * ball, 2 * ball + m * b * b, 2 * ball + m * b * b]);
  }
  if (name === 'convex_hull') return ascending([m * (b * b / 10 + c * c / 5), m * (a * a / 10 + c * c / 5), (m * (a * a + b * b)) / 10]);
  throw new Error(`no shape ${name}`);
}
/** The largest relative error of an engine's moments (any order) against the exact ones. */
export function shapeError(name, size, moments) {
  const exact = exactMoments(name, size), got = [...moments].sort((p, q) => p - q);
  return Math.max(...got.map((x, i) => Math.abs(x - exact[i]) / exact[i]));
}
/** Each shape's largest relative error, "shape_<name>_largest_relative_error", for the shapes momentsOf builds
 * (it returns null for one the engine does not offer). */
export function shapeLines(momentsOf) {
  for (const [name, size] of Object.entries(shapes)) {
    const moments = momentsOf(name, size);
    if (moments) console.log(`shape_${name}_largest_relative_error`, shapeError(name, size, moments).toExponential(6));
  }
}
