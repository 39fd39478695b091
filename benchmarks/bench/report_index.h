// The rows of results.csv as report.md's sections read them: grouped by case
// (repeats together), with the cells every section formats the same way.
//
//   const report_internal::Index idx(rows);
//   for (const report_internal::Group* g : idx.Section(kSectionSchemeSolve))
//     md << g->Get("scheme") << " " << report_internal::StatusCell(*g);
#ifndef THRUSTSCHED_BENCHMARKS_BENCH_REPORT_INDEX_H_
#define THRUSTSCHED_BENCHMARKS_BENCH_REPORT_INDEX_H_

#include <cstddef>
#include <functional>
#include <limits>
#include <map>
#include <string>
#include <vector>

#include "benchmarks/bench/matrix.h"
#include "benchmarks/bench/results.h"
#include "common/constants.h"

namespace thrustsched::bench::report_internal {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kDay = common::kSecondsPerDay;

/// Global order of each scheme for a smooth time-varying model
/// (dynamics/discretisation.h); 0 for exact_zoh (exact on LTI, the reference otherwise).
int ExpectedOrder(const std::string& scheme);

// Rows grouped by case id (repeats together), in first-appearance order.
struct Group {
  std::string id;
  std::vector<const Row*> rows;
  const Row& first() const { return *rows.front(); }
  std::string Get(const std::string& c) const { return first().Get(c); }
  double Num(const std::string& c) const { return first().Num(c); }
  std::vector<double> Values(const std::string& c) const {
    std::vector<double> v;
    for (const Row* r : rows) v.push_back(r->Num(c));
    return v;
  }
};

class Index {
 public:
  explicit Index(const std::vector<Row>& rows) {
    for (const Row& r : rows) {
      const std::string id = r.Get("case_id");
      // Accuracy cases hold one row per scheme and step: split them.
      const std::string key = r.Get("section") == kSectionAccuracy
                                  ? id + "|" + r.Get("scheme") + "|" + r.Get("step_s")
                                  : id;
      auto it = pos_.find(key);
      if (it == pos_.end()) {
        pos_[key] = groups_.size();
        groups_.push_back({id, {&r}});
      } else {
        groups_[it->second].rows.push_back(&r);
      }
    }
  }
  std::vector<const Group*> Where(const std::function<bool(const Group&)>& pred) const {
    std::vector<const Group*> out;
    for (const Group& g : groups_) {
      if (pred(g)) out.push_back(&g);
    }
    return out;
  }
  std::vector<const Group*> Section(const std::string& section) const {
    return Where([&](const Group& g) { return g.Get("section") == section; });
  }
  const std::vector<Group>& groups() const { return groups_; }

 private:
  std::vector<Group> groups_;
  std::map<std::string, size_t> pos_;
};

/// Median of a column over a group's repeats, with its spread and count.
std::string MedSpread(const Group& g, const std::string& col, bool missing_is_inf = false);
/// The statuses of a group's repeats ("optimal x3").
std::string StatusCell(const Group& g);
/// The checker's verdict on the group's first row.
std::string CheckerCell(const Group& g);
double HorizonDays(const Group& g);

}  // namespace thrustsched::bench::report_internal

#endif  // THRUSTSCHED_BENCHMARKS_BENCH_REPORT_INDEX_H_
