# Extend a schedule MILP with your own rows (a forbidden firing window, a keep-out row) and solve again.
import thrustsched as ts
from thrustsched import milp

scn = ts.Scenario.load(ts.data_path("scenarios/hcw_table41_1d.json"))
b = ts.build(scn)                                   # the MILP the CLI solves
first = b.solve()
print("as built:      ", first.schedule.to_string(index=False, header=False))

# Forbidden window: no thruster may fire from 2 h to 4 h (e.g. a ground-station pass).
j0, j1 = b.interval_at(2 * 3600.0), b.interval_at(4 * 3600.0)
b.add_constraints([b.on(t, j) == 0 for t in b.thruster_names for j in range(j0, j1)], "pass")
# Keep-out: at 12 h (node 144) stay out of the region more than 10 km behind (y < -10 km).
b.add_constraint(b.output_expr(144, 1) >= -10000.0, "keep_out_y")
second = b.solve()                                  # CBC on the whole MILP (your rows included)
print("with the rows: ", second.schedule.to_string(index=False, header=False))
print(f"{second.status}, {second.objective:.6g} m/s, y(12 h) = {second.outputs[144, 1]:.1f} m, "
      f"checker {'ok' if second.check.passed else 'FAILED'}")

m = milp.Model("knapsack")                          # the milp layer on its own
take = m.add_variables(3, 0, 1, "binary", "take")
m.add_constraint(milp.dot([2, 3, 4], take) <= 5, "weight")
m.maximize(milp.dot([3, 4, 5], take))
r = milp.solve(m)
print("knapsack:", r.status, r.objective, list(r.x))
