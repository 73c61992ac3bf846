"""Shared helpers: the repository's folders and the `camkin` command the package is compared to."""

import csv
import io
import os
import pathlib
import subprocess

import pytest

ROOT = pathlib.Path(__file__).resolve().parents[3]
EXAMPLES = ROOT / "examples"


def camkin_bin():
    return os.environ.get("CAMKIN_BIN", str(ROOT / "target" / "release" / "camkin"))


def run_cli(*args, cwd=None):
    """Runs the command; returns its standard output (text)."""
    out = subprocess.run([camkin_bin(), *map(str, args)], capture_output=True, text=True, cwd=cwd)
    assert out.returncode == 0, out.stderr
    return out.stdout


def csv_columns(text):
    """CSV text as {column: [cell text]}."""
    rows = list(csv.reader(io.StringIO(text)))
    head, body = rows[0], rows[1:]
    return {h: [r[k] for r in body] for k, h in enumerate(head)}


@pytest.fixture
def paper_toml():
    return EXAMPLES / "paper.toml"
