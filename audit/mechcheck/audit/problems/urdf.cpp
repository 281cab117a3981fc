// URDF read and written by tinyxml2 (problems/urdf.hpp).
#include "mechcheck/audit/problems/urdf.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string_view>

#include <tinyxml2.h>

namespace mechcheck::audit {

namespace {
using robots::robot_error;

/// A number written as text, whole (surrounding blanks allowed).
double number(std::string_view s, const std::string& what) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t' || s.front() == '\n')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\n')) s.remove_suffix(1);
  if (!s.empty() && s.front() == '+') s.remove_prefix(1);
  double x = 0;
  const auto [end, error] = std::from_chars(s.data(), s.data() + s.size(), x);
  if (s.empty() || error != std::errc() || end != s.data() + s.size())
    throw robot_error(what + ": \"" + std::string(s) + "\" is not a number");
  if (!std::isfinite(x)) throw robot_error(what + ": \"" + std::string(s) + "\" is not finite");
  return x;
}

/// Three numbers separated by blanks ("0 0.5 -1").
Eigen::Vector3d triple(const char* text, const std::string& what) {
  std::string_view s(text);
  Eigen::Vector3d v;
  int k = 0;
  std::size_t i = 0;
  while (i < s.size()) {
    while (i < s.size() && (s[i] == ' ' || s[i] == '\t' || s[i] == '\n')) ++i;
    if (i == s.size()) break;
    std::size_t j = i;
    while (j < s.size() && s[j] != ' ' && s[j] != '\t' && s[j] != '\n') ++j;
    if (k == 3) throw robot_error(what + ": \"" + std::string(s) + "\" has more than three numbers");
    v(k++) = number(s.substr(i, j - i), what);
    i = j;
  }
  if (k != 3) throw robot_error(what + ": \"" + std::string(s) + "\" has " + std::to_string(k) + " numbers, 3 expected");
  return v;
}

/// URDF's own vocabulary (https://wiki.ros.org/urdf/XML): an element's children and
/// attributes outside it are refused by name, so that a misspelt <inertail> or ixy= is not
/// read as an absent one. Children of elements that are not dynamics (visual, collision,
/// limit, ...) are not looked into; a robot's namespace declarations (xmlns:...) are allowed.
void known(const tinyxml2::XMLElement* e, std::initializer_list<std::string_view> children,
           std::initializer_list<std::string_view> attributes, const std::string& what) {
  const auto list = [](std::initializer_list<std::string_view> names) {
    std::string out;
    for (const std::string_view n : names) out += (out.empty() ? "" : ", ") + std::string(n);
    return out.empty() ? std::string("none") : out;
  };
  const auto in = [](std::initializer_list<std::string_view> names, std::string_view n) {
    return std::find(names.begin(), names.end(), n) != names.end();
  };
  for (const tinyxml2::XMLElement* c = e->FirstChildElement(); c; c = c->NextSiblingElement()) {
    if (!in(children, c->Name()))
      throw robot_error(what + ": <" + c->Name() + "> is not an element of URDF's <" + e->Name() + "> (it has " +
                        list(children) + ")");
    // The elements read once must be there once: a second would be silently ignored.
    const std::string_view n = c->Name();
    const bool repeatable = n == "link" || n == "joint" || n == "material" || n == "transmission" || n == "gazebo" ||
                            n == "visual" || n == "collision";
    if (!repeatable && c->NextSiblingElement(c->Name()))
      throw robot_error(what + ": <" + e->Name() + "> has more than one <" + c->Name() + ">");
  }
  for (const tinyxml2::XMLAttribute* a = e->FirstAttribute(); a; a = a->Next()) {
    const std::string_view n = a->Name();
    if (in(attributes, n) || (std::string_view(e->Name()) == "robot" && n.substr(0, 5) == "xmlns")) continue;
    throw robot_error(what + ": " + std::string(n) + "= is not an attribute of URDF's <" + e->Name() + "> (it has " +
                      list(attributes) + ")");
  }
}

robots::pose pose_of(const tinyxml2::XMLElement* parent, const std::string& what) {
  robots::pose p;
  const tinyxml2::XMLElement* o = parent->FirstChildElement("origin");
  if (!o) return p;
  known(o, {}, {"xyz", "rpy"}, what + " origin");
  if (const char* xyz = o->Attribute("xyz")) p.xyz = triple(xyz, what + " origin xyz");
  if (const char* rpy = o->Attribute("rpy")) p.rpy = triple(rpy, what + " origin rpy");
  return p;
}

double attribute(const tinyxml2::XMLElement* e, const char* name, const std::string& what) {
  const char* v = e->Attribute(name);
  if (!v) throw robot_error(what + " has no attribute " + name);
  return number(v, what + " " + name);
}

std::string text(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.17g", x);
  return buf;
}
std::string text(const Eigen::Vector3d& v) { return text(v(0)) + " " + text(v(1)) + " " + text(v(2)); }
}  // namespace

robots::robot parse_urdf(const std::string& document, const std::string& origin) {
  tinyxml2::XMLDocument doc;
  if (doc.Parse(document.c_str(), document.size()) != tinyxml2::XML_SUCCESS)
    throw robot_error(origin + ": not XML: " + std::string(doc.ErrorStr()));
  const tinyxml2::XMLElement* top = doc.FirstChildElement("robot");
  if (!top) throw robot_error(origin + ": not URDF: no <robot> element");
  robots::robot r;
  if (const char* name = top->Attribute("name")) r.name = name;
  const std::string who = origin + ": robot " + r.name;
  known(top, {"link", "joint", "material", "transmission", "gazebo"}, {"name", "version"}, who);
  for (const tinyxml2::XMLNode* n = doc.FirstChild(); n; n = n->NextSibling())
    if (const tinyxml2::XMLComment* c = n->ToComment()) {
      const std::string_view s(c->Value());
      const std::string_view key = " mechcheck gravity=\"";
      if (s.substr(0, key.size()) == key) {
        const std::size_t end = s.find('"', key.size());
        if (end == std::string_view::npos) throw robot_error(who + ": a gravity comment without its closing quote");
        r.gravity = triple(std::string(s.substr(key.size(), end - key.size())).c_str(), who + ": gravity");
      }
    }
  for (const tinyxml2::XMLElement* e = top->FirstChildElement("link"); e; e = e->NextSiblingElement("link")) {
    robots::link l;
    const char* name = e->Attribute("name");
    if (!name || !*name) throw robot_error(who + ": a <link> without a name");
    l.name = name;
    const std::string what = who + ": link " + l.name;
    known(e, {"inertial", "visual", "collision"}, {"name"}, what);
    if (const tinyxml2::XMLElement* in = e->FirstChildElement("inertial")) {
      known(in, {"origin", "mass", "inertia"}, {}, what + " inertial");
      robots::inertial b;
      b.origin = pose_of(in, what + " inertial");
      const tinyxml2::XMLElement* mass = in->FirstChildElement("mass");
      if (!mass) throw robot_error(what + ": <inertial> without <mass>");
      known(mass, {}, {"value"}, what + " mass");
      b.mass = attribute(mass, "value", what + " mass");
      const tinyxml2::XMLElement* i = in->FirstChildElement("inertia");
      if (!i) throw robot_error(what + ": <inertial> without <inertia>");
      known(i, {}, {"ixx", "ixy", "ixz", "iyy", "iyz", "izz"}, what + " inertia");
      const double ixx = attribute(i, "ixx", what + " inertia"), ixy = attribute(i, "ixy", what + " inertia"),
                   ixz = attribute(i, "ixz", what + " inertia"), iyy = attribute(i, "iyy", what + " inertia"),
                   iyz = attribute(i, "iyz", what + " inertia"), izz = attribute(i, "izz", what + " inertia");
      b.inertia << ixx, ixy, ixz, ixy, iyy, iyz, ixz, iyz, izz;
      l.body = b;
    }
    r.links.push_back(std::move(l));
  }
  std::vector<std::size_t> floating_joints;  // indices into r.joints
  for (const tinyxml2::XMLElement* e = top->FirstChildElement("joint"); e; e = e->NextSiblingElement("joint")) {
    robots::joint j;
    const char* name = e->Attribute("name");
    if (!name || !*name) throw robot_error(who + ": a <joint> without a name");
    j.name = name;
    const std::string what = who + ": joint " + j.name;
    known(e, {"origin", "parent", "child", "axis", "calibration", "dynamics", "limit", "mimic", "safety_controller"},
          {"name", "type"}, what);
    const char* type = e->Attribute("type");
    if (!type) throw robot_error(what + " has no type");
    const std::string t(type);
    if (t == "revolute") j.type = robots::joint_type::revolute;
    else if (t == "continuous") j.type = robots::joint_type::continuous;
    else if (t == "prismatic") j.type = robots::joint_type::prismatic;
    else if (t == "fixed") j.type = robots::joint_type::fixed;
    else if (t == "floating") floating_joints.push_back(r.joints.size());
    else if (t == "planar")
      throw robot_error(what + ": type " + t + " is not modelled (revolute, continuous, prismatic, fixed, floating)");
    else
      throw robot_error(what + ": unknown type \"" + t + "\"");
    for (const auto& [tag, target] : {std::pair{"parent", &j.parent}, std::pair{"child", &j.child}}) {
      const tinyxml2::XMLElement* x = e->FirstChildElement(tag);
      const char* link = x ? x->Attribute("link") : nullptr;
      if (!link) throw robot_error(what + ": no <" + tag + " link=...>");
      known(x, {}, {"link"}, what + " " + tag);
      *target = link;
    }
    j.origin = pose_of(e, what);
    // URDF's default axis where <axis> (or its xyz) is absent; an axis not of unit length
    // (written to a few digits) normalized, as MuJoCo's compiler does (urdfdom keeps it as
    // written). Both said in the robot's readings, which the report prints.
    const tinyxml2::XMLElement* a = e->FirstChildElement("axis");
    if (a) known(a, {}, {"xyz"}, what + " axis");
    const char* xyz = a ? a->Attribute("xyz") : nullptr;
    if (xyz) j.axis = triple(xyz, what + " axis");
    if (xyz && j.type != robots::joint_type::fixed) {
      const double n = j.axis.norm();
      if (!(n > 0)) throw robot_error(what + ": axis \"" + std::string(xyz) + "\" has no direction");
      // Unit to its rounding (a unit vector's computed length is within a few eps of 1):
      // kept as written, so that a file's doubles come back as they were written.
      if (std::abs(n - 1) > 8 * 0x1p-52) {
        j.axis /= n;
        r.readings.push_back(what + ": axis \"" + std::string(xyz) + "\" (length 1 " +
                               (n > 1 ? "+ " : "- ") + to_text(std::abs(n - 1)) + ") normalized to " +
                               robots::detail::vector_text(j.axis));
      }
    } else if (j.type != robots::joint_type::fixed && t != "floating") {
      r.readings.push_back(what + ": no axis given: URDF's default (1, 0, 0)");
    }
    // URDF's <dynamics damping friction>, and armature= beside them: mechcheck's attribute for
    // a rotor's reflected inertia, which URDF has no word for (urdfdom reads damping and
    // friction and passes over any other attribute of <dynamics>).
    if (const tinyxml2::XMLElement* d = e->FirstChildElement("dynamics")) {
      known(d, {}, {"damping", "friction", "armature"}, what + " dynamics");
      for (const auto& [name, target] : {std::pair{"damping", &j.damping}, std::pair{"friction", &j.friction},
                                         std::pair{"armature", &j.armature}})
        if (d->Attribute(name)) *target = attribute(d, name, what + " dynamics");
      if (j.friction > 0 && j.type != robots::joint_type::fixed)
        r.readings.push_back(what + ": friction " + to_text(j.friction) +
                             " (<dynamics friction>) is not part of the equations of motion held here: each library "
                             "makes Coulomb friction a constraint of its own, or nothing");
    }
    r.joints.push_back(std::move(j));
  }
  // A floating base: one floating joint from a link that is nothing else (no <inertial>, no
  // parent, no other joint; ROS's "world"), which is dropped with it. Its origin is the base's
  // pose at the start, which the audit's states give instead.
  if (floating_joints.size() > 1)
    throw robot_error(who + ": joints " + r.joints[floating_joints[0]].name + " and " + r.joints[floating_joints[1]].name +
                      " are both floating: a robot has one floating base");
  if (floating_joints.size() == 1) {
    const robots::joint f = r.joints[floating_joints[0]];
    const std::string what = who + ": joint " + f.name + " (floating)";
    const auto world = std::find_if(r.links.begin(), r.links.end(), [&](const robots::link& l) { return l.name == f.parent; });
    if (world == r.links.end()) throw robot_error(what + ": its parent \"" + f.parent + "\" is not a link");
    for (const robots::joint& j : r.joints)
      if (&j != &r.joints[floating_joints[0]] && (j.child == f.parent || j.parent == f.parent))
        throw robot_error(what + ": its parent link " + f.parent + " is joined to others (joint " + j.name +
                          "): a floating joint joins the world, a link of nothing else, to the robot's root");
    if (world->body)
      throw robot_error(what + ": its parent link " + f.parent + " has an <inertial>: a floating joint's parent is the world");
    if (f.origin.xyz != Eigen::Vector3d::Zero() || f.origin.rpy != Eigen::Vector3d::Zero())
      r.readings.push_back(what + ": its origin is the base's pose at the start, which each state of the audit gives "
                           "instead");
    r.links.erase(world);
    r.joints.erase(r.joints.begin() + std::ptrdiff_t(floating_joints[0]));
    r.floating = true;
  }
  // Refuse here what the dynamics would: the messages name the file.
  try {
    robots::validate(r);
  } catch (const robot_error& e) {
    throw robot_error(origin + ": " + e.what());
  }
  return r;
}

robots::robot read_urdf(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw robot_error("read_urdf: cannot open " + path);
  std::ostringstream s;
  s << in.rdbuf();
  return parse_urdf(s.str(), path);
}

std::string to_urdf(const robots::robot& r) {
  tinyxml2::XMLDocument doc;
  doc.InsertEndChild(doc.NewDeclaration());
  doc.InsertEndChild(doc.NewComment((" mechcheck gravity=\"" + text(r.gravity) + "\" ").c_str()));
  tinyxml2::XMLElement* top = doc.NewElement("robot");
  top->SetAttribute("name", r.name.c_str());
  doc.InsertEndChild(top);
  const auto origin = [&](tinyxml2::XMLElement* parent, const robots::pose& p) {
    tinyxml2::XMLElement* o = parent->InsertNewChildElement("origin");
    o->SetAttribute("xyz", text(p.xyz).c_str());
    o->SetAttribute("rpy", text(p.rpy).c_str());
  };
  // A floating base: the world as a link of its own, joined to the root by a floating joint.
  std::string world = "world";
  if (r.floating) {
    while (std::any_of(r.links.begin(), r.links.end(), [&](const robots::link& l) { return l.name == world; })) world += "_";
    top->InsertNewChildElement("link")->SetAttribute("name", world.c_str());
  }
  for (const robots::link& l : r.links) {
    tinyxml2::XMLElement* e = top->InsertNewChildElement("link");
    e->SetAttribute("name", l.name.c_str());
    if (!l.body) continue;
    tinyxml2::XMLElement* in = e->InsertNewChildElement("inertial");
    origin(in, l.body->origin);
    in->InsertNewChildElement("mass")->SetAttribute("value", text(l.body->mass).c_str());
    tinyxml2::XMLElement* i = in->InsertNewChildElement("inertia");
    const Eigen::Matrix3d& m = l.body->inertia;
    i->SetAttribute("ixx", text(m(0, 0)).c_str());
    i->SetAttribute("ixy", text(m(0, 1)).c_str());
    i->SetAttribute("ixz", text(m(0, 2)).c_str());
    i->SetAttribute("iyy", text(m(1, 1)).c_str());
    i->SetAttribute("iyz", text(m(1, 2)).c_str());
    i->SetAttribute("izz", text(m(2, 2)).c_str());
  }
  if (r.floating) {
    const std::string root = r.links[std::size_t(robots::validate(r).root)].name;
    std::string name = root + "_floating";
    while (std::any_of(r.joints.begin(), r.joints.end(), [&](const robots::joint& j) { return j.name == name; })) name += "_";
    tinyxml2::XMLElement* e = top->InsertNewChildElement("joint");
    e->SetAttribute("name", name.c_str());
    e->SetAttribute("type", "floating");
    e->InsertNewChildElement("parent")->SetAttribute("link", world.c_str());
    e->InsertNewChildElement("child")->SetAttribute("link", root.c_str());
  }
  for (const robots::joint& j : r.joints) {
    tinyxml2::XMLElement* e = top->InsertNewChildElement("joint");
    e->SetAttribute("name", j.name.c_str());
    e->SetAttribute("type", robots::joint_type_name(j.type));
    e->InsertNewChildElement("parent")->SetAttribute("link", j.parent.c_str());
    e->InsertNewChildElement("child")->SetAttribute("link", j.child.c_str());
    origin(e, j.origin);
    if (j.type != robots::joint_type::fixed) e->InsertNewChildElement("axis")->SetAttribute("xyz", text(j.axis).c_str());
    if (j.damping != 0 || j.friction != 0 || j.armature != 0) {
      tinyxml2::XMLElement* d = e->InsertNewChildElement("dynamics");
      d->SetAttribute("damping", text(j.damping).c_str());
      d->SetAttribute("friction", text(j.friction).c_str());
      if (j.armature != 0) d->SetAttribute("armature", text(j.armature).c_str());
    }
    if (j.type == robots::joint_type::revolute || j.type == robots::joint_type::prismatic) {
      // URDF requires limits on these types; the dynamics do not use them.
      tinyxml2::XMLElement* limit = e->InsertNewChildElement("limit");
      limit->SetAttribute("lower", "-1e9");
      limit->SetAttribute("upper", "1e9");
      limit->SetAttribute("effort", "1e9");
      limit->SetAttribute("velocity", "1e9");
    }
  }
  tinyxml2::XMLPrinter printer;
  doc.Print(&printer);
  return printer.CStr();
}

}  // namespace mechcheck::audit
