// The crash guard of `thrustsched simulate` (simulate_internal.h).
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

namespace thrustsched::app {
namespace simulate_detail {

namespace fs = std::filesystem;
using planning::CycleRecord;
using planning::Fallback;

std::optional<InProgress> ReadInProgress(const std::string& path, const std::string& fingerprint) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return std::nullopt;
  nlohmann::json j = nlohmann::json::parse(in, nullptr, /*allow_exceptions=*/false);
  // Types checked first: j.value() throws a JSON type_error on a value of another type.
  if (!j.is_object() || !j.contains("fingerprint") || !j.at("fingerprint").is_string() ||
      j.at("fingerprint").get<std::string>() != fingerprint || !j.contains("cycle") ||
      !j.at("cycle").is_number_integer()) {
    return std::nullopt;  // not ours or unreadable: ignore, it is rewritten below
  }
  InProgress p;
  p.cycle = j.at("cycle").get<int>();
  const auto safe = j.find("solver_preprocessing_off");
  p.safe = safe != j.end() && safe->is_boolean() && safe->get<bool>();
  return p;
}

InProgressGuard::InProgressGuard(std::string path, const std::string& fingerprint, int cycle,
                                 bool safe)
    : path_(std::move(path)) {
  nlohmann::json j;
  j["cycle"] = cycle;
  j["fingerprint"] = fingerprint;
  j["solver_preprocessing_off"] = safe;
  j["meaning"] = "this cycle was running; if the process is gone it died inside the cycle";
  WriteAtomically(path_, j.dump(1) + "\n");
}

InProgressGuard::~InProgressGuard() {
  std::error_code ec;
  fs::remove(path_, ec);
}

}  // namespace simulate_detail

}  // namespace thrustsched::app
