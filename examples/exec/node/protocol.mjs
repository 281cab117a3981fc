// The child's side of mechcheck's exec protocol (docs/protocol.md, version 1) for Node
// clients, engines and dynamics libraries: one JSON object a line on standard input and output. The handshake asks for
// decimal numbers (17 significant digits, which Number() reads exactly); replies carry JSON
// numbers (JSON.stringify writes the shortest decimal that reads back exactly).
//
// serveEngine(hello, start, moments, withoutMass) answers the audit until it closes our input.
// start(integrator, scenario) builds a run (or a promise of one), or throws Refused for a scenario
// the engine cannot express; a run has step(h) (throws on the engine's failure), reading() and optionally
// modelDiffers and free(). moments(shape) (optional) gives the principal moments the engine
// computes for a shape ({name, mass, size}), or throws Refused for a shape it does not offer;
// withoutMass(shape) (optional) what the engine gives a body built from the shape ({name,
// size}) with no mass properties: {mass, moments, said}, said how the engine got them.
import readline from 'node:readline';

/** The points of the shape convex_hull of size (a, b, c): (+-a, 0, c) and (0, +-b, -c). */
export function hullPoints({ size: [a, b, c] }) {
  return [[a, 0, c], [-a, 0, c], [0, b, -c], [0, -b, -c]];
}

/** A scenario the engine cannot express: the audit lists it as refused, with these words. */
export class Refused extends Error {}

function send(message) {
  process.stdout.write(JSON.stringify(message) + '\n');
}

/** A frame of the protocol: rotation (row-major), centre of mass, its velocity, omega. */
export function frame(rotation, position, velocity, omega) {
  const f = [...rotation, ...position, ...velocity, ...omega];
  if (f.length !== 18) throw new Error(`a frame of ${f.length} numbers`);
  f.forEach((x, i) => {
    if (!Number.isFinite(x)) throw new Error(`the state is not finite (frame number ${i})`);
  });
  return f;
}

/** The scenario of a "start" with its numbers read (the parent writes them as decimal
 * strings of 17 significant digits, which Number() reads exactly), recursively; its names
 * (a contact body's shape among them) and flags (contact.ground) as they are. */
export function scenarioOf(s) {
  const out = {};
  for (const [k, v] of Object.entries(s)) {
    if (Array.isArray(v)) out[k] = v.map((x) => (typeof x === 'object' ? scenarioOf(x) : Number(x)));
    else if (v !== null && typeof v === 'object') out[k] = scenarioOf(v);
    else if (typeof v === 'boolean' || ['name', 'structure', 'joint', 'shape'].includes(k)) out[k] = v;
    else out[k] = Number(v);
  }
  return out;
}

/** The precision an engine keeps a body's state in, measured: a free body started at
 * x = 1 + 2^-30 (a double, not a float) and read back at once. 'double' when x comes back,
 * 'single' when float's rounding of it (1) does; the handshake's "precision", from which the
 * audit sets its rounding floors. */
export async function precisionOf(start, integrator) {
  const x = 1 + 2 ** -30;
  const zero = [0, 0, 0];
  let run;
  try {
    run = await start(integrator, {
      name: 'precision', structure: 'one_body', joint: 'free', mass: 1, inertia: [1, 2, 3], com: zero,
      rotation0: [1, 0, 0, 0, 1, 0, 0, 0, 1], position0: [x, 0, 0], velocity0: zero, omega0: zero, gravity: 0, central: 0,
    });
  } catch (e) {
    // An engine without free bodies: nothing declared, the audit keeps double's floors.
    if (e instanceof Refused) return { precision: undefined, said: `precision not measured (${e.message})` };
    throw e;
  }
  try {
    const y = run.reading().frame[9];
    const said = `a free body started at x = 1 + 2^-30 reads back x = ${y === 1 ? '1' : y === x ? '1 + 2^-30' : y}`;
    if (y === x) return { precision: 'double', said: `${said}: double precision` };
    if (y === Math.fround(x)) return { precision: 'single', said: `${said}: single precision (float)` };
    throw new Error(`${said}: neither double nor single precision`);
  } finally {
    run.free?.();
  }
}

export async function serveEngine(hello, start, moments, withoutMass) {
  // The precision measured before the handshake, said in the origin.
  const { precision, said } = await precisionOf(start, hello.integrators[0].name);
  send({ protocol: 'mechcheck', version: 1, kind: 'engine', numbers: 'decimal', shapes: !!moments,
    ...(withoutMass ? { shapes_without_mass: true } : {}), precision, ...hello,
    origin: `${hello.origin}; ${said}` });
  const runs = new Map();
  const lines = readline.createInterface({ input: process.stdin, crlfDelay: Infinity });
  for await (const line of lines) {
    const r = JSON.parse(line);
    if (r.op === 'start') {
      try {
        const run = await start(r.integrator, r.scenario);
        runs.set(r.run, run);
        const reply = { ok: true, reading: run.reading() };
        if (run.modelDiffers) reply.model_differs = run.modelDiffers;
        send(reply);
      } catch (e) {
        send(e instanceof Refused ? { refused: e.message } : { error: String(e?.message ?? e) });
      }
    } else if (r.op === 'step') {
      const run = runs.get(r.run);
      const h = Number(r.h);
      const each = r.read === 'each';
      const readings = [];
      let seconds = 0;
      let failed = null;
      for (let k = 1; k <= r.n && !failed; ++k) {
        try {
          const t0 = process.hrtime.bigint();
          run.step(h);
          seconds += Number(process.hrtime.bigint() - t0) * 1e-9;
          if (each || k === r.n) readings.push(run.reading());
        } catch (e) {
          failed = { error: String(e?.message ?? e), at: k };
          if (each) failed.readings = readings;
        }
      }
      if (failed) {
        send(failed);
      } else {
        const reply = { readings };
        if (r.timed) reply.seconds = seconds;
        send(reply);
      }
    } else if (r.op === 'shape' && moments && (r.shape.mass !== undefined || withoutMass)) {
      try {
        const size = r.shape.size.map(Number);
        if (r.shape.mass === undefined) send(withoutMass({ name: r.shape.name, size }));
        else send({ moments: moments({ name: r.shape.name, mass: Number(r.shape.mass), size }) });
      } catch (e) {
        send(e instanceof Refused ? { refused: e.message } : { error: String(e?.message ?? e) });
      }
    } else if (r.op === 'end') {
      runs.get(r.run)?.free?.();
      runs.delete(r.run);
      send({ ok: true });
    } else {
      send({ error: `unknown op ${JSON.stringify(r.op)}` });
    }
  }
}

/** The dynamics side (kind "dynamics"): serveDynamics(hello, load) answers the audit until it
 * closes our input. load(urdf, gravity) builds a model of the robot, or throws Refused for a
 * robot the library cannot express; a model has massMatrix(q) (row by row), bias(q, qdot),
 * inverse(q, qdot, qddot), forward(q, qdot, tau), optionally `held` (the robot it computes
 * with, as URDF, where its builder changed the one given) and free(); and, where hello's
 * `quantities` lists them, the kinematics of docs/protocol.md: framePoses(q),
 * frameJacobians(q), frameBiasAccelerations(q, qdot), linkComJacobians(q), centreOfMass(q),
 * comJacobian(q), centroidalMomentumMatrix(q), each in the protocol's layout. */
export async function serveDynamics(hello, load) {
  send({ protocol: 'mechcheck', version: 1, kind: 'dynamics', numbers: 'decimal',
    quantities: ['mass_matrix', 'bias', 'inverse', 'forward'], ...hello });
  const models = new Map();
  const numbers = (v) => v.map(Number);
  // A value that is not finite goes as the protocol writes it ("nan", "inf"): the library's.
  const out = (v) => v.map((x) => (Number.isFinite(x) ? x : Number.isNaN(x) ? 'nan' : x > 0 ? 'inf' : '-inf'));
  const lines = readline.createInterface({ input: process.stdin, crlfDelay: Infinity });
  for await (const line of lines) {
    const r = JSON.parse(line);
    try {
      if (r.op === 'load') {
        try {
          const model = load(r.urdf, numbers(r.gravity));
          models.set(r.model, model);
          send(model.held ? { ok: true, held: model.held } : { ok: true });
        } catch (e) {
          send(e instanceof Refused ? { refused: e.message } : { error: String(e?.message ?? e) });
        }
      } else if (r.op === 'unload') {
        models.get(r.model)?.free?.();
        models.delete(r.model);
        send({ ok: true });
      } else {
        const m = models.get(r.model);
        if (!m) throw new Error(`no model ${r.model}`);
        if (r.op === 'mass_matrix') send({ m: out(m.massMatrix(numbers(r.q))) });
        else if (r.op === 'bias') send({ h: out(m.bias(numbers(r.q), numbers(r.qdot))) });
        else if (r.op === 'inverse') send({ tau: out(m.inverse(numbers(r.q), numbers(r.qdot), numbers(r.qddot))) });
        else if (r.op === 'forward') send({ qddot: out(m.forward(numbers(r.q), numbers(r.qdot), numbers(r.tau))) });
        else if (r.op === 'frame_poses') send({ poses: out(m.framePoses(numbers(r.q))) });
        else if (r.op === 'frame_jacobians') send({ jacobians: out(m.frameJacobians(numbers(r.q))) });
        else if (r.op === 'frame_bias_accelerations')
          send({ accelerations: out(m.frameBiasAccelerations(numbers(r.q), numbers(r.qdot))) });
        else if (r.op === 'link_com_jacobians') send({ com_jacobians: out(m.linkComJacobians(numbers(r.q))) });
        else if (r.op === 'centre_of_mass') send({ com: out(m.centreOfMass(numbers(r.q))) });
        else if (r.op === 'com_jacobian') send({ jc: out(m.comJacobian(numbers(r.q))) });
        else if (r.op === 'centroidal_momentum_matrix') send({ ag: out(m.centroidalMomentumMatrix(numbers(r.q))) });
        else send({ error: `unknown op ${JSON.stringify(r.op)}` });
      }
    } catch (e) {
      send({ error: String(e?.message ?? e) });
    }
  }
}
