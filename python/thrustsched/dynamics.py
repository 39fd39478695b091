"""The shipped linear models, thruster sets and discretisation schemes.

    import thrustsched as ts
    hcw = ts.dynamics.Hcw(7.2921159e-5)                                   # GEO mean motion, rad/s
    thr = ts.ThrusterSet.preset("ideal6", 0.265, 4850, 2005)              # N, kg, s
    d = hcw.discretise(ts.dynamics.uniform_grid(0, 86400, 288), thr, scheme="exact_zoh")
    d["phi"].shape, d["gamma"].shape, d["drift"].shape                    # (288, 6, 6) (288, 6, 6) (288, 6)

Models: Hcw, DoubleIntegrator1d, DoubleIntegrator3d, YamanakaAnkersen, Geo
(keywords: the GeoModelOptions fields). Each has evaluate(t_s) -> (A, B, d),
output_matrix(t_s), state_names, output_names, state_scale and
discretise(grid_s, inputs=None, scheme="exact_zoh", rk4_substeps=1,
reference_tolerance=1e-12) -> dict of numpy arrays (phi [N, n, n],
gamma [N, n, k], drift [N, n], grid_s [N + 1]), also spelt discretize;
schemes() lists the schemes.
"""
from ._core.dynamics import (  # noqa: F401
    DoubleIntegrator1d,
    DoubleIntegrator3d,
    Geo,
    Hcw,
    LinearModel,
    ThrusterSet,
    YamanakaAnkersen,
    schemes,
    uniform_grid,
)

__all__ = ["LinearModel", "Hcw", "DoubleIntegrator1d", "DoubleIntegrator3d", "YamanakaAnkersen", "Geo",
           "ThrusterSet", "schemes", "uniform_grid"]
