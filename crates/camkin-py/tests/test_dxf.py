"""Issue 49: `camkin profile`'s DXF read by an independent reader (ezdxf, from PyPI): every
example's file audits clean, declares every layer it uses in its LAYER table (PROFILE, PITCH
for a roller, CENTRE), carries its unit, and has the centre mark and the 0° line on CENTRE."""

import ezdxf
from ezdxf import recover
import pytest

from conftest import EXAMPLES, run_cli

CAMS = sorted(
    p.name for p in EXAMPLES.glob("*.toml")
    if "[[body]]" not in p.read_text() and "gear" not in p.name and "fzg" not in p.name
)


@pytest.mark.parametrize("example", CAMS)
def test_every_profile_dxf_is_a_clean_drawing(example, tmp_path):
    out = tmp_path / "shop"
    run_cli("profile", EXAMPLES / example, "--out", out)
    doc, auditor = recover.readfile(str(out / "profile.dxf"))
    assert not auditor.errors, [str(e) for e in auditor.errors]
    declared = {layer.dxf.name for layer in doc.layers}
    used = {e.dxf.layer for e in doc.modelspace()}
    assert used <= declared, (used, declared)
    assert {"PROFILE", "CENTRE"} <= used
    lines = [e for e in doc.modelspace() if e.dxftype() == "LINE"]
    assert all(e.dxf.layer == "CENTRE" for e in lines)
    # the centre mark crosses at the axis; the 0° line runs from it along +x
    assert any(e.dxf.start.isclose((0, 0, 0)) and e.dxf.end.y == 0 and e.dxf.end.x > 0 for e in lines)
    assert doc.header.get("$INSUNITS") in (1, 4, 5, 6)
    assert ezdxf.__version__
