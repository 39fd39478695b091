# The year loop (thesis ch. 5) with a progress bar, continued after a stop (resume).
#   python3 examples/python/year.py [OUT_DIR]
import sys
import thrustsched as ts

out = sys.argv[1] if len(sys.argv) > 1 else "out/python_year"
scn = ts.Scenario.load(ts.data_path("scenarios/year/year_test_4cycles.json"))  # 1-day GEO cycles
scn["horizon"]["step_s"] = 600                        # a 10-minute grid: a quick demo
scn["long_horizon"]["duration_s"] = 2 * 86400         # two cycles
run = ts.simulate(scn, cycles=1, out=out, plots=False)  # the first cycle (as if Ctrl-C stopped it)...
run = ts.simulate(scn, out=out, plots=False)            # ...and the rest: resume=True continues
print(run)
print(run.cycles[["cycle", "status", "consumption_l1_m_s", "max_abs_lat_deg", "max_abs_lon_deg"]].to_string(index=False))
print(f"total {run.year['consumption_l1_m_s']:.6g} m/s L1 over {run.year['simulated_days']:g} days")
