#!/usr/bin/env node
// MuJoCo's official WebAssembly build (npm @mujoco/mujoco) served to mechcheck's audit as an
// engine (docs/protocol.md): its integrators Euler, RK4, implicit and implicitfast, and
// RK4/dexp_corrected (the classical RK4 tableau on mj_forward with the orientation integrated
// as a Runge-Kutta-Munthe-Kaas method: the control for RK4's orientation), on every scenario
// the bindings can express.
//
//   mechcheck-audit -o report --exec-engine -- node examples/exec/node/mujoco_engine.mjs
//
// The scenario's model as MJCF (the same mapping as mechcheck's C++ adapter for Debian's
// MuJoCo 2.2.2, audit/mechcheck/audit/adapters/mujoco.cpp): a body with <inertial>, a free,
// hinge or ball joint; a chain as nested bodies with hinges about y placed at their start
// angles (joint ref), its loop an equality `connect`; free bodies each with a free joint.
// The central force and the mutual gravitation: the bindings expose no passive-force
// callback (mjcb_passive), so the force is set in qfrc_applied from the state at the start of
// each step -- what a callback would give to a method that evaluates forces once a step
// (Euler, implicit, implicitfast), not to RK4's four stages: refused there.
import loadMujoco from '@mujoco/mujoco';
import { Refused, frame, hullPoints, scenarioOf, serveEngine } from './protocol.mjs';

const mj = await loadMujoco();
const version = mj.mj_versionString();
const enumValue = (e) => e.value;
const INT = mj.mjtIntegrator;

// The integrators, their mjtIntegrator names and their comments in mjtype.h.
const integrators = [
  { name: 'Euler', value: 'mjINT_EULER', words: 'semi-implicit Euler', order: 1 },
  { name: 'RK4', value: 'mjINT_RK4', words: '4th-order Runge Kutta', order: 4 },
  { name: 'implicit', value: 'mjINT_IMPLICIT', words: 'implicit in velocity', order: 1 },
  { name: 'implicitfast', value: 'mjINT_IMPLICITFAST', words: 'implicit in velocity, no rne derivative', order: 1 },
];
for (const i of integrators) if (INT[i.value] === undefined) throw new Error(`MuJoCo ${version} has no ${i.value}`);
const xmlName = { Euler: 'Euler', RK4: 'RK4', implicit: 'implicit', implicitfast: 'implicitfast' };

const text = (x) => String(x); // the shortest decimal that reads back exactly
const vec = (v) => v.map(text).join(' ');

/** The damping ratio of solref that gives a soft contact's rebound e over an impact (the C++
 * adapter's damping_ratio): zeta = -ln e / sqrt(pi^2 + ln^2 e), 1 (critical) for e = 0. */
function dampingRatio(e) {
  if (e <= 0) return 1;
  const l = Math.log(e);
  return -l / Math.sqrt(Math.PI * Math.PI + l * l);
}

/** The MJCF of a contact scenario (the C++ adapter's mjcf_contact, line for line): the ground a
 * plane geom turned by the slope about y; each body a free body with its inertial and one geom
 * of its shape (a cylinder's axis turned onto the body's y); every geom friction "mu 0 0" and
 * condim 3 (1 where mu = 0): MuJoCo combines two geoms' friction by their maximum; e > 0
 * through solref's damping ratio at MuJoCo's default time constant 0.02 s. */
function mjcfContact(s, integrator, cone) {
  const c = s.contact;
  const surface =
    ` condim="${c.mu > 0 ? 3 : 1}" friction="${vec([c.mu > 0 ? c.mu : 1, 0, 0])}"` +
    (c.restitution > 0 ? ` solref="${vec([0.02, dampingRatio(c.restitution)])}"` : '');
  let xml = `<mujoco><compiler angle="radian"/><option timestep="0.01" gravity="0 0 ${text(-s.gravity)}" ` +
    `integrator="${xmlName[integrator]}" cone="${cone}"/><worldbody>`;
  if (c.ground) xml += `<geom name="ground" type="plane" size="0 0 1" euler="0 ${text(c.slope)} 0"${surface}/>`;
  for (const b of c.bodies) {
    xml += `<body><freejoint/><inertial pos="0 0 0" mass="${text(b.mass)}" diaginertia="${vec(b.inertia)}"/>`;
    if (b.shape === 'box') xml += `<geom type="box" size="${vec(b.size)}"${surface}/>`;
    else if (b.shape === 'sphere') xml += `<geom type="sphere" size="${text(b.size[0])}"${surface}/>`;
    else if (b.shape === 'cylinder') xml += `<geom type="cylinder" size="${vec(b.size.slice(0, 2))}" euler="${vec([-Math.PI / 2, 0, 0])}"${surface}/>`;
    else throw new Refused(`this client builds no ${b.shape} geom`);
    xml += '</body>';
  }
  return xml + '</worldbody></mujoco>';
}

/** The MJCF of a scenario. */
function mjcf(s, integrator) {
  const option = `<compiler angle="radian"/><option timestep="0.01" gravity="0 0 ${text(-s.gravity)}" integrator="${xmlName[integrator]}"/>`;
  const inertial = (b) => `<inertial pos="${vec(b.com)}" mass="${text(b.mass)}" diaginertia="${vec(b.inertia)}"/>`;
  if (s.structure === 'one_body') {
    const joint = { free: '<freejoint/>', hinge_y: '<joint type="hinge" axis="0 1 0"/>', ball: '<joint type="ball"/>' }[s.joint];
    return `<mujoco>${option}<worldbody><body>${joint}${inertial(s)}</body></worldbody></mujoco>`;
  }
  let xml = `<mujoco>${option}<worldbody>`;
  if (s.structure === 'chain') {
    s.links.forEach((l, k) => {
      xml += `<body name="link${k}" pos="${vec(l.hinge)}" axisangle="0 1 0 ${text(l.angle0)}">`;
      xml += `<joint type="hinge" axis="0 1 0" ref="${text(l.angle0)}"/>${inertial(l)}`;
    });
    xml += '</body>'.repeat(s.links.length) + '</worldbody>';
    if (s.loop) xml += `<equality><connect body1="link${s.links.length - 1}" anchor="${vec(s.loop.point)}"/></equality>`;
  } else {
    for (const l of s.links) xml += `<body><freejoint/>${inertial(l)}</body>`;
    xml += '</worldbody>';
  }
  return xml + '</mujoco>';
}

/** The classical RK4 on mj_forward with each stage's body-frame angular velocity through
 * the dexp^-1 series to degree 2 (mechcheck's correction of mj_RungeKutta; the C++ adapter's
 * rk4_dexp_corrected, line for line). */
function rk4DexpCorrected(m, d, h) {
  const nq = m.nq, nv = m.nv;
  const q0 = Float64Array.from(d.qpos), v0 = Float64Array.from(d.qvel), t0 = d.time;
  const a = [[0, 0, 0], [0.5, 0, 0], [0, 0.5, 0], [0, 0, 1]], b = [1 / 6, 1 / 3, 1 / 3, 1 / 6], c = [0, 0.5, 0.5, 1];
  const k = [], acc = [];
  const rotations = [];
  for (let j = 0; j < m.njnt; ++j) {
    const type = m.jnt_type[j];
    if (type === 0 /* free */) rotations.push(m.jnt_dofadr[j] + 3);
    else if (type === 1 /* ball */) rotations.push(m.jnt_dofadr[j]);
  }
  const cross = (x, y) => [x[1] * y[2] - x[2] * y[1], x[2] * y[0] - x[0] * y[2], x[0] * y[1] - x[1] * y[0]];
  for (let j = 0; j < 4; ++j) {
    const mix = new Array(nv).fill(0), v = Array.from(v0);
    for (let l = 0; l < j; ++l)
      for (let i = 0; i < nv; ++i) {
        mix[i] += a[j][l] * k[l][i];
        v[i] += h * a[j][l] * acc[l][i];
      }
    d.qpos.set(q0);
    mj.mj_integratePos(m, d.qpos, mix, h);
    d.qvel.set(v);
    d.time = t0 + c[j] * h;
    mj.mj_forward(m, d);
    acc.push(Float64Array.from(d.qacc));
    const kj = Array.from(v);
    for (const adr of rotations) {
      const theta = [0, 1, 2].map((i) => h * mix[adr + i]);
      const w = [0, 1, 2].map((i) => v[adr + i]);
      const tw = cross(theta, w), ttw = cross(theta, tw);
      for (let i = 0; i < 3; ++i) kj[adr + i] = w[i] + tw[i] / 2 + ttw[i] / 12;
    }
    k.push(kj);
  }
  const mix = new Array(nv).fill(0), v = Array.from(v0);
  for (let j = 0; j < 4; ++j)
    for (let i = 0; i < nv; ++i) {
      mix[i] += b[j] * k[j][i];
      v[i] += h * b[j] * acc[j][i];
    }
  d.qpos.set(q0);
  mj.mj_integratePos(m, d.qpos, mix, h);
  d.qvel.set(v);
  d.time = t0 + h;
}

function quaternion(rowMajor) {
  const q = new mj.DoubleBuffer(4);
  try {
    mj.mju_mat2Quat(q, rowMajor);
    return Array.from(q.GetView());
  } finally {
    q.delete();
  }
}

class Run {
  constructor(integrator, scenario) {
    this.name = `MuJoCo ${version} ${integrator}`;
    const s = scenarioOf(scenario);
    this.s = s;
    this.dexp = integrator === 'RK4/dexp_corrected';
    const elliptic = integrator === 'Euler/elliptic';
    const base = this.dexp ? 'RK4' : elliptic ? 'Euler' : integrator;
    if (!(base in xmlName)) throw new Refused(`no integrator ${integrator}`);
    if (s.structure === 'contact' && !declared.find((i) => i.name === integrator)?.contact)
      throw new Refused(`${integrator} builds no contact scenario (Euler and Euler/elliptic do)`);
    if (elliptic && s.structure !== 'contact')
      throw new Refused('a friction cone changes nothing without contact: contact scenarios only');
    this.forced = s.central !== 0 || s.gravitation !== 0;
    if (this.forced && base === 'RK4')
      throw new Refused(
        'the WebAssembly bindings expose no passive-force callback (mjcb_passive): a force set in qfrc_applied ' +
          "is held at the step's start over RK4's four stages, not the scenario's force",
      );
    if (s.central !== 0 && (s.structure !== 'one_body' || s.joint !== 'free'))
      throw new Refused('the central force is applied to a free body only');
    this.m = mj.MjModel.from_xml_string(s.structure === 'contact' ? mjcfContact(s, base, elliptic ? 'elliptic' : 'pyramidal') : mjcf(s, base));
    this.d = new mj.MjData(this.m);
    this.velocity = new mj.DoubleBuffer(6);
    const d = this.d;
    if (s.structure === 'contact') {
      s.contact.bodies.forEach((b, k) => {
        const r = b.rotation0, w = b.omega0;
        d.qpos.set([...b.position0, ...quaternion(r)], 7 * k);
        d.qvel.set([...b.velocity0, ...[0, 1, 2].map((i) => r[i] * w[0] + r[3 + i] * w[1] + r[6 + i] * w[2])], 6 * k);
      });
    } else if (s.structure === 'chain') {
      s.links.forEach((l, k) => {
        d.qpos[k] = l.angle0;
        d.qvel[k] = l.rate0;
      });
    } else if (s.structure === 'free_bodies') {
      s.links.forEach((l, k) => {
        d.qpos.set([...l.position0, 1, 0, 0, 0], 7 * k);
        d.qvel.set([...l.velocity0, 0, 0, 0], 6 * k);
      });
    } else {
      const r = s.rotation0; // row-major, body to world
      const w = [0, 1, 2].map((i) => r[i] * s.omega0[0] + r[3 + i] * s.omega0[1] + r[6 + i] * s.omega0[2]); // R^T omega
      if (s.joint === 'free') {
        d.qpos.set([...s.position0, ...quaternion(r)]);
        d.qvel.set([...s.velocity0, ...w]);
      } else if (s.joint === 'hinge_y') {
        d.qpos[0] = Math.atan2(r[2], r[0]);
        d.qvel[0] = s.omega0[1];
      } else {
        d.qpos.set(quaternion(r));
        d.qvel.set(w);
      }
    }
    mj.mj_forward(this.m, d);
    this.steps = 0;
    // A model with no geom, equality, tendon, actuator, flex, joint range (a joint without one
    // has no limit: the compiler's autolimits; 3.14.0's bindings cannot read jnt_limited, a
    // bool array) or friction loss has no contact, constraint or control for MuJoCo to warn
    // about: its only warnings are mj_step's bad position, velocity and acceleration, each
    // raised after mj_resetData (the default autoreset) has set the time back to 0. For it, the
    // warnings (an embind copy per warning) are read after a step only when the time did not
    // advance by the step; for any other model, and for the corrected RK4 (mj_forward, which
    // checks nothing, and its own time), after every step.
    const m = this.m;
    this.onlyResetWarnings = !this.dexp && m.ngeom === 0 && m.neq === 0 && m.ntendon === 0 && m.nu === 0 && m.nflex === 0 &&
      Array.from(m.jnt_range).every((v) => v === 0) && Array.from(m.dof_frictionloss).every((v) => v === 0) &&
      (m.opt.disableflags & enumValue(mj.mjtDisableBit.mjDSBL_AUTORESET)) === 0;
    this.timestep = undefined;
    if (s.loop)
      this.modelDiffers =
        'MuJoCo closes the loop with a soft equality constraint (connect, default solref 0.02 1: a time constant ' +
        "of 0.02 s, documented in MuJoCo's Modeling chapter, section Solver parameters): it integrates a compliant " +
        'linkage, not the rigid one';
  }

  /** The force of the scenario on each free joint, in qfrc_applied, from the current state. */
  applyForces() {
    const s = this.s, d = this.d;
    d.qfrc_applied.fill(0);
    if (s.central !== 0) {
      const x = [d.qpos[0], d.qpos[1], d.qpos[2]];
      const r = Math.hypot(...x);
      for (let i = 0; i < 3; ++i) d.qfrc_applied[i] = (-s.mass * s.central * x[i]) / (r * r * r);
    }
    if (s.gravitation !== 0) {
      const n = s.links.length;
      for (let a = 0; a < n; ++a)
        for (let b = a + 1; b < n; ++b) {
          const r = [0, 1, 2].map((i) => d.qpos[7 * b + i] - d.qpos[7 * a + i]);
          const dist = Math.hypot(...r);
          const scale = (s.gravitation * s.links[a].mass * s.links[b].mass) / (dist * dist * dist);
          for (let i = 0; i < 3; ++i) {
            d.qfrc_applied[6 * a + i] += scale * r[i];
            d.qfrc_applied[6 * b + i] -= scale * r[i];
          }
        }
    }
  }

  step(h) {
    ++this.steps;
    if (h !== this.timestep) this.m.opt.timestep = this.timestep = h;
    if (this.forced) this.applyForces();
    const before = this.d.time;
    if (this.dexp) rk4DexpCorrected(this.m, this.d, h);
    else mj.mj_step(this.m, this.d);
    if (!this.onlyResetWarnings || before < h || this.d.time - before < h / 2) this.checkWarnings();
    for (let i = 0; i < this.m.nq; ++i)
      if (!Number.isFinite(this.d.qpos[i])) throw new Error(`${this.name}: step ${this.steps}: qpos[${i}] is not finite`);
  }

  checkWarnings() {
    const warnings = this.d.warning;
    for (let i = 0; i < warnings.size(); ++i) {
      const w = warnings.get(i);
      const count = w.number;
      w.delete?.();
      if (count > 0) throw new Error(`${this.name}: step ${this.steps}: MuJoCo warning ${i}`);
    }
  }

  reading() {
    const m = this.m, d = this.d;
    // The positions and velocities of the state mj_step left (its xpos and cvel are those
    // of the step's start).
    mj.mj_kinematics(m, d);
    mj.mj_comPos(m, d);
    mj.mj_comVel(m, d);
    const frameOf = (b) => {
      mj.mj_objectVelocity(m, d, enumValue(mj.mjtObj.mjOBJ_BODY), b, this.velocity, 0);
      const v = Array.from(this.velocity.GetView()); // (angular, linear) at xipos, world axes
      return frame(Array.from(d.xmat.subarray(9 * b, 9 * b + 9)), Array.from(d.xipos.subarray(3 * b, 3 * b + 3)), v.slice(3), v.slice(0, 3));
    };
    if (this.s.structure !== 'one_body') {
      const links = [];
      for (let b = 1; b < m.nbody; ++b) links.push(frameOf(b));
      if (this.s.structure === 'chain') return { links, q: Array.from(d.qpos), v: Array.from(d.qvel) };
      return { links };
    }
    const out = { frame: frameOf(1) };
    if (this.s.joint === 'hinge_y') Object.assign(out, { q: [d.qpos[0]], v: [d.qvel[0]] });
    return out;
  }

  free() {
    this.velocity.delete();
    this.d.delete();
    this.m.delete();
  }
}

const declared = integrators.map((i) => ({
  name: i.name,
  origin:
    `mjtIntegrator ${i.value} (mjtype.h: "${i.words}"); ` +
    `declared order ${i.order}${i.name === 'RK4' ? ' (the name)' : ' (a first-order method by its description)'}`,
  claims: { order: i.order },
}));
// The default integrator and cone meet contact; the elliptic cone on it, contact only. The
// claims: MuJoCo's documentation (the C++ adapter's contact_claims_of).
const contactWords =
  'MuJoCo XML reference, option/cone: "[pyramidal, elliptic], \'pyramidal\'. The type of contact friction cone. ' +
  'Elliptic cones are a better model of the physical reality, but pyramidal cones sometimes make the solver faster ' +
  'and more robust."; the contacts are soft constraints (solref, solimp); no restitution coefficient (a bounce ' +
  "through solref's damping ratio)";
declared[0].contact = { friction_cone: 'pyramidal', newton_restitution: false, soft: true, words: `${contactWords}; the default cone` };
// How the contact scenarios are built (mjcfContact), said in the origin of both integrators that build them.
const contactBuild =
  'contact: a plane geom ground and a geom a free body, friction "mu 0 0" and condim 3 on every geom (MuJoCo takes ' +
  "the larger of two: every pair mu), e > 0 as solref's damping ratio at the default time constant 0.02 s, solimp, " +
  'impratio and the solver at their defaults';
declared[0].origin += `; ${contactBuild} (the default cone, pyramidal)`;
declared.push({
  name: 'Euler/elliptic',
  origin: `mjINT_EULER with <option cone="elliptic"/>: the contact scenarios only; ${contactBuild}`,
  contact: { friction_cone: 'elliptic', newton_restitution: false, soft: true, only: true, words: `${contactWords}; cone="elliptic" set` },
});
declared.push({
  name: 'RK4/dexp_corrected',
  origin:
    'mj_forward at each of the four stages of the classical RK4 tableau, the orientation integrated as a ' +
    "Runge-Kutta-Munthe-Kaas method (dexp^-1 to degree 2): mechcheck's correction of mj_RungeKutta, declared order 4",
  claims: { order: 4 },
});

/** A model of one free body whose geoms carry the shape: of the shape's mass (each geom's
 * mass attribute), or without one; f(model) reads it. */
function withModel(shape, f) {
  const [a, b, c] = shape.size;
  const mass = (m) => (shape.mass === undefined ? '' : ` mass="${text(m)}"`);
  const geoms = {
    box: `<geom type="box" size="${vec([a / 2, b / 2, c / 2])}"${mass(shape.mass)}/>`,
    sphere: `<geom type="sphere" size="${text(a)}"${mass(shape.mass)}/>`,
    cylinder: `<geom type="cylinder" size="${vec([a, b / 2])}"${mass(shape.mass)}/>`,
    capsule: `<geom type="capsule" size="${vec([a, b / 2])}"${mass(shape.mass)}/>`,
    ellipsoid: `<geom type="ellipsoid" size="${vec([a, b, c])}"${mass(shape.mass)}/>`,
    two_spheres:
      `<geom type="sphere" size="${text(a)}" pos="${text(b)} 0 0"${mass(shape.mass / 2)}/>` +
      `<geom type="sphere" size="${text(a)}" pos="${text(-b)} 0 0"${mass(shape.mass / 2)}/>`,
    convex_hull: `<geom type="mesh" mesh="hull"${mass(shape.mass)}/>`,
  }[shape.name];
  if (!geoms) throw new Refused(`MuJoCo ${version} has no ${shape.name} geom`);
  const asset = shape.name === 'convex_hull' ? `<asset><mesh name="hull" vertex="${vec(hullPoints(shape).flat())}"/></asset>` : '';
  const model = mj.MjModel.from_xml_string(`<mujoco>${asset}<worldbody><body><freejoint/>${geoms}</body></worldbody></mujoco>`);
  try {
    return f(model);
  } finally {
    model.delete();
  }
}

/** The principal moments MuJoCo computes for a shape: a body without <inertial> whose geom
 * carries the mass (inertiafromgeom), mjModel.body_inertia after loading. */
function moments(shape) {
  return withModel(shape, (model) => Array.from(model.body_inertia.subarray(3, 6)));
}

/** What MuJoCo gives a body whose geoms carry no mass: mjModel.body_mass and body_inertia. */
function withoutMass(shape) {
  return withModel(shape, (model) => ({
    mass: model.body_mass[1],
    moments: Array.from(model.body_inertia.subarray(3, 6)),
    said:
      'no geom mass or density (XML reference, geom/density: "Material density used to compute the geom mass and ' +
      'inertia ... The internal default of 1000 is the density of water in SI units"); mjModel.body_mass, body_inertia',
  }));
}

await serveEngine(
  {
    name: `mujoco_wasm`,
    origin: `MuJoCo ${version}, npm @mujoco/mujoco (the official WebAssembly build) in Node ${process.version}; the model from an MJCF string, mj_step at fixed timestep`,
    integrators: declared,
  },
  (integrator, scenario) => new Run(integrator, scenario),
  moments,
  withoutMass,
);
