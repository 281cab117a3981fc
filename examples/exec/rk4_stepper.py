#!/usr/bin/env python3
"""Classical RK4 served to mechcheck's audit by the exec protocol (docs/protocol.md).

The standard library only. Run it under the audit:

    mechcheck-audit -o report --exec-stepper -p oscillator -- python3 examples/exec/rk4_stepper.py

The audit sends the state and the step; the stepper asks the audit for the right-hand side
f(t, y) at each stage and replies with the state after the step.
"""
import json
import sys


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


def rhs(t, y):
    # A stage that has diverged is sent as it is ("nan", "inf"): the audit answers with an
    # error and records the run as diverged at this step; the error goes back as the step's.
    send({"op": "rhs", "t": t.hex(), "y": [v.hex() for v in y]})
    reply = receive()
    if "error" in reply:
        raise ValueError(reply["error"])
    return [number(v) for v in reply["dydt"]]


def step(t, h, y):
    def plus(a, c, k):
        return [ai + c * ki for ai, ki in zip(a, k)]

    k1 = rhs(t, y)
    k2 = rhs(t + h / 2, plus(y, h / 2, k1))
    k3 = rhs(t + h / 2, plus(y, h / 2, k2))
    k4 = rhs(t + h, plus(y, h, k3))
    return [yi + h / 6 * (a + 2 * b + 2 * c + d) for yi, a, b, c, d in zip(y, k1, k2, k3, k4)]


def main():
    send({"protocol": "mechcheck", "version": 1, "kind": "stepper", "name": "python_rk4",
          "origin": "examples/exec/rk4_stepper.py: the classical fourth-order Runge-Kutta method",
          "claims": {"order": 4}})
    while True:
        request = receive()
        op = request.get("op")
        if op in ("start", "end"):
            send({"ok": True})
        elif op == "step":
            try:
                y = step(number(request["t"]), number(request["h"]), [number(v) for v in request["y"]])
                send({"y": [v.hex() for v in y]})
            except ValueError as e:
                send({"error": str(e)})
        else:
            send({"error": "unknown op %r" % op})


if __name__ == "__main__":
    main()
