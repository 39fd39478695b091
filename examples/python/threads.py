# Several solves at once in threads (the GIL is released while the C++ code runs).
from concurrent.futures import ThreadPoolExecutor
import thrustsched as ts

scn = ts.Scenario.load(ts.data_path("scenarios/hcw_table41_2d.json"))
variants = []
for half_width_m in (36800, 25000):
    s = scn.copy()
    s["window"] = dict(s["window"], half_width_m=half_width_m)
    variants.append(s)
with ThreadPoolExecutor(max_workers=2) as pool:       # 2 cores: two solves at a time
    results = list(pool.map(lambda s: ts.solve(s, threads=1), variants))
for s, r in zip(variants, results):
    print(f"half width {s['window']['half_width_m']} m: {r.status}, {r.objective:.6g} m/s, "
          f"{len(r.schedule)} burns")
