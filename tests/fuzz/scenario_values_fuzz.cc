// libFuzzer harness: valid shipped scenarios with a few values changed, so
// that the fuzzer works on content (numbers out of range, wrong types,
// missing and unknown keys) rather than on JSON syntax. The bytes choose a
// base scenario, then up to four edits, each a walk down the document (one
// byte per step: stop here or which child) and an edit of the node reached.
// The edited document goes through the text path of `thrustsched validate`
// (scenario_build.h). Contract: fuzz_common.h.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <iterator>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "app/scenario.h"
#include "tests/fuzz/fuzz_common.h"
#include "tests/fuzz/scenario_build.h"

namespace {

using nlohmann::json;
using thrustsched::fuzz::ByteReader;

const std::vector<json>& Bases() {
  static const std::vector<json> bases = [] {
    std::vector<json> b;
    for (const char* f :
         {"hcw_table41_1d.json", "geo_2day_anzel4.json", "geo_2day_anzel4_conjunction.json",
          "serra_double_integrator_impulsive.json", "serra_avoidance_ex1.json",
          "serra_gto_nuf3.json", "hcw_10km_relaxed_2d.json"}) {
      b.push_back(json::parse(thrustsched::fuzz::DataFile(std::string("scenarios/") + f)));
    }
    return b;
  }();
  return bases;
}

// Numbers that sit on the edges parsers get wrong.
double Interesting(uint8_t k) {
  static const double values[] = {0.0,    -1.0,   1.0,     0.5,      -0.5,         1e-9,
                                  1e9,    1e300,  -1e300,  3.5,      2147483648.0, -2147483649.0,
                                  9.3e18, 1e-320, 86400.0, 100001.0, 1e15,         -1e-300};
  return values[k % (sizeof(values) / sizeof(values[0]))];
}

double AnyFiniteDouble(ByteReader* bytes) {
  const uint64_t w = bytes->Word();
  double d = 0.0;
  std::memcpy(&d, &w, sizeof d);
  return std::isfinite(d) ? d : 1e308;
}

// Replaces, removes or adds at `node` (child of `parent`, at `index`).
void Edit(ByteReader* bytes, json* parent, size_t index, json* node) {
  switch (bytes->Byte() % 12) {
    case 0:
      *node = Interesting(bytes->Byte());
      break;
    case 1:
      *node = AnyFiniteDouble(bytes);
      break;
    case 2:
      if (node->is_number()) *node = node->get<double>() * std::pow(10.0, bytes->Below(13) - 6.0);
      break;
    case 3:
      *node = bytes->Chars(16);
      break;
    case 4:
      *node = nullptr;
      break;
    case 5:
      *node = bytes->Byte() % 2 == 0;
      break;
    case 6:
      *node = json::array();
      break;
    case 7:
      *node = json::object();
      break;
    case 8:
      if (parent != nullptr) parent->erase(std::next(parent->begin(), static_cast<long>(index)));
      break;
    case 9:
      if (node->is_array() && !node->empty()) node->push_back(node->back());
      if (node->is_object()) (*node)[bytes->Chars(8)] = Interesting(bytes->Byte());
      break;
    case 10:
      *node = json::array({*node});
      break;
    default:
      *node = static_cast<int64_t>(bytes->Word());
      break;
  }
}

void Mutate(ByteReader* bytes, json* doc) {
  json* parent = nullptr;
  json* node = doc;
  size_t index = 0;
  while (node->is_structured() && !node->empty() && bytes->Byte() % 4 != 0) {
    parent = node;
    index = bytes->Below(node->size());
    node = &*std::next(node->begin(), static_cast<long>(index));
  }
  Edit(bytes, parent, index, node);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace thrustsched;
  ByteReader bytes(data, size);
  json doc = Bases()[bytes.Below(Bases().size())];
  const int edits = 1 + static_cast<int>(bytes.Below(4));
  for (int k = 0; k < edits && !bytes.empty(); ++k) Mutate(&bytes, &doc);
  const std::string text = doc.dump(-1, ' ', false, json::error_handler_t::replace);
  fuzz::ExpectContract([&] {
    const app::Scenario s = app::ParseScenarioText(text);
    fuzz::BuildIfSmall(s);
  });
  return 0;
}
