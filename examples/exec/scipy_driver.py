#!/usr/bin/env python3
"""SciPy's solve_ivp served to mechcheck's audit as an adaptive driver (docs/protocol.md).

    mechcheck-audit -o report --exec-driver -- python3 examples/exec/scipy_driver.py RK45

METHOD is one of solve_ivp's: RK45, RK23, DOP853, Radau, BDF, LSODA. The audit's tolerance
is given as rtol = atol = tolerance; the implicit methods (Radau, BDF, LSODA) get the
Jacobian from the audit (by automatic differentiation) instead of SciPy's finite
differences. The right-hand side and the Jacobian are the audit's, asked for at every
evaluation.
"""
import json
import sys

try:
    import scipy
except ImportError:
    # Debian's python3-scipy cannot be installed next to libboost1.81-dev (it depends on
    # python3-pythran, which depends on libboost-dev 1.74): ci/install-deps unpacks it here.
    sys.path.append("/opt/mechcheck/scipy/usr/lib/python3/dist-packages")
    try:
        import scipy
    except ImportError as e:
        sys.stderr.write(f"scipy_driver.py: no SciPy for {sys.executable}: {e}\n")
        sys.exit(1)
if sys.argv[1:] == ["--version"]:  # for the build: which SciPy this client runs
    print(scipy.__version__)
    sys.exit(0)
import numpy as np
from scipy.integrate import solve_ivp

METHODS = ("RK45", "RK23", "DOP853", "Radau", "BDF", "LSODA")
# solve_ivp's documentation (scipy.integrate.solve_ivp, SciPy 1.10): the order of each
# method's error estimate and of its propagated solution, in its own words.
WORDS = {
    "RK45": "'Explicit Runge-Kutta method of order 5(4)' (Dormand-Prince); 'The error is controlled assuming "
            "accuracy of the fourth-order method, but steps are taken using the fifth-order accurate formula'",
    "RK23": "'Explicit Runge-Kutta method of order 3(2)' (Bogacki-Shampine); 'The error "
            "is controlled assuming accuracy of the second-order method, but steps are taken using the third-order "
            "accurate formula'",
    "DOP853": "'Explicit Runge-Kutta method of order 8'",
    "Radau": "'Implicit Runge-Kutta method of the Radau IIA family of order 5'; 'The error is controlled with a "
             "third-order accurate embedded formula'",
    "BDF": "'Implicit multi-step variable-order (1 to 5) method based on a backward differentiation formula'",
    "LSODA": "'Adams/BDF method with automatic stiffness detection and switching'; 'a wrapper of the Fortran "
             "solver from ODEPACK'",
}


def send(message):
    sys.stdout.write(json.dumps(message) + "\n")
    sys.stdout.flush()


def receive():
    line = sys.stdin.readline()
    if not line:
        sys.exit(0)
    return json.loads(line)


def number(v):
    if isinstance(v, str):
        return float.fromhex(v) if "0x" in v.lower() else float(v)
    return float(v)


def ask(op, t, y, field):
    send({"op": op, "t": float(t).hex(), "y": [float(v).hex() for v in y]})
    reply = receive()
    if "error" in reply:
        raise ValueError(reply["error"])
    return np.array([number(v) for v in reply[field]])


def integrate(method, request):
    y0 = np.array([number(v) for v in request["y"]])
    t0, t1, tol = number(request["t0"]), number(request["t1"]), number(request["tolerance"])
    n = len(y0)
    options = {}
    if method in ("Radau", "BDF", "LSODA"):
        options["jac"] = lambda t, y: ask("jacobian", t, y, "dfdy").reshape(n, n)
    solution = solve_ivp(lambda t, y: ask("rhs", t, y, "dydt"), (t0, t1), y0, method=method,
                         rtol=tol, atol=tol, **options)
    if solution.status != 0:
        return {"error": "solve_ivp: status %d: %s" % (solution.status, solution.message)}
    # solution.t holds the start and every accepted step's end (no t_eval).
    return {"y": [float(v).hex() for v in solution.y[:, -1]], "accepted": len(solution.t) - 1}


def main():
    method = sys.argv[1] if len(sys.argv) > 1 else "RK45"
    if method not in METHODS:
        sys.stderr.write("scipy_driver.py: METHOD is one of %s, got %r\n" % (", ".join(METHODS), method))
        sys.exit(2)
    send({"protocol": "mechcheck", "version": 1, "kind": "driver", "name": "scipy::" + method,
          "origin": "SciPy %s scipy.integrate.solve_ivp(method='%s', rtol=tol, atol=tol): %s; rtol, atol: 'The "
                    "solver keeps the local error estimates less than atol + rtol * abs(y)'"
                    % (scipy.__version__, method, WORDS[method])})
    while True:
        request = receive()
        op = request.get("op")
        if op in ("start", "end"):
            send({"ok": True})
        elif op == "integrate":
            try:
                send(integrate(method, request))
            except ValueError as e:
                send({"error": str(e)})
        else:
            send({"error": "unknown op %r" % op})


if __name__ == "__main__":
    main()
