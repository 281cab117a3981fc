// MuJoCo's official WebAssembly build (npm @mujoco/mujoco) -- RK4 (mjINT_RK4) on a free
// symmetric top: the order of the orientation, and the same four mj_forward evaluations with
// each stage's body angular velocity corrected by the dexp^-1 series. The setup and the exact
// motion of mujoco_rk4_orientation.c (Debian's MuJoCo 2.2.2), in JavaScript; uses the package
// only.
//
// The body: I = (1, 1, 2), body angular velocity w0 = (0.6, 0, 1), no gravity, starting at the
// identity orientation. Exact motion: the symmetry axis x3 turns about the angular momentum
// M = (0.6, 0, 2) at |M| / I1 (Landau & Lifshitz section 33).
//
// Run: node mujoco_wasm_rk4_orientation.mjs PATH/TO/node_modules/@mujoco/mujoco/mujoco.js
// Prints: lines "name value" (see ci/findings).
import { pathToFileURL } from 'node:url';

const { default: loadMujoco } = await import(pathToFileURL(process.argv[2]).href);
const mj = await loadMujoco();
const m = mj.MjModel.from_xml_string(
  '<mujoco><option timestep="0.01" gravity="0 0 0" integrator="RK4"/><worldbody><body><freejoint/>' +
    '<inertial pos="0 0 0" mass="1" diaginertia="1 1 2"/></body></worldbody></mujoco>',
);
const d = new mj.MjData(m);

function start() {
  mj.mj_resetData(m, d);
  d.qpos[3] = 1; // identity quaternion (w x y z)
  d.qvel.set([0, 0, 0, 0.6, 0, 1]); // angular velocity in the body frame
  mj.mj_forward(m, d);
}

/** The exact symmetry axis (world frame) at time t: e3 rotated about M by |M| t / I1. */
function exactAxis(t) {
  const mn = Math.hypot(0.6, 2), k = [0.6 / mn, 0, 2 / mn], e3 = [0, 0, 1];
  const phi = (mn / 1.0) * t, c = Math.cos(phi), s = Math.sin(phi);
  const kxe = [k[1] * e3[2] - k[2] * e3[1], k[2] * e3[0] - k[0] * e3[2], k[0] * e3[1] - k[1] * e3[0]];
  return [0, 1, 2].map((i) => e3[i] * c + kxe[i] * s + k[i] * k[2] * (1 - c));
}

/** The third column of the rotation of quaternion (w x y z). */
function axisOf(q) {
  const [w, x, y, z] = q;
  return [2 * (x * z + w * y), 2 * (y * z - w * x), 1 - 2 * (x * x + y * y)];
}

const cross = (a, b) => [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];

/** RK4 with the orientation as a Runge-Kutta-Munthe-Kaas method: mj_forward per stage, stage
 * orientation q0 exp(Theta_j), k_j = w_j + Theta_j x w_j / 2 + Theta_j x (Theta_j x w_j) / 12. */
function rk4Dexp(h) {
  const q0 = Float64Array.from(d.qpos), v0 = Array.from(d.qvel), nv = 6;
  const a = [[0, 0, 0], [0.5, 0, 0], [0, 0.5, 0], [0, 0, 1]], b = [1 / 6, 1 / 3, 1 / 3, 1 / 6];
  const k = [], acc = [];
  for (let j = 0; j < 4; ++j) {
    const mix = new Array(nv).fill(0), v = v0.slice();
    for (let l = 0; l < j; ++l)
      for (let i = 0; i < nv; ++i) mix[i] += a[j][l] * k[l][i], (v[i] += h * a[j][l] * acc[l][i]);
    d.qpos.set(q0);
    mj.mj_integratePos(m, d.qpos, mix, h);
    d.qvel.set(v);
    mj.mj_forward(m, d);
    acc.push(Array.from(d.qacc));
    const theta = [0, 1, 2].map((i) => h * mix[3 + i]), w = v.slice(3);
    const tw = cross(theta, w), ttw = cross(theta, tw);
    k.push([...v.slice(0, 3), ...[0, 1, 2].map((i) => w[i] + tw[i] / 2 + ttw[i] / 12)]);
  }
  const mix = new Array(nv).fill(0), v = v0.slice();
  for (let j = 0; j < 4; ++j) for (let i = 0; i < nv; ++i) mix[i] += b[j] * k[j][i], (v[i] += h * b[j] * acc[j][i]);
  d.qpos.set(q0);
  mj.mj_integratePos(m, d.qpos, mix, h);
  d.qvel.set(v);
  d.time += h;
}

function axisError(n, tEnd, corrected) {
  start();
  const h = tEnd / n;
  m.opt.timestep = h;
  for (let i = 0; i < n; ++i) corrected ? rk4Dexp(h) : mj.mj_step(m, d);
  const x = axisOf(Array.from(d.qpos.subarray(3, 7))), e = exactAxis(tEnd);
  return Math.hypot(x[0] - e[0], x[1] - e[1], x[2] - e[2]);
}

console.log(`mujoco_version_string ${mj.mj_versionString()}`);
console.log(`mujoco_version ${mj.mj_version()}`);
// Global order of the axis at t = 5: log2 of the error ratio as n doubles.
for (const corrected of [false, true]) {
  let previous = 0, order = 0;
  for (let n = 64; n <= 2048; n *= 2) {
    const e = axisError(n, 5.0, corrected);
    if (previous > 0) order = Math.log2(previous / e);
    previous = e;
  }
  console.log(`${corrected ? 'rk4_dexp_corrected' : 'rk4'}_axis_order ${order.toFixed(3)}`);
}
d.delete();
m.delete();
