# Bad input raises ValueError with the CLI's message; infeasible is a status, not an exception.
import thrustsched as ts

scn = ts.Scenario.load(ts.data_path("scenarios/hcw_table41_1d.json"))
scn["horizon"]["step_s"] = 7                   # does not divide one day
try:
    ts.solve(scn)
except ValueError as e:                        # thrustsched.ScenarioError is a ValueError
    print("bad input:", e)

scn = ts.Scenario.load(ts.data_path("scenarios/hcw_table41_1d.json"))
scn["window"]["half_width_m"] = 2000           # the 1 km start drifts 3 km in a day
scn["operations"]["max_burns_per_thruster"] = 0
res = ts.solve(scn, search=False)
print("status:", res.status, "| schedule rows:", len(res.schedule), "| check:", res.check)
