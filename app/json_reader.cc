#include "app/json_reader.h"

#include <algorithm>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <sstream>

namespace thrustsched::app {
namespace {

std::string TypeName(const nlohmann::json& v) {
  if (v.is_boolean()) return "boolean";
  if (v.is_number()) return "number";
  if (v.is_string()) return "string";
  if (v.is_array()) return "array";
  if (v.is_object()) return "object";
  if (v.is_null()) return "null";
  return "value";
}

// Tracks the path while parsing, to report duplicate keys by path.
struct Frame {
  bool is_object;
  std::set<std::string> keys;
  std::string last_key;
  long index = -1;
};

std::string PathOf(const std::string& root, const std::vector<Frame>& frames, size_t upto) {
  std::string p = root;
  for (size_t k = 0; k < upto && k < frames.size(); ++k) {
    if (frames[k].is_object) {
      p += "." + frames[k].last_key;
    } else {
      p += "[" + std::to_string(frames[k].index) + "]";
    }
  }
  return p;
}

}  // namespace

std::string FormatNumber(double value) {
  if (std::isnan(value)) return "NaN";
  if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
  char buf[64];
  if (value == std::floor(value) && std::abs(value) < 1e15) {
    std::snprintf(buf, sizeof(buf), "%.0f", value);
    return buf;
  }
  for (int prec = 6; prec <= 17; ++prec) {
    std::snprintf(buf, sizeof(buf), "%.*g", prec, value);
    if (std::strtod(buf, nullptr) == value) break;
  }
  return buf;
}

std::string DescribeJson(const nlohmann::json& value) {
  std::string s;
  if (value.is_number_float()) {
    s = FormatNumber(value.get<double>());
  } else {
    s = value.dump();
  }
  if (s.size() > 60) s = s.substr(0, 57) + "...";
  return s;
}

constexpr size_t kMaxJsonDepth = 64;

nlohmann::json ParseJsonText(std::string_view text, const std::string& what) {
  std::vector<Frame> frames;
  std::string duplicate;
  // Root name for paths: "scenario" (the documented prefix of every field path).
  const std::string root = "scenario";
  auto on_value_in_array = [&frames]() {
    if (!frames.empty() && !frames.back().is_object) ++frames.back().index;
  };
  auto open_level = [&](bool is_object) {
    on_value_in_array();
    // No scenario nests deeper than a few levels; a deeper document is
    // refused here, before printing or copying it would recurse that deep
    // (a stack overflow under the sanitizers at some thousands of levels).
    if (frames.size() >= kMaxJsonDepth) {
      throw ScenarioError(what + ": nested deeper than " + std::to_string(kMaxJsonDepth) +
                          " levels at " + PathOf(root, frames, frames.size()));
    }
    frames.push_back(Frame{is_object, {}, "", -1});
  };
  nlohmann::json::parser_callback_t cb = [&](int /*depth*/, nlohmann::json::parse_event_t event,
                                             nlohmann::json& parsed) -> bool {
    using E = nlohmann::json::parse_event_t;
    switch (event) {
      case E::object_start:
        open_level(true);
        break;
      case E::array_start:
        open_level(false);
        break;
      case E::object_end:
      case E::array_end:
        if (!frames.empty()) frames.pop_back();
        break;
      case E::key: {
        if (!frames.empty() && frames.back().is_object) {
          const std::string key = parsed.get<std::string>();
          if (!frames.back().keys.insert(key).second && duplicate.empty()) {
            duplicate = PathOf(root, frames, frames.size() - 1) + "." + key;
          }
          frames.back().last_key = key;
        }
        break;
      }
      case E::value:
        on_value_in_array();
        break;
    }
    return true;
  };
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(text.begin(), text.end(), cb, /*allow_exceptions=*/true,
                              /*ignore_comments=*/false);
  } catch (const nlohmann::json::exception& e) {
    // Name the field being read (e.g. a number too large for a double, such
    // as 1e999, fails here, before any field check could see it).
    std::string where;
    if (!frames.empty()) {
      std::vector<Frame> at = frames;
      if (!at.back().is_object) ++at.back().index;  // the element being read
      where = " at " + PathOf(root, at, at.size());
    }
    throw ScenarioError(what + ": not valid JSON" + where + ": " + e.what());
  }
  if (!duplicate.empty()) {
    throw ScenarioError(duplicate + ": duplicate key in " + what);
  }
  return j;
}

double CheckedNumber(const nlohmann::json& v, const std::string& path, Bound bound) {
  if (!v.is_number()) {
    throw ScenarioError(path + ": expected a number, got " + TypeName(v) + " " + DescribeJson(v));
  }
  const double x = v.get<double>();
  if (!std::isfinite(x)) {
    throw ScenarioError(path + ": must be finite, got " + FormatNumber(x));
  }
  if (bound == Bound::kPositive && !(x > 0.0)) {
    throw ScenarioError(path + ": must be > 0, got " + FormatNumber(x));
  }
  if (bound == Bound::kNonNegative && !(x >= 0.0)) {
    throw ScenarioError(path + ": must be >= 0, got " + FormatNumber(x));
  }
  return x;
}

JsonObject::JsonObject(const nlohmann::json& value, std::string path)
    : value_(value), path_(std::move(path)) {
  if (!value_.is_object()) {
    throw ScenarioError(path_ + ": expected an object, got " + TypeName(value_) + " " +
                        DescribeJson(value_));
  }
}

std::string JsonObject::FieldPath(std::string_view key) const {
  return path_ + "." + std::string(key);
}

namespace {

std::string Lower(std::string t) {
  for (char& c : t) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return t;
}

// Levenshtein distance.
size_t EditDistance(const std::string& a, const std::string& b) {
  std::vector<size_t> row(b.size() + 1);
  for (size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (size_t i = 1; i <= a.size(); ++i) {
    size_t diagonal = row[0];
    row[0] = i;
    for (size_t j = 1; j <= b.size(); ++j) {
      const size_t up = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = up;
    }
  }
  return row[b.size()];
}

// Same but for case, or one letter wrong, missing or extra.
bool IsNearMiss(const std::string& word, const std::string& name) {
  return EditDistance(Lower(word), Lower(name)) <= 1;
}

}  // namespace

std::string ClosestName(const std::string& word, const std::vector<std::string>& names) {
  const std::string w = Lower(word);
  std::string best;
  size_t best_distance = std::max<size_t>(2, w.size() / 3) + 1;
  for (const std::string& n : names) {
    const size_t d = EditDistance(w, Lower(n));
    if (d < best_distance) {
      best_distance = d;
      best = n;
    }
  }
  return best;
}

void JsonObject::Fail(std::string_view key, const std::string& message) const {
  throw ScenarioError(FieldPath(key) + ": " + message);
}

const nlohmann::json* JsonObject::Find(std::string_view key) {
  known_.insert(std::string(key));
  auto it = value_.find(std::string(key));
  if (it == value_.end()) return nullptr;
  return &*it;
}

const nlohmann::json& JsonObject::Require(std::string_view key) {
  const nlohmann::json* v = Find(key);
  if (v == nullptr) {
    // A present key that is not read here and looks like this one is a
    // misspelling of it, not an absence.
    for (auto it = value_.begin(); it != value_.end(); ++it) {
      // Only a near miss (one letter or case): other keys may be read later.
      if (known_.count(it.key()) == 0 && IsNearMiss(it.key(), std::string(key))) {
        throw ScenarioError(FieldPath(it.key()) + ": unknown field '" + it.key() +
                            "'; did you mean '" + std::string(key) + "'?");
      }
    }
    Fail(key, "required field is missing");
  }
  return *v;
}

bool JsonObject::Has(std::string_view key) { return Find(key) != nullptr; }

void JsonObject::Accept(std::string_view key) { known_.insert(std::string(key)); }

const nlohmann::json& JsonObject::Raw(std::string_view key) { return Require(key); }

double JsonObject::Number(std::string_view key, Bound bound) {
  return CheckedNumber(Require(key), FieldPath(key), bound);
}

std::optional<double> JsonObject::OptionalNumber(std::string_view key, Bound bound) {
  const nlohmann::json* v = Find(key);
  if (v == nullptr) return std::nullopt;
  return CheckedNumber(*v, FieldPath(key), bound);
}

int JsonObject::Integer(std::string_view key, int min, int max) {
  const double x = Number(key);
  if (x != std::floor(x)) Fail(key, "expected an integer, got " + FormatNumber(x));
  if (x < min || x > max) {
    Fail(key, "must be in [" + std::to_string(min) + ", " + std::to_string(max) + "], got " +
                  FormatNumber(x));
  }
  return static_cast<int>(x);
}

std::optional<int> JsonObject::OptionalInteger(std::string_view key, int min, int max) {
  if (!Has(key)) return std::nullopt;
  return Integer(key, min, max);
}

bool JsonObject::Bool(std::string_view key) {
  const nlohmann::json& v = Require(key);
  if (!v.is_boolean()) {
    Fail(key, "expected true or false, got " + TypeName(v) + " " + DescribeJson(v));
  }
  return v.get<bool>();
}

std::optional<bool> JsonObject::OptionalBool(std::string_view key) {
  if (!Has(key)) return std::nullopt;
  return Bool(key);
}

std::string JsonObject::String(std::string_view key) {
  const nlohmann::json& v = Require(key);
  if (!v.is_string()) {
    Fail(key, "expected a string, got " + TypeName(v) + " " + DescribeJson(v));
  }
  return v.get<std::string>();
}

std::optional<std::string> JsonObject::OptionalString(std::string_view key) {
  if (!Has(key)) return std::nullopt;
  return String(key);
}

std::string JsonObject::Choice(std::string_view key, const std::vector<std::string>& choices) {
  const std::string s = String(key);
  for (const std::string& c : choices) {
    if (s == c) return s;
  }
  std::string list;
  for (size_t i = 0; i < choices.size(); ++i) list += (i ? ", " : "") + choices[i];
  Fail(key, "unknown value \"" + s + "\" (expected one of: " + list + ")");
}

std::vector<double> JsonObject::NumberArray(std::string_view key, int size, Bound bound) {
  const nlohmann::json& v = Require(key);
  if (!v.is_array()) {
    Fail(key, "expected an array of numbers, got " + TypeName(v) + " " + DescribeJson(v));
  }
  if (size >= 0 && static_cast<int>(v.size()) != size) {
    Fail(key, "expected " + std::to_string(size) + " numbers, got " + std::to_string(v.size()) +
                  " (" + DescribeJson(v) + ")");
  }
  if (size < 0 && v.empty()) Fail(key, "must not be empty");
  std::vector<double> out;
  for (size_t i = 0; i < v.size(); ++i) {
    out.push_back(CheckedNumber(v[i], FieldPath(key) + "[" + std::to_string(i) + "]", bound));
  }
  return out;
}

Eigen::MatrixXd JsonObject::NumberMatrix(std::string_view key, int rows, int cols, Bound bound) {
  const nlohmann::json& v = Require(key);
  const std::string path = FieldPath(key);
  const std::string shape = (rows >= 0 ? std::to_string(rows) : std::string("one or more")) +
                            " rows of " + std::to_string(cols) + " numbers";
  if (!v.is_array() || v.empty() || (rows >= 0 && static_cast<int>(v.size()) != rows))
    throw ScenarioError(path + ": expected " + shape + ", got " + DescribeJson(v));
  Eigen::MatrixXd out(static_cast<int>(v.size()), cols);
  for (size_t i = 0; i < v.size(); ++i) {
    const std::string row_path = path + "[" + std::to_string(i) + "]";
    if (!v[i].is_array() || static_cast<int>(v[i].size()) != cols) {
      throw ScenarioError(row_path + ": expected " + std::to_string(cols) + " numbers, got " +
                          DescribeJson(v[i]));
    }
    for (int j = 0; j < cols; ++j) {
      out(static_cast<int>(i), j) =
          CheckedNumber(v[i][j], row_path + "[" + std::to_string(j) + "]", bound);
    }
  }
  return out;
}

std::vector<std::string> JsonObject::StringArray(std::string_view key) {
  const nlohmann::json& v = Require(key);
  if (!v.is_array()) {
    Fail(key, "expected an array of strings, got " + TypeName(v) + " " + DescribeJson(v));
  }
  std::vector<std::string> out;
  std::set<std::string> seen;
  for (size_t i = 0; i < v.size(); ++i) {
    const std::string p = FieldPath(key) + "[" + std::to_string(i) + "]";
    if (!v[i].is_string()) {
      throw ScenarioError(p + ": expected a string, got " + TypeName(v[i]) + " " +
                          DescribeJson(v[i]));
    }
    std::string s = v[i].get<std::string>();
    if (!seen.insert(s).second) throw ScenarioError(p + ": \"" + s + "\" is listed twice");
    out.push_back(std::move(s));
  }
  return out;
}

JsonObject JsonObject::Object(std::string_view key) {
  return JsonObject(Require(key), FieldPath(key));
}

std::vector<JsonObject> JsonObject::ObjectArray(std::string_view key) {
  const nlohmann::json& v = Require(key);
  if (!v.is_array()) {
    Fail(key, "expected an array of objects, got " + TypeName(v) + " " + DescribeJson(v));
  }
  std::vector<JsonObject> out;
  for (size_t i = 0; i < v.size(); ++i) {
    out.emplace_back(v[i], FieldPath(key) + "[" + std::to_string(i) + "]");
  }
  return out;
}

void JsonObject::Finish() const {
  for (auto it = value_.begin(); it != value_.end(); ++it) {
    if (known_.count(it.key()) == 0) {
      std::string list;
      for (const std::string& k : known_) list += (list.empty() ? "" : ", ") + k;
      const std::string near =
          ClosestName(it.key(), std::vector<std::string>(known_.begin(), known_.end()));
      throw ScenarioError(FieldPath(it.key()) + ": unknown field '" + it.key() + "'" +
                          (near.empty() ? "" : "; did you mean '" + near + "'?") +
                          " (accepted here: " + list + ")");
    }
  }
}

void JsonObject::ExactlyOneOf(const std::vector<std::string>& keys, bool required) {
  std::vector<std::string> present;
  std::string list;
  for (const std::string& k : keys) {
    list += (list.empty() ? "" : ", ") + k;
    if (value_.contains(k)) present.push_back(k);
  }
  if (present.size() > 1) {
    throw ScenarioError(path_ + ": give only one of " + list + " (found " + present[0] + " and " +
                        present[1] + ")");
  }
  if (required && present.empty()) {
    if (keys.size() == 1) throw ScenarioError(FieldPath(keys[0]) + ": required field is missing");
    throw ScenarioError(path_ + ": one of " + list + " is required");
  }
}

}  // namespace thrustsched::app
