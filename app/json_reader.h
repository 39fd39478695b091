// Strict reading of JSON objects for scenario files: every value is checked
// for its type and range, every error names the full path of the field and
// the offending value, and every key that was not read is rejected.
//
//   nlohmann::json j = ParseJsonText(text, "scenario.json");   // duplicate keys rejected
//   app::JsonObject o(j.at("horizon"), "scenario.horizon");
//   double step = o.Number("step_s", app::Bound::kPositive);     // required
//   double t0 = o.OptionalNumber("start_s", app::Bound::kAny).value_or(0.0);
//   o.Finish();   // throws "scenario.horizon.stpe_s: unknown field (accepted: ...)"
//
// All errors are ScenarioError (a std::invalid_argument): callers map them to
// "bad input" (exit code 2 in the CLI). Callers that add their own sections
// to a scenario file (e.g. a "long_horizon" section for a year simulation)
// parse them with this class to get the same messages.
#ifndef THRUSTSCHED_APP_JSON_READER_H_
#define THRUSTSCHED_APP_JSON_READER_H_

#include <optional>
#include <set>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include <Eigen/Core>
#include <nlohmann/json.hpp>

namespace thrustsched::app {

/// Invalid scenario or input file; the message names the field and the value.
class ScenarioError : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

/// Calls `f` and turns a library std::invalid_argument into a ScenarioError
/// at `path` (a ScenarioError passes through unchanged).
template <typename F>
auto Wrap(const std::string& path, F&& f) -> decltype(f()) {
  try {
    return f();
  } catch (const ScenarioError&) {
    throw;
  } catch (const std::invalid_argument& e) {
    throw ScenarioError(path + ": " + e.what());
  }
}

/// Range a number must satisfy (always finite).
/// The name in `names` closest to `word` (case-insensitive edit distance at
/// most max(2, |word| / 3)), for "did you mean" messages; "" if none is close.
std::string ClosestName(const std::string& word, const std::vector<std::string>& names);

enum class Bound {
  kAny,          // any finite value
  kPositive,     // > 0
  kNonNegative,  // >= 0
};

/// Parses JSON text. @throws ScenarioError naming `what`, the line/column and
/// the parser's reason on malformed JSON, on duplicate object keys (named
/// with their path), and on numbers that overflow a double.
nlohmann::json ParseJsonText(std::string_view text, const std::string& what);

/// Short rendering of a JSON value for error messages (truncated).
std::string DescribeJson(const nlohmann::json& value);
/// "%.17g"-style rendering of a double without trailing noise.
std::string FormatNumber(double value);

class JsonObject {
 public:
  /// @throws ScenarioError if `value` is not a JSON object.
  JsonObject(const nlohmann::json& value, std::string path);

  const std::string& path() const { return path_; }
  /// "<path>.<key>".
  std::string FieldPath(std::string_view key) const;

  /// True if the key is present (and marks it as known).
  bool Has(std::string_view key);
  /// Marks a key as known without reading it (e.g. a section another command owns).
  void Accept(std::string_view key);
  /// Raw value. @throws ScenarioError if missing.
  const nlohmann::json& Raw(std::string_view key);

  /// Finite number within `bound`. @throws ScenarioError if missing, not a
  /// number (booleans and strings are not numbers), not finite or out of bound.
  double Number(std::string_view key, Bound bound = Bound::kAny);
  std::optional<double> OptionalNumber(std::string_view key, Bound bound = Bound::kAny);
  /// Integer-valued number in [min, max].
  int Integer(std::string_view key, int min, int max);
  std::optional<int> OptionalInteger(std::string_view key, int min, int max);
  bool Bool(std::string_view key);
  std::optional<bool> OptionalBool(std::string_view key);
  std::string String(std::string_view key);
  std::optional<std::string> OptionalString(std::string_view key);
  /// String that must be one of `choices`; the message lists them.
  std::string Choice(std::string_view key, const std::vector<std::string>& choices);
  /// Array of finite numbers; `size` < 0 = any non-empty length.
  std::vector<double> NumberArray(std::string_view key, int size, Bound bound = Bound::kAny);
  /// Array of `rows` arrays of `cols` finite numbers (rows < 0: any non-empty
  /// count), row by row.
  Eigen::MatrixXd NumberMatrix(std::string_view key, int rows, int cols, Bound bound = Bound::kAny);
  /// Array of strings (possibly empty), no duplicates.
  std::vector<std::string> StringArray(std::string_view key);
  /// Nested object.
  JsonObject Object(std::string_view key);
  /// Array of objects (possibly empty).
  std::vector<JsonObject> ObjectArray(std::string_view key);

  /// @throws ScenarioError "<path>.<key>: unknown field (accepted: ...)" for
  /// the first key (in file order) that was never asked for.
  void Finish() const;
  /// @throws ScenarioError naming the path if more than one of `keys` is present,
  /// or (if required) none is.
  void ExactlyOneOf(const std::vector<std::string>& keys, bool required);

  /// Error with the field path prefixed: "<path>.<key>: <message>".
  [[noreturn]] void Fail(std::string_view key, const std::string& message) const;

 private:
  const nlohmann::json* Find(std::string_view key);
  const nlohmann::json& Require(std::string_view key);

  const nlohmann::json& value_;
  std::string path_;
  std::set<std::string, std::less<>> known_;
};

/// Checks a JSON number element (in an array) the same way; `path` names it.
double CheckedNumber(const nlohmann::json& value, const std::string& path, Bound bound);

}  // namespace thrustsched::app

#endif  // THRUSTSCHED_APP_JSON_READER_H_
