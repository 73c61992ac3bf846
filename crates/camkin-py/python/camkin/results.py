"""Results: dicts whose keys carry units (``"acceleration_cm_s2"``), their tables as NumPy
arrays, with ``to_pandas()`` for people who want a DataFrame (pandas is optional, not a
dependency of camkin)."""

from __future__ import annotations

from collections import Counter
from typing import Any

import numpy as _np

__all__ = ["Result"]


class Result(dict):  # type: ignore[type-arg]
    """A result of camkin: a dict (keys with units), nested results too.

    ``to_pandas()`` gives its table — the entries that are 1-D arrays of the table's length (the
    most common length among them) — as a ``pandas.DataFrame``, one column per key, in order.

    Example::

        r = camkin.paper_cam().analyze(range(0, 360, 10))
        df = r.to_pandas()          # columns angle_deg, lift_cm, …
    """

    def __init__(self, *args: Any, **kwargs: Any) -> None:
        super().__init__(*args, **kwargs)
        for k, v in self.items():
            if type(v) is dict:
                self[k] = Result(v)

    def to_pandas(self) -> Any:
        """The table of this result as a ``pandas.DataFrame`` (needs pandas installed); its
        columns keep their units in their names.

        Example::

            df = camkin.paper_cam().analyze(np.arange(0.0, 360.0, 1.0)).to_pandas()
            df[["angle_deg", "lift_cm", "acceleration_cm_s2"]].describe()
        """
        try:
            import pandas as pd
        except ImportError as e:  # pragma: no cover - depends on the environment
            raise ImportError("to_pandas() needs pandas: pip install pandas") from e
        arrays = {k: v for k, v in self.items() if isinstance(v, _np.ndarray) and v.ndim == 1}
        if not arrays:
            nested = [k for k, v in self.items() if isinstance(v, Result)]
            hint = f"; its tables: {', '.join(repr(k) for k in nested)}" if nested else ""
            raise ValueError(f"this result has no table of its own{hint}")
        n, _ = Counter(len(v) for v in arrays.values()).most_common(1)[0]
        return pd.DataFrame({k: v for k, v in arrays.items() if len(v) == n})
