# Type stubs of thrustsched.dynamics (the classes are C++: thrustsched._core.dynamics).
from typing import Any, Dict, List, Optional, Sequence, Tuple, Union

import numpy as np
import numpy.typing as npt

ArrayLike = npt.ArrayLike

def uniform_grid(t0_s: float, t1_s: float, num_intervals: int) -> List[float]: ...
def schemes() -> List[str]: ...

class ThrusterSet:
    def __init__(self, names: Sequence[str], directions_rtn: ArrayLike, thrust_n: float, mass_kg: float,
                 isp_s: float) -> None: ...
    @staticmethod
    def preset(preset: str, thrust_n: float, mass_kg: float, isp_s: float, theta_deg: float = ...,
               alpha_deg: float = ...) -> "ThrusterSet": ...
    names: List[str]
    size: int
    thrust_n: float
    mass_kg: float
    isp_s: float
    acceleration_m_s2: float
    mass_flow_kg_s: float
    directions_rtn: np.ndarray
    enabled: List[bool]
    acceleration_matrix: np.ndarray
    l1_factors: np.ndarray
    def __len__(self) -> int: ...
    def index(self, name: str) -> int: ...
    def subset(self, names: Sequence[str]) -> "ThrusterSet": ...
    def disable(self, names: Sequence[str]) -> None: ...

class LinearModel:
    name: str
    num_states: int
    num_inputs: int
    num_outputs: int
    is_time_invariant: bool
    state_names: List[str]
    output_names: List[str]
    state_scale: np.ndarray
    time_scale_s: float
    def evaluate(self, t_s: float) -> Tuple[np.ndarray, np.ndarray, np.ndarray]: ...
    def output_matrix(self, t_s: float) -> np.ndarray: ...
    def discretise(self, grid_s: Sequence[float], inputs: Union[None, ThrusterSet, ArrayLike] = None,
                   scheme: str = "exact_zoh", rk4_substeps: int = 1,
                   reference_tolerance: float = 1e-12) -> Dict[str, np.ndarray]: ...
    def discretize(self, grid_s: Sequence[float], inputs: Union[None, ThrusterSet, ArrayLike] = None,
                   scheme: str = "exact_zoh", rk4_substeps: int = 1,
                   reference_tolerance: float = 1e-12) -> Dict[str, np.ndarray]: ...

class DoubleIntegrator1d(LinearModel):
    def __init__(self, time_scale_s: float = 1.0, length_scale_m: float = 1.0) -> None: ...

class DoubleIntegrator3d(LinearModel):
    def __init__(self, time_scale_s: float = 1.0, length_scale_m: float = 1.0) -> None: ...

class Hcw(LinearModel):
    def __init__(self, mean_motion_rad_s: float, length_scale_m: float = 1000.0) -> None: ...
    mean_motion_rad_s: float
    def transition_matrix(self, tau_s: float) -> np.ndarray: ...

class YamanakaAnkersen(LinearModel):
    def __init__(self, semi_major_axis_m: float, eccentricity: float, mu_m3_s2: float = ...,
                 true_anomaly_at_epoch_rad: float = 0.0, length_scale_m: float = 1000.0) -> None: ...

class Geo(LinearModel):
    def __init__(self, **options: Any) -> None: ...
