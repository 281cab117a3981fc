// The exec protocol's dynamics libraries (docs/protocol.md): a robot loaded as URDF text and
// its gravity, each quantity asked at a state, the model unloaded; a model loaded again into
// the child that replaces one that failed.
#include <algorithm>
#include <memory>
#include <string>
#include <vector>

#include "mechcheck/audit/adapters/detail/exec_child.hpp"
#include "mechcheck/audit/adapters/exec.hpp"
#include "mechcheck/audit/problems/urdf.hpp"

namespace mechcheck::audit {

namespace {
using namespace exec_detail;

std::string vector_text(const Eigen::VectorXd& v) {
  std::string out;
  for (Eigen::Index i = 0; i < v.size(); ++i) out += (i ? ", " : "") + to_text(v(i));
  return "(" + out + ")";
}

/// The reply field of each quantity.
const char* reply_field(dynamics_quantity q) {
  switch (q) {
    case dynamics_quantity::mass_matrix: return "m";
    case dynamics_quantity::bias: return "h";
    case dynamics_quantity::inverse: return "tau";
    case dynamics_quantity::forward: return "qddot";
    case dynamics_quantity::frame_poses: return "poses";
    case dynamics_quantity::frame_jacobians: return "jacobians";
    case dynamics_quantity::frame_bias_accelerations: return "accelerations";
    case dynamics_quantity::link_com_jacobians: return "com_jacobians";
    case dynamics_quantity::centre_of_mass: return "com";
    case dynamics_quantity::com_jacobian: return "jc";
    case dynamics_quantity::centroidal_momentum_matrix: return "ag";
  }
  return "?";
}

class exec_dynamics_model final : public dynamics_model {
 public:
  exec_dynamics_model(std::shared_ptr<session> s, std::vector<dynamics_quantity> offered, const robots::robot& robot)
      : s_(std::move(s)),
        offered_(std::move(offered)),
        urdf_(to_urdf(robot)),
        gravity_(robot.gravity),
        robot_(robot.name),
        n_(robots::validate(robot).dofs + (robot.floating ? 6 : 0)),
        nq_(n_ + (robot.floating ? 1 : 0)),
        links_(static_cast<int>(robot.links.size())) {
    load();
  }
  ~exec_dynamics_model() override {
    if (!loaded_into_live()) return;
    try {
      exchange(*s_, {{"op", "unload"}, {"model", id_}}, "unload of model " + std::to_string(id_));
    } catch (const error&) {
      // The child failed on the way out: the session has recorded it; nothing to undo.
    }
  }
  exec_dynamics_model(const exec_dynamics_model&) = delete;
  exec_dynamics_model& operator=(const exec_dynamics_model&) = delete;

  std::optional<robots::robot> held_robot() const override { return held_; }

  std::optional<Eigen::MatrixXd> mass_matrix(const Eigen::VectorXd& q) override {
    std::vector<double> m;
    if (!ask(dynamics_quantity::mass_matrix, {{"q", &q}}, n_ * n_, m)) return std::nullopt;
    return Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>>(m.data(), n_, n_);
  }
  std::optional<Eigen::VectorXd> bias(const Eigen::VectorXd& q, const Eigen::VectorXd& qdot) override {
    return vector(dynamics_quantity::bias, {{"q", &q}, {"qdot", &qdot}});
  }
  std::optional<Eigen::VectorXd> inverse(const Eigen::VectorXd& q, const Eigen::VectorXd& qdot,
                                         const Eigen::VectorXd& qddot) override {
    return vector(dynamics_quantity::inverse, {{"q", &q}, {"qdot", &qdot}, {"qddot", &qddot}});
  }
  std::optional<Eigen::VectorXd> forward(const Eigen::VectorXd& q, const Eigen::VectorXd& qdot,
                                         const Eigen::VectorXd& tau) override {
    return vector(dynamics_quantity::forward, {{"q", &q}, {"qdot", &qdot}, {"tau", &tau}});
  }
  /// The kinematics (dynamics_quantity's layouts): the poses link by link, 12 numbers each
  /// (the 12 x L matrix by columns); every other matrix row by row.
  std::optional<Eigen::MatrixXd> frame_poses(const Eigen::VectorXd& q) override {
    std::vector<double> p;
    if (!ask(dynamics_quantity::frame_poses, {{"q", &q}}, 12 * links_, p)) return std::nullopt;
    return Eigen::Map<const Eigen::MatrixXd>(p.data(), 12, links_);
  }
  std::optional<Eigen::MatrixXd> frame_jacobians(const Eigen::VectorXd& q) override {
    return matrix(dynamics_quantity::frame_jacobians, {{"q", &q}}, 6 * links_, n_);
  }
  std::optional<Eigen::VectorXd> frame_bias_accelerations(const Eigen::VectorXd& q, const Eigen::VectorXd& qdot) override {
    std::optional<Eigen::MatrixXd> a =
        matrix(dynamics_quantity::frame_bias_accelerations, {{"q", &q}, {"qdot", &qdot}}, 6 * links_, 1);
    if (!a) return std::nullopt;
    return Eigen::VectorXd(*a);
  }
  std::optional<Eigen::MatrixXd> link_com_jacobians(const Eigen::VectorXd& q) override {
    return matrix(dynamics_quantity::link_com_jacobians, {{"q", &q}}, 6 * links_, n_);
  }
  std::optional<Eigen::VectorXd> centre_of_mass(const Eigen::VectorXd& q) override {
    std::optional<Eigen::MatrixXd> c = matrix(dynamics_quantity::centre_of_mass, {{"q", &q}}, 3, 1);
    if (!c) return std::nullopt;
    return Eigen::VectorXd(*c);
  }
  std::optional<Eigen::MatrixXd> com_jacobian(const Eigen::VectorXd& q) override {
    return matrix(dynamics_quantity::com_jacobian, {{"q", &q}}, 3, n_);
  }
  std::optional<Eigen::MatrixXd> centroidal_momentum_matrix(const Eigen::VectorXd& q) override {
    return matrix(dynamics_quantity::centroidal_momentum_matrix, {{"q", &q}}, 6, n_);
  }

 private:
  using fields = std::vector<std::pair<const char*, const Eigen::VectorXd*>>;

  bool loaded_into_live() const { return s_->current && generation_ == s_->failures; }

  /// The robot into the live child: "load", refused (robot_refused) or failed (library_failure).
  void load() {
    id_ = ++s_->next_run;
    generation_ = s_->failures;
    held_.reset();  // what this child says, not what an earlier one said
    const std::string what = "load of robot " + robot_ + " as model " + std::to_string(id_);
    const json reply = exchange(
        *s_, {{"op", "load"}, {"model", id_}, {"urdf", urdf_}, {"gravity", numbers_json(gravity_.data(), 3, s_->decimal)}},
        what);
    checked(*s_, what, [&] {
      only_known_fields(reply, {"ok", "refused", "error", "held"}, "the reply");
      return 0;
    });
    if (const auto r = reply.find("refused"); r != reply.end())
      throw robot_refused("exec::" + s_->name + " refused robot " + robot_ + ": " + error_text(*r));
    if (const auto e = reply.find("error"); e != reply.end())
      throw library_failure("exec::" + s_->name + ": " + what + ": " + error_text(*e));
    if (reply.value("ok", false) != true) {
      const std::string message = s_->prefix() + what + ": neither ok, refused nor error: " + excerpt_json(reply);
      s_->failed(message);
      throw exec_error(message);
    }
    if (const auto h = reply.find("held"); h != reply.end()) held_ = checked(*s_, what, [&] { return held_of(*h); });
  }

  /// The robot the library holds (a load's "held" URDF): its moving joints the robot's
  /// coordinates, in order; gravity the robot's.
  robots::robot held_of(const json& text) const {
    if (!text.is_string()) throw exec_error("\"held\" is not a URDF text");
    robots::robot r;
    try {
      r = parse_urdf(text.get<std::string>(), "the held robot");
    } catch (const error& e) {
      throw exec_error(std::string("\"held\": ") + e.what());
    }
    r.gravity = gravity_;
    const bool floating = nq_ != n_;
    const int dofs = robots::validate(r).dofs, joints = n_ - (floating ? 6 : 0);
    if (dofs != joints || r.floating != floating)
      throw exec_error("\"held\": a robot of " + std::to_string(dofs) + " moving joints" +
                       (r.floating ? " on a floating base" : "") + ", the robot " + std::to_string(joints) +
                       (floating ? " on a floating base" : ""));
    return r;
  }

  /// A rows x cols matrix sent row by row.
  std::optional<Eigen::MatrixXd> matrix(dynamics_quantity quantity, const fields& in, int rows, int cols) {
    std::vector<double> y;
    if (!ask(quantity, in, rows * cols, y)) return std::nullopt;
    return Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>>(y.data(), rows, cols);
  }

  std::optional<Eigen::VectorXd> vector(dynamics_quantity quantity, const fields& in) {
    std::vector<double> y;
    if (!ask(quantity, in, n_, y)) return std::nullopt;
    return Eigen::Map<const Eigen::VectorXd>(y.data(), n_);
  }

  /// One quantity at a state: false where the child does not compute it.
  bool ask(dynamics_quantity quantity, const fields& in, int count, std::vector<double>& out) {
    if (std::find(offered_.begin(), offered_.end(), quantity) == offered_.end()) return false;
    for (const auto& [name, v] : in)
      if (v->size() != size_of(name))
        throw dimension_error("exec::" + s_->name + ": " + quantity_op(quantity) + ": the robot has " +
                              std::to_string(size_of(name)) + " components of " + name + ", given " + std::to_string(v->size()));
    if (!loaded_into_live()) load();  // the child that held the model failed since
    json request = {{"op", quantity_op(quantity)}, {"model", id_}};
    for (const auto& [name, v] : in) request[name] = numbers_json(v->data(), v->size(), s_->decimal);
    const std::string what = std::string(quantity_op(quantity)) + " of model " + std::to_string(id_) + " (robot " +
                             robot_ + ") at q = " + vector_text(*in.front().second);
    const json reply = exchange(*s_, request, what);
    const char* field = reply_field(quantity);
    checked(*s_, what, [&] {
      only_known_fields(reply, {field, "error"}, "the reply");
      return 0;
    });
    if (const auto e = reply.find("error"); e != reply.end())
      throw library_failure("exec::" + s_->name + ": " + what + ": " + error_text(*e));
    out.resize(static_cast<std::size_t>(count));
    // A non-finite number is read as such: check_dynamics names it as the library's value.
    checked(*s_, what, [&] { return numbers_into(reply, field, count, out.data(), "the reply", false); });
    return true;
  }

  /// q has 7 + n components on a floating base (the base's position and quaternion), every
  /// other vector 6 + n (dynamics_state's layout).
  int size_of(const std::string& name) const { return name == "q" ? nq_ : n_; }

  std::shared_ptr<session> s_;
  std::vector<dynamics_quantity> offered_;
  std::string urdf_;
  Eigen::Vector3d gravity_;
  std::string robot_;
  int n_ = 0;   ///< velocities: the moving joints, and the base's six on a floating base
  int nq_ = 0;  ///< coordinates: n_, and one more on a floating base (its quaternion's four)
  int links_ = 0;  ///< the robot's links, in the order of its <link> elements
  long long id_ = 0;
  int generation_ = 0;  ///< the session's failures when the model was loaded
  std::optional<robots::robot> held_;
};
}  // namespace

exec_dynamics_target exec_dynamics(const std::vector<std::string>& command, const exec_options& options) {
  exec_protocol::handshake_fields h;
  auto s = open_session(command, options, "dynamics", h);
  exec_dynamics_target target;
  target.library.name = "exec::" + h.name;
  target.library.origin = served_by(h.origin, command);
  target.library.selector = "--exec-dynamics -- " + command_text(command);
  if (!h.floating_base)
    target.library.no_floating_base = "the child's handshake does not say \"floating_base\": true (docs/protocol.md)";
  else
    target.library.no_floating_base.clear();
  const std::vector<dynamics_quantity> offered = h.quantities;
  target.library.load = [s, offered](const robots::robot& robot) -> std::unique_ptr<dynamics_model> {
    return std::make_unique<exec_dynamics_model>(s, offered, robot);
  };
  target.failures = [s] { return s->failures; };
  target.last_failure = [s] { return s->last_failure; };
  return target;
}

}  // namespace mechcheck::audit
