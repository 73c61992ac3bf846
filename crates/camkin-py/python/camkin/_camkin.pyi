"""Type stubs of the extension module (camkin._camkin); see the docstrings for units."""

from os import PathLike
from typing import Any, Dict, List, Optional, Sequence, Tuple, Union, final

import numpy as np
import numpy.typing as npt

from .results import Result

# as the extension module's own __all__ (pyo3 lists every function and class it adds)
__all__ = [
    "Mechanism",
    "System",
    "Curve",
    "Body",
    "paper_cam",
    "_mechanism_from_json",
    "_mechanism_from_text",
    "_curve_from_state",
    "_contact",
    "Spline",
    "Circle",
    "Ellipse",
    "Line",
    "Point",
    "motion_laws",
    "motion_law",
    "spline_variants",
    "summarize",
    "_studio_answer",
    "_studio_assets",
    "MAX_ANGLES",
    "MAX_TEXT_BYTES",
]

MAX_ANGLES: int
MAX_TEXT_BYTES: int

_ArrayLike = Union[float, Sequence[float], npt.NDArray[np.floating[Any]]]

@final
class System:
    @staticmethod
    def from_toml(source: Union[str, PathLike[str]], *, large: bool = False) -> System: ...
    @property
    def bodies(self) -> List[str]: ...
    @property
    def contacts(self) -> List[str]: ...
    def analyze(
        self, angles_deg: _ArrayLike, *, strict: bool = False, large: bool = False
    ) -> Result: ...
    def simulate(
        self,
        *,
        revolutions: Optional[float] = None,
        step_deg: float = 1.0,
        duration: Optional[float] = None,
        interval: Optional[float] = None,
        rtol: float = 1e-10,
        atol: float = 1e-10,
        large: bool = False,
        integrator: str = "auto",
    ) -> Tuple[Result, Result]: ...
    def lash_sweep(
        self,
        lashes: Sequence[float],
        *,
        revolutions: float = 1.0,
        step_deg: float = 1.0,
        large: bool = False,
    ) -> Result: ...
    def lubrication(self, *, step_deg: float = 1.0, large: bool = False) -> Result: ...
    def forces(
        self,
        *,
        step_deg: float = 1.0,
        margin: float = 0.0,
        allowable_mpa: Optional[float] = None,
        target_rpm: Optional[float] = None,
        large: bool = False,
    ) -> Result: ...

@final
class Mechanism:
    @staticmethod
    def from_toml(source: Union[str, PathLike[str]], *, large: bool = False) -> Mechanism: ...
    @staticmethod
    def from_dict(d: Dict[str, Any], base_dir: Optional[str] = None, *, large: bool = False) -> Mechanism: ...
    def to_dict(self) -> Dict[str, Any]: ...
    def to_toml(self) -> str: ...
    @property
    def length_unit(self) -> str: ...
    @property
    def speed_rpm(self) -> float: ...
    @property
    def follower_kind(self) -> str: ...
    @property
    def oscillating(self) -> bool: ...
    @property
    def name(self) -> str: ...
    @property
    def has_dynamics(self) -> bool: ...
    @property
    def base_dir(self) -> str: ...
    def analyze(
        self,
        angles_deg: _ArrayLike,
        *,
        per: str = "s",
        angle_unit: str = "deg",
        contiguous: Optional[bool] = None,
        strict: bool = False,
        large: bool = False,
    ) -> Result: ...
    def contacts(
        self,
        angles_deg: _ArrayLike,
        *,
        contiguous: Optional[bool] = None,
        strict: bool = False,
        large: bool = False,
    ) -> Result: ...
    def mesh(
        self,
        angles_deg: _ArrayLike,
        *,
        contiguous: Optional[bool] = None,
        strict: bool = False,
        large: bool = False,
    ) -> Result: ...
    def travel(self) -> Result: ...
    def checks(self, *, step_deg: float = 0.5, pressure_limit_deg: float = 30.0) -> Result: ...
    def profile(self, n: int = 720) -> npt.NDArray[np.float64]: ...
    def with_nodes(self, points: npt.NDArray[np.float64], *, large: bool = False) -> Mechanism: ...
    def compare(
        self, nodes: Sequence[int] = ..., *, step_deg: float = 0.05, large: bool = False
    ) -> Result: ...
    def simulate(
        self,
        *,
        revolutions: float = 1.0,
        step_deg: float = 1.0,
        rtol: float = 1e-10,
        atol: float = 1e-10,
        start_angle_deg: float = 0.0,
        large: bool = False,
        integrator: str = "auto",
    ) -> Result: ...
    def forces(
        self,
        *,
        step_deg: float = 0.5,
        margin: float = 0.0,
        target_rpm: Optional[float] = None,
        face_width: Optional[float] = None,
        materials: Union[str, Tuple[str, str], None] = None,
        allowable_mpa: Optional[float] = None,
        oil: Optional[str] = None,
        roughness_um: Optional[Tuple[float, float]] = None,
        film: Optional[str] = None,
        friction: Union[float, Tuple[float, float], None] = None,
    ) -> Result: ...
    def shop(
        self,
        *,
        step_deg: float = 1.0,
        tool_radius: Optional[float] = None,
        tolerance: Optional[float] = None,
        dxf_path: Union[str, PathLike[str], None] = None,
    ) -> Result: ...
    def deviation(
        self,
        measured: Union[str, PathLike[str], npt.ArrayLike],
        *,
        tolerance: Optional[float] = None,
        step_deg: float = 1.0,
    ) -> Result: ...
    def gear_loads(
        self,
        *,
        torque: Optional[float] = None,
        power_kw: Optional[float] = None,
        face_width: Optional[float] = None,
        materials: Union[str, Tuple[str, str], None] = None,
        oil: Optional[str] = None,
        roughness_um: Optional[Tuple[float, float]] = None,
        film: Optional[str] = None,
        friction: Union[float, Tuple[float, float], None] = None,
        points: int = 201,
    ) -> Result: ...

@final
class Curve:
    @property
    def kind(self) -> str: ...
    @property
    def domain(self) -> Tuple[str, float, float]: ...
    def eval(self, u: float) -> Dict[str, Any]: ...
    def breakpoints(self) -> List[float]: ...

@final
class Body:
    def __new__(
        cls,
        position: Sequence[float] = ...,
        angle: float = 0.0,
        velocity: Sequence[float] = ...,
        angular_velocity: float = 0.0,
        acceleration: Sequence[float] = ...,
        angular_acceleration: float = 0.0,
    ) -> Body: ...
    @property
    def position(self) -> Tuple[float, float]: ...
    @property
    def angle(self) -> float: ...
    @property
    def velocity(self) -> Tuple[float, float]: ...
    @property
    def angular_velocity(self) -> float: ...
    @property
    def acceleration(self) -> Tuple[float, float]: ...
    @property
    def angular_acceleration(self) -> float: ...
    def to_world(self, r: Sequence[float]) -> Tuple[float, float]: ...

def Spline(points: Any, parameterization: str = "uniform") -> Curve: ...
def Circle(center: Sequence[float], radius: float) -> Curve: ...
def Ellipse(center: Sequence[float], semi_axes: Sequence[float], rotation_deg: float = 0.0) -> Curve: ...
def Line(anchor: Sequence[float], direction: Sequence[float]) -> Curve: ...
def Point(at: Sequence[float]) -> Curve: ...
def paper_cam() -> Mechanism: ...
def motion_laws() -> List[str]: ...
def motion_law(name: str, x: _ArrayLike) -> Result: ...
def spline_variants(
    base: Mechanism,
    nodes: npt.NDArray[np.float64],
    *,
    angles_deg: Optional[_ArrayLike] = None,
    threads: Optional[int] = None,
    large: bool = False,
) -> Result: ...
def summarize(
    mechanisms: Sequence[Mechanism],
    *,
    angles_deg: Optional[_ArrayLike] = None,
    threads: Optional[int] = None,
    large: bool = False,
) -> Result: ...
def _contact(
    curve_a: Curve,
    body_a: Body,
    curve_b: Curve,
    body_b: Body,
    *,
    at: Optional[Tuple[float, float]] = None,
    guess: Optional[Tuple[float, float]] = None,
    length_scale: Optional[float] = None,
) -> Dict[str, Any]: ...
def _mechanism_from_json(text: str, base_dir: str, name: str) -> Mechanism: ...
def _curve_from_state(kind: str, args: List[float], chord: bool) -> Curve: ...
def _mechanism_from_text(text: str, base_dir: str, name: str, file: str) -> Mechanism: ...
def _studio_answer(what: str, body: str, name: str, folder: Optional[str] = None) -> Tuple[int, str, Optional[str]]: ...
def _studio_assets() -> Tuple[str, str, str]: ...
