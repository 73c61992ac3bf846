"""camkin's exceptions and warnings.

Every error camkin raises is a ``CamkinError``:

- ``InputError`` (also a ``ValueError``): bad input. ``.field`` names it as the mechanism file does
  (``"follower.roller_radius"``, ``"cam.profile.points[3]"``) or by the argument's name
  (``"angles_deg"``); ``.value`` is the value given, as text (``None`` when it is missing);
  ``.line`` and ``.column`` (1-based) place it in a mechanism file or TOML text (``None`` for
  other input).
- ``ContactError`` (also an ``ArithmeticError``): the numerics stopped, and the message says why
  (conformal contact, no convergence, a follower that cannot follow the profile).
- ``ResourceError``: work refused up front, with the estimate; pass ``large=True`` to run it.
"""

from typing import Optional

__all__ = ["CamkinError", "InputError", "ContactError", "ResourceError", "CamkinWarning"]


class CamkinError(Exception):
    """Base class of camkin's errors."""


class _Placed:
    """What ``InputError`` and ``CamkinWarning`` say: the message, the field (a dotted path as
    the files write it, or an argument's name), the value (text, or None) and the place in a
    mechanism's text (1-based line and column, or None)."""

    message: str
    field: Optional[str]
    value: Optional[str]
    line: Optional[int]
    column: Optional[int]

    def _place(
        self,
        message: str,
        field: Optional[str],
        value: Optional[str],
        line: Optional[int],
        column: Optional[int],
    ) -> None:
        self.message = message
        self.field = field
        self.value = value
        self.line = line
        self.column = column

    def __str__(self) -> str:
        return self.message


class InputError(_Placed, CamkinError, ValueError):
    """Bad input: ``.field`` names the field, ``.value`` the value given (text, or None);
    ``.line`` and ``.column`` its place in a mechanism file's text (1-based, or None)."""

    def __init__(
        self,
        message: str,
        field: Optional[str] = None,
        value: Optional[str] = None,
        line: Optional[int] = None,
        column: Optional[int] = None,
    ) -> None:
        super().__init__(message, field, value, line, column)
        self._place(message, field, value, line, column)

    def add_note(self, note: str) -> None:
        """Python's note; a bad argument's "while processing 'NAME'" (added by the extension
        module) names the field when the error did not: ``.field`` becomes ``NAME`` and the
        message starts with it."""
        prefix, suffix = "while processing '", "'"
        if not self.field and note.startswith(prefix) and note.endswith(suffix):
            self.field = note[len(prefix) : -len(suffix)]
            self.message = f"{self.field} = {self.message}" if self.value is None else f"{self.field}: {self.message}"
            self.args = (self.message, self.field, self.value, self.line, self.column)
            return
        if hasattr(super(), "add_note"):
            super().add_note(note)


class ContactError(CamkinError, ArithmeticError):
    """The contact could not be computed; the message says why the solver stopped."""

    def __init__(self, message: str) -> None:
        super().__init__(message)
        self.message = message

    def __str__(self) -> str:
        return self.message


class ResourceError(CamkinError):
    """Work refused up front (hours or gigabytes), with the estimate."""

    def __init__(self, message: str) -> None:
        super().__init__(message)
        self.message = message

    def __str__(self) -> str:
        return self.message


class CamkinWarning(_Placed, UserWarning):
    """A valid input that is probably not what was meant, or a result to read with care (a
    contact that jumps). Its fields are an ``InputError``'s: ``.field`` names what it is about
    (``"cam.profile.points"``, ``"angles_deg"``), ``.value`` the value (text, or None), ``.line``
    and ``.column`` its place in a mechanism file's text (1-based, or None)."""

    def __init__(
        self,
        message: str,
        field: Optional[str] = None,
        value: Optional[str] = None,
        line: Optional[int] = None,
        column: Optional[int] = None,
    ) -> None:
        super().__init__(message)
        self._place(message, field, value, line, column)
