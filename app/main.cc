// thrustsched: minimum-fuel on-off thruster schedules from a scenario file.
//
//   thrustsched solve data/scenarios/geo_week_anzel4.json --out out/demo
//   thrustsched export data/scenarios/hcw_table41_2d.json model.mps
//   thrustsched check data/scenarios/hcw_table41_2d.json out/x/schedule.csv
//   thrustsched import-solution SCENARIO.json cbc.sol --format cbc --out schedule.csv
//   thrustsched simulate data/scenarios/year/year_anzel4_fixed.json --out out/year [--cycles N]
//   [--resume]
//
// Exit codes: 0 solved (optimal or feasible) / check passed, 1 internal
// error, 2 bad input, 3 infeasible, 4 no solution within the time limit,
// 5 the checked schedule fails. The command line itself is app/cli.h.
#include "app/cli.h"

int main(int argc, char** argv) { return thrustsched::app::RunCli(argc, argv); }
