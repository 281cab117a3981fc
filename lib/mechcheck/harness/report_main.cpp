/// mechcheck_report --rows DIR --out DIR [--expect FILE] [--equations MAP --numbered N]
/// Gathers the rows the property tests wrote, writes laws.json and laws.md, prints the
/// law table, and exits 1 when a law failed or an expected row (a line of FILE, as
/// printed by `<property executable> --list-laws`) is missing. With an equation map
/// (coverage.hpp) it prints the coverage line, puts it in the report, and exits 1 when an
/// equation 1..N is unclassified or the map and the laws' equation lists disagree. With
/// --domains MAP [--parameters LIST] it checks which regions of the validated parameters'
/// domains the laws' cases reached (coverage.hpp) and exits 1 on an unreached one that
/// the map gives no reason for.

#include <cstdlib>
#include <fstream>
#include <iostream>
#include <set>
#include <string>

#include "mechcheck/harness/report.hpp"

int main(int argc, char** argv) {
  using namespace mechcheck::harness;
  std::string rows_dir, out_dir, expect_file, equations_file, domains_file, parameters_file;
  int numbered = 0;
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string key = argv[i];
    if (key == "--rows") rows_dir = argv[i + 1];
    else if (key == "--out") out_dir = argv[i + 1];
    else if (key == "--expect") expect_file = argv[i + 1];
    else if (key == "--equations") equations_file = argv[i + 1];
    else if (key == "--numbered") numbered = std::atoi(argv[i + 1]);
    else if (key == "--domains") domains_file = argv[i + 1];
    else if (key == "--parameters") parameters_file = argv[i + 1];
    else {
      std::cerr << "mechcheck_report: unknown option " << key << "\n";
      return 2;
    }
  }
  if (rows_dir.empty() || out_dir.empty()) {
    std::cerr << "usage: mechcheck_report --rows DIR --out DIR [--expect FILE]\n";
    return 2;
  }
  if (!equations_file.empty() && numbered <= 0) {
    std::cerr << "mechcheck_report: --equations needs --numbered N (the last equation)\n";
    return 2;
  }
  std::vector<law_result> rows;
  coverage equations;
  domain_coverage domains;
  const bool with_domains = !domains_file.empty();
  try {
    rows = read_rows(rows_dir);
    if (!equations_file.empty())
      equations = check_coverage(read_equation_map(equations_file), rows, numbered);
    if (with_domains)
      domains = check_domains(rows, read_domain_map(domains_file),
                              parameters_file.empty()
                                  ? std::vector<std::pair<std::string, std::string>>{}
                                  : read_parameter_list(parameters_file));
    write_report(rows, out_dir, equations_file.empty() ? nullptr : &equations,
                 with_domains ? &domains : nullptr);
  } catch (const std::exception& e) {
    // A missing, truncated or malformed row leaves no report at all: a partial one could
    // claim a pass for a law whose row was lost.
    std::cerr << "mechcheck_report: " << e.what() << "\n";
    return 2;
  }
  std::cout << format_table(rows);
  int failed = 0;
  std::set<std::string> seen;
  for (const auto& r : rows) {
    seen.insert(r.info.id + "." + r.tier);
    if (!r.passed) {
      ++failed;
      std::cout << "\nFAILED " << r.info.id << " [" << r.tier << "]\n" << r.message << "\n";
    }
  }
  int missing = 0;
  if (!expect_file.empty()) {
    std::ifstream in(expect_file);
    for (std::string name; std::getline(in, name);) {
      if (!name.empty() && !seen.count(name)) {
        ++missing;
        std::cout << "MISSING " << name << " (its test did not write a row: crashed or not run)\n";
      }
    }
  }
  int coverage_problems = 0;
  if (!equations_file.empty()) {
    std::cout << "\ncoverage: " << equations.line() << "\n";
    for (const auto& p : equations.problems) {
      ++coverage_problems;
      std::cout << "COVERAGE " << p << "\n";
    }
  }
  if (with_domains) {
    std::cout << "domains: " << domains.line() << "\n";
    for (const auto& e : domains.exempted) std::cout << "  left out: " << e << "\n";
    for (const auto& p : domains.problems) {
      ++coverage_problems;
      std::cout << "DOMAIN " << p << "\n";
    }
  }
  std::size_t laws = 0, errata = 0;
  std::set<std::string> ids;
  for (const auto& r : rows) {
    (r.info.expect == expectation::holds ? laws : errata) += 1;
    ids.insert(r.info.id);
  }
  std::cout << "\n" << ids.size() << " laws and errata, " << laws << " law rows, " << errata
            << " erratum rows: " << rows.size() - failed << " passed, " << failed << " failed"
            << (missing ? ", " + std::to_string(missing) + " missing" : std::string()) << "\n"
            << "outcomes:";
  for (const auto& [name, n] : count_outcomes(rows)) std::cout << " " << name << " " << n << ",";
  std::cout << " missing " << missing << "\n"
            << "report: " << out_dir << "/laws.json, " << out_dir << "/laws.md\n";
  return failed || missing || coverage_problems ? 1 : 0;
}
