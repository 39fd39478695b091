// Result rows of thrustsched-bench: one row per measured configuration (or
// per scheme and step for the accuracy study), written to results.csv and
// read back to produce report.md, so the report can be regenerated from the
// CSV alone (`thrustsched-bench --report-only DIR`).
//
//   bench::Row r;
//   r.Set("scenario", "hcw_table41_1d");
//   r.Set("objective", 0.0164);
//   bench::WriteResultsCsv("out/results.csv", {r});
//   std::vector<bench::Row> back = bench::ReadResultsCsv("out/results.csv");
//   double v = back[0].Num("objective");          // NaN when empty
//
// Values are kept as text: numbers are written with up to 10 significant
// digits, missing values are empty cells. Column order is ResultColumns();
// the CSV quoting follows RFC 4180 (fields with ',' '"' or newlines quoted).
#ifndef THRUSTSCHED_BENCHMARKS_BENCH_RESULTS_H_
#define THRUSTSCHED_BENCHMARKS_BENCH_RESULTS_H_

#include <map>
#include <string>
#include <vector>

namespace thrustsched::bench {

/// Every column of results.csv, in order. The contract columns (fixed names
/// scripts rely on) are a subset (ContractColumns()).
const std::vector<std::string>& ResultColumns();
/// The contract columns: their names and order never change.
const std::vector<std::string>& ContractColumns();

class Row {
 public:
  /// @throws std::invalid_argument if `column` is not in ResultColumns().
  void Set(const std::string& column, const std::string& value);
  void Set(const std::string& column, const char* value) { Set(column, std::string(value)); }
  /// Non-finite numbers are stored as empty cells.
  void Set(const std::string& column, double value);
  void Set(const std::string& column, int value);
  void Set(const std::string& column, long long value);
  void Set(const std::string& column, bool value) { Set(column, value ? "1" : "0"); }

  /// "" when unset.
  std::string Get(const std::string& column) const;
  /// NaN when unset or not a number.
  double Num(const std::string& column) const;
  bool Has(const std::string& column) const { return !Get(column).empty(); }
  const std::map<std::string, std::string>& values() const { return values_; }

 private:
  std::map<std::string, std::string> values_;
};

/// Number formatting used in the CSV (%.10g; "" for NaN/inf).
std::string FormatValue(double value);

/// @throws std::runtime_error naming the path if it cannot be written.
void WriteResultsCsv(const std::string& path, const std::vector<Row>& rows);
/// Reads a file written by WriteResultsCsv (unknown columns are an error).
/// @throws std::runtime_error naming the path and line on failure.
std::vector<Row> ReadResultsCsv(const std::string& path);

/// One CSV line split into fields (RFC 4180 quoting). @throws std::runtime_error
/// on an unterminated quote.
std::vector<std::string> SplitCsvLine(const std::string& line);

}  // namespace thrustsched::bench

#endif  // THRUSTSCHED_BENCHMARKS_BENCH_RESULTS_H_
