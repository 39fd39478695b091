// Number formatting and small tables shared by the sections of report.md.
//
//   MdTable t({"case", "time (s)"});
//   t.Add({"geo_week_anzel4", Sec(7.46)});
//   md << t.Str();                                  // a Markdown table
//   md << Verdict(7.46, 10.0);                      // "met (74.6 % of the limit)"
#ifndef THRUSTSCHED_BENCHMARKS_BENCH_REPORT_FORMAT_H_
#define THRUSTSCHED_BENCHMARKS_BENCH_REPORT_FORMAT_H_

#include <string>
#include <vector>

namespace thrustsched::bench {

/// `sig` significant digits; "-" when not finite.
std::string G(double v, int sig = 4);
/// Seconds with a precision that suits their size; "-" for NaN, "not reached" for inf.
std::string Sec(double v);
/// One decimal, fixed ("130.0"), as the thesis prints its yearly figures.
std::string Fixed1(double v);
/// A fraction as a percentage with two decimals ("-" when not finite).
std::string Pct(double v);
/// Scientific notation with three digits ("-" for NaN, "0" for 0).
std::string Sci(double v);
/// The median (NaN entries dropped); NaN entries count as +inf ("not
/// reached") when `missing_is_inf`.
double MedianOf(std::vector<double> v, bool missing_is_inf);
/// "met (x % of the limit)" or "**missed** by ..." for a time against its limit.
std::string Verdict(double value, double limit);

/// Characters (UTF-8 code points) of `s`.
size_t CharCount(const std::string& s);

/// A Markdown table; '|' inside a cell is escaped, empty cells print "-".
/// A table whose lines would be longer than kReportMaxLineChars is printed
/// as several tables of consecutive columns, each repeating the first
/// `key_columns` (the row's name), so that no line of report.md is wider
/// than a screen.
class MdTable {
 public:
  explicit MdTable(std::vector<std::string> header, size_t key_columns = 1)
      : header_(std::move(header)), key_columns_(key_columns) {}
  void Add(std::vector<std::string> row) {
    row.resize(header_.size());
    rows_.push_back(std::move(row));
  }
  bool empty() const { return rows_.empty(); }
  std::string Str() const;

 private:
  std::vector<std::string> header_;
  size_t key_columns_;
  std::vector<std::vector<std::string>> rows_;
};

/// Markdown with every prose line longer than `width` characters broken at
/// spaces (list items continue indented under their text); tables, headings
/// and fenced code are left as they are. Never breaks before a word that
/// would start a Markdown block ("-", "1.", "#", "|", ...).
std::string WrapMarkdown(const std::string& md, size_t width);

}  // namespace thrustsched::bench

#endif  // THRUSTSCHED_BENCHMARKS_BENCH_REPORT_FORMAT_H_
