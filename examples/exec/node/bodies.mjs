// The scenario's bodies in world terms, for the Node engine clients that build each body
// from its world pose (cannon-es, Rapier): vectors and rotations (row-major 3x3 arrays),
// quaternions {x, y, z, w}, and the frames of a chain's links at their start.

/** R x, for R row-major. */
export const rotate = (r, x) => [0, 1, 2].map((i) => r[3 * i] * x[0] + r[3 * i + 1] * x[1] + r[3 * i + 2] * x[2]);
export const cross = (a, b) => [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
export const add = (a, b) => a.map((x, i) => x + b[i]);
export const sub = (a, b) => a.map((x, i) => x - b[i]);
/** Rotation about y by angle t, row-major. */
export const aboutY = (t) => [Math.cos(t), 0, Math.sin(t), 0, 1, 0, -Math.sin(t), 0, Math.cos(t)];
/** A B, row-major. */
export function times(a, b) {
  const out = new Array(9).fill(0);
  for (let i = 0; i < 3; ++i) for (let j = 0; j < 3; ++j) for (let k = 0; k < 3; ++k) out[3 * i + j] += a[3 * i + k] * b[3 * k + j];
  return out;
}

/** The unit quaternion {x, y, z, w} of a rotation matrix (row-major), Shepperd's method. */
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

/** A one-body scenario's body at its start, in the world: its centre of mass and that point's
 * velocity (a jointed body's pivot is the world origin, its centre of mass at R0 com). */
export function oneBodyStart(s) {
  const com = s.joint === 'free' ? s.position0 : rotate(s.rotation0, s.com);
  return { com, velocity: s.joint === 'free' ? s.velocity0 : cross(s.omega0, com) };
}

/** Each link of a chain scenario at its start, in the world: its rotation, its centre of mass,
 * that point's velocity and the angular velocity. Each link's frame is its parent's turned
 * about y by its joint angle, at its hinge (link::hinge in the parent's frame, link 0's in
 * the world). */
export function chainLinks(s) {
  const out = [];
  let rotation = [1, 0, 0, 0, 1, 0, 0, 0, 1], origin = [0, 0, 0], omega = [0, 0, 0], velocity = [0, 0, 0];
  for (const l of s.links) {
    const hinge = add(origin, rotate(rotation, l.hinge));
    velocity = add(velocity, cross(omega, sub(hinge, origin)));
    rotation = times(rotation, aboutY(l.angle0));
    omega = add(omega, [0, l.rate0, 0]);
    origin = hinge;
    const com = add(origin, rotate(rotation, l.com));
    out.push({ rotation, com, velocity: add(velocity, cross(omega, sub(com, origin))), omega });
  }
  return out;
}
