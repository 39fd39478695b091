#include "milp/model_io.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <initializer_list>
#include <sstream>
#include <stdexcept>
#include <string_view>
#include <unordered_set>

#include "common/format.h"

namespace thrustsched::milp {

using common::FormatG;

namespace {

constexpr int kMaxNameLength = 96;  // CoinLpIO accepts 100; aux LP columns add "~"
constexpr char kObjectiveRow[] = "OBJ";
constexpr char kOffsetColumnFree[] = "OBJ_CONST";
constexpr char kOffsetColumnFixed[] = "OBJCONST";  // fixed MPS names have <= 8 chars

// ------------------------------------------------------------------ names

bool IsLpKeyword(const std::string& s) {
  // Words the CPLEX LP readers of CBC and GLPK treat specially.
  static const char* const kKeywords[] = {
      "st",       "s.t.",     "st.",     "subject", "such",     "to",   "bound",  "bounds",
      "general",  "generals", "gen",     "integer", "integers", "int",  "binary", "binaries",
      "bin",      "semi",     "semis",   "sos",     "end",      "free", "inf",    "infinity",
      "minimize", "maximize", "minimum", "maximum", "min",      "max"};
  std::string lower(s);
  for (char& c : lower) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  for (const char* k : kKeywords) {
    if (lower == k) return true;
  }
  return false;
}

// Maps a name to one that free MPS, fixed MPS (if short) and the CPLEX LP
// readers of CBC (CoinLpIO) and GLPK all accept: letters, digits, '_', '.',
// '(' and ')' only ('[' -> '(', ']' -> ')', anything else -> '_'); not starting
// with a digit, '.', or an 'e'/'E' that could read as an exponent; not an LP
// or MPS keyword; at most kMaxNameLength characters.
std::string Sanitize(const std::string& raw) {
  std::string s;
  s.reserve(raw.size() + 1);
  for (char c : raw) {
    const unsigned char u = static_cast<unsigned char>(c);
    if (std::isalnum(u) && u < 128) {
      s += c;
    } else if (c == '_' || c == '.' || c == '(' || c == ')') {
      s += c;
    } else if (c == '[') {
      s += '(';
    } else if (c == ']') {
      s += ')';
    } else {
      s += '_';
    }
  }
  const bool digit_or_dot = std::isdigit(static_cast<unsigned char>(s[0])) || s[0] == '.';
  const bool exponent_like = (s[0] == 'e' || s[0] == 'E') &&
                             (s.size() == 1 || std::isdigit(static_cast<unsigned char>(s[1])) ||
                              s[1] == 'e' || s[1] == 'E' || s[1] == '.');
  if (digit_or_dot || exponent_like || IsLpKeyword(s)) s.insert(s.begin(), '_');
  if (static_cast<int>(s.size()) > kMaxNameLength) s.resize(kMaxNameLength);
  return s;
}

std::string Numbered(char prefix, size_t index) {
  char buf[32];
  std::snprintf(buf, sizeof(buf), "%c%06zu", prefix, index + 1);
  return buf;
}

std::vector<std::string> ExportNames(const std::vector<std::string>& raw, size_t count, char prefix,
                                     bool obfuscate, std::initializer_list<const char*> reserved) {
  std::vector<std::string> out;
  out.reserve(count);
  if (obfuscate || raw.size() != count) {
    for (size_t i = 0; i < count; ++i) out.push_back(Numbered(prefix, i));
    return out;
  }
  std::unordered_set<std::string> used;
  used.reserve(count + reserved.size());
  for (const char* r : reserved) used.insert(r);
  for (size_t i = 0; i < count; ++i) {
    std::string name = raw[i].empty() ? Numbered(prefix, i) : Sanitize(raw[i]);
    if (used.count(name) != 0) {
      // Restore uniqueness with the smallest free suffix "_k".
      for (long long k = 1;; ++k) {
        const std::string suffix = "_" + std::to_string(k);
        std::string base = name;
        if (base.size() + suffix.size() > static_cast<size_t>(kMaxNameLength)) {
          base.resize(static_cast<size_t>(kMaxNameLength) - suffix.size());
        }
        std::string candidate = base + suffix;
        if (used.count(candidate) == 0) {
          name = std::move(candidate);
          break;
        }
      }
    }
    used.insert(name);
    out.push_back(std::move(name));
  }
  return out;
}

// ---------------------------------------------------------------- numbers

std::string Fmt17(double v) {
  if (v == 0.0) return "0";  // also for -0
  return FormatG(v, 17);
}

// Fixed MPS number fields hold 12 characters: full precision when it fits,
// else the shortest exact representation, else as many digits as fit.
std::string FmtFixed(double v) {
  std::string s = Fmt17(v);
  if (s.size() <= 12) return s;
  char buf[40];
  const auto res = std::to_chars(buf, buf + sizeof(buf), v);
  if (res.ptr - buf <= 12) return std::string(buf, res.ptr);
  for (int precision = 11; precision >= 1; --precision) {
    const int n = std::snprintf(buf, sizeof(buf), "%.*g", precision, v);
    if (n <= 12) return std::string(buf, static_cast<size_t>(n));
  }
  return s;  // unreachable for finite doubles
}

// ----------------------------------------------------------- buffered out

class Out {
 public:
  explicit Out(std::ostream& os) : os_(os) { buf_.reserve(1 << 16); }
  ~Out() { Flush(); }
  Out& operator<<(std::string_view s) {
    buf_.append(s.data(), s.size());
    if (buf_.size() >= (1 << 16)) Flush();
    return *this;
  }
  Out& operator<<(char c) {
    buf_ += c;
    return *this;
  }
  void Flush() {
    if (!buf_.empty()) {
      os_.write(buf_.data(), static_cast<std::streamsize>(buf_.size()));
      buf_.clear();
    }
  }

 private:
  std::ostream& os_;
  std::string buf_;
};

void CheckProblem(const LpData& problem, const char* what) {
  std::string error;
  if (!problem.IsValid(&error)) {
    throw std::invalid_argument(std::string(what) + ": invalid problem: " + error);
  }
  // Integer bounds are written rounded inward (below); a column whose bounds
  // hold no integer would come out as LO > UP, which readers reject as a bad
  // file rather than an infeasible model.
  for (int j = 0; j < problem.num_cols(); ++j) {
    if (problem.col_type[static_cast<size_t>(j)] == VarType::kContinuous) continue;
    const double lo = problem.col_lower[j], up = problem.col_upper[j];
    if (IntegerLowerBound(lo) > IntegerUpperBound(up)) {
      const std::string name = static_cast<size_t>(j) < problem.col_names.size()
                                   ? problem.col_names[static_cast<size_t>(j)]
                                   : "#" + std::to_string(j);
      throw std::invalid_argument(std::string(what) + ": integer column '" + name +
                                  "' has no integer value within its bounds [" + Fmt17(lo) + ", " +
                                  Fmt17(up) + "] (the model is infeasible as stated)");
    }
  }
}

// Which of the two MPS encodings of lower <= row <= upper (finite, lower <
// upper) reproduces both bounds exactly in a reader: 'G' (rhs = lower,
// upper = lower + |R|) or 'L' (rhs = upper, lower = upper - |R|).
struct RangeEncoding {
  char type;
  double rhs;
  double range;
};
RangeEncoding EncodeRange(double lower, double upper) {
  const double r0 = upper - lower;
  const double candidates[] = {r0, std::nextafter(r0, 0.0), std::nextafter(r0, kInfinity)};
  for (double r : candidates) {
    if (lower + r == upper) return {'G', lower, r};
    if (upper - r == lower) return {'L', upper, r};
  }
  return {'G', lower, r0};
}

// ------------------------------------------------------------ MPS layout

class MpsLine {
 public:
  explicit MpsLine(bool fixed) : fixed_(fixed) {}
  // Fields 1..6 start at columns 2, 5, 15, 25, 40, 50 (fixed MPS).
  std::string Make(std::string_view f1, std::string_view f2, std::string_view f3 = {},
                   std::string_view f4 = {}) const {
    std::string line;
    if (fixed_) {
      line.assign(1, ' ');
      line += f1;
      Pad(&line, 4);
      line += f2;
      if (!f3.empty()) {
        Pad(&line, 14);
        line += f3;
      }
      if (!f4.empty()) {
        Pad(&line, 24);
        line += f4;
      }
    } else {
      line.assign(1, ' ');
      line += f1;
      Pad(&line, 4);
      line += f2;
      if (!f3.empty()) {
        line += "  ";
        line += f3;
      }
      if (!f4.empty()) {
        line += "  ";
        line += f4;
      }
    }
    line += '\n';
    return line;
  }
  std::string Number(double v) const { return fixed_ ? FmtFixed(v) : Fmt17(v); }

 private:
  static void Pad(std::string* s, size_t column) {
    if (s->size() < column) {
      s->append(column - s->size(), ' ');
    } else if (s->back() != ' ') {
      *s += ' ';
    }
  }
  bool fixed_;
};

}  // namespace

std::vector<std::string> ExportedColumnNames(const LpData& problem, bool obfuscate) {
  return ExportNames(problem.col_names, static_cast<size_t>(problem.num_cols()), 'C', obfuscate,
                     {kOffsetColumnFree, kOffsetColumnFixed});
}

std::vector<std::string> ExportedRowNames(const LpData& problem, bool obfuscate) {
  return ExportNames(problem.row_names, static_cast<size_t>(problem.num_rows()), 'R', obfuscate,
                     {kObjectiveRow});
}

void WriteMps(std::ostream& os, const LpData& problem, const MpsOptions& options) {
  CheckProblem(problem, "WriteMps");
  const std::vector<std::string> cols = ExportedColumnNames(problem, options.obfuscate_names);
  const std::vector<std::string> rows = ExportedRowNames(problem, options.obfuscate_names);
  const bool fixed = !options.free_format;
  const std::string offset_col = fixed ? kOffsetColumnFixed : kOffsetColumnFree;
  std::string problem_name = problem.name.empty() ? std::string() : Sanitize(problem.name);
  if (fixed) {
    auto check = [](const std::vector<std::string>& names, const char* what) {
      for (const std::string& n : names) {
        if (n.size() > 8) {
          throw std::invalid_argument(std::string("WriteMps: fixed MPS needs names of at most 8 "
                                                  "characters, but ") +
                                      what + " name '" + n +
                                      "' is longer (use free MPS or obfuscate_names)");
        }
      }
    };
    check(cols, "column");
    check(rows, "row");
    if (problem_name.size() > 8) problem_name.resize(8);
  }
  const int n = problem.num_cols();
  const int m = problem.num_rows();
  const double sign = problem.sense == ObjectiveSense::kMaximize ? -1.0 : 1.0;
  const double offset = sign * problem.objective_offset;
  const MpsLine L(fixed);
  Out out(os);

  out << "* thrustsched " << (fixed ? "fixed" : "free") << " MPS export";
  if (!problem.name.empty()) out << " of '" << problem_name << "'";
  out << '\n';
  if (problem.sense == ObjectiveSense::kMaximize) {
    out << "* The model MAXIMISES; written as the minimisation of the negated objective\n"
        << "* (negate the optimal value read from this file).\n";
  } else {
    out << "* Objective: minimise.\n";
  }
  if (offset != 0.0) {
    out << "* Objective offset carried by column " << offset_col << " fixed to 1.\n";
  }
  // Free MPS says so on the NAME line (CoinMpsIO otherwise guesses fixed
  // fields and rejects long numbers); the name is then mandatory.
  if (problem_name.empty() && !fixed) problem_name = "unnamed";
  out << "NAME";
  if (!problem_name.empty()) out << "          " << problem_name;
  if (!fixed) out << "  FREE";
  out << '\n';

  // ROWS, remembering each row's encoding.
  std::vector<RangeEncoding> enc(static_cast<size_t>(m));
  out << "ROWS\n" << L.Make("N", kObjectiveRow);
  for (int i = 0; i < m; ++i) {
    const double lo = problem.row_lower[i], up = problem.row_upper[i];
    RangeEncoding e{'N', 0.0, 0.0};
    if (lo == up) {
      e = {'E', lo, 0.0};
    } else if (std::isfinite(lo) && std::isfinite(up)) {
      e = EncodeRange(lo, up);
    } else if (std::isfinite(lo)) {
      e = {'G', lo, 0.0};
    } else if (std::isfinite(up)) {
      e = {'L', up, 0.0};
    }
    enc[static_cast<size_t>(i)] = e;
    out << L.Make(std::string(1, e.type), rows[static_cast<size_t>(i)]);
  }

  // COLUMNS, integers between quoted markers.
  out << "COLUMNS\n";
  bool in_marker = false;
  int marker_count = 0;
  auto marker = [&](const char* what) {
    char name[16];
    std::snprintf(name, sizeof(name), "MARKER%02d", marker_count % 100);
    if (fixed) {
      std::string line = L.Make("", name, "'MARKER'");
      line.pop_back();
      line.append(39 - line.size(), ' ');
      line += what;
      line += '\n';
      out << line;
    } else {
      out << "    " << name << "  'MARKER'  " << what << '\n';
    }
  };
  for (int j = 0; j < n; ++j) {
    const bool integer = problem.col_type[static_cast<size_t>(j)] != VarType::kContinuous;
    if (integer && !in_marker) {
      marker("'INTORG'");
      in_marker = true;
    } else if (!integer && in_marker) {
      marker("'INTEND'");
      ++marker_count;
      in_marker = false;
    }
    const std::string& c = cols[static_cast<size_t>(j)];
    bool wrote = false;
    const double cost = sign * problem.col_cost[j];
    if (cost != 0.0) {
      out << L.Make("", c, kObjectiveRow, L.Number(cost));
      wrote = true;
    }
    for (Eigen::SparseMatrix<double, Eigen::ColMajor, int>::InnerIterator it(problem.a_matrix, j);
         it; ++it) {
      if (it.value() == 0.0) continue;
      out << L.Make("", c, rows[static_cast<size_t>(it.row())], L.Number(it.value()));
      wrote = true;
    }
    // A column must appear in COLUMNS to exist for the reader.
    if (!wrote) out << L.Make("", c, kObjectiveRow, "0");
  }
  if (in_marker) marker("'INTEND'");
  if (offset != 0.0) out << L.Make("", offset_col, kObjectiveRow, L.Number(offset));

  // RHS and RANGES.
  out << "RHS\n";
  for (int i = 0; i < m; ++i) {
    const RangeEncoding& e = enc[static_cast<size_t>(i)];
    if (e.type != 'N' && e.rhs != 0.0) {
      out << L.Make("", "RHS", rows[static_cast<size_t>(i)], L.Number(e.rhs));
    }
  }
  bool any_range = false;
  for (int i = 0; i < m; ++i) {
    const RangeEncoding& e = enc[static_cast<size_t>(i)];
    if (e.range == 0.0) continue;
    if (!any_range) out << "RANGES\n";
    any_range = true;
    out << L.Make("", "RNG", rows[static_cast<size_t>(i)], L.Number(e.range));
  }

  // BOUNDS: explicit LO and UP (or MI/PL) for every integer column.
  out << "BOUNDS\n";
  for (int j = 0; j < n; ++j) {
    const std::string& c = cols[static_cast<size_t>(j)];
    const bool integer = problem.col_type[static_cast<size_t>(j)] != VarType::kContinuous;
    const double lo = integer ? IntegerLowerBound(problem.col_lower[j]) : problem.col_lower[j];
    const double up = integer ? IntegerUpperBound(problem.col_upper[j]) : problem.col_upper[j];
    if (integer) {
      out << (std::isfinite(lo) ? L.Make("LO", "BND", c, L.Number(lo)) : L.Make("MI", "BND", c));
      out << (std::isfinite(up) ? L.Make("UP", "BND", c, L.Number(up)) : L.Make("PL", "BND", c));
      continue;
    }
    if (lo == up) {
      out << L.Make("FX", "BND", c, L.Number(lo));
    } else if (!std::isfinite(lo) && !std::isfinite(up)) {
      out << L.Make("FR", "BND", c);
    } else if (!std::isfinite(lo)) {
      // MI first, so that readers never apply the "UP < 0 with lower 0" rule.
      out << L.Make("MI", "BND", c) << L.Make("UP", "BND", c, L.Number(up));
    } else if (!std::isfinite(up)) {
      if (lo != 0.0) out << L.Make("LO", "BND", c, L.Number(lo));
    } else {
      out << L.Make("LO", "BND", c, L.Number(lo)) << L.Make("UP", "BND", c, L.Number(up));
    }
  }
  if (offset != 0.0) out << L.Make("FX", "BND", offset_col, "1");
  out << "ENDATA\n";
  out.Flush();
}

std::string ToMpsString(const LpData& problem, const MpsOptions& options) {
  std::ostringstream os;
  WriteMps(os, problem, options);
  return os.str();
}

namespace {

template <typename Writer>
void WriteFile(const std::string& path, const char* what, Writer write) {
  std::ofstream file(path, std::ios::binary | std::ios::trunc);
  if (!file) {
    throw std::runtime_error(std::string(what) + ": cannot open '" + path +
                             "' for writing: " + std::strerror(errno));
  }
  write(file);
  file.flush();
  if (!file) {
    throw std::runtime_error(std::string(what) + ": write to '" + path +
                             "' failed: " + std::strerror(errno));
  }
  file.close();
  if (file.fail()) {
    throw std::runtime_error(std::string(what) + ": closing '" + path +
                             "' failed: " + std::strerror(errno));
  }
}

void LpTerm(Out& out, double coefficient, const std::string& name, int* count) {
  if (*count > 0 && *count % 8 == 0) out << "\n   ";
  out << (coefficient < 0.0 ? " - " : " + ") << Fmt17(std::abs(coefficient)) << ' ' << name;
  ++*count;
}

}  // namespace

void WriteMpsFile(const std::string& path, const LpData& problem, const MpsOptions& options) {
  CheckProblem(problem, "WriteMpsFile");
  WriteFile(path, "WriteMpsFile", [&](std::ostream& os) { WriteMps(os, problem, options); });
}

void WriteLp(std::ostream& os, const LpData& problem, const LpFormatOptions& options) {
  CheckProblem(problem, "WriteLp");
  const std::vector<std::string> cols = ExportedColumnNames(problem, options.obfuscate_names);
  const std::vector<std::string> rows = ExportedRowNames(problem, options.obfuscate_names);
  const int n = problem.num_cols();
  const int m = problem.num_rows();
  const double sign = problem.sense == ObjectiveSense::kMaximize ? -1.0 : 1.0;
  const double offset = sign * problem.objective_offset;
  // The LP format needs at least one term per row and in the objective; with
  // no column at all, the offset column serves as the placeholder.
  const bool offset_col = offset != 0.0 || n == 0;
  const std::string placeholder = n > 0 ? cols[0] : std::string(kOffsetColumnFree);
  const Eigen::SparseMatrix<double, Eigen::RowMajor, int> by_row = problem.a_matrix;
  std::vector<char> used(static_cast<size_t>(n), 0);
  for (int j = 0; j < n; ++j) {
    bool any = problem.col_cost[j] != 0.0;
    for (Eigen::SparseMatrix<double, Eigen::ColMajor, int>::InnerIterator it(problem.a_matrix, j);
         it && !any; ++it) {
      any = it.value() != 0.0;
    }
    used[static_cast<size_t>(j)] = any ? 1 : 0;
  }
  Out out(os);
  out << "\\ thrustsched CPLEX LP export";
  if (!problem.name.empty()) out << " of '" << Sanitize(problem.name) << "'";
  out << '\n';
  if (problem.sense == ObjectiveSense::kMaximize) {
    out << "\\ The model MAXIMISES; written as the minimisation of the negated objective\n"
        << "\\ (negate the optimal value read from this file).\n";
  }
  if (offset != 0.0) out << "\\ Objective offset carried by column OBJ_CONST fixed to 1.\n";
  out << "Minimize\n " << kObjectiveRow << ':';
  int count = 0;
  for (int j = 0; j < n; ++j) {
    const double c = sign * problem.col_cost[j];
    // Columns used nowhere else are declared here with a zero cost.
    if (c != 0.0 || !used[static_cast<size_t>(j)])
      LpTerm(out, c, cols[static_cast<size_t>(j)], &count);
  }
  if (offset_col) LpTerm(out, offset, kOffsetColumnFree, &count);
  if (count == 0) LpTerm(out, 0.0, placeholder, &count);
  out << "\nSubject To\n";
  // GLPK rejects an empty "Subject To": a model without rows gets one row
  // that always holds (its name cannot clash: '~' never survives Sanitize).
  if (m == 0) out << " ~no_rows: + 0 " << placeholder << " >= -1\n";
  std::vector<int> aux_rows;  // ranged and free rows get a column "~<row>"
  for (int i = 0; i < m; ++i) {
    const std::string& r = rows[static_cast<size_t>(i)];
    out << ' ' << r << ':';
    count = 0;
    for (Eigen::SparseMatrix<double, Eigen::RowMajor, int>::InnerIterator it(by_row, i); it; ++it) {
      if (it.value() != 0.0) LpTerm(out, it.value(), cols[static_cast<size_t>(it.col())], &count);
    }
    const double lo = problem.row_lower[i], up = problem.row_upper[i];
    const bool ranged = std::isfinite(lo) && std::isfinite(up) && lo < up;
    const bool free_row = !std::isfinite(lo) && !std::isfinite(up);
    if (ranged || free_row) {
      LpTerm(out, -1.0, "~" + r, &count);
      aux_rows.push_back(i);
    } else if (count == 0) {
      LpTerm(out, 0.0, placeholder, &count);
    }
    if (ranged) {
      out << " = " << Fmt17(lo) << '\n';
    } else if (free_row) {
      out << " = 0\n";
    } else if (lo == up) {
      out << " = " << Fmt17(lo) << '\n';
    } else if (std::isfinite(lo)) {
      out << " >= " << Fmt17(lo) << '\n';
    } else {
      out << " <= " << Fmt17(up) << '\n';
    }
  }
  out << "Bounds\n";
  for (int j = 0; j < n; ++j) {
    const std::string& c = cols[static_cast<size_t>(j)];
    const bool integer = problem.col_type[static_cast<size_t>(j)] != VarType::kContinuous;
    const double lo = integer ? IntegerLowerBound(problem.col_lower[j]) : problem.col_lower[j];
    const double up = integer ? IntegerUpperBound(problem.col_upper[j]) : problem.col_upper[j];
    if (lo == up) {
      out << ' ' << c << " = " << Fmt17(lo) << '\n';
    } else if (!std::isfinite(lo) && !std::isfinite(up)) {
      out << ' ' << c << " free\n";
    } else if (!std::isfinite(lo)) {
      out << " -inf <= " << c << " <= " << Fmt17(up) << '\n';
    } else if (!std::isfinite(up)) {
      if (lo != 0.0 || integer) out << ' ' << c << " >= " << Fmt17(lo) << '\n';
    } else {
      out << ' ' << Fmt17(lo) << " <= " << c << " <= " << Fmt17(up) << '\n';
    }
  }
  for (int i : aux_rows) {
    const double lo = problem.row_lower[i], up = problem.row_upper[i];
    const std::string aux = "~" + rows[static_cast<size_t>(i)];
    if (std::isfinite(lo)) {
      out << " 0 <= " << aux << " <= " << Fmt17(up - lo) << '\n';
    } else {
      out << ' ' << aux << " free\n";
    }
  }
  if (offset_col) out << ' ' << kOffsetColumnFree << " = 1\n";
  auto section = [&](const char* title, auto predicate) {
    bool any = false;
    int k = 0;
    for (int j = 0; j < n; ++j) {
      if (!predicate(j)) continue;
      if (!any) out << title << '\n';
      any = true;
      out << ' ' << cols[static_cast<size_t>(j)];
      if (++k % 8 == 0) out << '\n';
    }
    if (any && k % 8 != 0) out << '\n';
  };
  auto pure_binary = [&](int j) {
    return problem.col_type[static_cast<size_t>(j)] == VarType::kBinary &&
           IntegerLowerBound(problem.col_lower[j]) == 0.0 &&
           IntegerUpperBound(problem.col_upper[j]) == 1.0;
  };
  section("Generals", [&](int j) {
    return problem.col_type[static_cast<size_t>(j)] != VarType::kContinuous && !pure_binary(j);
  });
  section("Binaries", pure_binary);
  out << "End\n";
  out.Flush();
}

std::string ToLpString(const LpData& problem, const LpFormatOptions& options) {
  std::ostringstream os;
  WriteLp(os, problem, options);
  return os.str();
}

void WriteLpFile(const std::string& path, const LpData& problem, const LpFormatOptions& options) {
  CheckProblem(problem, "WriteLpFile");
  WriteFile(path, "WriteLpFile", [&](std::ostream& os) { WriteLp(os, problem, options); });
}

}  // namespace thrustsched::milp
