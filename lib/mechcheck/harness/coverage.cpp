#include "mechcheck/harness/coverage.hpp"

#include <fstream>
#include <set>
#include <sstream>
#include <stdexcept>

namespace mechcheck::harness {

namespace {
std::vector<std::string> split(const std::string& s, char sep) {
  std::vector<std::string> out;
  std::string item;
  std::istringstream in(s);
  while (std::getline(in, item, sep)) out.push_back(item);
  return out;
}

const std::set<std::string>& statuses() {
  static const std::set<std::string> s{"law", "erratum", "derivation", "uncheckable", "open"};
  return s;
}

bool is_number(const std::string& s) {
  return !s.empty() && s.find_first_not_of("0123456789") == std::string::npos;
}
}  // namespace

std::vector<equation_entry> read_equation_map(const std::filesystem::path& file) {
  std::ifstream in(file);
  if (!in) throw std::runtime_error("read_equation_map: cannot read " + file.string());
  std::vector<equation_entry> map;
  int number = 0;
  for (std::string text; std::getline(in, text);) {
    ++number;
    if (text.empty() || text[0] == '#') continue;
    const auto fail = [&](const std::string& why) {
      throw std::runtime_error("read_equation_map: " + file.string() + ":" +
                               std::to_string(number) + ": " + why);
    };
    const auto fields = split(text, '\t');
    if (fields.size() < 2 || fields.size() > 4) fail("needs 2 to 4 tab-separated fields");
    equation_entry e;
    e.equation = fields[0];
    e.status = fields[1];
    e.line = number;
    if (!is_number(e.equation) && e.equation.rfind("claim:", 0) != 0)
      fail("equation '" + e.equation + "' is neither a number nor claim:<name>");
    if (!statuses().count(e.status)) fail("unknown status '" + e.status + "'");
    if (fields.size() > 2)
      for (const auto& r : split(fields[2], ','))
        if (!r.empty()) e.references.push_back(r);
    if (fields.size() > 3) e.note = fields[3];
    const bool needs_refs = e.status == "law" || e.status == "erratum" || e.status == "derivation";
    if (needs_refs && e.references.empty()) fail(e.status + " needs references");
    if ((e.status == "uncheckable" || e.status == "derivation" || e.status == "open") &&
        e.note.empty())
      fail(e.status + " needs a note saying why");
    map.push_back(std::move(e));
  }
  return map;
}

std::string coverage::line() const {
  const auto n = [this](const char* s) {
    const auto it = by_status.find(s);
    return it == by_status.end() ? 0 : it->second;
  };
  std::ostringstream os;
  os << numbered << " numbered equations: " << n("law") << " asserted by a law, " << n("erratum")
     << " by errata alone, " << n("derivation") << " derivation steps, " << n("uncheckable")
     << " not checkable, " << n("open") << " open (no law yet), " << unclassified
     << " unclassified; " << claims << " unnumbered claims";
  return os.str();
}

coverage check_coverage(const std::vector<equation_entry>& map,
                        const std::vector<law_result>& rows, int last_equation) {
  coverage c;
  c.numbered = last_equation;
  // What the laws say: equation -> ids, and the ids that exist (holds or falsified).
  std::map<std::string, std::set<std::string>> named_by;
  std::map<std::string, bool> is_law;  // id -> holds (false: erratum)
  for (const auto& r : rows) {
    is_law[r.info.id] = r.info.expect == expectation::holds;
    for (const auto& e : r.info.equations) named_by[e].insert(r.info.id);
  }
  std::map<std::string, const equation_entry*> entry;
  for (const auto& e : map) {
    if (!entry.emplace(e.equation, &e).second) {
      c.problems.push_back("equation " + e.equation + " is in the map twice (line " +
                           std::to_string(e.line) + ")");
      continue;
    }
    if (is_number(e.equation)) {
      const int n = std::stoi(e.equation);
      if (n < 1 || n > last_equation)
        c.problems.push_back("equation " + e.equation + " is outside 1.." +
                             std::to_string(last_equation));
      else
        ++c.by_status[e.status];
    } else {
      ++c.claims;
    }
    if (e.status == "law" || e.status == "erratum") {
      const std::set<std::string> listed(e.references.begin(), e.references.end());
      for (const auto& id : listed)
        if (!is_law.count(id))
          c.problems.push_back("equation " + e.equation + ": the map names law " + id +
                               ", which does not exist");
      const auto& actual = named_by[e.equation];
      for (const auto& id : actual)
        if (!listed.count(id))
          c.problems.push_back("equation " + e.equation + ": law " + id +
                               " lists it, the map does not name that law");
      bool any_law = false;
      for (const auto& id : listed) any_law = any_law || (is_law.count(id) && is_law[id]);
      if (e.status == "erratum" && any_law)
        c.problems.push_back("equation " + e.equation +
                             " is marked erratum, but a law that holds asserts it: mark it law");
      if (e.status == "law" && !any_law && !listed.empty())
        c.problems.push_back("equation " + e.equation +
                             " is marked law, but only errata name it: mark it erratum");
    } else if (named_by.count(e.equation)) {
      std::string ids;
      for (const auto& id : named_by[e.equation]) ids += (ids.empty() ? "" : ", ") + id;
      c.problems.push_back("equation " + e.equation + " is marked " + e.status + ", but " + ids +
                           " list it");
    }
  }
  for (const auto& e : map) {
    if (e.status != "derivation") continue;
    for (const auto& through : e.references) {
      const auto it = entry.find(through);
      if (it == entry.end() || (it->second->status != "law" && it->second->status != "erratum"))
        c.problems.push_back("equation " + e.equation + " is a derivation step asserted through " +
                             through + ", which no law asserts");
    }
  }
  for (int n = 1; n <= last_equation; ++n)
    if (!entry.count(std::to_string(n))) {
      ++c.unclassified;
      c.problems.push_back("equation " + std::to_string(n) + " is unclassified");
    }
  for (const auto& [eq, ids] : named_by)
    if (!entry.count(eq))
      c.problems.push_back("equation " + eq + " is listed by " + *ids.begin() +
                           " but missing from the map");
  return c;
}

std::vector<domain_exemption> read_domain_map(const std::filesystem::path& file) {
  std::ifstream in(file);
  if (!in) throw std::runtime_error("read_domain_map: cannot read " + file.string());
  std::vector<domain_exemption> map;
  int number = 0;
  for (std::string text; std::getline(in, text);) {
    ++number;
    if (text.empty() || text[0] == '#') continue;
    const auto fields = split(text, '\t');
    if (fields.size() != 4 || fields[0].empty() || fields[1].empty() || fields[2].empty() ||
        fields[3].empty())
      throw std::runtime_error("read_domain_map: " + file.string() + ":" +
                               std::to_string(number) +
                               ": needs 4 non-empty tab-separated fields: where, what, region "
                               "('*' for the whole parameter), reason");
    map.push_back({fields[0], fields[1], fields[2], fields[3], number});
  }
  return map;
}

std::vector<std::pair<std::string, std::string>> read_parameter_list(
    const std::filesystem::path& file) {
  std::ifstream in(file);
  if (!in) throw std::runtime_error("read_parameter_list: cannot read " + file.string());
  std::vector<std::pair<std::string, std::string>> out;
  int number = 0;
  for (std::string text; std::getline(in, text);) {
    ++number;
    if (text.empty() || text[0] == '#') continue;
    const auto fields = split(text, '\t');
    if (fields.size() != 2)
      throw std::runtime_error("read_parameter_list: " + file.string() + ":" +
                               std::to_string(number) + ": needs 'where<TAB>what'");
    out.emplace_back(fields[0], fields[1]);
  }
  return out;
}

std::string domain_coverage::line() const {
  return std::to_string(parameters) + " validated parameters: " + std::to_string(complete) +
         " reached in every region of their domain, " + std::to_string(left_out) +
         " with a region left out for a stated reason, " + std::to_string(problems.size()) +
         " problems";
}

domain_coverage check_domains(const std::vector<law_result>& rows,
                              const std::vector<domain_exemption>& map,
                              const std::vector<std::pair<std::string, std::string>>& listed) {
  using key = std::pair<std::string, std::string>;
  struct reach {
    std::vector<std::string> regions;
    std::map<std::string, std::string> by;  // region -> first law reaching it
  };
  std::map<key, reach> reached;
  for (const auto& r : rows)
    for (const auto& d : r.domains) {
      auto& e = reached[{d.where, d.what}];
      if (e.regions.empty()) e.regions = d.regions;
      for (const auto& [region, n] : d.cases)
        if (n > 0) e.by.emplace(region, r.info.id);
    }
  std::map<std::pair<key, std::string>, const domain_exemption*> exempt;
  for (const auto& m : map) exempt[{{m.where, m.what}, m.region}] = &m;
  std::set<key> all(listed.begin(), listed.end());
  for (const auto& [k, e] : reached) all.insert(k);

  domain_coverage c;
  const auto name = [](const key& k) { return k.first + " " + k.second; };
  for (const auto& k : all) {
    ++c.parameters;
    const auto it = reached.find(k);
    if (it == reached.end() || it->second.by.empty()) {
      if (const auto x = exempt.find({k, "*"}); x != exempt.end()) {
        ++c.left_out;
        c.exempted.push_back(name(k) + ": not drawn (" + x->second->reason + ")");
      } else {
        c.problems.push_back(name(k) + ": validated, but no law's cases reach it");
      }
      continue;
    }
    bool complete = true, left = false;
    for (const auto& region : it->second.regions) {
      if (it->second.by.count(region)) continue;
      complete = false;
      if (const auto x = exempt.find({k, region}); x != exempt.end()) {
        left = true;
        c.exempted.push_back(name(k) + ": " + region + " not drawn (" + x->second->reason + ")");
      } else {
        c.problems.push_back(name(k) + ": no law draws it " + region);
      }
    }
    if (complete) ++c.complete;
    if (left) ++c.left_out;
  }
  // A map entry must stay true: its parameter exists and its region is not reached.
  for (const auto& m : map) {
    const key k{m.where, m.what};
    if (!all.count(k)) {
      c.problems.push_back("domain map line " + std::to_string(m.line) + ": " + name(k) +
                           " is neither listed nor reached (renamed?)");
      continue;
    }
    const auto it = reached.find(k);
    if (it == reached.end()) continue;
    if (m.region == "*" && !it->second.by.empty())
      c.problems.push_back("domain map line " + std::to_string(m.line) + ": " + name(k) +
                           " is said not to be drawn, but " + it->second.by.begin()->second +
                           " reaches it");
    else if (const auto b = it->second.by.find(m.region); b != it->second.by.end())
      c.problems.push_back("domain map line " + std::to_string(m.line) + ": " + name(k) + " " +
                           m.region + " is said not to be drawn, but " + b->second +
                           " reaches it");
  }
  return c;
}

}  // namespace mechcheck::harness
