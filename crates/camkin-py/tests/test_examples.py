"""The Python examples run as a newcomer runs them and make their figures."""

import subprocess
import sys

from conftest import ROOT


def test_figure4_example(tmp_path):
    out = tmp_path / "fig4.png"
    subprocess.run([sys.executable, ROOT / "examples/python/figure4.py", out], check=True)
    assert out.stat().st_size > 10_000


def test_tolerance_study_example(tmp_path):
    out = tmp_path / "tol.png"
    r = subprocess.run(
        [sys.executable, ROOT / "examples/python/tolerance_study.py", "--designs", "400", "--out", out],
        check=True, capture_output=True, text=True,
    )
    assert "designs per second" in r.stdout and "through Dask" in r.stdout, r.stdout
    assert out.stat().st_size > 10_000
