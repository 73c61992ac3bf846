"""Python against the command, bit for bit, on every example: the manufacturing output
(`camkin profile` ↔ `Mechanism.shop`), a measured profile's deviation (`camkin deviation` ↔
`Mechanism.deviation`), and a refusal where the command refuses."""

import subprocess

import numpy as np
import pytest

import camkin
from conftest import EXAMPLES, camkin_bin, csv_columns

EXAMPLE_FILES = sorted(p for p in EXAMPLES.glob("*.toml"))


def same_column(cells, values):
    """The command's CSV cells (shortest round-trip text) and Python's floats are the same numbers."""
    assert len(cells) == len(values)
    for c, v in zip(cells, values):
        assert float(c) == float(v) or (c == "" and np.isnan(v)), (c, v)


@pytest.mark.parametrize("path", EXAMPLE_FILES, ids=lambda p: p.stem)
def test_shop_output_is_the_commands(path, tmp_path):
    out = tmp_path / "shop"
    tool = ["--tool-radius", "1.0"] if path.stem in ("paper", "eccentric-roller", "tangent-cam") else []
    r = subprocess.run(
        [camkin_bin(), "profile", path, "--out", out, "--step", "2", *tool],
        capture_output=True, text=True,
    )
    if r.returncode == 2:
        # not a cam the command makes (a system, a gear pair): Python refuses it too
        with pytest.raises((camkin.InputError, AttributeError, TypeError)):
            camkin.Mechanism.from_toml(path).shop(step_deg=2.0)
        return
    assert r.returncode in (0, 3), r.stderr
    mech = camkin.Mechanism.from_toml(path)
    s = mech.shop(step_deg=2.0, tool_radius=1.0 if tool else None)
    assert isinstance(s, camkin.Result)
    if (out / "polar.csv").exists():
        cols = csv_columns((out / "polar.csv").read_text())
        assert list(cols) == list(s["polar"])
        for k in cols:
            same_column(cols[k], s["polar"][k])
    else:
        assert s["polar"] is None and s["polar_missing"]
    for name in ("pitch", "cutter"):
        f = out / f"{name}.csv"
        assert f.exists() == (s[name] is not None), name
        if f.exists():
            cols = csv_columns(f.read_text())
            assert list(cols) == list(s[name])
            for k in cols:
                same_column(cols[k], s[name][k])
    assert (out / "profile.dxf").read_text() == s["dxf"]
    if tool:
        undercut = s["cutter_check"]["undercut"]
        assert undercut == ("UNDERCUT" in r.stdout)
        assert (r.returncode == 3) == undercut


def test_the_dxf_is_written_to_a_new_path_and_never_over_a_file(tmp_path):
    mech = camkin.Mechanism.from_toml(EXAMPLES / "eccentric-roller.toml")
    p = tmp_path / "cam.dxf"
    s = mech.shop(dxf_path=p)
    assert p.read_text() == s["dxf"]
    p.write_text("keep me")
    with pytest.raises(camkin.InputError) as e:
        mech.shop(dxf_path=p)
    assert e.value.field == "dxf_path" and "exists" in str(e.value)
    assert p.read_text() == "keep me"
    assert [q.name for q in tmp_path.iterdir()] == ["cam.dxf"]  # no temporary file left


@pytest.mark.parametrize("bad,field", [(-1.0, "tool_radius"), (float("nan"), "tool_radius")])
def test_a_bad_tool_radius_is_named(bad, field):
    with pytest.raises(camkin.InputError) as e:
        camkin.paper_cam().shop(tool_radius=bad)
    assert e.value.field == field and "tool_radius" in str(e.value)


def measured_points(mech, bump):
    """The design's polar points with a 3-lobed bump of `bump` in radius (a known deviation)."""
    polar = mech.shop(step_deg=1.0)["polar"]
    unit = mech.length_unit
    x, y = polar[f"x_{unit}"], polar[f"y_{unit}"]
    phi = np.arctan2(y, x)
    r = np.hypot(x, y) + bump * np.cos(3 * phi)
    return np.column_stack([r * np.cos(phi), r * np.sin(phi)])


@pytest.mark.parametrize("name", ["eccentric-roller", "paper", "oscillating-roller"])
def test_deviation_is_the_commands(name, tmp_path):
    path = EXAMPLES / f"{name}.toml"
    mech = camkin.Mechanism.from_toml(path)
    size = float(np.max(np.abs(mech.profile())))
    bump = 1e-3 * size
    pts = measured_points(mech, bump)
    f = tmp_path / "measured.csv"
    np.savetxt(f, pts, delimiter=",", fmt="%.17g")
    out = tmp_path / "dev"
    subprocess.run(
        [camkin_bin(), "deviation", f, "--against", path, "--out", out, "--step", "2"],
        capture_output=True, text=True, check=True,
    )
    for source in (f, pts):  # a path and an array give the same
        d = mech.deviation(source, step_deg=2.0)
        for table, csvname in (("radius", "radius.csv"), ("motion", "motion.csv")):
            cols = csv_columns((out / csvname).read_text())
            assert list(cols) == list(d[table])
            for k in cols:
                same_column(cols[k], d[table][k])
    # the known bump is found: the largest radius deviation is the bump, to the fit's noise
    assert abs(abs(d["radius_largest"]) - bump) < 1e-9 * size
    assert d["harmonics"] >= 3


@pytest.mark.parametrize(
    "bad",
    [[[1.0, "x"]] * 10, [[1.0, None]] * 10, [[1 + 2j, 0.0]] * 10, [1.0, 2.0, 3.0], "no-such-file.csv"],
    ids=["string", "None", "complex", "flat", "missing-file"],
)
def test_bad_measured_points_are_named(bad):
    with pytest.raises(camkin.InputError) as e:
        camkin.paper_cam().deviation(bad)
    assert e.value.field.startswith("measured"), e.value.field


def test_results_give_dataframes():
    pd = pytest.importorskip("pandas")
    mech = camkin.paper_cam()
    r = mech.analyze(np.arange(0.0, 360.0, 10.0))
    df = r.to_pandas()
    assert isinstance(df, pd.DataFrame) and len(df) == 36
    assert list(df.columns)[:2] == ["angle_deg", "lift_cm"] or "lift_cm" in df.columns
    assert (df["acceleration_cm_s2"].to_numpy() == r["acceleration_cm_s2"]).all()
    s = mech.shop(step_deg=5.0)
    assert len(s["polar"].to_pandas()) == 72
    with pytest.raises(ValueError, match="polar"):
        s.to_pandas()


SYSTEM_FILES = sorted(p for p in EXAMPLE_FILES if "[[bod" in p.read_text())


@pytest.mark.parametrize("path", SYSTEM_FILES, ids=lambda p: p.stem)
def test_system_forces_are_the_commands(path, tmp_path):
    out = tmp_path / "forces"
    r = subprocess.run(
        [camkin_bin(), "forces", path, "--out", out, "--step", "2", "--margin", "5", "--target-rpm", "9000"],
        capture_output=True, text=True,
    )
    system = camkin.System.from_toml(path)
    if r.returncode == 2 and "--duration" in r.stderr:
        # no driver of an angle (a benchmark released from a state): its forces are not over a
        # revolution, and Python says so too, naming the setting a run in time needs
        with pytest.raises(camkin.InputError) as e:
            system.forces(step_deg=2.0)
        assert e.value.field == "duration"
        return
    if r.returncode == 2:
        # no [dynamics]: Python refuses it too, naming it
        assert "[dynamics]" in r.stderr
        with pytest.raises(camkin.InputError) as e:
            system.forces(step_deg=2.0)
        assert e.value.field == "dynamics"
        return
    assert r.returncode in (0, 3), r.stderr
    f = system.forces(step_deg=2.0, margin=5.0, target_rpm=9000.0)
    cols = csv_columns((out / "forces.csv").read_text())
    assert list(cols) == list(f["columns"])
    for k in cols:
        same_column(cols[k], f["columns"][k])
    # the checks fail in both or in neither, on the same contacts
    assert (r.returncode == 3) == bool(f["failures"]), (r.stderr, f["failures"])
    for failure in f["failures"]:
        (kind, body), = failure.items()
        assert f'contact "{body["contact"]}"' in r.stderr, (failure, r.stderr)
        if kind == "NoFollow":  # the same sweep: the same speed, as the command rounds it
            assert f"at {round(body['speed_rpm'], 1):g} rpm, below the target 9000 rpm" in r.stderr, r.stderr


def test_system_forces_refuse_bad_checks():
    s = camkin.System.from_toml(EXAMPLES / "valve-train.toml")
    with pytest.raises(camkin.InputError) as e:
        s.forces(allowable_mpa=-3.0)
    assert e.value.field == "allowable_mpa"
