#!/usr/bin/env python3
"""A chain of N revolute joints about x, y, z in turn, each link 0.2 m below the last, its
centre of mass 0.1 m below its joint and its inertia turned off its axes: a robot of any size
for the dynamics audit (docs/audit.md, "Robots of any size").

    python3 examples/robots/chain.py 512 > chain512.urdf
"""
import sys


def chain(n):
    out = [f'<robot name="chain{n}">', '  <link name="base"/>']
    parent = "base"
    for i in range(n):
        out.append(f'  <link name="l{i}"><inertial><origin xyz="0 0 -0.1" rpy="0.1 0.2 0.3"/><mass value="1"/>'
                   '<inertia ixx="0.02" ixy="0.001" ixz="0" iyy="0.03" iyz="0.002" izz="0.025"/></inertial></link>')
        axis = ("1 0 0", "0 1 0", "0 0 1")[i % 3]
        out.append(f'  <joint name="j{i}" type="continuous"><parent link="{parent}"/><child link="l{i}"/>'
                   f'<origin xyz="0 0 -0.2"/><axis xyz="{axis}"/></joint>')
        parent = f"l{i}"
    out.append("</robot>")
    return "\n".join(out) + "\n"


if __name__ == "__main__":
    if len(sys.argv) != 2 or not sys.argv[1].isdigit() or int(sys.argv[1]) < 1:
        sys.exit("usage: chain.py N   (N >= 1 moving joints)")
    sys.stdout.write(chain(int(sys.argv[1])))
