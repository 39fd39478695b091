#include "benchmarks/bench/report_format.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "benchmarks/bench/report.h"
#include "common/format.h"

namespace thrustsched::bench {

using common::FormatG;

namespace {
constexpr double kInf = std::numeric_limits<double>::infinity();
}  // namespace

std::string G(double v, int sig) {
  if (!std::isfinite(v)) return "-";
  return FormatG(v, sig);
}

std::string Sec(double v) {
  if (std::isnan(v)) return "-";
  if (std::isinf(v)) return "not reached";
  char buf[64];
  if (v < 0.01)
    std::snprintf(buf, sizeof(buf), "%.4f", v);
  else if (v < 1)
    std::snprintf(buf, sizeof(buf), "%.3g", v);
  else if (v < 10)
    std::snprintf(buf, sizeof(buf), "%.2f", v);
  else
    std::snprintf(buf, sizeof(buf), "%.1f", v);
  return buf;
}

std::string Fixed1(double v) {
  char buf[64];
  std::snprintf(buf, sizeof(buf), "%.1f", v);
  return buf;
}

std::string Pct(double v) {
  if (!std::isfinite(v)) return "-";
  char buf[64];
  std::snprintf(buf, sizeof(buf), "%.2f %%", 100.0 * v);
  return buf;
}

std::string Sci(double v) {
  if (std::isnan(v)) return "-";
  if (v == 0.0) return "0";
  char buf[64];
  std::snprintf(buf, sizeof(buf), "%.2e", v);
  return buf;
}

size_t CharCount(const std::string& s) {
  size_t n = 0;
  for (unsigned char c : s) n += (c & 0xC0) != 0x80 ? 1 : 0;  // not a continuation byte
  return n;
}

namespace {

// A cell as printed: '|' escaped (it would end the cell), "-" when empty.
std::string Cell(const std::string& c) {
  std::string e;
  for (char ch : c) e += ch == '|' ? std::string("\\|") : std::string(1, ch);
  return e.empty() ? "-" : e;
}

}  // namespace

std::string MdTable::Str() const {
  // Every line of the table as cells: header, then the rows.
  std::vector<std::vector<std::string>> lines;
  lines.push_back(header_);
  for (const auto& r : rows_) lines.push_back(r);
  for (auto& l : lines) {
    for (std::string& c : l) c = Cell(c);
  }
  // Greedy split into parts of consecutive columns, each after the key columns:
  // a column joins the current part unless some line would grow too long.
  const size_t n = header_.size(), keys = std::min(key_columns_, n);
  std::vector<std::vector<size_t>> parts;
  std::vector<size_t> part;
  std::vector<size_t> width(lines.size(), 1);  // "|"
  auto reset = [&] {
    part.clear();
    std::fill(width.begin(), width.end(), 1);
    for (size_t c = 0; c < keys; ++c) {
      part.push_back(c);
      for (size_t i = 0; i < lines.size(); ++i) width[i] += CharCount(lines[i][c]) + 3;
    }
  };
  reset();
  for (size_t c = keys; c < n; ++c) {
    bool fits = true;
    for (size_t i = 0; i < lines.size(); ++i) {
      fits = fits && width[i] + CharCount(lines[i][c]) + 3 <= kReportMaxLineChars;
    }
    if (!fits && part.size() > keys) {
      parts.push_back(part);
      reset();
    }
    part.push_back(c);
    for (size_t i = 0; i < lines.size(); ++i) width[i] += CharCount(lines[i][c]) + 3;
  }
  parts.push_back(part);
  std::ostringstream os;
  for (size_t p = 0; p < parts.size(); ++p) {
    if (p > 0) os << "\n";
    for (size_t i = 0; i < lines.size(); ++i) {
      os << "|";
      for (size_t c : parts[p]) os << " " << lines[i][c] << " |";
      os << "\n";
      if (i == 0) {
        os << "|";
        for (size_t k = 0; k < parts[p].size(); ++k) os << "---|";
        os << "\n";
      }
    }
  }
  return os.str();
}

namespace {

// True if a line starting with `word` would open a Markdown block (a list
// item, a heading, a quote, a table row, a fence, a rule) instead of
// continuing the paragraph.
bool OpensBlock(const std::string& word) {
  if (word.empty()) return true;  // keeps double spaces where they were
  if (word == "-" || word == "+" || word == "*" || word == "=" || word == "---") return true;
  const char c = word[0];
  if (c == '#' || c == '>' || c == '|' || word.rfind("```", 0) == 0) return true;
  size_t digits = 0;
  while (digits < word.size() && std::isdigit(static_cast<unsigned char>(word[digits]))) ++digits;
  return digits > 0 && digits + 1 == word.size() && (word.back() == '.' || word.back() == ')');
}

// The indentation that continues `line` (a list item's text column).
std::string ContinuationIndent(const std::string& line) {
  size_t i = 0;
  while (i < line.size() && line[i] == ' ') ++i;
  size_t j = i;
  if (j < line.size() && (line[j] == '-' || line[j] == '*' || line[j] == '+')) {
    ++j;
  } else {
    while (j < line.size() && std::isdigit(static_cast<unsigned char>(line[j]))) ++j;
    if (j == i || j >= line.size() || line[j] != '.') return std::string(i, ' ');
    ++j;
  }
  if (j >= line.size() || line[j] != ' ') return std::string(i, ' ');
  return std::string(j + 1, ' ');
}

void WrapLine(const std::string& line, size_t width, std::string* out) {
  const std::string indent = ContinuationIndent(line);
  // The first piece (indentation and list marker) never starts a break.
  size_t start = line.find(
      ' ', line.find_first_not_of(' ') == std::string::npos ? 0 : line.find_first_not_of(' '));
  if (start == std::string::npos) {
    *out += line + "\n";
    return;
  }
  std::string cur = line.substr(0, start);
  size_t pos = start + 1;
  while (pos <= line.size()) {
    size_t end = line.find(' ', pos);
    if (end == std::string::npos) end = line.size();
    const std::string word = line.substr(pos, end - pos);
    if (CharCount(cur) + 1 + CharCount(word) > width && CharCount(cur) > indent.size() &&
        !OpensBlock(word)) {
      *out += cur + "\n";
      cur = indent + word;
    } else {
      cur += " " + word;
    }
    pos = end + 1;
  }
  *out += cur + "\n";
}

}  // namespace

std::string WrapMarkdown(const std::string& md, size_t width) {
  std::string out;
  bool fenced = false;
  std::istringstream in(md);
  std::string line;
  while (std::getline(in, line)) {
    const size_t first = line.find_first_not_of(' ');
    const bool fence = first != std::string::npos && line.compare(first, 3, "```") == 0;
    if (fence) fenced = !fenced;
    const bool prose =
        !fenced && !fence && first != std::string::npos && line[first] != '|' && line[first] != '#';
    if (prose && CharCount(line) > width) {
      WrapLine(line, width, &out);
    } else {
      out += line + "\n";
    }
  }
  if (!md.empty() && md.back() != '\n' && !out.empty()) out.pop_back();
  return out;
}

// Median treating NaN as "not reached" (+inf) when `missing_is_inf`.
double MedianOf(std::vector<double> v, bool missing_is_inf) {
  if (missing_is_inf) {
    for (double& x : v) {
      if (std::isnan(x)) x = kInf;
    }
  }
  return Median(v);
}

std::string Verdict(double value, double limit) {
  if (std::isnan(value)) return "not measured";
  if (std::isinf(value)) return "**missed**: not reached within the time limit";
  if (value < limit) return "met (" + G(100.0 * value / limit, 3) + " % of the limit)";
  return "**missed** by " + Sec(value - limit) + " s (" + G(value / limit, 3) + "x the limit)";
}

}  // namespace thrustsched::bench
