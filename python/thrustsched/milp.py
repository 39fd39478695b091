"""MILP building, solving with CBC, and MPS/LP files (the C++ milp layer).

    from thrustsched import milp
    m = milp.Model("knapsack")
    take = m.add_variables(3, 0, 1, "binary", "take")
    m.add_constraint(milp.dot([2, 3, 4], take) <= 5, "weight")
    m.maximize(milp.dot([3, 4, 5], take))
    r = milp.solve(m)                 # r.status "optimal", r.objective 7.0, r.x
    milp.write(m, "knapsack.lp")

Expressions: Variable and LinearExpr support +, -, * and / by numbers, and
<=, >=, == (which make a BoundedLinearExpr for add_constraint; a constraint
has no truth value). Long sums: quicksum(items) or dot(coefficients,
variables) (linear time). Bulk rows: Model.add_rows(matrix, variables,
lower, upper) with a scipy.sparse or dense matrix. solve() releases the GIL
and stops on Ctrl-C keeping the best solution, as thrustsched.solve.
A schedule MILP to extend comes from thrustsched.build (BuiltSchedule).
"""
from ._core.milp import (  # noqa: F401
    BoundedLinearExpr,
    LinearExpr,
    LpData,
    Model,
    SolveResult,
    Variable,
    VarBlock,
    dot,
    quicksum,
    solve,
    to_lp_string,
    to_mps_string,
)
from ._core.milp import write as _write


def write(model, path, obfuscate_names: bool = False) -> None:
    """Writes a Model or LpData as free MPS (.mps) or CPLEX LP (.lp), by the extension."""
    import os

    _write(model, os.fspath(path), obfuscate_names)


__all__ = ["Model", "Variable", "VarBlock", "LinearExpr", "BoundedLinearExpr", "LpData", "SolveResult",
           "quicksum", "dot", "solve", "write", "to_mps_string", "to_lp_string"]
