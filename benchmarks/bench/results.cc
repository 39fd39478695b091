#include "benchmarks/bench/results.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <stdexcept>

#include "common/format.h"

namespace thrustsched::bench {

const std::vector<std::string>& ContractColumns() {
  static const std::vector<std::string> kColumns = {"scenario",
                                                    "scheme",
                                                    "formulation",
                                                    "encoding",
                                                    "step_s",
                                                    "horizon_s",
                                                    "discretise_s",
                                                    "max_rel_err_phi",
                                                    "max_rel_err_gamma",
                                                    "n_binaries",
                                                    "n_rows",
                                                    "n_columns",
                                                    "n_nonzeros",
                                                    "build_s",
                                                    "peak_rss_mb",
                                                    "lp_bound",
                                                    "lp_s",
                                                    "status",
                                                    "objective",
                                                    "best_bound",
                                                    "gap",
                                                    "time_to_first_s",
                                                    "time_to_1pct_s",
                                                    "solve_s",
                                                    "consumption_l1_m_s",
                                                    "delta_v_m_s",
                                                    "n_burns",
                                                    "max_window_violation",
                                                    "max_window_violation_nonlinear_deg"};
  return kColumns;
}

const std::vector<std::string>& ResultColumns() {
  // Contract columns first (same order), then the extensions documented in
  // the report's "Columns" section.
  static const std::vector<std::string> kColumns = [] {
    std::vector<std::string> c = {"section", "case_id", "repeat", "variant"};
    for (const std::string& name : ContractColumns()) c.push_back(name);
    for (const char* name :
         {"model", "n_thrusters", "threads", "time_limit_s", "relative_gap", "lp_algorithm",
          "lp_relaxation_algorithm", "objective_step", "global_rel_err", "observed_order_phi",
          "observed_order_gamma", "nodes", "time_to_opt_s", "time_within_1pct_of_opt_s",
          "operational_ok", "max_window_violation_nodes", "window_unit", "terminal_ok",
          "terminal_error", "published", "published_source", "ratio", "ext_cbc_status",
          "ext_cbc_objective", "ext_cbc_s", "ext_glpsol_status", "ext_glpsol_objective",
          "ext_glpsol_s", "published_time_s", "start_objective", "budget_rounds",
          "keep_out_binaries", "max_risk", "max_risk_unmanoeuvred", "published_risk_unmanoeuvred",
          "mc_samples", "mc_collisions_linear", "mc_collisions_nonlinear", "mc_min_distance_m",
          "verify_s", "wall_s", "cpu_s", "load_1min", "exit", "solver_path", "search_steps",
          "target_1pct_s", "target_opt_s", "target_gap", "target_gap_s", "note",
          // Added after the first published results.csv: appended, so that
          // every earlier column keeps its position.
          "ext_highs_status", "ext_highs_objective", "ext_highs_s", "ext_highs_bound",
          "ext_highs_gap", "without_conjunction", "extra_cost", "without_max_risk",
          "without_mc_collisions_linear", "without_mc_collisions_nonlinear", "allocator_tuned",
          "transfer_method", "transfer_figure", "transfer_unit", "feedback_phase",
          "published_feedback_phase", "switch_rule", "propellant_kg", "propellant_limit_kg",
          "revolutions"}) {
      c.push_back(name);
    }
    return c;
  }();
  return kColumns;
}

namespace {

bool KnownColumn(const std::string& column) {
  const auto& c = ResultColumns();
  return std::find(c.begin(), c.end(), column) != c.end();
}

std::string Quote(const std::string& value) {
  if (value.find_first_of(",\"\n\r") == std::string::npos) return value;
  std::string out = "\"";
  for (char ch : value) {
    if (ch == '"')
      out += "\"\"";
    else if (ch == '\n' || ch == '\r')
      out += ' ';
    else
      out += ch;
  }
  return out + "\"";
}

}  // namespace

std::string FormatValue(double value) {
  if (!std::isfinite(value)) return "";
  return common::FormatG(value, 10);
}

void Row::Set(const std::string& column, const std::string& value) {
  if (!KnownColumn(column)) {
    throw std::invalid_argument("bench::Row: unknown column \"" + column + "\"");
  }
  values_[column] = value;
}

void Row::Set(const std::string& column, double value) { Set(column, FormatValue(value)); }
void Row::Set(const std::string& column, int value) { Set(column, std::to_string(value)); }
void Row::Set(const std::string& column, long long value) { Set(column, std::to_string(value)); }

std::string Row::Get(const std::string& column) const {
  const auto it = values_.find(column);
  return it == values_.end() ? std::string() : it->second;
}

double Row::Num(const std::string& column) const {
  const std::string v = Get(column);
  if (v.empty()) return std::numeric_limits<double>::quiet_NaN();
  char* end = nullptr;
  const double d = std::strtod(v.c_str(), &end);
  if (end == v.c_str() || *end != '\0') return std::numeric_limits<double>::quiet_NaN();
  return d;
}

void WriteResultsCsv(const std::string& path, const std::vector<Row>& rows) {
  std::ofstream out(path);
  if (!out) throw std::runtime_error("cannot write " + path);
  const auto& cols = ResultColumns();
  for (size_t i = 0; i < cols.size(); ++i) out << (i ? "," : "") << cols[i];
  out << "\n";
  for (const Row& r : rows) {
    for (size_t i = 0; i < cols.size(); ++i) out << (i ? "," : "") << Quote(r.Get(cols[i]));
    out << "\n";
  }
  if (!out) throw std::runtime_error("error writing " + path);
}

std::vector<std::string> SplitCsvLine(const std::string& line) {
  std::vector<std::string> fields;
  std::string cur;
  bool quoted = false;
  for (size_t i = 0; i < line.size(); ++i) {
    const char ch = line[i];
    if (quoted) {
      if (ch == '"') {
        if (i + 1 < line.size() && line[i + 1] == '"') {
          cur += '"';
          ++i;
        } else {
          quoted = false;
        }
      } else {
        cur += ch;
      }
    } else if (ch == '"') {
      quoted = true;
    } else if (ch == ',') {
      fields.push_back(cur);
      cur.clear();
    } else if (ch != '\r') {
      cur += ch;
    }
  }
  if (quoted) throw std::runtime_error("unterminated quote in CSV line: " + line);
  fields.push_back(cur);
  return fields;
}

std::vector<Row> ReadResultsCsv(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot read " + path);
  std::string line;
  if (!std::getline(in, line)) throw std::runtime_error(path + ": empty file");
  const std::vector<std::string> header = SplitCsvLine(line);
  for (const std::string& h : header) {
    if (!KnownColumn(h)) throw std::runtime_error(path + ": unknown column \"" + h + "\"");
  }
  std::vector<Row> rows;
  int line_no = 1;
  while (std::getline(in, line)) {
    ++line_no;
    if (line.empty()) continue;
    const std::vector<std::string> f = SplitCsvLine(line);
    if (f.size() != header.size()) {
      throw std::runtime_error(path + ":" + std::to_string(line_no) + ": " +
                               std::to_string(f.size()) + " fields, header has " +
                               std::to_string(header.size()));
    }
    Row r;
    for (size_t i = 0; i < f.size(); ++i) {
      if (!f[i].empty()) r.Set(header[i], f[i]);
    }
    rows.push_back(std::move(r));
  }
  return rows;
}

}  // namespace thrustsched::bench
