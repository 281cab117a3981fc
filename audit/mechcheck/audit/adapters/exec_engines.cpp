// The exec protocol's engines (docs/protocol.md): a scenario in engine-neutral terms sent at
// "start", batches of steps read back as frames and joint coordinates (simdjson: a thousand
// states a reply), the inertia of shapes.
#include <algorithm>
#include <cmath>
#include <memory>
#include <string>
#include <tuple>
#include <vector>

#include <simdjson.h>

#include "mechcheck/audit/adapters/detail/exec_child.hpp"
#include "mechcheck/audit/adapters/exec.hpp"

namespace mechcheck::audit {

namespace {
using namespace exec_detail;
using exec_protocol::number_text;
using exec_protocol::number_value;

const char* structure_name(body_structure b) {
  switch (b) {
    case body_structure::one_body: return "one_body";
    case body_structure::chain: return "chain";
    case body_structure::free_bodies: return "free_bodies";
    case body_structure::robot: return "robot";
    case body_structure::contact: return "contact";
  }
  return "?";
}
const char* joint_name(joint_kind j) {
  return j == joint_kind::free ? "free" : j == joint_kind::hinge_y ? "hinge_y" : "ball";
}

json vector_json(const Eigen::Vector3d& v, bool decimal) { return numbers_json(v.data(), 3, decimal); }

/// Frames in a reading: one for a one-body scenario, one a link otherwise; joint
/// coordinates: one a hinge (a chain's links, a one-body hinge), none otherwise.
std::size_t frames_of(const scenario& s) {
  return s.structure == body_structure::one_body  ? 1
         : s.structure == body_structure::contact ? s.contact->bodies.size()
                                                  : s.links.size();
}
std::size_t hinges_of(const scenario& s) {
  return s.structure == body_structure::chain                                        ? s.links.size()
         : s.structure == body_structure::one_body && s.joint == joint_kind::hinge_y ? 1
                                                                                     : 0;
}

/// A frame: rotation (row-major, body to world), centre of mass, its velocity, the angular
/// velocity in the world frame: 18 numbers.
constexpr int frame_numbers = 18;

/// Only the fields version 1 has, in an object of a step reply (parsed by simdjson).
void only_known_fields(simdjson::dom::object object, std::initializer_list<const char*> known, const std::string& what) {
  for (const auto field : object)
    if (!known_field(field.key, known)) unknown_field(field.key, known, what);
}

/// The numbers of an array of a reply (a JSON number, or a string in C's decimal or
/// hexadecimal form), counted against the line's budget of values.
void numbers_of(simdjson::dom::element e, const std::string& what, std::vector<double>& out, std::size_t& budget) {
  simdjson::dom::array a;
  if (e.get_array().get(a)) throw exec_error(what + " is not an array: " + excerpt(simdjson::minify(e)));
  out.clear();
  for (simdjson::dom::element x : a) {
    if (budget-- == 0) throw exec_error("a line of more than " + std::to_string(exec_protocol::max_numbers) + " values");
    double v = 0;
    if (x.is_string()) {
      const std::string_view text = x.get_string().value_unsafe();
      if (text.size() > 64) throw exec_error(what + "[" + std::to_string(out.size()) + "]: a number of " + std::to_string(text.size()) + " characters");
      const std::optional<double> read = number_value(text);
      if (!read) throw exec_error(what + "[" + std::to_string(out.size()) + "]: \"" + excerpt(text) + "\" is not a number");
      v = *read;
    } else if (x.get_double().get(v)) {
      throw exec_error(what + "[" + std::to_string(out.size()) + "]: " + excerpt(simdjson::minify(x)) + " is not a number");
    }
    if (!std::isfinite(v)) throw exec_error(what + "[" + std::to_string(out.size()) + "] is not finite (" + excerpt(simdjson::minify(x)) + ")");
    out.push_back(v);
  }
}

body_frame frame_of(const std::vector<double>& x, const std::string& what) {
  if (x.size() != frame_numbers)
    throw exec_error(what + " has " + std::to_string(x.size()) + " numbers, " + std::to_string(frame_numbers) + " expected");
  body_frame f;
  f.rotation = Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>(x.data());
  f.position = Eigen::Map<const Eigen::Vector3d>(x.data() + 9);
  f.velocity = Eigen::Map<const Eigen::Vector3d>(x.data() + 12);
  f.omega = Eigen::Map<const Eigen::Vector3d>(x.data() + 15);
  return f;
}

/// A reading: {"frame": [18]} or {"links": [[18], ...]}, and "q", "v" where the engine has
/// joint coordinates.
body_reading reading_of(simdjson::dom::element e, const scenario& s, const std::string& what, std::size_t& budget) {
  simdjson::dom::object r;
  if (e.get_object().get(r)) throw exec_error(what + ": a reading is not an object: " + excerpt(simdjson::minify(e)));
  only_known_fields(r, {"frame", "links", "q", "v"}, what + ": a reading");
  std::vector<double> x;
  body_reading out;
  if (s.structure == body_structure::one_body) {
    simdjson::dom::element f;
    if (r["frame"].get(f)) throw exec_error(what + ": a reading of a one-body scenario has no \"frame\"");
    numbers_of(f, what + ": \"frame\"", x, budget);
    static_cast<body_frame&>(out) = frame_of(x, what + ": \"frame\"");
  } else {
    simdjson::dom::array links;
    if (r["links"].get_array().get(links) || links.size() != frames_of(s))
      throw exec_error(what + ": a reading of " + s.name + " has \"links\", one frame each of its " +
                       std::to_string(frames_of(s)) + " bodies");
    std::size_t k = 0;
    for (simdjson::dom::element l : links) {
      const std::string name = what + ": \"links\"[" + std::to_string(k++) + "]";
      numbers_of(l, name, x, budget);
      out.links.push_back(frame_of(x, name));
    }
  }
  const std::size_t hinges = hinges_of(s);
  simdjson::dom::element q, v;
  const bool has_q = !r["q"].get(q), has_v = !r["v"].get(v);
  if (has_q != has_v) throw exec_error(what + ": a reading has \"q\" and \"v\" together or neither");
  if (has_q) {
    if (hinges == 0) throw exec_error(what + ": a reading of " + s.name + " (no hinge) has joint coordinates");
    for (const auto& [e2, name, target] : {std::tuple{q, "q", &out.joint_q}, std::tuple{v, "v", &out.joint_v}}) {
      numbers_of(e2, what + ": \"" + name + "\"", x, budget);
      if (x.size() != hinges)
        throw exec_error(what + ": \"" + name + "\" has " + std::to_string(x.size()) + " numbers, " +
                         std::to_string(hinges) + " expected");
      *target = Eigen::Map<const Eigen::VectorXd>(x.data(), static_cast<Eigen::Index>(hinges));
    }
  }
  return out;
}

/// A step reply to a request of `steps` steps that reads `expected` states (1: the last),
/// parsed by simdjson (the long run reads a reply of a thousand states every thousand steps:
/// about 14 times faster than a document of nlohmann_json), nested at most max_depth deep.
exec_protocol::step_reply step_reply_of(std::string_view line, const scenario& s, long steps, long expected) {
  thread_local simdjson::dom::parser parser;
  if (parser.capacity() < line.size() || parser.max_depth() != exec_protocol::max_depth)
    if (parser.allocate(std::max<std::size_t>(line.size(), 4096), exec_protocol::max_depth))
      throw exec_error("a reply of " + std::to_string(line.size()) + " bytes cannot be parsed here (memory)");
  const simdjson::padded_string padded(line);
  simdjson::dom::element doc;
  if (const auto error = parser.parse(padded).get(doc)) {
    if (error == simdjson::DEPTH_ERROR)
      throw exec_error("a line nested deeper than " + std::to_string(exec_protocol::max_depth) + " levels");
    throw exec_error(std::string("the reply is not JSON (") + simdjson::error_message(error) + "): \"" + excerpt(line) + "\"");
  }
  simdjson::dom::object top;
  if (doc.get_object().get(top)) throw exec_error("the reply is not a JSON object: " + excerpt(line));
  if (!top["op"].error()) throw exec_error("an unknown request from the child: " + excerpt(line));
  only_known_fields(top, {"readings", "error", "at", "seconds"}, "a step reply");
  simdjson::dom::array readings;
  std::size_t count = 0;
  if (simdjson::dom::element r; !top["readings"].get(r)) {
    if (r.get_array().get(readings)) throw exec_error("\"readings\" is not an array");
    count = readings.size();
  }
  exec_protocol::step_reply out;
  if (simdjson::dom::element e; !top["error"].get(e)) {
    out.error = e.is_string() ? excerpt(e.get_string().value_unsafe()) : excerpt(simdjson::minify(e));
    int64_t at = 0;
    if (top["at"].get_int64().get(at) || at < 1 || at > steps)
      throw exec_error("an error reply names the step that failed (\"at\", 1 to " + std::to_string(steps) + "): " + excerpt(line));
    out.at = static_cast<long>(at);
    // With the state read after each step: the readings of the steps before the failure.
    if (count != 0 && (expected != steps || count != static_cast<std::size_t>(out.at - 1)))
      throw exec_error("an error at step " + std::to_string(out.at) + " with " + std::to_string(count) + " readings");
  } else if (count != static_cast<std::size_t>(expected)) {
    throw exec_error("\"readings\" has " + std::to_string(count) + " readings, " + std::to_string(expected) + " expected");
  }
  std::size_t budget = exec_protocol::max_numbers;
  out.readings.reserve(count);
  if (count > 0) {
    std::size_t k = 0;
    for (simdjson::dom::element r : readings) out.readings.push_back(reading_of(r, s, "readings[" + std::to_string(k++) + "]", budget));
  }
  if (simdjson::dom::element t; !top["seconds"].get(t)) {
    std::vector<double> x;
    const std::string wrapped = "[" + simdjson::minify(t) + "]";
    const simdjson::padded_string one(wrapped);
    simdjson::dom::parser small;
    numbers_of(small.parse(one).value_unsafe(), "\"seconds\"", x, budget);
    out.seconds = x.empty() ? -1 : x.front();
    if (x.size() != 1 || out.seconds < 0) throw exec_error("\"seconds\" is not a number >= 0");
  }
  return out;
}

/// The start's reading, from its reply (a document: one a run).
body_reading start_reading_of(const json& r, const scenario& s) {
  return step_reply_of(json{{"readings", json::array({r})}}.dump(), s, 1, 1).readings.front();
}

/// The bytes of one reading in a reply, about: 25 a number.
std::size_t reading_bytes(const scenario& s) { return 25 * (frame_numbers * frames_of(s) + 2 * hinges_of(s)) + 64; }

class exec_engine_run final : public engine_run {
 public:
  exec_engine_run(std::shared_ptr<session> s, std::string integrator, const scenario& sc)
      : s_(std::move(s)), integrator_(std::move(integrator)), scenario_(sc), id_(++s_->next_run) {
    const std::string what = "start of run " + std::to_string(id_) + " (" + integrator_ + " on " + sc.name + ")";
    const json reply = exchange(*s_,
                                {{"op", "start"},
                                 {"run", id_},
                                 {"integrator", integrator_},
                                 {"scenario", json::parse(exec_protocol::scenario_json(sc, s_->decimal))}},
                                what);
    if (const auto r = reply.find("refused"); r != reply.end())
      throw scenario_refused("exec::" + s_->name + "::" + integrator_ + ": " + error_text(*r));
    if (const auto e = reply.find("error"); e != reply.end())
      throw error(s_->prefix() + what + ": the engine failed: " + error_text(*e));
    checked(*s_, what, [&] {
      if (reply.value("ok", false) != true) throw exec_error("neither ok, refused nor error: " + excerpt_json(reply));
      const auto r = reply.find("reading");
      if (r == reply.end()) throw exec_error("no \"reading\" of the start");
      last_ = start_reading_of(*r, scenario_);
      differs_ = text_of(reply, "model_differs", "the reply", false);
      return 0;
    });
    open_ = true;
  }
  ~exec_engine_run() override {
    if (!open_ || !s_->current) return;
    try {
      exchange(*s_, {{"op", "end"}, {"run", id_}}, "end of run " + std::to_string(id_));
    } catch (const std::exception&) {
      // The run's outcome is already recorded; the child that failed here is gone.
    }
  }
  exec_engine_run(const exec_engine_run&) = delete;
  exec_engine_run& operator=(const exec_engine_run&) = delete;

  void step(double h) override { advance(h, 1); }
  void advance(double h, long n) override {
    if (n <= 0) return;
    const exec_protocol::step_reply r = request(h, n, false, false);
    if (!r.error.empty()) fail(r);
    last_ = r.readings.back();
    steps_ += n;
  }
  double trajectory(double h, long n, const std::function<void(long, const body_reading&)>& each, bool timed) override {
    // Batches whose reply stays within half the line limit and half the values a line may
    // hold. The next batch is asked for before this one's reply is read, so that the child
    // steps while the parent reads: one request is in flight at most, and a reply that ends
    // the run (an error, a reading the audit refuses) has the one after it read and dropped.
    const std::size_t values = frame_numbers * frames_of(scenario_) + 2 * hinges_of(scenario_) + 4;
    const long batch = std::max<long>(
        1, static_cast<long>(std::min(s_->options.max_line / 2 / reading_bytes(scenario_), exec_protocol::max_numbers / 2 / values)));
    double seconds = 0;
    long sent = 0;  // steps asked for
    const auto ask = [&] {
      const long m = std::min(batch, n - sent);
      send_request(h, m, true, timed, steps_ + sent);
      sent += m;
    };
    in_flight_ = false;
    try {
      ask();
      for (long done = 0; done < n;) {
        const long m = std::min(batch, n - done);
        std::string line = receive_reply(steps_ + 1, m, h);
        if (sent < n) ask();
        const exec_protocol::step_reply r = read_reply(line, m, true);
        for (std::size_t k = 0; k < r.readings.size(); ++k) each(done + static_cast<long>(k) + 1, r.readings[k]);
        if (!r.error.empty()) fail(r);
        if (timed && r.seconds < 0) {
          const std::string message = s_->prefix() + "step of run " + std::to_string(id_) + ": no \"seconds\" in a timed reply";
          s_->failed(message);
          throw exec_error(message);
        }
        seconds += r.seconds;
        last_ = r.readings.back();
        steps_ += m;
        done += m;
      }
    } catch (...) {
      drop_in_flight();
      throw;
    }
    return seconds;
  }
  body_reading read() const override { return last_; }
  std::string model_differs() const override { return differs_; }

 private:
  /// Asks for n steps of h from step `from` + 1 (the state after each, or after the last).
  void send_request(double h, long n, bool each, bool timed, long long from) {
    if (!(h != 0 && std::isfinite(h)))
      throw domain_error("exec::" + s_->name + "::" + integrator_ + ": the step must be finite and non-zero, got " + to_text(h));
    json message = {{"op", "step"}, {"run", id_}, {"h", number_text(h, s_->decimal)}, {"n", n}, {"read", each ? "each" : "last"}};
    if (timed) message["timed"] = true;
    const std::string what = request_name(from + 1, n, h);
    try {
      s_->live().send(message, what);
    } catch (const exec_error& e) {
      s_->failed(e.what());
      throw;
    }
    in_flight_ = true;
  }
  std::string request_name(long long first, long n, double h) const {
    return "steps " + std::to_string(first) + " to " + std::to_string(first + n - 1) + " of run " + std::to_string(id_) +
           " (" + integrator_ + " on " + scenario_.name + ", h = " + to_text(h) + ")";
  }
  /// The reply line of the request in flight (steps from `first`).
  std::string receive_reply(long long first, long n, double h) {
    what_ = request_name(first, n, h);
    try {
      std::string line = s_->live().receive_line(what_);
      in_flight_ = false;
      return line;
    } catch (const exec_error& e) {
      in_flight_ = false;
      s_->failed(e.what());
      throw;
    }
  }
  /// The reply, read by step_reply_of (simdjson).
  exec_protocol::step_reply read_reply(const std::string& line, long n, bool each) {
    try {
      return step_reply_of(line, scenario_, n, each ? n : 1);
    } catch (const exec_error& e) {
      const exec_error named = s_->live().failure(what_, e.what());
      in_flight_ = false;  // the child is ended: nothing more is read from it
      s_->failed(named.what());
      throw named;
    }
  }
  /// Reads and drops the reply of a request still in flight (the run ended before it).
  void drop_in_flight() {
    if (!in_flight_ || !s_->current) return;
    in_flight_ = false;
    try {
      s_->current->receive_line(what_ + ": the reply after the run ended");
    } catch (const exec_error& e) {
      s_->failed(e.what());
    }
  }
  exec_protocol::step_reply request(double h, long n, bool each, bool timed) {
    send_request(h, n, each, timed, steps_);
    return read_reply(receive_reply(steps_ + 1, n, h), n, each);
  }
  /// The engine's own failure at step `at` of the request: a failed run, the child goes on.
  [[noreturn]] void fail(const exec_protocol::step_reply& r) const {
    throw convergence_error("exec::" + s_->name + "::" + integrator_ + ": step " + std::to_string(steps_ + r.at) + ": " +
                            r.error);
  }

  std::shared_ptr<session> s_;
  std::string integrator_;
  scenario scenario_;
  long long id_ = 0;
  long long steps_ = 0;
  bool open_ = false;
  bool in_flight_ = false;  ///< a step request whose reply is not read yet
  body_reading last_;
  std::string differs_, what_;
};
}  // namespace

exec_engine_target exec_engine(const std::vector<std::string>& command, const exec_options& options) {
  exec_protocol::handshake_fields h;
  auto s = open_session(command, options, "engine", h);
  exec_engine_target target;
  for (const auto& i : h.integrators) {
    engine_integrator e;
    e.name = "exec::" + h.name + "::" + i.name;
    e.origin = served_by((h.origin.empty() ? "" : h.origin + "; ") + i.origin, command);
    e.declared = i.declared;
    e.epsilon = h.epsilon;
    e.multibody = true;  // the child refuses what it cannot build
    e.command_arguments = "--exec-engine -- " + command_text(command);
    e.contact = i.contact;
    e.contact_only = i.contact_only;
    const std::string name = i.name;
    // A contact case as the lines the child reads: its start, the steps at h = 1/60 to the
    // scenario's end (the last reading answered) and its end. Piped into the child's command
    // alone (`COMMAND < FILE`), they replay the case in the engine without mechcheck.
    e.contact_model = [name, decimal = s->decimal](const scenario& sc) {
      const double h = 1.0 / 60;
      const json start = {{"op", "start"}, {"run", 1}, {"integrator", name},
                          {"scenario", json::parse(exec_protocol::scenario_json(sc, decimal))}};
      const json step = {{"op", "step"}, {"run", 1}, {"h", number_text(h, decimal)},
                         {"n", std::lround(sc.t_end / h)}, {"read", "last"}};
      const json end = {{"op", "end"}, {"run", 1}};
      return start.dump() + "\n" + step.dump() + "\n" + end.dump() + "\n";
    };
    e.contact_model_extension = "jsonl";
    e.start = [s, name](const scenario& sc) -> std::unique_ptr<engine_run> {
      return std::make_unique<exec_engine_run>(s, name, sc);
    };
    target.integrators.push_back(std::move(e));
  }
  if (h.shapes) {
    engine_shapes shapes;
    shapes.engine = "exec::" + h.name;
    shapes.origin = served_by(h.origin, command);
    shapes.moments = [s](const shape& sh) -> Eigen::Vector3d {
      const bool decimal = s->decimal;
      const std::string what = "the inertia of shape " + sh.name;
      const json reply = exchange(*s,
                                  {{"op", "shape"},
                                   {"shape", {{"name", sh.name}, {"mass", number_text(sh.mass, decimal)},
                                              {"size", vector_json(sh.size, decimal)}}}},
                                  what);
      if (const auto r = reply.find("refused"); r != reply.end())
        throw scenario_refused("exec::" + s->name + ": " + error_text(*r));
      Eigen::Vector3d m;
      checked(*s, what, [&] {
        numbers_into(reply, "moments", 3, m.data(), "the reply");
        return 0;
      });
      return m;
    };
    if (h.shapes_without_mass)
      shapes.without_mass = [s](const shape& sh) -> engine_default_mass {
        const bool decimal = s->decimal;
        const std::string what = "the mass and inertia of shape " + sh.name + " given without a mass";
        const json reply =
            exchange(*s, {{"op", "shape"}, {"shape", {{"name", sh.name}, {"size", vector_json(sh.size, decimal)}}}}, what);
        if (const auto r = reply.find("refused"); r != reply.end())
          throw scenario_refused("exec::" + s->name + ": " + error_text(*r));
        engine_default_mass d;
        checked(*s, what, [&] {
          numbers_into(reply, "moments", 3, d.moments.data(), "the reply");
          const auto mass = reply.find("mass");
          if (mass == reply.end()) throw exec_error("the reply has no \"mass\": " + excerpt_json(reply));
          d.mass = number_of(*mass, "the reply: mass");
          d.said = text_of(reply, "said", "the reply", false);
          return 0;
        });
        return d;
      };
    target.shapes = std::move(shapes);
  }
  target.failures = [s] { return s->failures; };
  target.last_failure = [s] { return s->last_failure; };
  return target;
}

namespace exec_protocol {
step_reply parse_step_reply(std::string_view line, const scenario& s, long steps, bool each) {
  if (steps < 1) throw domain_error("parse_step_reply: steps must be positive");
  return step_reply_of(line, s, steps, each ? steps : 1);
}

std::string scenario_json(const scenario& s, bool decimal) {
  const auto num = [&](double x) { return number_text(x, decimal); };
  json j = {{"name", s.name},
            {"structure", structure_name(s.structure)},
            {"joint", joint_name(s.joint)},
            {"mass", num(s.mass)},
            {"inertia", vector_json(s.inertia, decimal)},
            {"com", vector_json(s.com, decimal)},
            {"gravity", num(s.gravity)},
            {"central", num(s.central)},
            {"gravitation", num(s.gravitation)},
            {"position0", vector_json(s.position0, decimal)},
            {"velocity0", vector_json(s.velocity0, decimal)},
            {"omega0", vector_json(s.omega0, decimal)}};
  const Eigen::Matrix<double, 3, 3, Eigen::RowMajor> r = s.rotation0;
  j["rotation0"] = numbers_json(r.data(), 9, decimal);
  json links = json::array();
  for (const link& l : s.links)
    links.push_back({{"mass", num(l.mass)},
                     {"inertia", vector_json(l.inertia, decimal)},
                     {"com", vector_json(l.com, decimal)},
                     {"hinge", vector_json(l.hinge, decimal)},
                     {"angle0", num(l.angle0)},
                     {"rate0", num(l.rate0)},
                     {"position0", vector_json(l.position0, decimal)},
                     {"velocity0", vector_json(l.velocity0, decimal)}});
  j["links"] = links;
  if (s.loop) j["loop"] = {{"point", vector_json(s.loop->point, decimal)}, {"anchor", vector_json(s.loop->anchor, decimal)}};
  if (s.contact) {
    const contact_setup& c = *s.contact;
    json bodies = json::array();
    for (const contact_body& b : c.bodies) {
      const Eigen::Matrix<double, 3, 3, Eigen::RowMajor> rb = b.rotation0;
      bodies.push_back({{"shape", contact_shape_name(b.shape)},
                        {"size", vector_json(b.size, decimal)},
                        {"mass", num(b.mass)},
                        {"inertia", vector_json(b.inertia, decimal)},
                        {"rotation0", numbers_json(rb.data(), 9, decimal)},
                        {"position0", vector_json(b.position0, decimal)},
                        {"velocity0", vector_json(b.velocity0, decimal)},
                        {"omega0", vector_json(b.omega0, decimal)}});
    }
    j["contact"] = {{"ground", c.ground},
                    {"slope", num(c.slope)},
                    {"normal", vector_json(c.normal(), decimal)},
                    {"mu", num(c.mu)},
                    {"restitution", num(c.restitution)},
                    {"bodies", bodies}};
  }
  return j.dump();
}
}  // namespace exec_protocol

}  // namespace mechcheck::audit
