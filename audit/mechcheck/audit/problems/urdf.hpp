#pragma once
/// URDF in and out (the ROS robot description format: https://wiki.ros.org/urdf/XML): a
/// user's robot file read into a robots::robot, and every robot -- a generated one, a shrunk
/// counterexample -- written as a file the libraries' URDF loaders read. XML by tinyxml2.
///
/// Read: <robot>, its <link>s (<inertial>: <origin xyz rpy>, <mass value>, <inertia ixx
/// ixy ixz iyy iyz izz>; visual and collision are not dynamics and are skipped) and <joint>s
/// (type revolute, continuous, prismatic or fixed; <parent link>, <child link>, <origin>,
/// <axis xyz>, default (1, 0, 0) as URDF says). One joint of type floating, from a link that is
/// nothing else (ROS's "world") to the root, makes the base float (robots::robot::floating;
/// the link and the joint are dropped, and written back so). An element or attribute URDF
/// does not have where the reader looks (a misspelt <inertail>, an ixy= spelt iyx=), or a
/// second copy of one read once, is refused by name; <dynamics damping friction> is read
/// (robots::joint: damping is part of h, friction is carried and not modelled, said in the
/// readings), with armature= beside them, mechcheck's attribute for a rotor's reflected
/// inertia (URDF has none; urdfdom passes over it); <limit>, <calibration>, <mimic> and
/// <safety_controller> are URDF's and are not read.
/// Gravity is not part of URDF: the file mechcheck writes carries it in a comment
/// (<!-- mechcheck gravity="0 0 -9.81" -->), read back when present; otherwise (0, 0,
/// -9.81). A file that is not URDF, a joint type the dynamics do not model (planar, a
/// floating joint inside the tree), a number that is not one, and everything
/// robots::validate refuses is a robots::robot_error naming the element and the value.
///
/// Written: every number with 17 significant digits, so that reading the file back gives
/// the same doubles.

#include <string>

#include "mechcheck/robots/robot.hpp"

namespace mechcheck::audit {

/// The robot of a URDF document (its text); `origin` names it in messages (a path).
robots::robot parse_urdf(const std::string& text, const std::string& origin = "URDF");

/// The robot of a URDF file.
robots::robot read_urdf(const std::string& path);

/// The robot as a URDF document.
std::string to_urdf(const robots::robot& r);

}  // namespace mechcheck::audit
