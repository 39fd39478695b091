# Results as pandas DataFrames, matplotlib plots, the checker on any schedule, MPS/LP export.
#   python3 examples/python/results_and_plots.py [OUT_DIR]
import os
import sys

import matplotlib
matplotlib.use("Agg")                       # files, no window
import thrustsched as ts

out = sys.argv[1] if len(sys.argv) > 1 else "out/python_example"
os.makedirs(out, exist_ok=True)
scn = ts.Scenario.load(ts.data_path("scenarios/hcw_table41_1d.json"))
res = ts.solve(scn)
print(res)                                  # status, objective, gap, burns, check
print(res.schedule.to_string(index=False))  # thruster, start_s, end_s, duration_s
print(res.trajectory.describe().loc[["min", "max"], ["y_m", "z_m", "drift_m"]])
for name, fig in res.plot().items():        # window, timeline, outputs
    fig.savefig(os.path.join(out, f"{name}.png"))

late = res.schedule.copy()
late["start_s"] += 60                       # off the grid, and 300 s after its start...
late["end_s"] -= 180                        # ...cut to 60 s: shorter than min_burn_s
check = ts.check(scn, late)
print("edited schedule:", "passed" if check.passed else "FAILED", *check.findings, sep="\n  ")
print(ts.export(scn, os.path.join(out, "one_day.lp")))  # CPLEX LP (or .mps)
