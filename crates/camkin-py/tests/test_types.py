"""The type stubs checked by a type checker: mypy --strict on the package's Python, stubtest of
the extension module's stubs against the module itself (every function, class, parameter and
default), and a user's typed code against the stubs."""

import subprocess
import sys

from conftest import ROOT

PACKAGE = ROOT / "crates" / "camkin-py" / "python"

USER_CODE = '''
import numpy as np
import camkin
from camkin.widget import Studio

mech: camkin.Mechanism = camkin.Mechanism.from_toml("examples/paper.toml")
r: camkin.Result = mech.analyze(np.arange(0.0, 360.0, 1.0), per="s")
lift = r["lift_cm"]
shop: camkin.Result = mech.shop(step_deg=2.0, tool_radius=1.0)
dev: camkin.Result = mech.deviation("examples/measured-eccentric.csv", tolerance=0.01)
w: Studio = Studio(mech)
m2: camkin.Mechanism = w.mechanism
sys_: camkin.System = camkin.System.from_toml("examples/valve-train.toml")
samples, events = sys_.simulate(revolutions=1.0)
c: camkin.Contact = camkin.contact(camkin.Circle((0, 0), 2.0), camkin.Body(), camkin.Circle((0, 0), 1.0), camkin.Body(position=(3.0, 0.0)))
'''

BAD_CODE = '''
import camkin
mech = camkin.paper_cam()
mech.analyze("ninety")
mech.shop(tool_radius="10mm")
'''


def mypy(*args, cwd=None):
    return subprocess.run([sys.executable, "-m", "mypy", *args], capture_output=True, text=True, cwd=cwd)


def test_the_package_passes_mypy_strict():
    r = mypy("--strict", "camkin", cwd=PACKAGE)
    assert r.returncode == 0, r.stdout + r.stderr


def test_the_stubs_are_the_extension_modules(tmp_path):
    # from a folder without the package's source, so the installed module is the one checked
    r = subprocess.run(
        [sys.executable, "-m", "mypy.stubtest", "camkin._camkin"], capture_output=True, text=True, cwd=tmp_path
    )
    assert r.returncode == 0, r.stdout + r.stderr


def test_typed_user_code_checks_and_mistakes_are_caught(tmp_path):
    good = tmp_path / "good.py"
    good.write_text(USER_CODE)
    r = mypy("--strict", str(good), cwd=tmp_path)
    assert r.returncode == 0, r.stdout + r.stderr
    bad = tmp_path / "bad.py"
    bad.write_text(BAD_CODE)
    r = mypy(str(bad), cwd=tmp_path)
    assert r.returncode == 1 and r.stdout.count("error:") == 2, r.stdout
