// Formatting and file helpers of `thrustsched simulate`.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "app/outputs.h"
#include "app/scenario.h"
#include "app/simulate.h"
#include "app/simulate_internal.h"

#include "common/format.h"
#include "dynamics/time.h"

namespace thrustsched::app {
namespace simulate_detail {

namespace fs = std::filesystem;
using planning::CycleRecord;
using planning::Fallback;

std::string G(double v, int digits) {
  if (std::isnan(v)) return "nan";
  if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
  return common::FormatG(v, digits);
}

std::string Hms(double seconds) {
  if (!std::isfinite(seconds) || seconds < 0) return "--:--:--";
  const long s = std::lround(seconds);
  char buf[32];
  std::snprintf(buf, sizeof(buf), "%02ld:%02ld:%02ld", s / 3600, (s / 60) % 60, s % 60);
  return buf;
}

std::string CycleTag(int index) {
  char buf[32];
  std::snprintf(buf, sizeof(buf), "cycle_%03d", index + 1);
  return buf;
}

std::string Utc(const std::string& epoch, double t) {
  try {
    return dynamics::Epoch::Parse(epoch).PlusSeconds(t).ToIso8601();
  } catch (const std::exception&) {
    return "";
  }
}

// 64-bit FNV-1a of a text, as 16 hex digits (stable across builds).
std::string Fingerprint(const std::string& text) {
  std::uint64_t h = 1469598103934665603ULL;
  for (unsigned char c : text) {
    h ^= c;
    h *= 1099511628211ULL;
  }
  char buf[24];
  std::snprintf(buf, sizeof(buf), "%016llx", static_cast<unsigned long long>(h));
  return buf;
}

std::string CsvQuote(const std::string& s) {
  std::string out = "\"";
  for (char c : s) {
    if (c == '"') out += '"';
    out += (c == '\n' || c == '\r') ? ' ' : c;
  }
  return out + "\"";
}

void MakeDirectory(const std::string& dir) {
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec || !fs::is_directory(dir)) {
    throw ScenarioError(dir + ": cannot create the output directory (" + ec.message() + ")");
  }
}

// Writes through a temporary file and a rename, so a reader (or a resume
// after a crash) never sees half a file.
void WriteAtomically(const std::string& path, const std::string& text) {
  const std::string tmp = path + ".tmp";
  WriteTextFile(tmp, text);
  std::error_code ec;
  fs::rename(tmp, path, ec);
  if (ec) throw std::runtime_error(path + ": cannot replace the file (" + ec.message() + ")");
}

}  // namespace simulate_detail

}  // namespace thrustsched::app
