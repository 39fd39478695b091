# Bring your own dynamics: a schedule from numpy arrays Phi, Gamma, drift (here the HCW
# model's, so the answer can be compared with the shipped scenario's).
import numpy as np
import thrustsched as ts

hcw = ts.dynamics.Hcw(7.2921159e-5)                        # GEO mean motion, rad/s
thrusters = ts.ThrusterSet.preset("ideal6", 0.265, 4850, 2005)  # N, kg, s
grid_s = ts.dynamics.uniform_grid(0, 86400, 288)            # one day, 5-min steps
d = hcw.discretise(grid_s, thrusters, scheme="exact_zoh")   # dict of numpy arrays
print({k: v.shape for k, v in d.items()})                   # phi (288, 6, 6), gamma (288, 6, 6), ...

problem = ts.ScheduleProblem(
    d["phi"], d["gamma"], drift=d["drift"], grid_s=d["grid_s"],
    initial_state=np.array([1000.0, 0, 0, 0, 0, 0]),          # m, m/s
    output_matrix=hcw.output_matrix(0.0), thrusters=thrusters,
    window={"outputs": [1, 2], "half_widths": [36800.0, 36800.0], "enforce_from_s": 0.0},
    rules={"min_burn_s": 300, "min_off_same_s": 1200, "min_gap_other_s": 300},
    state_scale=hcw.state_scale, state_names=hcw.state_names, output_names=hcw.output_names)
mine = ts.solve(problem)
ours = ts.solve(ts.Scenario.load(ts.data_path("scenarios/hcw_table41_1d.json")))
print(f"arrays: {mine.status} {mine.objective:.9g} m/s; scenario: {ours.status} {ours.objective:.9g} m/s")
print(mine.schedule.to_string(index=False))
print("final state (discrete model):", np.round(mine.states[-1], 3))
