#include "app/solution_import.h"

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <unordered_map>

#include "app/json_reader.h"

namespace thrustsched::app {
namespace {

bool ParseDouble(const std::string& s, double* v) {
  if (s.empty()) return false;
  char* end = nullptr;
  *v = std::strtod(s.c_str(), &end);
  return end == s.c_str() + s.size();
}

std::vector<std::string> Tokens(const std::string& line) {
  std::istringstream is(line);
  std::vector<std::string> out;
  std::string t;
  while (is >> t) out.push_back(t);
  return out;
}

std::string Where(const std::string& path, int line) { return path + ":" + std::to_string(line); }

// A count or an index read as a number: an integer in [min, max] (NaN fails
// every comparison, so it is rejected too), so that the cast is defined and
// the count cannot size a vector beyond any model.
bool IsIntegerIn(double v, double min, double max) {
  return v >= min && v <= max && v == std::floor(v);
}

ImportedSolution ReadCbc(const std::string& path, std::istream& in) {
  ImportedSolution sol;
  std::string line;
  int number = 0;
  long previous_index = -1;
  while (std::getline(in, line)) {
    ++number;
    if (number == 1) {
      // e.g. "Optimal - objective value 0.75000000", "Stopped on time - objective value 3.2",
      // "Infeasible - objective value 0.0", "Stopped on time (no integer solution - ...)".
      const size_t dash = line.find(" - ");
      sol.status = line.substr(0, dash == std::string::npos ? line.size() : dash);
      const size_t ov = line.find("objective value");
      double obj = 0.0;
      if (ov != std::string::npos) {
        std::vector<std::string> tok = Tokens(line.substr(ov + 15));
        if (!tok.empty() && ParseDouble(tok[0], &obj)) sol.objective = obj;
      }
      const bool infeasible = line.find("nfeasible") != std::string::npos ||
                              line.find("no integer solution") != std::string::npos ||
                              line.find("Unbounded") != std::string::npos;
      sol.has_solution = !infeasible && ov != std::string::npos;
      continue;
    }
    std::vector<std::string> tok = Tokens(line);
    if (tok.empty()) continue;
    if (tok[0] == "**") tok.erase(tok.begin());  // CBC marks values outside bounds with **
    double idx = 0.0, value = 0.0;
    if (tok.size() < 3 || !ParseDouble(tok[0], &idx) || !ParseDouble(tok[2], &value)) {
      throw ScenarioError(Where(path, number) +
                          ": expected \"index name value [reduced cost]\", got \"" + line + "\"");
    }
    if (!IsIntegerIn(idx, 0.0, kMaxSolutionColumns)) {
      throw ScenarioError(Where(path, number) + ": index " + tok[0] + " is not an integer in [0, " +
                          std::to_string(kMaxSolutionColumns) + "]: \"" + line + "\"");
    }
    // With "printingOptions all" CBC lists rows first, then columns, each
    // numbered from 0: a restart of the numbering means the rows are over.
    if (static_cast<long>(idx) <= previous_index) sol.values.clear();
    previous_index = static_cast<long>(idx);
    sol.values[tok[1]] = value;
  }
  if (number == 0) throw ScenarioError(path + ": empty solution file");
  return sol;
}

ImportedSolution ReadGlpsol(const std::string& path, std::istream& in) {
  ImportedSolution sol;
  std::string line;
  int number = 0;
  bool in_columns = false;
  std::string pending_name;  // a long name printed alone on its line
  while (std::getline(in, line)) {
    ++number;
    if (line.rfind("Status:", 0) == 0) {
      sol.status = line.substr(7);
      sol.status.erase(0, sol.status.find_first_not_of(' '));
      sol.has_solution = sol.status == "INTEGER OPTIMAL" || sol.status == "INTEGER NON-OPTIMAL" ||
                         sol.status == "OPTIMAL" || sol.status == "FEASIBLE";
      continue;
    }
    if (line.rfind("Objective:", 0) == 0) {
      const size_t eq = line.find('=');
      double v = 0.0;
      if (eq != std::string::npos) {
        std::vector<std::string> tok = Tokens(line.substr(eq + 1));
        if (!tok.empty() && ParseDouble(tok[0], &v)) sol.objective = v;
      }
      continue;
    }
    if (line.find("Column name") != std::string::npos) {
      in_columns = true;
      continue;
    }
    if (!in_columns) continue;
    if (line.rfind("------", 0) == 0) continue;
    std::vector<std::string> tok = Tokens(line);
    if (tok.empty()) {  // a blank line ends the column section
      in_columns = false;
      continue;
    }
    size_t k = 0;
    std::string name;
    double idx = 0.0;
    if (!pending_name.empty()) {
      name = pending_name;
      pending_name.clear();
    } else {
      if (!ParseDouble(tok[0], &idx) || tok.size() < 2) {
        throw ScenarioError(Where(path, number) + ": unexpected line in the column section: \"" +
                            line + "\"");
      }
      name = tok[1];
      k = 2;
      if (tok.size() == 2) {  // name too long: the numbers follow on the next line
        pending_name = name;
        continue;
      }
    }
    if (k < tok.size() && tok[k] == "*") ++k;  // integer column marker (MIP report)
    // LP reports have a status column (basic, at lower/upper bound, free, fixed).
    if (k < tok.size() &&
        (tok[k] == "B" || tok[k] == "NL" || tok[k] == "NU" || tok[k] == "NF" || tok[k] == "NS")) {
      ++k;
    }
    double value = 0.0;
    if (k >= tok.size() || !ParseDouble(tok[k], &value)) {
      throw ScenarioError(Where(path, number) + ": no activity value for column " + name + ": \"" +
                          line + "\"");
    }
    sol.values[name] = value;
  }
  if (sol.status.empty())
    throw ScenarioError(path + ": no \"Status:\" line (not a glpsol -o report?)");
  return sol;
}

// GLPK raw format (glpsol -w): "s bas|ipt|mip rows cols status... obj" then
// "i ..." row lines and "j col ..." column lines (LP: j col stat prim dual;
// interior: j col prim dual; MIP: j col value).
ImportedSolution ReadGlpkRaw(const std::string& path, std::istream& in) {
  ImportedSolution sol;
  std::string line, kind;
  int number = 0;
  long cols = -1;
  while (std::getline(in, line)) {
    ++number;
    std::vector<std::string> tok = Tokens(line);
    if (tok.empty() || tok[0] == "c" || tok[0] == "i" || tok[0] == "e") continue;
    if (tok[0] == "s") {
      double c = 0.0, obj = 0.0;
      if (tok.size() < 6 || !ParseDouble(tok[3], &c) || !ParseDouble(tok.back(), &obj)) {
        throw ScenarioError(Where(path, number) + ": bad solution line \"" + line + "\"");
      }
      if (!IsIntegerIn(c, 0.0, kMaxSolutionColumns)) {
        throw ScenarioError(Where(path, number) + ": column count " + tok[3] +
                            " is not an integer in [0, " + std::to_string(kMaxSolutionColumns) +
                            "]: \"" + line + "\"");
      }
      kind = tok[1];
      cols = static_cast<long>(c);
      sol.objective = obj;
      const std::string& st = tok[4];  // primal status (bas), or the status (ipt, mip)
      sol.status = kind + " " + st;
      sol.has_solution = kind == "mip" ? (st == "o" || st == "f") : (st == "f" || st == "o");
      if (!sol.has_solution && (st == "n" || st == "i")) sol.status += " (infeasible)";
      sol.values_by_index.assign(cols, 0.0);
      continue;
    }
    if (tok[0] == "j") {
      if (cols < 0)
        throw ScenarioError(Where(path, number) + ": column line before the \"s\" line");
      double idx = 0.0, v = 0.0;
      const size_t at = kind == "bas" ? 3 : 2;
      if (tok.size() <= at || !ParseDouble(tok[1], &idx) || !ParseDouble(tok[at], &v) ||
          !IsIntegerIn(idx, 1.0, static_cast<double>(cols))) {
        throw ScenarioError(Where(path, number) + ": bad column line \"" + line + "\"");
      }
      sol.values_by_index[static_cast<size_t>(idx) - 1] = v;
      continue;
    }
    throw ScenarioError(Where(path, number) + ": unexpected line \"" + line +
                        "\" (not a glpsol -w raw solution?)");
  }
  if (cols < 0) throw ScenarioError(path + ": no \"s\" line (not a glpsol -w raw solution?)");
  return sol;
}

ImportedSolution ReadSolution(const std::string& path, std::istream& in, SolutionFormat format) {
  switch (format) {
    case SolutionFormat::kCbc:
      return ReadCbc(path, in);
    case SolutionFormat::kGlpsol:
      return ReadGlpsol(path, in);
    case SolutionFormat::kGlpkRaw:
      return ReadGlpkRaw(path, in);
  }
  throw ScenarioError(path + ": unknown solution format");
}

}  // namespace

SolutionFormat ParseSolutionFormat(std::string_view name) {
  if (name == "cbc") return SolutionFormat::kCbc;
  if (name == "glpsol") return SolutionFormat::kGlpsol;
  if (name == "glpsol-raw") return SolutionFormat::kGlpkRaw;
  throw ScenarioError("--format: unknown solution format \"" + std::string(name) +
                      "\" (expected cbc, glpsol or glpsol-raw)");
}

ImportedSolution ReadSolutionFile(const std::string& path, SolutionFormat format) {
  std::ifstream in(path);
  if (!in) throw ScenarioError(path + ": cannot open the solution file");
  return ReadSolution(path, in, format);
}

ImportedSolution ParseSolutionText(std::string_view text, SolutionFormat format,
                                   const std::string& source) {
  std::istringstream in{std::string(text)};
  return ReadSolution(source, in, format);
}

Eigen::VectorXd ToColumnVector(const ImportedSolution& sol,
                               const std::vector<std::string>& column_names) {
  std::unordered_map<std::string, int> index;
  for (size_t i = 0; i < column_names.size(); ++i) index[column_names[i]] = static_cast<int>(i);
  Eigen::VectorXd x = Eigen::VectorXd::Zero(static_cast<int>(column_names.size()));
  if (!sol.values_by_index.empty()) {
    if (sol.values_by_index.size() != column_names.size()) {
      throw ScenarioError("solution has " + std::to_string(sol.values_by_index.size()) +
                          " columns, the scenario's model has " +
                          std::to_string(column_names.size()) +
                          " (was the model exported from this scenario with the same options?)");
    }
    for (size_t i = 0; i < column_names.size(); ++i) {
      if (!std::isfinite(sol.values_by_index[i])) {
        throw ScenarioError("solution value of column \"" + column_names[i] + "\" is not finite");
      }
      x[static_cast<int>(i)] = sol.values_by_index[i];
    }
    return x;
  }
  for (const auto& [name, value] : sol.values) {
    // "~<row>" columns are the LP writer's slacks of ranged and free rows
    // (milp/model_io.h): not part of the model, and '~' never starts one of
    // its sanitised names.
    if (!name.empty() && name[0] == '~') continue;
    auto it = index.find(name);
    if (it == index.end()) {
      throw ScenarioError("solution names column \"" + name +
                          "\", which the scenario's model does not have (was the model exported "
                          "from this scenario with the same options?)");
    }
    if (!std::isfinite(value)) {
      throw ScenarioError("solution value of column \"" + name + "\" is not finite");
    }
    x[it->second] = value;
  }
  return x;
}

}  // namespace thrustsched::app
