# Type stub of the compiled module (python/src/core.cpp).
from typing import Callable, List, Optional, Tuple

import numpy as np
import numpy.typing as npt

SETTINGS: Tuple[str, ...]
SAMPLINGS: Tuple[str, ...]
AGGREGATIONS: Tuple[str, ...]

def estimate_normals(
    points: npt.NDArray[np.float64],
    neighbors: Optional[npt.NDArray[np.float64]],
    ids: Optional[npt.NDArray[np.uint64]],
    k: int,
    radius: Optional[float],
    planes: Optional[int],
    rotations: int,
    slices: int,
    confidence_interval: bool,
    sampling: str,
    presampling: int,
    aggregation: str,
    cluster_angle: float,
    seed: int,
    least_squares_first: bool,
    adaptive: bool,
    refit: bool,
    threads: Optional[int],
    return_confidence: bool,
    return_support: bool,
    progress: Optional[Callable[[float], None]],
) -> Tuple[npt.NDArray[np.float64], Optional[npt.NDArray[np.float64]], Optional[npt.NDArray[np.float64]]]: ...
def orient_normals(
    points: npt.NDArray[np.float64],
    normals: npt.NDArray[np.float64],
    direction: Optional[Tuple[float, float, float]],
    viewpoint: Optional[Tuple[float, float, float]],
    viewpoints: Optional[npt.NDArray[np.float64]],
    k: int,
    threads: Optional[int],
) -> None: ...

class LASError(ValueError): ...

class LASFile:
    def __init__(self, path: str) -> None: ...
    def __len__(self) -> int: ...
    @property
    def version(self) -> Tuple[int, int]: ...
    @property
    def point_format(self) -> int: ...
    @property
    def fields(self) -> List[str]: ...
    def read_points(self, start: int = 0, stop: Optional[int] = None) -> npt.NDArray[np.float64]: ...
    def read_field(self, name: str, start: int = 0, stop: Optional[int] = None) -> npt.NDArray[np.float64]: ...
    def write_with_normals(
        self, path: str, normals: npt.NDArray[np.float64], confidences: Optional[npt.NDArray[np.float64]] = None
    ) -> None: ...
