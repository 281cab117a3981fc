#!/usr/bin/env python3
"""A robot's equations of motion by SymPy's mechanics module, served to mechcheck's audit by
the exec protocol's dynamics kind (docs/protocol.md).

Run it under the audit (Debian's python3 with python3-sympy):

    mechcheck-audit -o report --exec-dynamics --robots 20 -- /usr/bin/python3 examples/exec/sympy_dynamics.py [--max-joints N]

For each robot the audit sends (its URDF text and its gravity), the kinematic tree is built
of sympy.physics.mechanics objects -- a ReferenceFrame and a Point per link and joint frame,
each joint's origin by orient_body_fixed (URDF's roll-pitch-yaw: R = Rz(yaw) Ry(pitch)
Rx(roll)), a revolute joint by orient_axis about its axis, a prismatic one by a point moved
along it, each link a RigidBody at its centre of mass with its inertia dyadic and its
weight at its centre of mass -- and KanesMethod, with the generalized speeds u = qdot, forms
the equations of motion M(q) udot = F(q, u). The bias forces are h = -F; inverse dynamics
tau = M qddot + h; forward dynamics qddot = M^-1 (tau - h).

The numbers are carried at 40 digits: a double of the file or of the state is exactly a
40-digit number, the constant rotations and the derivation are SymPy's on such numbers, and
the expressions (q and u symbolic) are compiled once by lambdify (mpmath, common
subexpressions shared) and evaluated at 40 digits, each result rounded once to double. What
is measured is the derivation, not floating point: a correct one lands within a rounding of
the exact value. A tree of more than --max-joints moving joints (default 3) is refused: the
symbolic derivation grows fast with the tree (under a second for two joints on skew axes,
15 s for three, minutes beyond).
"""
import json
import sys
import xml.etree.ElementTree as ET

import mpmath
import sympy as sp
from mpmath.libmp import libmpf
from sympy.physics import mechanics as me

MAX_JOINTS = int(sys.argv[sys.argv.index("--max-joints") + 1]) if "--max-joints" in sys.argv else 3
DIGITS = 40


def send(message):
    sys.stdout.write(json.dumps(message) + "\n")
    sys.stdout.flush()


def receive():
    line = sys.stdin.readline()
    if not line:  # the audit closed our input: done
        sys.exit(0)
    return json.loads(line)


def number(v):
    """A number of the protocol: C's hexadecimal form, a decimal string or a JSON number."""
    if isinstance(v, str):
        return float.fromhex(v) if "0x" in v.lower() else float(v)
    return float(v)


def exact(x):
    """A double, exactly, as a 40-digit number."""
    return sp.Float(float(x), DIGITS)


def triple(text, default="0 0 0"):
    values = (text if text is not None else default).split()
    if len(values) != 3:
        raise ValueError(f'"{text}" is not three numbers')
    return [exact(float(v)) for v in values]


class Refused(Exception):
    pass


class Model:
    """A URDF robot's M(q) and F(q, qdot) from KanesMethod, in the file's order of moving
    joints."""

    def __init__(self, urdf, gravity):
        root = ET.fromstring(urdf)
        if root.tag != "robot":
            raise ValueError("not a URDF document (its root is <%s>)" % root.tag)
        links = {l.get("name"): l for l in root.findall("link")}
        joints = root.findall("joint")
        moving = [j for j in joints if j.get("type") != "fixed"]
        for j in joints:
            if j.get("type") not in ("revolute", "continuous", "prismatic", "fixed"):
                raise Refused("joint %s: type %s" % (j.get("name"), j.get("type")))
        if len(moving) > MAX_JOINTS:
            raise Refused("%d moving joints: KanesMethod is run on at most %d here (--max-joints; the "
                          "symbolic derivation grows fast with the tree)" % (len(moving), MAX_JOINTS))
        children = {j.find("child").get("link") for j in joints}
        roots = [name for name in links if name not in children]
        if len(roots) != 1:
            raise ValueError("%d root links" % len(roots))

        t = me.dynamicsymbols._t
        self.q = list(me.dynamicsymbols("q0:%d" % len(moving))) if moving else []
        coordinate = {j.get("name"): k for k, j in enumerate(moving)}

        world = me.ReferenceFrame("N")
        origin = me.Point("O")
        origin.set_vel(world, 0)
        frame = {roots[0]: world}
        point = {roots[0]: origin}
        pending = list(joints)
        while pending:  # parents before children, whatever the file's order
            ready = [j for j in pending if j.find("parent").get("link") in frame]
            if not ready:
                raise ValueError("joints %s do not reach the root" % [j.get("name") for j in pending])
            for j in ready:
                pending.remove(j)
                name = j.get("name")
                parent = j.find("parent").get("link")
                child = j.find("child").get("link")
                o = j.find("origin")
                xyz = triple(o.get("xyz") if o is not None else None)
                rpy = triple(o.get("rpy") if o is not None else None)
                a = j.find("axis")
                axis = triple(a.get("xyz") if a is not None else None, "1 0 0")
                length = sp.sqrt(sum(c * c for c in axis))
                axis = [c / length for c in axis]
                p_frame, p_point = frame[parent], point[parent]
                # The joint frame: the parent's turned by the origin's rpy and moved by its xyz.
                jf = me.ReferenceFrame("J_" + name)
                jf.orient_body_fixed(p_frame, (rpy[2], rpy[1], rpy[0]), "ZYX")
                jp = p_point.locatenew("P_" + name, xyz[0] * p_frame.x + xyz[1] * p_frame.y + xyz[2] * p_frame.z)
                kind = j.get("type")
                along = axis[0] * jf.x + axis[1] * jf.y + axis[2] * jf.z
                if kind in ("revolute", "continuous"):
                    cf = me.ReferenceFrame("L_" + child)
                    cf.orient_axis(jf, along, self.q[coordinate[name]])
                    cp = jp
                elif kind == "prismatic":
                    cf = jf
                    cp = jp.locatenew("Q_" + name, self.q[coordinate[name]] * along)
                else:
                    cf, cp = jf, jp
                frame[child], point[child] = cf, cp

        g = [exact(x) for x in gravity]
        down = g[0] * world.x + g[1] * world.y + g[2] * world.z
        bodies, loads, points_moved = [], [], []
        for name, l in links.items():
            inertial = l.find("inertial")
            if inertial is None:
                continue
            mass = exact(float(inertial.find("mass").get("value")))
            o = inertial.find("origin")
            xyz = triple(o.get("xyz") if o is not None else None)
            rpy = triple(o.get("rpy") if o is not None else None)
            i = inertial.find("inertia")
            ixx, ixy, ixz, iyy, iyz, izz = (exact(float(i.get(k))) for k in ("ixx", "ixy", "ixz", "iyy", "iyz", "izz"))
            lf, lp = frame[name], point[name]
            cf = me.ReferenceFrame("C_" + name)
            cf.orient_body_fixed(lf, (rpy[2], rpy[1], rpy[0]), "ZYX")
            cp = lp.locatenew("c_" + name, xyz[0] * lf.x + xyz[1] * lf.y + xyz[2] * lf.z)
            points_moved.append(cp)
            bodies.append(me.RigidBody("B_" + name, cp, cf, mass, (me.inertia(cf, ixx, iyy, izz, ixy, iyz, ixz), cp)))
            loads.append((cp, mass * down))

        self.n = len(moving)
        if self.n == 0:
            self.x, self.v = [], []
            self.mass_function = self.forcing_function = None
            return
        # Kane's method with generalized speeds u = qdot: M(q) udot = F(q, u).
        self.u = list(me.dynamicsymbols("u0:%d" % self.n))
        kinematics = [sp.diff(qi, t) - ui for qi, ui in zip(self.q, self.u)]
        for p in points_moved:
            p.set_vel(world, p.pos_from(origin).dt(world))
        method = me.KanesMethod(world, q_ind=self.q, u_ind=self.u, kd_eqs=kinematics)
        method.kanes_equations(bodies, loads)
        # Numbers in for q(t) and u(t): plain symbols; the expressions compiled once, their
        # common subexpressions shared, to functions of mpmath numbers at DIGITS digits.
        self.x = sp.symbols("x0:%d" % self.n)
        self.v = sp.symbols("v0:%d" % self.n)
        plain = dict(zip(self.q, self.x)) | dict(zip(self.u, self.v))
        mass = me.msubs(method.mass_matrix, plain)
        forcing = me.msubs(method.forcing, plain)
        self.mass_function = sp.lambdify([self.x], mass, modules="mpmath", cse=True)
        self.forcing_function = sp.lambdify([self.x, self.v], forcing, modules="mpmath", cse=True)

    def mass_matrix(self, q):
        with mpmath.workdps(DIGITS):
            return mpmath.matrix(self.mass_function([mpmath.mpf(v) for v in q]))

    def bias(self, q, qdot):
        with mpmath.workdps(DIGITS):
            return -mpmath.matrix(self.forcing_function([mpmath.mpf(v) for v in q], [mpmath.mpf(v) for v in qdot]))


def doubles(matrix):
    """An mpmath matrix's entries, row by row, each rounded once to the nearest double."""
    return [libmpf.to_float(matrix[i, j]._mpf_, rnd=libmpf.round_nearest).hex()
            for i in range(matrix.rows) for j in range(matrix.cols)]


def main():
    send({"protocol": "mechcheck", "version": 1, "kind": "dynamics", "name": "sympy_lagrange",
          "origin": "SymPy %s, sympy.physics.mechanics.KanesMethod on the URDF's tree of RigidBody "
                    "(examples/exec/sympy_dynamics.py): derived and evaluated at %d digits, rounded once to "
                    "double; at most %d moving joints" % (sp.__version__, DIGITS, MAX_JOINTS),
          "quantities": ["mass_matrix", "bias", "inverse", "forward"]})
    models = {}
    while True:
        request = receive()
        op = request.get("op")
        try:
            if op == "load":
                try:
                    models[request["model"]] = Model(request["urdf"], [number(x) for x in request["gravity"]])
                    send({"ok": True})
                except Refused as why:
                    send({"refused": str(why)})
                continue
            if op == "unload":
                models.pop(request["model"], None)
                send({"ok": True})
                continue
            model = models[request["model"]]
            q = [number(x) for x in request["q"]]
            if op == "mass_matrix":
                send({"m": doubles(model.mass_matrix(q))})
                continue
            qdot = [number(x) for x in request["qdot"]]
            h = model.bias(q, qdot)
            if op == "bias":
                send({"h": doubles(h)})
            elif op == "inverse":
                with mpmath.workdps(DIGITS):
                    qddot = mpmath.matrix([number(x) for x in request["qddot"]])
                    send({"tau": doubles(model.mass_matrix(q) * qddot + h)})
            elif op == "forward":
                with mpmath.workdps(DIGITS):
                    tau = mpmath.matrix([number(x) for x in request["tau"]])
                    send({"qddot": doubles(mpmath.lu_solve(model.mass_matrix(q), tau - h))})
            else:
                send({"error": "unknown request %s" % op})
        except Exception as e:  # a robot SymPy could not build or evaluate: the audit's library_failure
            send({"error": "%s: %s" % (type(e).__name__, e)})


if __name__ == "__main__":
    main()
