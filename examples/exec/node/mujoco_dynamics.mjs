#!/usr/bin/env node
// MuJoCo's official WebAssembly build (npm @mujoco/mujoco) served to mechcheck's audit as a
// dynamics library (docs/protocol.md, kind "dynamics"): a robot's mass matrix, bias forces,
// inverse and forward dynamics from MuJoCo's own URDF import.
//
//   mechcheck-audit -o report --exec-dynamics --robots 100 -- node examples/exec/node/mujoco_dynamics.mjs
//
// The robot's URDF goes to MjModel.from_xml_string (MuJoCo's URDF reader; gravity, which URDF
// does not carry, set on mjModel.opt); the coordinates are mapped by joint name. The same
// functions as mechcheck's C++ adapter for Debian's MuJoCo 2.2.2 (`mujoco-urdf`,
// audit/mechcheck/audit/adapters/mujoco_dynamics.cpp): M from mj_fullM of qM, h = qfrc_bias
// and forward dynamics qacc after mj_forward, inverse dynamics qfrc_inverse after
// mj_inverse. MuJoCo's compiler changes the robot it is given (each inertia tensor turned
// into principal moments and a frame; links joined by fixed joints fused): the robot it holds
// is read back from mjModel (body_pos, body_quat, body_ipos, body_iquat, body_inertia,
// body_mass, jnt_axis) and sent as the load's "held" URDF, so the audit holds MuJoCo's
// algorithms to that robot and measures the compiler's change apart.
//
// The kinematics: each link's frame (xpos, xmat after mj_kinematics), its Jacobian
// (mj_jacBody) and at its centre of mass (mj_jacBodyCom) after mj_kinematics and mj_comPos,
// and Jdot qdot (mj_jacDot at xpos, after mj_comVel as well, times qvel) on a second model of
// the robot compiled without fusing (`<compiler fusestatic="false"/>` in the URDF's <mujoco>
// element: every link a body of its name); the centre of mass (the world body's subtree_com),
// J_c (mj_jacSubtreeCom of the world body) on that model too, so that a root welded to the
// world keeps its mass; A_G column by column from the world body's subtree mass times
// subtree_linvel and subtree_angmom after mj_subtreeVel at qvel = e_k, on the model the
// dynamics use (the held robot's inertias, as the audit holds A_G to them).
import loadMujoco from '@mujoco/mujoco';
import { Refused, serveDynamics } from './protocol.mjs';

const mj = await loadMujoco();
const version = mj.mj_versionString();
const JOINT = mj.mjtObj.mjOBJ_JOINT.value, BODY = mj.mjtObj.mjOBJ_BODY.value;
const SLIDE = mj.mjtJoint.mjJNT_SLIDE.value, HINGE = mj.mjtJoint.mjJNT_HINGE.value;

/** Calls f with DoubleBuffers of the given sizes and returns copies of what it wrote. */
function withBuffers(sizes, f) {
  const buffers = sizes.map((n) => new mj.DoubleBuffer(n));
  try {
    f(...buffers);
    return buffers.map((b) => Array.from(b.GetView()));
  } finally {
    buffers.forEach((b) => b.delete());
  }
}

const text = (x) => String(x); // the shortest decimal that reads back exactly
const triple = (v) => v.map(text).join(' ');

/** The rotation (row-major) of a quaternion w x y z, by MuJoCo's own mju_quat2Mat. */
const rotation = (q) => withBuffers([9], (out) => mj.mju_quat2Mat(out, Array.from(q)))[0];

/** Roll, pitch and yaw of a rotation, R = Rz(yaw) Ry(pitch) Rx(roll) (URDF's convention). */
function rpyOf(r) {
  const c = Math.hypot(r[7], r[8]), pitch = Math.atan2(-r[6], c);
  if (c === 0) return [0, pitch, Math.atan2(-r[1], r[4])];
  return [Math.atan2(r[7], r[8]), pitch, Math.atan2(r[3], r[0])];
}

/** The moving joints of a URDF text, in the order of their elements (the robot's coordinates). */
function movingJoints(urdf) {
  const names = [];
  for (const [element] of urdf.matchAll(/<joint\b[^>]*>/g)) {
    const name = /\bname="([^"]*)"/.exec(element)?.[1], type = /\btype="([^"]*)"/.exec(element)?.[1];
    if (name === undefined || type === undefined) throw new Error(`a joint without a name or a type: ${element}`);
    if (type !== 'fixed') names.push(name);
  }
  return names;
}

/** The names of a URDF text's links, in the order of their elements (the robot's links). */
const linkNames = (urdf) => Array.from(urdf.matchAll(/<link\b[^>]*\bname="([^"]*)"/g), (x) => x[1]);

/** A compiled model with its data and the robot's coordinates at its addresses. */
class Compiled {
  constructor(xml, gravity, joints) {
    this.m = mj.MjModel.from_xml_string(xml);
    for (let i = 0; i < 3; ++i) this.m.opt.gravity[i] = gravity[i];
    this.d = new mj.MjData(this.m);
    this.qpos = [];
    this.dof = [];
    for (const name of joints) {
      const id = mj.mj_name2id(this.m, JOINT, name);
      if (id < 0) throw new Refused(`the model has no joint ${name}`);
      this.qpos.push(this.m.jnt_qposadr[id]);
      this.dof.push(this.m.jnt_dofadr[id]);
    }
  }
  set(q, qdot) {
    mj.mj_resetData(this.m, this.d);
    for (let i = 0; i < this.qpos.length; ++i) {
      this.d.qpos[this.qpos[i]] = q[i];
      this.d.qvel[this.dof[i]] = qdot ? qdot[i] : 0;
    }
  }
  /** Rows of a 3 x nv MuJoCo Jacobian at the robot's coordinates. */
  columns(jac) {
    const nv = this.m.nv;
    return [0, 1, 2].map((r) => this.dof.map((k) => jac[r * nv + k]));
  }
  free() {
    this.d.delete();
    this.m.delete();
  }
}

class Model {
  constructor(urdf, gravity) {
    const joints = movingJoints(urdf);
    this.links = linkNames(urdf);
    try {
      // A second model without fusing, for the links' kinematics (every link a body).
      this.k = new Compiled(urdf.replace(/<robot\b[^>]*>/, (open) => `${open}<mujoco><compiler fusestatic="false"/></mujoco>`),
        gravity, joints);
    } catch (e) {
      throw e instanceof Refused ? e : new Refused(`MuJoCo ${version} did not compile the robot unfused: ${e?.message ?? e}`);
    }
    this.body = this.links.map((name) => mj.mj_name2id(this.k.m, BODY, name));
    const missing = this.links.find((name, l) => this.body[l] < 0);
    if (missing !== undefined) throw new Refused(`the unfused model has no body ${missing}`);
    try {
      this.m = mj.MjModel.from_xml_string(urdf);
    } catch (e) {
      throw new Refused(`MuJoCo ${version} did not compile the robot: ${e?.message ?? e}`);
    }
    const m = this.m;
    for (let i = 0; i < 3; ++i) m.opt.gravity[i] = gravity[i];
    this.d = new mj.MjData(m);
    this.n = joints.length;
    if (m.nv !== this.n) throw new Refused(`the model has ${m.nv} degrees of freedom, the robot ${this.n}`);
    this.qpos = [];
    this.dof = [];
    for (const name of joints) {
      const id = mj.mj_name2id(m, JOINT, name);
      if (id < 0) throw new Refused(`the model has no joint ${name}`);
      this.qpos.push(m.jnt_qposadr[id]);
      this.dof.push(m.jnt_dofadr[id]);
    }
    this.held = this.heldUrdf(gravity);
  }

  /** The robot of the compiled model as URDF: a body a link (its mass at body_ipos, the
   * tensor of its principal moments in the frame of body_iquat), a body's frame in its parent's a joint
   * (body_pos, body_quat), hinge or slide along jnt_axis, or fixed; the moving joints first,
   * in the order of the robot's coordinates. */
  heldUrdf(gravity) {
    const m = this.m;
    const name = (b) => mj.mj_id2name(m, BODY, b) || `body${b}`;
    const at = (array, k, n) => Array.from(array.slice(n * k, n * k + n));
    let links = '';
    const moving = new Array(this.n), fixed = [];
    for (let b = 0; b < m.nbody; ++b) {
      links += `<link name="${name(b)}">`;
      if (b > 0 && m.body_mass[b] > 0) {
        // The tensor R diag(body_inertia) R^T, R = mju_quat2Mat(body_iquat): what MuJoCo's
        // kinematics compute with (the quaternion as it is, unit or not).
        const r = rotation(at(m.body_iquat, b, 4)), l = at(m.body_inertia, b, 3);
        const t = (i, j) => text(r[3 * i] * l[0] * r[3 * j] + r[3 * i + 1] * l[1] * r[3 * j + 1] + r[3 * i + 2] * l[2] * r[3 * j + 2]);
        links += `<inertial><origin xyz="${triple(at(m.body_ipos, b, 3))}" rpy="0 0 0"/><mass value="${text(m.body_mass[b])}"/>` +
          `<inertia ixx="${t(0, 0)}" ixy="${t(0, 1)}" ixz="${t(0, 2)}" iyy="${t(1, 1)}" iyz="${t(1, 2)}" izz="${t(2, 2)}"/></inertial>`;
      }
      links += '</link>';
      if (b === 0) continue;
      const origin = `<parent link="${name(m.body_parentid[b])}"/><child link="${name(b)}"/>` +
        `<origin xyz="${triple(at(m.body_pos, b, 3))}" rpy="${triple(rpyOf(rotation(at(m.body_quat, b, 4))))}"/>`;
      if (m.body_jntnum[b] > 1) throw new Error(`body ${name(b)} has ${m.body_jntnum[b]} joints`);
      if (m.body_jntnum[b] === 0) {
        fixed.push(`<joint name="${name(b)}_weld" type="fixed">${origin}</joint>`);
        continue;
      }
      const j = m.body_jntadr[b];
      if (at(m.jnt_pos, j, 3).some((x) => x !== 0)) throw new Error(`joint ${mj.mj_id2name(m, JOINT, j)} is not at its body's origin`);
      const type = m.jnt_type[j] === SLIDE ? 'prismatic' : m.jnt_type[j] === HINGE ? 'continuous' : null;
      if (type === null) throw new Error(`joint ${mj.mj_id2name(m, JOINT, j)} is neither a hinge nor a slide`);
      const k = this.dof.indexOf(m.jnt_dofadr[j]);
      moving[k] = `<joint name="${mj.mj_id2name(m, JOINT, j)}" type="${type}">${origin}<axis xyz="${triple(at(m.jnt_axis, j, 3))}"/></joint>`;
    }
    return `<robot name="mujoco_held"><!-- mechcheck gravity="${triple(gravity)}" -->${links}${moving.join('')}${fixed.join('')}</robot>`;
  }

  set(q, qdot) {
    mj.mj_resetData(this.m, this.d);
    for (let i = 0; i < this.n; ++i) {
      this.d.qpos[this.qpos[i]] = q[i];
      this.d.qvel[this.dof[i]] = qdot ? qdot[i] : 0;
    }
  }
  read(x) {
    if (this.d.warning.get(mj.mjtWarning.mjWARN_BADQACC.value).number > 0) throw new Error('a bad acceleration (mjWARN_BADQACC)');
    return this.dof.map((k) => x[k]);
  }
  massMatrix(q) {
    this.set(q);
    mj.mj_forward(this.m, this.d);
    const nv = this.m.nv;
    const [dense] = withBuffers([nv * nv], (out) => mj.mj_fullM(this.m, this.d, out));
    return this.dof.flatMap((i) => this.dof.map((j) => dense[i * nv + j]));
  }
  bias(q, qdot) {
    this.set(q, qdot);
    mj.mj_forward(this.m, this.d);
    return this.read(this.d.qfrc_bias);
  }
  inverse(q, qdot, qddot) {
    this.set(q, qdot);
    this.dof.forEach((k, i) => (this.d.qacc[k] = qddot[i]));
    mj.mj_inverse(this.m, this.d);
    return this.read(this.d.qfrc_inverse);
  }
  forward(q, qdot, tau) {
    this.set(q, qdot);
    this.dof.forEach((k, i) => (this.d.qfrc_applied[k] = tau[i]));
    mj.mj_forward(this.m, this.d);
    return this.read(this.d.qacc);
  }
  /** The links' bodies placed at q (mj_kinematics, mj_comPos) on the unfused model. */
  place(q, qdot) {
    this.k.set(q, qdot);
    mj.mj_kinematics(this.k.m, this.k.d);
    mj.mj_comPos(this.k.m, this.k.d);
  }
  framePoses(q) {
    this.place(q);
    const { d } = this.k;
    return this.body.flatMap((b) => {
      const x = Array.from(d.xpos.slice(3 * b, 3 * b + 3)), r = Array.from(d.xmat.slice(9 * b, 9 * b + 9));
      return [...x, r[0], r[3], r[6], r[1], r[4], r[7], r[2], r[5], r[8]];
    });
  }
  /** Each link's 6 x n Jacobian by f (mj_jacBody or mj_jacBodyCom), stacked row by row. */
  jacobians(q, f) {
    this.place(q);
    const { m, d } = this.k;
    return this.body.flatMap((b) => {
      const [jacp, jacr] = withBuffers([3 * m.nv, 3 * m.nv], (p, r) => f(m, d, p, r, b));
      return [...this.k.columns(jacp), ...this.k.columns(jacr)].flat();
    });
  }
  frameJacobians(q) {
    return this.jacobians(q, mj.mj_jacBody);
  }
  linkComJacobians(q) {
    return this.jacobians(q, mj.mj_jacBodyCom);
  }
  /** mj_jacDot at each body's origin (xpos) times qvel: (a_o; alpha) at qacc = 0. */
  frameBiasAccelerations(q, qdot) {
    this.place(q, qdot);
    const { m, d } = this.k;
    mj.mj_comVel(m, d);
    return this.body.flatMap((b) => {
      const point = Array.from(d.xpos.slice(3 * b, 3 * b + 3));
      const [jacp, jacr] = withBuffers([3 * m.nv, 3 * m.nv], (p, r) => mj.mj_jacDot(m, d, p, r, point, b));
      return [...this.k.columns(jacp), ...this.k.columns(jacr)].map((row) => row.reduce((s, j, i) => s + j * qdot[i], 0));
    });
  }
  centreOfMass(q) {
    this.place(q);
    return Array.from(this.k.d.subtree_com.slice(0, 3));
  }
  comJacobian(q) {
    this.place(q);
    const { m, d } = this.k;
    const [jacp] = withBuffers([3 * m.nv], (p) => mj.mj_jacSubtreeCom(m, d, p, 0));
    return this.k.columns(jacp).flat();
  }
  /** Column k: the world body's subtree mass times subtree_linvel, and subtree_angmom, after
   * mj_subtreeVel at qvel = e_k on the model of the dynamics; rows (P; L_G), row by row. */
  centroidalMomentumMatrix(q) {
    const columns = this.dof.map((k, i) => {
      this.set(q, this.dof.map((_, j) => (j === i ? 1 : 0)));
      mj.mj_kinematics(this.m, this.d);
      mj.mj_comPos(this.m, this.d);
      mj.mj_comVel(this.m, this.d);
      mj.mj_subtreeVel(this.m, this.d);
      const mass = this.m.body_subtreemass[0];
      return [...Array.from(this.d.subtree_linvel.slice(0, 3), (v) => v * mass), ...Array.from(this.d.subtree_angmom.slice(0, 3))];
    });
    return [0, 1, 2, 3, 4, 5].flatMap((r) => columns.map((c) => c[r]));
  }
  free() {
    this.d.delete();
    this.m.delete();
    this.k.free();
  }
}

await serveDynamics(
  {
    name: 'mujoco_wasm',
    origin: `MuJoCo ${version} (npm @mujoco/mujoco, WebAssembly, double): its URDF import (MjModel.from_xml_string); ` +
      'mj_fullM of qM, qfrc_bias and qacc after mj_forward, qfrc_inverse after mj_inverse; qfrc_bias is Coriolis, ' +
      'centrifugal and gravity (M qacc + qfrc_bias = qfrc_applied, the sign of h); no armature, damping or friction ' +
      'loss set; the robot the compiler holds read back from mjModel; each link\'s frame (xpos, xmat), Jacobian ' +
      '(mj_jacBody), Jacobian at its centre of mass (mj_jacBodyCom) and Jdot qdot (mj_jacDot at xpos, times qvel), ' +
      'the centre of mass (the world body\'s subtree_com) and J_c (mj_jacSubtreeCom) on the robot compiled without ' +
      'fusing (fusestatic false); A_G from mj_subtreeVel at qvel = e_k (the world body\'s subtree mass times ' +
      'subtree_linvel, subtree_angmom)',
    quantities: ['mass_matrix', 'bias', 'inverse', 'forward', 'frame_poses', 'frame_jacobians',
      'frame_bias_accelerations', 'link_com_jacobians', 'centre_of_mass', 'com_jacobian', 'centroidal_momentum_matrix'],
  },
  (urdf, gravity) => new Model(urdf, gravity),
);
