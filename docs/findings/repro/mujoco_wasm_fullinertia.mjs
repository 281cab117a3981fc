// MuJoCo's official WebAssembly build (npm @mujoco/mujoco) given a body's full inertia tensor
// (fullinertia): the tensor the compiled model holds, R diag(body_inertia) R^T with R from
// body_iquat, against the tensor given, and the mass matrix of a hinge about z through the
// centre of mass, which is I_zz exactly. The setup of mujoco_fullinertia.c (Debian's MuJoCo
// 2.2.2), in JavaScript; uses the package only. And the mass and largest moment MuJoCo gives a
// body whose box geom carries no mass (its density, 1000 unless set); and the audit's shapes
// (scenarios.mjs), each a body of one geom of mass 2 (two spheres of 1; the hull a mesh), the
// largest relative error of mjModel.body_inertia against the exact moments.
//
// Run: node mujoco_wasm_fullinertia.mjs PATH/TO/node_modules/@mujoco/mujoco/mujoco.js
// Prints: lines "name value" (see ci/findings).
import { pathToFileURL } from 'node:url';
import { SHAPE_MASS, hullPoints, shapeLines } from './scenarios.mjs';

const { default: loadMujoco } = await import(pathToFileURL(process.argv[2]).href);
const mj = await loadMujoco();

// ixx iyy izz ixy ixz iyz of the counterexample (docs/findings/dynamics.md).
const given = [0.65228281870983662, 0.99999469420290399, 0.85162873708725917, -0.0013582771479765583,
  0.23139648338362692, 0.00090389711068041825];
const full = [given[0], given[3], given[4], given[3], given[1], given[5], given[4], given[5], given[2]];
const text = given.map((x) => x.toPrecision(17)).join(' ');

const m = mj.MjModel.from_xml_string(
  '<mujoco><option gravity="0 0 0"/><worldbody><body><joint type="hinge" axis="0 0 1"/>' +
    `<inertial pos="0 0 0" mass="1" fullinertia="${text}"/></body></worldbody></mujoco>`,
);
const d = new mj.MjData(m);
mj.mj_forward(m, d);
/** Calls f with DoubleBuffers of the given sizes (the package's out parameters; its README calls the view getView, its type definitions GetView) and returns
 * copies of what it wrote, then frees them, with f's own result last. */
function withBuffers(sizes, f) {
  const buffers = sizes.map((n) => new mj.DoubleBuffer(n));
  try {
    const result = f(...buffers);
    return [...buffers.map((b) => Array.from(b.GetView())), result];
  } finally {
    buffers.forEach((b) => b.delete());
  }
}

const [mass] = withBuffers([1], (out) => mj.mj_fullM(m, d, out));

/** max_ij |R diag(l) R^T - a|_ij / max(l), R of the quaternion q (w x y z). */
function tensorError(q, l, a) {
  const [r] = withBuffers([9], (out) => mj.mju_quat2Mat(out, Array.from(q)));
  let worst = 0;
  for (let i = 0; i < 3; ++i)
    for (let j = 0; j < 3; ++j) {
      let s = 0;
      for (let k = 0; k < 3; ++k) s += r[3 * i + k] * l[k] * r[3 * j + k];
      worst = Math.max(worst, Math.abs(s - a[3 * i + j]));
    }
  return worst / Math.max(...l);
}

const exact = given[2], eps = 2 ** -52;
console.log(`mass_matrix ${mass[0].toPrecision(17)}`);
console.log(`exact ${exact.toPrecision(17)}`);
console.log(`mass_matrix_error ${Math.abs(mass[0] - exact).toExponential(6)}`);
console.log(`mass_matrix_relative_error ${(Math.abs(mass[0] - exact) / exact).toExponential(3)}`);
console.log(`mass_matrix_error_eps ${(Math.abs(mass[0] - exact) / (eps * exact)).toExponential(3)}`);
console.log(`compiled_tensor_relative_error ${tensorError(m.body_iquat.slice(4, 8), Array.from(m.body_inertia.slice(3, 6)), full).toExponential(3)}`);
const [l, , q, iterations] = withBuffers([3, 9, 4], (l, vec, q) => mj.mju_eig3(l, vec, q, full));
console.log(`eig3_iterations ${iterations}`);
console.log(`eig3_tensor_relative_error ${tensorError(q, l, full).toExponential(3)}`);

// 10000 tensors R diag(p) R^T, principal moments uniform in [0.1, 1] (triangle inequality
// held), R uniform: the numbers of mujoco_fullinertia.c, drawn alike (xorshift64*, its seed).
let state = 20261126n;
function uniform() {
  state ^= state >> 12n;
  state = BigInt.asUintN(64, state ^ (state << 25n));
  state ^= state >> 27n;
  return Number(BigInt.asUintN(64, state * 2685821657736338717n) >> 11n) * 2 ** -53;
}
const count = 10000, errors = [];
while (errors.length < count) {
  const p = [0.1 + 0.9 * uniform(), 0.1 + 0.9 * uniform(), 0.1 + 0.9 * uniform()];
  if (p[0] > p[1] + p[2] || p[1] > p[0] + p[2] || p[2] > p[0] + p[1]) continue;
  const u1 = uniform(), u2 = 2 * Math.PI * uniform(), u3 = 2 * Math.PI * uniform();
  const qr = [Math.sqrt(1 - u1) * Math.sin(u2), Math.sqrt(1 - u1) * Math.cos(u2), Math.sqrt(u1) * Math.sin(u3),
    Math.sqrt(u1) * Math.cos(u3)];
  const [r] = withBuffers([9], (out) => mj.mju_quat2Mat(out, qr));
  const t9 = new Array(9).fill(0);
  for (let i = 0; i < 3; ++i)
    for (let j = 0; j < 3; ++j)
      for (let k = 0; k < 3; ++k) t9[3 * i + j] += r[3 * i + k] * p[k] * r[3 * j + k];
  for (let i = 0; i < 3; ++i) for (let j = 0; j < i; ++j) t9[3 * i + j] = t9[3 * j + i];
  const [lr, , qt] = withBuffers([3, 9, 4], (l, vec, q) => mj.mju_eig3(l, vec, q, t9));
  errors.push(tensorError(qt, lr, t9));
}
errors.sort((a, b) => a - b);
console.log(`random_tensors ${count}`);
console.log(`random_largest_relative_error ${errors[count - 1].toExponential(3)}`);
console.log(`random_median_relative_error ${errors[count / 2].toExponential(3)}`);
console.log(`random_above_1e-12 ${errors.filter((e) => e > 1e-12).length}`);
// A body whose box geom (0.3 x 0.5 x 0.7: half-sizes in MJCF) has no mass or density: exact for a
// density of 1000, mass 105 and largest moment 105 (0.5^2 + 0.7^2) / 12 = 6.475.
{
  const box = mj.MjModel.from_xml_string(
    '<mujoco><worldbody><body><freejoint/><geom type="box" size="0.15 0.25 0.35"/></body></worldbody></mujoco>',
  );
  console.log(`box_alone_mass ${box.body_mass[1].toExponential(6)}`);
  console.log(`box_alone_moment_max ${Math.max(...box.body_inertia.subarray(3, 6)).toExponential(6)}`);
  box.delete();
}
shapeLines((name, [a, b, c]) => {
  const mass = (m) => ` mass="${m}"`, vec = (v) => v.join(' ');
  const geoms = {
    box: `<geom type="box" size="${vec([a / 2, b / 2, c / 2])}"${mass(SHAPE_MASS)}/>`,
    sphere: `<geom type="sphere" size="${a}"${mass(SHAPE_MASS)}/>`,
    cylinder: `<geom type="cylinder" size="${vec([a, b / 2])}"${mass(SHAPE_MASS)}/>`,
    capsule: `<geom type="capsule" size="${vec([a, b / 2])}"${mass(SHAPE_MASS)}/>`,
    ellipsoid: `<geom type="ellipsoid" size="${vec([a, b, c])}"${mass(SHAPE_MASS)}/>`,
    two_spheres: [b, -b].map((x) => `<geom type="sphere" size="${a}" pos="${x} 0 0"${mass(SHAPE_MASS / 2)}/>`).join(''),
    convex_hull: `<geom type="mesh" mesh="hull"${mass(SHAPE_MASS)}/>`,
  }[name];
  if (!geoms) return null; // no cone
  const asset = name === 'convex_hull' ? `<asset><mesh name="hull" vertex="${vec(hullPoints([a, b, c]).flat())}"/></asset>` : '';
  const model = mj.MjModel.from_xml_string(`<mujoco>${asset}<worldbody><body><freejoint/>${geoms}</body></worldbody></mujoco>`);
  const moments = Array.from(model.body_inertia.subarray(3, 6));
  model.delete();
  return moments;
});
