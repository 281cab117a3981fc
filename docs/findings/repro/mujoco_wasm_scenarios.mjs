// mujoco_wasm_scenarios.mjs -- the audit's free bodies (scenarios.mjs: the tops, the boxes, the random bodies) and its
// heavy top in MuJoCo's official WebAssembly build (npm @mujoco/mujoco), at each of its integrators (mjtIntegrator
// Euler, RK4, implicit, implicitfast): a body of the scenario's mass and principal moments (<inertial pos diaginertia>)
// on a free joint, or on a ball joint at the origin (the heavy top, its centre of mass at pos), gravity the
// scenario's; qpos its position and orientation (mju_mat2Quat of its rotation), qvel its velocity and body angular
// velocity, then mj_forward; each step mj_step, a run stopped at the first step that raises a MuJoCo warning (its
// number printed). Read back as the state mj_step left: mj_kinematics, mj_comPos, mj_comVel, then the body's
// rotation xmat, centre of mass xipos and mj_objectVelocity's (angular, linear) velocity there in world axes. Printed
// for each: the long run's largest angular momentum change and energy change (1e5 steps of h: 0.01, the boxes'
// 0.0025, the heavy top's 0.002; scenarios.mjs's longRun) and the order study's errors (scenarios.mjs's orderStudy).
// Run: node mujoco_wasm_scenarios.mjs PATH/TO/node_modules/@mujoco/mujoco/mujoco.js
// Output: lines "name value". Uses only MuJoCo and plain JavaScript.
import { pathToFileURL } from 'node:url';
import { bodiesAtStart, longRun, orderStudy, rotateBack, scenarios } from './scenarios.mjs';

const entry = process.argv[2];
if (!entry) { console.error('usage: node mujoco_wasm_scenarios.mjs PATH/TO/node_modules/@mujoco/mujoco/mujoco.js'); process.exit(1); }
const mj = await (await import(pathToFileURL(entry).href)).default();
console.log('mujoco_version', mj.mj_versionString());

function world(s, integrator, h = s.h) {
  const joint = s.joint === 'free' ? '<freejoint/>' : '<joint type="ball"/>';
  const m = mj.MjModel.from_xml_string(
    `<mujoco><compiler angle="radian"/><option timestep="0.01" gravity="0 0 ${String(-s.gravity)}" integrator="${integrator}"/>` +
    `<worldbody><body>${joint}<inertial pos="${s.com.join(' ')}" mass="${s.mass}" diaginertia="${s.inertia.join(' ')}"/></body>` +
    '</worldbody></mujoco>');
  const d = new mj.MjData(m), velocity = new mj.DoubleBuffer(6), q = new mj.DoubleBuffer(4);
  const [start] = bodiesAtStart(s);
  mj.mju_mat2Quat(q, start.rotation);
  const wb = rotateBack(start.rotation, start.w);
  if (s.joint === 'free') {
    d.qpos.set([...start.x, ...q.GetView()]);
    d.qvel.set([...start.v, ...wb]);
  } else {
    d.qpos.set(q.GetView());
    d.qvel.set(wb);
  }
  q.delete();
  mj.mj_forward(m, d);
  m.opt.timestep = h;
  // The model has no geom, constraint, actuator or flex: MuJoCo's only warnings here are mj_step's bad position,
  // velocity and acceleration, each raised after mj_resetData (its default autoreset) has set the time back to 0.
  // The warnings (an embind copy each) are read after the first step and after any step the time did not advance.
  if (m.ngeom + m.neq + m.ntendon + m.nu + m.nflex !== 0) throw new Error('a model with more than a body and a joint');
  let steps = 0;
  return {
    step() {
      ++steps;
      const before = d.time;
      mj.mj_step(m, d);
      if (before >= h && d.time - before >= h / 2) return;
      const warnings = d.warning;
      for (let i = 0; i < warnings.size(); ++i) {
        const count = warnings.get(i).number;
        if (count > 0) throw Object.assign(new Error(`MuJoCo warning ${i} at step ${steps}`), { warning: i, step: steps });
      }
    },
    frames() {
      mj.mj_kinematics(m, d);
      mj.mj_comPos(m, d);
      mj.mj_comVel(m, d);
      mj.mj_objectVelocity(m, d, mj.mjtObj.mjOBJ_BODY.value, 1, velocity, 0);
      const v = Array.from(velocity.GetView());
      return [{ rotation: Array.from(d.xmat.subarray(9, 18)), x: Array.from(d.xipos.subarray(3, 6)), v: v.slice(3), w: v.slice(0, 3) }];
    },
    free() {
      velocity.delete();
      d.delete();
      m.delete();
    },
  };
}

for (const integrator of ['Euler', 'RK4', 'implicit', 'implicitfast'])
  for (const [name, s] of Object.entries(scenarios)) {
    // The free bodies without an applied force (MuJoCo's WebAssembly bindings have no force callback) and the top.
    if (!((s.joint === 'free' && !s.bodies && !s.central) || name === 'heavy_top')) continue;
    const w = world(s, integrator);
    try {
      longRun(`${name}_${integrator}`, s, w, 100000);
    } catch (e) {
      if (e.warning === undefined) throw e;
      console.log(`${name}_${integrator}_stopped_at_step`, e.step);
      console.log(`${name}_${integrator}_stopped_by_warning`, e.warning);
    }
    w.free();
    await orderStudy(`${name}_${integrator}`, name, s, (h) => world(s, integrator, h));
  }
