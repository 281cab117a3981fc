// A dynamics library behind C calls (user_dynamics.hpp): statuses and sizes turned into
// typed errors, the robot handed over as URDF text.
#include "mechcheck/audit/dynamics/user_dynamics.hpp"

#include <array>

namespace mechcheck::audit {

namespace {
class c_model final : public dynamics_model {
 public:
  c_model(const c_dynamics& library, void* handle, int n) : library_(library), handle_(handle), n_(n) {}
  ~c_model() override {
    if (library_.unload) library_.unload(handle_);
  }
  c_model(const c_model&) = delete;
  c_model& operator=(const c_model&) = delete;

  std::optional<Eigen::MatrixXd> mass_matrix(const Eigen::VectorXd& q) override {
    if (!library_.mass_matrix) return std::nullopt;
    Eigen::MatrixXd m(n_, n_);  // column-major, as the C function writes it
    require(q, "mass_matrix");
    status(library_.mass_matrix(handle_, n_, q.data(), m.data()), "mass_matrix", q);
    return m;
  }
  std::optional<Eigen::VectorXd> bias(const Eigen::VectorXd& q, const Eigen::VectorXd& qdot) override {
    if (!library_.bias) return std::nullopt;
    Eigen::VectorXd h(n_);
    require(q, "bias"), require(qdot, "bias");
    status(library_.bias(handle_, n_, q.data(), qdot.data(), h.data()), "bias", q);
    return h;
  }
  std::optional<Eigen::VectorXd> inverse(const Eigen::VectorXd& q, const Eigen::VectorXd& qdot,
                                         const Eigen::VectorXd& qddot) override {
    if (!library_.inverse) return std::nullopt;
    Eigen::VectorXd tau(n_);
    require(q, "inverse"), require(qdot, "inverse"), require(qddot, "inverse");
    status(library_.inverse(handle_, n_, q.data(), qdot.data(), qddot.data(), tau.data()), "inverse", q);
    return tau;
  }
  std::optional<Eigen::VectorXd> forward(const Eigen::VectorXd& q, const Eigen::VectorXd& qdot,
                                         const Eigen::VectorXd& tau) override {
    if (!library_.forward) return std::nullopt;
    Eigen::VectorXd qddot(n_);
    require(q, "forward"), require(qdot, "forward"), require(tau, "forward");
    status(library_.forward(handle_, n_, q.data(), qdot.data(), tau.data(), qddot.data()), "forward", q);
    return qddot;
  }

 private:
  void require(const Eigen::VectorXd& v, const char* what) const {
    if (v.size() != n_)
      throw dimension_error(library_.name + ": " + what + ": the robot has " + std::to_string(n_) +
                            " coordinates, given a vector of " + std::to_string(v.size()));
  }
  void status(int code, const char* what, const Eigen::VectorXd& q) const {
    if (code == 0) return;
    std::string at;
    for (Eigen::Index i = 0; i < q.size(); ++i) at += (i ? ", " : "") + to_text(q(i));
    throw library_failure(library_.name + ": " + what + " returned status " + std::to_string(code) + " at q = (" + at + ")");
  }
  c_dynamics library_;  // a copy: the model may outlive the dynamics_library
  void* handle_;
  int n_;
};
}  // namespace

dynamics_library c_dynamics_library(const c_dynamics& library) {
  if (!library.load) throw domain_error("c_dynamics_library: " + library.name + " has no load function");
  if (library.name.empty()) throw domain_error("c_dynamics_library: the library has no name");
  dynamics_library out;
  out.name = library.name;
  out.origin = library.origin;
  out.no_floating_base = "a library behind C calls takes robots fixed to the world only";
  out.load = [library](const robots::robot& robot) -> std::unique_ptr<dynamics_model> {
    const int n = robots::validate(robot).dofs;
    const std::string urdf = to_urdf(robot);
    std::array<char, 1024> why{};
    void* handle = library.load(urdf.c_str(), robot.gravity.data(), why.data(), static_cast<int>(why.size()));
    if (!handle) {
      why.back() = '\0';
      const std::string reason(why.data());
      throw robot_refused(library.name + " refused robot " + robot.name + ": " +
                          (reason.empty() ? std::string("(no reason given)") : reason));
    }
    return std::make_unique<c_model>(library, handle, n);
  };
  return out;
}

}  // namespace mechcheck::audit
