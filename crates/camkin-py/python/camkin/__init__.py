"""camkin: exact contact kinematics of rotating planar curves and cam-follower analysis.

A thin layer over the camkin Rust library (K. Lee, *Efficient computation of the acceleration of
the contact point between rotating surfaces*, 2005): every number comes from the library, the same
code as the ``camkin`` command.

Cam-follower mechanisms::

    import numpy as np, camkin
    mech = camkin.paper_cam()                      # or Mechanism.from_toml("cam.toml")
    r = mech.analyze(np.arange(0, 360, 0.05))      # dict of arrays, keys carry units
    r["acceleration_cm_s2"]

Any two curves on moving bodies (for a multibody solver)::

    c = camkin.contact(camkin.Circle((0, 0), 2.0), camkin.Body(angular_velocity=10.0),
                       camkin.Circle((0, 0), 1.0), camkin.Body(position=(3.0, 0.0)))
    c.phi_q, c.gamma                               # the constraint row: phi_q · q̈ = gamma

Every result is a ``camkin.Result``: a dict whose keys carry their units, its tables NumPy
arrays, with ``to_pandas()``. The studio in a notebook: ``camkin.widget.Studio(mech)`` (needs
``pip install 'camkin[notebook]'``).

Conventions (angles counter-clockwise, left normals, σ, the gap's sign): see docs/gears.md and the
library's documentation.
"""

from dataclasses import dataclass as _dataclass
from typing import Any as _Any, Dict as _Dict, Optional as _Optional, Sequence as _Sequence, Tuple as _Tuple

import numpy as _np

from . import errors
from .results import Result
from ._camkin import (
    MAX_ANGLES,
    Body,
    Circle,
    Curve,
    Ellipse,
    Line,
    Mechanism,
    Point,
    Spline,
    System,
    motion_law,
    motion_laws,
    paper_cam,
    spline_variants,
    summarize,
)
from ._camkin import _contact
from .errors import CamkinError, CamkinWarning, ContactError, InputError, ResourceError

__all__ = [
    "Body",
    "CamkinError",
    "CamkinWarning",
    "Circle",
    "Contact",
    "ContactError",
    "Curve",
    "Ellipse",
    "InputError",
    "Line",
    "MAX_ANGLES",
    "Mechanism",
    "Point",
    "ResourceError",
    "Result",
    "Spline",
    "System",
    "contact",
    "errors",
    "motion_law",
    "motion_laws",
    "paper_cam",
    "spline_variants",
    "summarize",
    "synthesize",
]


@_dataclass(frozen=True)
class Contact:
    """Where two curves on bodies touch, and the contact's kinematics (all in the world frame).

    ``status`` is ``"touching"`` (|gap| within the contact tolerance), ``"apart"`` or
    ``"overlapping"`` (``gap`` > 0 apart, < 0 overlapping, with curves oriented material-on-the-
    left). ``u_a``, ``u_b`` are the pairing points' parameters, ``point_a``, ``point_b`` the points,
    ``normal`` the common normal (A's left normal).

    At a contact (or at a pairing given with ``at=``) the kinematics are set, else None:
    ``sigma`` (= t_A·t_B, ±1), curvatures ``kappa_a``, ``kappa_b``, the sliding rates
    ``sliding_rate_a``, ``sliding_rate_b`` (length/s along each curve relative to its body, eqs. 5,
    6) and parameter rates, the normal velocity, the normal accelerations ``normal_acceleration_a``
    (eq. 1) and ``normal_acceleration_b`` (eq. 2) with their material, Coriolis and relative terms,
    and the acceleration constraint (eq. 11) ``phi_q · q̈ = gamma`` with
    q = (x_A, y_A, θ_A, x_B, y_B, θ_B). ``acceleration_residual`` is ``phi_q · q̈ − gamma`` for the
    bodies' given accelerations (0 when they keep contact).
    """

    status: str
    gap: float
    u_a: float
    u_b: float
    point_a: _np.ndarray
    point_b: _np.ndarray
    normal: _np.ndarray
    iterations: int
    sigma: _Optional[float] = None
    kappa_a: _Optional[float] = None
    kappa_b: _Optional[float] = None
    metric_a: _Optional[float] = None
    metric_b: _Optional[float] = None
    sliding_rate_a: _Optional[float] = None
    sliding_rate_b: _Optional[float] = None
    param_rate_a: _Optional[float] = None
    param_rate_b: _Optional[float] = None
    normal_velocity: _Optional[float] = None
    normal_acceleration_a: _Optional[float] = None
    normal_acceleration_b: _Optional[float] = None
    normal_acceleration_a_terms: _Optional[_Dict[str, float]] = None
    normal_acceleration_b_terms: _Optional[_Dict[str, float]] = None
    phi_q: _Optional[_np.ndarray] = None
    gamma: _Optional[float] = None
    acceleration_residual: _Optional[float] = None

    @property
    def touching(self) -> bool:
        """The curves touch."""
        return self.status == "touching"


def contact(
    curve_a: Curve,
    body_a: Body,
    curve_b: Curve,
    body_b: Body,
    *,
    at: _Optional[_Tuple[float, float]] = None,
    guess: _Optional[_Tuple[float, float]] = None,
    length_scale: _Optional[float] = None,
) -> Contact:
    """The contact between ``curve_a`` on ``body_a`` and ``curve_b`` on ``body_b``.

    Without ``guess`` or ``at``: the nearest pair of pairing points by a global search (never a far
    pair when a nearer one exists). ``guess=(u_a, u_b)``: Newton's method from there (a solver's
    previous step). ``at=(u_a, u_b)``: the kinematics at exactly that pairing, searched for nothing.
    ``length_scale`` (default: the curves' size) sets the tolerances (1e-13 of it for positions,
    1e-9 for touching). Raises ``ContactError`` when the search stops without a pairing (two
    unbounded curves, no convergence) or the contact is conformal (the point is not determined).
    Lengths in the curves' one unit, angles in rad, time in s.

    Example::

        cam = camkin.Body(angular_velocity=10.0)                  # rad/s
        c = camkin.contact(camkin.Circle((0, 0), 2.0), cam, camkin.Circle((0, 0), 1.0), camkin.Body(position=(3.0, 0.0)))
        c.touching, c.phi_q, c.gamma                              # the row phi_q · q̈ = gamma
    """
    d = _contact(curve_a, body_a, curve_b, body_b, at=at, guess=guess, length_scale=length_scale)
    return Contact(**d)


def synthesize(
    *,
    segments: _Sequence[_Dict[str, _Any]],
    base_radius: float,
    follower: _Dict[str, _Any],
    speed_rpm: float,
    length_unit: str,
    direction: str = "ccw",
    dynamics: _Optional[_Dict[str, _Any]] = None,
) -> Mechanism:
    """A cam synthesised exactly from a motion program (``kind = "motion"`` in a mechanism file).

    ``segments`` is a list of dicts ``{"law": "cycloidal", "rise": 12.0, "degrees": 120}`` (laws:
    ``motion_laws()``; a ``"dwell"`` has no rise) covering 360° in all; ``base_radius`` and the
    rises are in ``length_unit`` (an arm's rises in degrees); ``follower`` is the ``[follower]``
    table as a dict. Check the result with ``mech.checks()`` (round trip, undercut, pressure angle).
    ``speed_rpm`` in rpm, ``degrees`` of the cam's turn.

    Example::

        program = [{"law": "cycloidal", "rise": 10.0, "degrees": 150}, {"law": "dwell", "degrees": 30},
                   {"law": "cycloidal", "rise": -10.0, "degrees": 150}, {"law": "dwell", "degrees": 30}]
        mech = camkin.synthesize(segments=program, base_radius=30.0, speed_rpm=500.0, length_unit="mm",
                                 follower={"kind": "translating-roller", "direction": [0.0, 1.0], "roller_radius": 8.0})
    """
    spec = {
        "length_unit": length_unit,
        "cam": {
            "speed_rpm": speed_rpm,
            "direction": direction,
            "profile": {"kind": "motion", "base_radius": base_radius, "segments": list(segments)},
        },
        "follower": dict(follower),
    }
    if dynamics is not None:
        spec["dynamics"] = dict(dynamics)
    return Mechanism.from_dict(spec)
