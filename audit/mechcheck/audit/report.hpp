#pragma once
/// Reporting audits: a console table, JSON, Markdown and SVG plots (written directly, no
/// plotting program needed). Compiled once in the mechcheck::audit library.
///
/// Everything but the timing fields is a function of the audit results alone, so the
/// same audit gives byte-identical audit.json and audit.md; timings (seconds per step,
/// per audit) go to a separate "timing" object and a separate Markdown section, and only
/// when asked for.

#include <cstddef>
#include <iosfwd>
#include <string>
#include <vector>

#include "mechcheck/audit/result.hpp"

namespace mechcheck::audit {

/// What the report includes.
struct report_options {
  bool timing = false;  ///< include wall-time figures (not reproducible run to run)
  std::string long_run_problem = "kepler_e0.5";  ///< the problem of the plots' long runs
};

/// Words for an outcome (outcome_text: "confirmed", "CONTRADICTED", "not resolvable", ...).
std::string outcome_name(verdict::outcome o);

/// A console table that stays a table (the stepper, driver and engine tables): each
/// column as wide as its longest cell up to its cap (0: none), a longer cell cut to its
/// first line and its cap, ending in "..."; `cut` is set when any cell was cut, so the table
/// can say that the report holds them whole. The rows (the header first) come back as
/// lines, without their newlines.
std::vector<std::string> format_columns(std::vector<std::vector<std::string>> rows,
                                        const std::vector<std::size_t>& caps, bool& cut);

/// A line of text below a console table: its first line, at most `cap` characters (cut
/// ending in "..."); sets `cut` when anything was left out.
std::string clip_line(const std::string& text, std::size_t cap, bool& cut);

/// A word as a POSIX shell reads it back: as is when plain, else in single quotes (a quote
/// inside as '\''), for the commands the reports print.
std::string shell_word(const std::string& s);

/// A verdict as the text of a JSON object: claim, declared, measured, result, evidence and,
/// where it has them, needs and readings (the drivers' and engines' reports use it too).
std::string verdict_json_text(const verdict& v);

/// One line per stepper and tier: declared and measured order, symplectic, symmetric,
/// the energy behaviour of the long run, evaluations per step and the verdict.
void print_table(std::ostream& out, const std::vector<stepper_audit>& audits,
                 const report_options& opt = {});

/// The audits as JSON (every point of every study, every verdict with its evidence).
std::string to_json(const std::vector<stepper_audit>& audits, const report_options& opt = {});

/// The audits as Markdown: the summary table, then each stepper's evidence.
std::string to_markdown(const std::vector<stepper_audit>& audits,
                        const report_options& opt = {});

/// A series of a plot: a name and its (x, y) points.
struct plot_series {
  std::string name;
  std::vector<std::pair<double, double>> points;
};

/// An SVG plot on log-log axes (decades marked), one polyline with markers per series and
/// a legend; non-positive points are left out.
std::string svg_loglog(const std::string& title, const std::string& x_label,
                       const std::string& y_label, const std::vector<plot_series>& series);

/// Writes audit.json, audit.md and, per tier, convergence-<tier>.svg (global error
/// against h on the long-run problem, with the fitted slopes in the legend),
/// energy-<tier>.svg (energy error against time) and work-precision-<tier>.svg (error
/// against evaluations) into `directory` (created if missing). Each file is written to a
/// temporary name and renamed, so an interrupted run leaves no half-written report.
/// Returns the paths written.
std::vector<std::string> write_report(const std::string& directory,
                                      const std::vector<stepper_audit>& audits,
                                      const report_options& opt = {});

}  // namespace mechcheck::audit
