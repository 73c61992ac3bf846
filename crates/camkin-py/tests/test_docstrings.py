"""Every public function and method of the package says its units and shows an example, and every
example runs (from a folder where `examples/` is the repository's): docs that cannot rot."""

import inspect
import math
import os
import re

import numpy as np
import pytest

import camkin
from camkin.widget import Studio
from conftest import ROOT

UNITS = re.compile(
    r"\b(mm|cm|rad|rpm|degrees?|MPa|N·m|m/s|µm|kg|length unit|unit|units|°|s\b|Pa|N\b|K\b|W\b)|°|/s"
)


def public_callables():
    out = []
    for name in camkin.__all__:
        obj = getattr(camkin, name)
        if inspect.isclass(obj):
            if issubclass(obj, (BaseException, Warning)) or name == "Contact":
                continue
            for m, v in vars(obj).items():
                if m.startswith("_") or isinstance(v, property) or type(v).__name__ == "getset_descriptor":
                    continue
                out.append((f"{name}.{m}", getattr(obj, m)))
        elif callable(obj):
            out.append((name, obj))
    out.append(("widget.Studio", Studio))
    out.append(("widget.Studio.from_toml", Studio.from_toml))
    return out


def example(doc):
    """The code of a docstring's `Example::` block (its indented lines) or its `>>>` lines."""
    lines = doc.split("\n")
    if "Example::" in doc:
        k = next(i for i, l in enumerate(lines) if l.strip() == "Example::") + 1
        block = []
        for line in lines[k:]:
            if line.strip() == "" and not block:
                continue
            if line.strip() and not line.startswith("    "):
                break
            block.append(line)
        return "\n".join(l[4:] if l.startswith("    ") else l for l in block).strip()
    return "\n".join(l.strip()[4:] for l in lines if l.strip().startswith(">>> "))


CALLABLES = public_callables()


@pytest.mark.parametrize("name,obj", CALLABLES, ids=[n for n, _ in CALLABLES])
def test_every_public_function_says_its_units_and_shows_an_example_that_runs(name, obj, tmp_path, monkeypatch):
    doc = inspect.getdoc(obj) or ""
    assert UNITS.search(doc), f"{name}: no unit named in its docstring"
    code = example(doc)
    assert len(code.split("\n")) >= 1 and code, f"{name}: no example"
    os.symlink(ROOT / "examples", tmp_path / "examples")
    monkeypatch.chdir(tmp_path)
    namespace = {"camkin": camkin, "np": np, "math": math, "Studio": Studio}
    import warnings

    with warnings.catch_warnings():
        warnings.simplefilter("ignore", camkin.CamkinWarning)
        exec(compile(code, f"<{name} example>", "exec"), namespace)


def test_the_guide_lists_every_public_function():
    section = (ROOT / "docs" / "python.md").read_text()
    missing = []
    for name, _ in CALLABLES:
        short = name.split(".")[-1]
        if f"`{short}" not in section and f"{short}(" not in section and f".{short}`" not in section:
            missing.append(name)
    assert not missing, f"not in docs/python.md: {missing}"
