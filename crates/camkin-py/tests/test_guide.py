"""The guide cannot rot: every fenced `sh` command of README.md and docs/*.md runs as it is written
(the release `camkin` for `camkin …` and `cargo run --release -- …`), from a scratch folder where
`examples/` is the repository's, one folder a page so a page's later commands see its earlier
files; it must exit 0, or the code its comment names (`# exit 3`), and print what its comment
quotes (`# prints "jump speed: 1511 rpm"`). Every fenced `python` block
runs too, in order, in the same folder. Lines that set up a machine (`scripts/…`, `pip install`,
`cargo install`, the fuzzers) are not run; a command the harness does not know fails the test."""

import os
import pathlib
import re
import shlex
import subprocess
import warnings

import pytest

import camkin
from conftest import ROOT, camkin_bin

PAGES = [ROOT / "README.md"] + sorted((ROOT / "docs").glob("*.md"))
# set-up commands, shown for people, not run here
NOT_RUN = ("scripts/", "pip install", "cargo install", "cd ", "cargo +nightly", ".ci/run")
# commands that do not end by themselves: their arguments are checked, the server not started
SERVERS = ("serve",)


def blocks(text, info):
    """The fenced blocks of `text` whose info string is `info`: (first line number, body)."""
    out, lines, k = [], text.split("\n"), 0
    while k < len(lines):
        if lines[k].strip() == "```" + info:
            j = k + 1
            while not lines[j].startswith("```"):
                j += 1
            out.append((k + 2, "\n".join(lines[k + 1 : j])))
            k = j
        k += 1
    return out


def commands(page):
    """The page's shell commands: (line, argv, expected exit code, quoted output)."""
    out = []
    for start, body in blocks(page.read_text(), "sh"):
        for n, line in enumerate(body.split("\n")):
            if not line.strip():
                continue
            code, _, comment = line.partition(" #")
            expect = int(m.group(1)) if (m := re.search(r"\bexit (\d+)\b", comment)) else 0
            quoted = re.findall(r'prints "([^"]+)"', comment)
            argv = shlex.split(code)
            if code.startswith(NOT_RUN):
                continue
            if argv[:4] == ["cargo", "run", "--release", "--"]:
                argv = ["camkin"] + argv[4:]
            assert argv[0] == "camkin", f"{page.name}:{start + n}: a command the guide's test does not know: {line}"
            out.append((start + n, argv, expect, quoted))
    return out


CASES = [(p, commands(p)) for p in PAGES]


@pytest.mark.parametrize("page,cmds", [c for c in CASES if c[1]], ids=[p.name for p, c in CASES if c])
def test_every_command_of_the_page_runs_as_written(page, cmds, tmp_path):
    os.symlink(ROOT / "examples", tmp_path / "examples")
    for line, argv, expect, quoted in cmds:
        if argv[1] in SERVERS:
            # the file it would serve is read and valid
            files = [a for a in argv[2:] if a.endswith(".toml")]
            for f in files:
                camkin.Mechanism.from_toml(tmp_path / f) if "[[bod" not in (tmp_path / f).read_text() else camkin.System.from_toml(tmp_path / f)
            continue
        r = subprocess.run([camkin_bin(), *argv[1:]], cwd=tmp_path, capture_output=True, text=True, timeout=300)
        assert r.returncode == expect, f"{page.name}:{line}: {' '.join(argv)} exited {r.returncode}, the guide says {expect}\n{r.stderr[-2000:]}"
        for q in quoted:
            assert q in r.stdout + r.stderr, f"{page.name}:{line}: {' '.join(argv)} does not print {q!r}"


PY_CASES = [(p, blocks(p.read_text(), "python")) for p in PAGES]


@pytest.mark.parametrize(
    "page,code", [c for c in PY_CASES if c[1]], ids=[p.name for p, c in PY_CASES if c]
)
def test_every_python_block_of_the_page_runs(page, code, tmp_path, monkeypatch):
    os.symlink(ROOT / "examples", tmp_path / "examples")
    monkeypatch.chdir(tmp_path)
    namespace = {}
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", camkin.CamkinWarning)
        for line, body in code:
            exec(compile(body, f"{page.name}:{line}", "exec"), namespace)


def test_the_guide_links_resolve():
    """Every relative link of the guide's pages names a file that exists."""
    broken = []
    for page in PAGES:
        for target in re.findall(r"\]\(([^)#\s]+)(?:#[^)]*)?\)", page.read_text()):
            if re.match(r"[a-z]+:", target):
                continue
            if not (page.parent / target).exists():
                broken.append(f"{page.relative_to(ROOT)} → {target}")
    assert not broken, broken
