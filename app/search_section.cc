#include "app/search_section.h"

#include <limits>
#include <string>

namespace thrustsched::app {

namespace {

constexpr int kMaxInt = std::numeric_limits<int>::max();

void SetInt(JsonObject& o, std::string_view key, int min, int* value) {
  if (auto v = o.OptionalInteger(key, min, kMaxInt)) *value = *v;
}

void SetNumber(JsonObject& o, std::string_view key, double* value) {
  if (auto v = o.OptionalNumber(key, Bound::kAny)) *value = *v;
}

void SetBool(JsonObject& o, std::string_view key, bool* value) {
  if (auto v = o.OptionalBool(key)) *value = *v;
}

void ParseNets(JsonObject o, transcription::NetOptions* n) {
  SetNumber(o, "candidate_threshold", &n->candidate_threshold);
  SetInt(o, "neighbourhood", 0, &n->neighbourhood);
  SetInt(o, "max_widenings", 0, &n->max_widenings);
  SetInt(o, "fired_thrusters_net_after", 0, &n->fired_thrusters_net_after);
  SetInt(o, "max_widened_slots", 0, &n->max_widened_slots);
  SetNumber(o, "time_share", &n->time_share);
  SetInt(o, "improvement_rounds", 0, &n->improvement_rounds);
  SetInt(o, "max_improvement_slots", 0, &n->max_improvement_slots);
  SetNumber(o, "improvement_time_share", &n->improvement_time_share);
  o.Finish();
}

void ParseRestricted(JsonObject o, transcription::RestrictedMilpOptions* r) {
  if (auto n = o.OptionalInteger("max_nodes", 0, kMaxInt)) r->max_nodes = *n;
  SetBool(o, "lazy_rows", &r->lazy_rows);
  o.Finish();
}

void ParseExact(JsonObject o, transcription::ExactOptions* e) {
  SetInt(o, "max_slots", 0, &e->max_slots);
  SetNumber(o, "time_share_before_tree", &e->time_share_before_tree);
  o.Finish();
}

void ParseTree(JsonObject o, transcription::TreePhaseOptions* t) {
  SetInt(o, "max_lps", 0, &t->max_lps);
  SetInt(o, "window_levels", 0, &t->window_levels);
  SetInt(o, "max_exact_leaf_slots", 0, &t->max_exact_leaf_slots);
  SetInt(o, "max_leaf_net_slots", 0, &t->max_leaf_net_slots);
  SetInt(o, "other_leaf_nets", 0, &t->other_leaf_nets);
  o.Finish();
}

void ParseExchange(JsonObject o, transcription::ExchangeOptions* e) {
  SetInt(o, "max_slots", 0, &e->max_slots);
  SetNumber(o, "time_share", &e->time_share);
  o.Finish();
}

}  // namespace

void ParseSearch(JsonObject& solver, std::string_view key, transcription::SearchOptions* search) {
  if (!solver.Has(key)) return;
  if (solver.Raw(key).is_boolean()) {
    search->enabled = solver.Bool(key);
    return;
  }
  JsonObject o = solver.Object(key);
  SetBool(o, "enabled", &search->enabled);
  if (auto plan = o.OptionalString("plan")) search->plan = *plan;
  if (o.Has("disabled_phases")) search->disabled_phases = o.StringArray("disabled_phases");
  if (o.Has("relaxation")) {
    JsonObject r = o.Object("relaxation");
    SetBool(r, "drop_dormant_blocks", &search->relaxation.drop_dormant_blocks);
    if (r.Has("lp_method")) {
      using Method = transcription::RelaxationOptions::LpMethod;
      transcription::ParseLpMethod(
          r.Choice("lp_method", {transcription::ToString(Method::kClpBarrier),
                                 transcription::ToString(Method::kInteriorPoint)}),
          &search->relaxation.lp_method);
    }
    r.Finish();
  }
  if (o.Has("nets")) ParseNets(o.Object("nets"), &search->nets);
  if (o.Has("restricted")) ParseRestricted(o.Object("restricted"), &search->restricted);
  if (o.Has("exact")) ParseExact(o.Object("exact"), &search->exact);
  if (o.Has("tree")) ParseTree(o.Object("tree"), &search->tree);
  if (o.Has("exchange")) ParseExchange(o.Object("exchange"), &search->exchange);
  o.Finish();
  std::string error;
  if (!search->IsValid(&error)) {
    // "search.nets.x must be ..." -> "solver.search.nets.x: must be ..."
    const std::string prefix = "search.";
    const size_t space = error.find(' ');
    if (error.rfind(prefix, 0) == 0 && space != std::string::npos) {
      const std::string field = error.substr(prefix.size(), space - prefix.size());
      throw ScenarioError(o.path() + "." + field + ": " + error.substr(space + 1));
    }
    throw ScenarioError(o.path() + ": " + error);
  }
}

}  // namespace thrustsched::app
