# Quick start (verbatim in README.md): two days of HCW station keeping, thesis Table 4.1.
import sys
import thrustsched as ts

scn = ts.Scenario.load(ts.data_path("scenarios/hcw_table41_2d.json"))  # shipped; any cwd
scn["solver"]["time_limit_s"] = 120                     # plain dict access, the JSON's fields
res = ts.solve(scn, threads=1)                          # GIL released while CBC runs
print(f"{res.status}: {res.objective:.6g} m/s, gap {res.gap:.2g}, "
      f"{len(res.schedule)} burns; checker {'ok' if res.check.operational_ok else 'FAILED'}")
print(res.schedule)                                     # pandas DataFrame (schedule.csv)
print(res.trajectory[["t_s", "y_m", "z_m", "drift_m"]].tail(3))  # trajectory.csv
assert ts.check(scn, res.schedule).passed               # the independent checker on any schedule
ts.export(scn, sys.argv[1] if len(sys.argv) > 1 else "two_days.mps")  # MPS / LP for other solvers
