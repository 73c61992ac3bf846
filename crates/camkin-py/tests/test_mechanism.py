"""Mechanisms from files and dicts; analyze equals `camkin analyze` to the last bit."""

import math
import os
import pathlib
import pickle

import numpy as np
import pytest

import camkin
from conftest import EXAMPLES, csv_columns, run_cli

# every example the command analyses (the dynamics examples share their geometry)
# mechanism files (a system file, [[body]] …, is camkin.System's)
EXAMPLE_FILES = sorted(p.name for p in EXAMPLES.glob("*.toml") if "[[body]]" not in p.read_text())


def same_cells(py_col, cli_cells, name):
    """A numeric column against the CSV's text: equal as float64, NaN where the cell is empty."""
    assert len(py_col) == len(cli_cells), name
    for k, (x, c) in enumerate(zip(py_col, cli_cells)):
        if c == "":
            assert math.isnan(x), (name, k, x)
        else:
            # the command writes the shortest text that reads back as the same float64
            assert float(c) == x, (name, k, x, c)


@pytest.mark.parametrize("name", EXAMPLE_FILES)
def test_analyze_equals_the_command_csv_bit_for_bit(name):
    path = EXAMPLES / name
    mech = camkin.Mechanism.from_toml(path)
    angles = np.arange(0.0, 360.0, 0.5)
    r = mech.analyze(angles)
    cli = csv_columns(run_cli("analyze", path, "--angles", "0:360:0.5"))
    assert list(r) == list(cli), "the same columns in the same order"
    for col, cells in cli.items():
        if col in ("found", "error", "corner"):
            assert [("" if v is None else v) for v in r[col]] == cells, col
        elif col == "at_node":
            assert [("1" if v else "0") if c != "" else "" for v, c in zip(r[col], cells)] == cells
        else:
            same_cells(r[col], cells, col)


@pytest.mark.parametrize("per,unit", [("deg", "deg"), ("s", "rad"), ("deg", "rad")])
def test_per_degree_and_radians_equal_the_command(per, unit):
    path = EXAMPLES / "oscillating-roller.toml"
    r = camkin.Mechanism.from_toml(path).analyze(np.arange(0.0, 360.0, 2.0), per=per, angle_unit=unit)
    cli = csv_columns(run_cli("analyze", path, "--angles", "0:360:2", "--per", per, "--angle-unit", unit))
    assert list(r) == list(cli)
    for col, cells in cli.items():
        if col not in ("found", "error", "at_node"):
            same_cells(r[col], cells, col)


def test_angle_list_equals_the_command_at_list():
    path = EXAMPLES / "paper.toml"
    at = [0.0, 45.0, 90.0, 350.5, 12.25]
    r = camkin.Mechanism.from_toml(path).analyze(at)
    cli = csv_columns(run_cli("analyze", path, "--at", ",".join(map(str, at))))
    for col in ("position_cm", "acceleration_cm_s2", "pressure_angle_deg", "sliding_rate_cam_cm_s"):
        same_cells(r[col], cli[col], col)


def test_paper_cam_is_the_example_file_and_gives_the_paper_curve():
    a = camkin.paper_cam()
    b = camkin.Mechanism.from_toml(EXAMPLES / "paper.toml")
    assert a.to_dict() == b.to_dict()
    r = a.analyze(np.arange(0, 360, 0.05))
    assert r["acceleration_cm_s2"].shape == (7200,)
    # the paper's values at 45°: position 4.448456 cm, acceleration −6291.918 cm/s² (the
    # library's doc example, from the paper's section 3)
    one = a.analyze(45.0)
    assert abs(one["position_cm"] - 4.448456) < 1e-6
    assert abs(one["acceleration_cm_s2"] + 6291.918) < 1e-3


def test_dtypes_shapes_and_scalars():
    m = camkin.paper_cam()
    r = m.analyze(np.arange(0, 10, 1.0))
    for k, v in r.items():
        assert isinstance(v, np.ndarray) and v.shape == (10,), k
        if k in ("found", "error"):
            assert v.dtype == object
        elif k == "at_node":
            assert v.dtype == np.bool_
        else:
            assert v.dtype == np.float64, k
    s = m.analyze(10.0)
    assert isinstance(s["acceleration_cm_s2"], float) and s["error"] is None
    # a number gives the row an array gives (a cold query; the sweep's first row is one too)
    assert s["acceleration_cm_s2"] == m.analyze([10.0])["acceleration_cm_s2"][0]
    assert m.analyze(np.float32(3.0))["angle_deg"] == 3.0
    assert m.analyze([])["position_cm"].shape == (0,)
    # an integer array is converted
    assert m.analyze(np.arange(3))["angle_deg"].dtype == np.float64


def test_rows_that_cannot_be_computed_are_nan_with_the_reason():
    text = """length_unit = "mm"
[cam]
speed_rpm = 10
[cam.profile]
kind = "circle"
center = [0.8, 0]
radius = 1
[follower]
kind = "translating-knife"
offset = 1.5
"""
    m = camkin.Mechanism.from_toml(text)
    r = m.analyze([0.0, 90.0])
    assert "misses the cam" in r["error"][0] and np.isnan(r["acceleration_mm_s2"][0])
    assert r["error"][1] is None and np.isfinite(r["acceleration_mm_s2"][1])
    with pytest.raises(camkin.ContactError, match="misses the cam"):
        m.analyze([0.0, 90.0], strict=True)


def test_from_toml_takes_paths_pathlike_and_text(tmp_path):
    text = (EXAMPLES / "paper.toml").read_text()
    a = camkin.Mechanism.from_toml(str(EXAMPLES / "paper.toml"))
    b = camkin.Mechanism.from_toml(pathlib.Path(EXAMPLES / "paper.toml"))
    c = camkin.Mechanism.from_toml(text)
    assert a.to_dict() == b.to_dict() == c.to_dict()
    # a points file is read from the mechanism file's folder, wherever Python runs
    cwd = os.getcwd()
    try:
        os.chdir(tmp_path)
        m = camkin.Mechanism.from_toml(EXAMPLES / "oscillating-flat.toml")
        assert m.to_dict()["cam"]["profile"]["kind"] == "points-file"
        assert np.isfinite(m.analyze(10.0)["acceleration_deg_s2"])
        # and so is a pickled copy's
        m2 = pickle.loads(pickle.dumps(m))
        assert m2.analyze(10.0)["acceleration_deg_s2"] == m.analyze(10.0)["acceleration_deg_s2"]
    finally:
        os.chdir(cwd)


def test_dict_round_trip_and_toml_round_trip():
    for name in EXAMPLE_FILES:
        m = camkin.Mechanism.from_toml(EXAMPLES / name)
        d = m.to_dict()
        m2 = camkin.Mechanism.from_dict(d, base_dir=str(EXAMPLES))
        assert m2.to_dict() == d
        # text has no folder: a mechanism reading a file (a points file's path, a lift table's
        # file) is read back through its dict and folder instead
        reads = "'path'" in str(d) or "'file'" in str(d)
        m3 = m2 if reads else camkin.Mechanism.from_toml(m.to_toml())
        assert m3.to_dict() == d


def test_properties_and_travel():
    m = camkin.Mechanism.from_toml(EXAMPLES / "eccentric-roller.toml")
    assert m.length_unit in ("mm", "cm", "m", "in")
    assert m.follower_kind == "translating-roller" and not m.oscillating
    u = m.length_unit
    # an eccentric circle under a roller on a line through the axis: the stroke is twice the
    # eccentricity
    d = m.to_dict()
    d["follower"]["offset"] = 0.0
    t = camkin.Mechanism.from_dict(d).travel()
    e = math.hypot(*d["cam"]["profile"]["center"])
    assert abs(t[f"stroke_{u}"] - 2 * e) < 1e-9 * d["cam"]["profile"]["radius"]
    # the rest and peak angles in degrees, where the lift is least and greatest (the disc's
    # centre turned away from and towards the roller: 180° apart), against a scan of analyze
    mech = camkin.Mechanism.from_dict(d)
    grid = np.arange(0.0, 360.0, 0.01)
    lift = mech.analyze(grid)[f"lift_{u}"]
    for key, k in (("rest_angle_deg", np.argmin(lift)), ("peak_angle_deg", np.argmax(lift))):
        assert abs((t[key] - grid[k] + 180.0) % 360.0 - 180.0) < 0.02, (key, t[key], grid[k])
    assert abs((t["peak_angle_deg"] - t["rest_angle_deg"]) % 360.0 - 180.0) < 1e-6
    # an arm's positions in degrees too
    arm = camkin.Mechanism.from_toml(EXAMPLES / "oscillating-roller.toml")
    ta = arm.travel()
    r = arm.analyze(grid)
    pos = [k for k in r if k.startswith("position_")][0]
    assert pos == "position_deg"
    k = np.argmin(np.abs(grid - ta["rest_angle_deg"]))
    assert abs(ta["rest_deg"] - r[pos][k]) < 1e-3, (ta, r[pos][k])


def test_mechanisms_are_immutable_and_pickle():
    m = camkin.paper_cam()
    with pytest.raises(AttributeError):
        m.speed_rpm = 5.0
    for name in EXAMPLE_FILES:
        m = camkin.Mechanism.from_toml(EXAMPLES / name)
        m2 = pickle.loads(pickle.dumps(m))
        assert m2 == m and m2.to_dict() == m.to_dict()
        a, b = m.analyze(np.arange(0, 360, 5.0)), m2.analyze(np.arange(0, 360, 5.0))
        key = [k for k in a if k.startswith("acceleration_")][0]
        assert np.array_equal(a[key], b[key], equal_nan=True)


def test_with_nodes_replaces_the_spline_nodes():
    m = camkin.paper_cam()
    nodes = np.array(m.to_dict()["cam"]["profile"]["points"])
    same = m.with_nodes(nodes)
    assert same.to_dict() == m.to_dict()
    moved = m.with_nodes(nodes * 1.1)
    # scale invariance: lengths scale by 1.1 with the nodes, so do positions and accelerations
    a = m.analyze([10.0, 100.0])
    b = moved.analyze([10.0, 100.0])
    assert np.allclose(b["position_cm"], 1.1 * a["position_cm"], rtol=1e-12)
    assert np.allclose(b["acceleration_cm_s2"], 1.1 * a["acceleration_cm_s2"], rtol=1e-10)


def test_uneven_nodes_warn():
    d = camkin.paper_cam().to_dict()
    d["cam"]["profile"]["points"] = [[5, 0], [4.9, 1], [0, 4], [-4, 0], [0, -4]]
    with pytest.warns(camkin.CamkinWarning, match="unevenly spaced"):
        camkin.Mechanism.from_dict(d)


def test_contacts_equal_the_command_csv_bit_for_bit():
    """Every contact of the 20/42 pair over a mesh cycle: the same rows as `camkin contacts`."""
    path = EXAMPLES / "gear-pair-20-42.toml"
    mech = camkin.Mechanism.from_toml(path)
    r = mech.contacts(np.arange(0.0, 18.0, 0.5))
    cli = csv_columns(run_cli("contacts", path, "--angles", "0:18:0.5"))
    assert list(r) == list(cli), "the same columns in the same order"
    for col, cells in cli.items():
        if col in ("curve", "corner", "error"):
            assert [("" if v is None else v) for v in r[col]] == cells, col
        else:
            same_cells(r[col], cells, col)
    # two to four contacts at every angle, and each row holds at the ideal motion (no
    # acceleration of either gear: gamma is zero)
    _, counts = np.unique(r["angle_deg"], return_counts=True)
    assert counts.min() >= 2 and counts.max() <= 4
    assert np.all(np.abs(r["gamma_mm_s2"]) <= 1e-6)


def test_contacts_of_a_one_contact_cam_and_a_refusal():
    mech = camkin.Mechanism.from_toml(EXAMPLES / "paper.toml")
    r = mech.contacts(10.0)
    assert list(r["contact"]) == [0.0]
    # the first contact's row gives the follower's acceleration: row_follower q̈ = gamma (the cam
    # at constant speed)
    a = mech.analyze(10.0)
    q_dd = a["acceleration_cm_s2"]
    assert abs(r["row_follower_cm_per_cm"][0] * q_dd - r["gamma_cm_s2"][0]) <= 1e-9 * abs(q_dd)
    # 3.6 million angles of a gear pair: refused up front with the estimate
    with pytest.raises(camkin.ResourceError, match="would take about"):
        camkin.Mechanism.from_toml(EXAMPLES / "gear-pair-20-42.toml").contacts(
            np.arange(0.0, 360.0, 1e-4)
        )


def test_mesh_equals_the_command_csv_bit_for_bit():
    """A gear pair read as gears from Python: the rows of `camkin mesh`, to the last bit."""
    for name in ("gear-pair-20-42.toml", "gear-pair-tip-relief.toml"):
        path = EXAMPLES / name
        mech = camkin.Mechanism.from_toml(path)
        r = mech.mesh(np.arange(0.0, 36.0, 0.25))
        cli = csv_columns(run_cli("mesh", path, "--angles", "0:36:0.25"))
        assert list(r) == list(cli), "the same columns in the same order"
        for col, cells in cli.items():
            if col in ("driver_flank", "found", "error"):
                assert [("" if v is None else v) for v in r[col]] == cells, col
            elif col == "on_flanks":
                assert [str(v).lower() for v in r[col]] == cells, col
            else:
                same_cells(r[col], cells, col)
    # the ideal pair's ratio, z1/z2, at a single angle
    one = camkin.Mechanism.from_toml(EXAMPLES / "gear-pair-20-42.toml").mesh(7.0)
    assert abs(one["speed_ratio"] + 20 / 42) <= 1e-12


def test_mesh_of_a_cam_is_refused_naming_the_field():
    with pytest.raises(camkin.InputError) as e:
        camkin.paper_cam().mesh(0.0)
    assert e.value.field == "cam.profile.kind"


def test_a_conjugate_follower_from_python():
    """The constant-diameter cam: the second roller's play column is zero, both rollers are
    contacts (named in the `curve` column); the simulation, without a spring, keeps the yoke on
    the cam's motion with the load passing between the rollers (the `on_conjugate` column), and
    refuses a second roller that cuts into the cam, naming the table."""
    path = EXAMPLES / "conjugate-yoke.toml"
    mech = camkin.Mechanism.from_toml(path)
    a = mech.analyze(np.arange(0.0, 360.0, 2.5))
    assert np.all(np.abs(a["conjugate_play_mm"]) <= 1e-9)
    c = mech.contacts([10.0, 200.0])
    assert list(c["curve"]) == ["follower", "conjugate"] * 2
    checks = mech.checks()
    assert checks["conjugate_play"]["passed"] and checks["passed"]
    assert abs(checks["conjugate_play"]["min"][0]) <= 1e-9
    d = mech.to_dict()
    assert d["follower"]["conjugate"]["kind"] == "circle"
    d["dynamics"] = {"mass": 0.5, "spring_stiffness": 0.0, "spring_preload": 0.0}
    run = camkin.Mechanism.from_dict(d).simulate(step_deg=2.0)
    s = run["samples"]
    assert run["events"] == []
    assert np.all(s["in_contact"] == 1)
    assert np.max(np.abs(s["position_mm"] - s["kinematic_position_mm"])) <= 1e-9
    assert set(s["on_conjugate"]) == {0, 1}
    d["follower"]["conjugate"]["center"] = [-119.8, 0.0]
    with pytest.raises(camkin.InputError) as e:
        camkin.Mechanism.from_dict(d).simulate()
    assert e.value.field == "follower.conjugate"


def test_a_mechanism_too_large_to_index_is_refused_unless_large():
    """Issue 44: two 100 000-node splines (a cam and the curve its follower carries) would hold
    about 1.4 GB of search index: refused before it is built, with the estimate, naming
    large=True."""
    t = np.linspace(0.0, 2.0 * np.pi, 100_000, endpoint=False)
    ring = lambda r, x: np.column_stack([x + r * np.cos(t), 0.8 * r * np.sin(t)]).tolist()
    d = {
        "length_unit": "mm",
        "cam": {"speed_rpm": 1000.0, "profile": {"kind": "spline", "points": ring(40.0, 0.0)}},
        "follower": {
            "kind": "translating",
            "direction": [1.0, 0.0],
            "offset": 0.0,
            "profile": {"kind": "spline", "points": ring(2.0, 3.0)},
        },
    }
    with pytest.raises(camkin.ResourceError, match=r"would take about .* GB.*large=True"):
        camkin.Mechanism.from_dict(d)


def same_as_the_command(r, cli):
    """A system's columns from Python are the command's CSV columns, to the last bit."""
    assert list(r) == list(cli)
    for key, cells in cli.items():
        if key == "error":
            assert all(e is None for e in r[key])
        elif key.endswith("_jump"):
            assert [bool(x) for x in r[key]] == [c == "true" for c in cells]
        else:
            assert list(r[key]) == [float(c) for c in cells], key


def test_a_system_file_in_python_equals_the_command():
    """Issue 45: camkin.System reads a system file and analyses it over its driver's angle with
    the command's columns, the same numbers to the last bit."""
    sys = camkin.System.from_toml(EXAMPLES / "valve-train-kinematics.toml")
    assert sys.bodies == ["camshaft", "finger", "valve"]
    assert sys.contacts == ["cam on roller", "pad on valve"]
    angles = np.arange(0.0, 360.0, 15.0)
    r = sys.analyze(angles)
    cli = csv_columns(run_cli("analyze", EXAMPLES / "valve-train-kinematics.toml", "--angles", "0:360:15"))
    assert list(r) == list(cli)
    same_as_the_command(r, cli)
    # the valve opens 16 mm: its tip from -33 mm at full lift
    assert r["valve_y_mm"][0] == -33.0 or abs(r["valve_y_mm"][0] + 33.0) < 1e-12
    with pytest.raises(camkin.InputError) as e:
        camkin.System.from_toml(
            (EXAMPLES / "valve-train-kinematics.toml").read_text().replace('"fixed"', '"fixed"').replace(
                'kind = "prismatic"', 'kind = "slider"'
            )
        )
    assert e.value.line is not None and "joint[2].kind" in str(e.value)


def test_a_cam_file_as_a_system_in_python():
    """Issue 45: a cam file read by camkin.System is its mechanism as a system (bodies cam and
    follower): the command's --system columns to the last bit, and the follower's motion the
    cam path's to 1e-12 of the size (a clockwise cam under an offset roller)."""
    path = EXAMPLES / "eccentric-roller.toml"
    sys = camkin.System.from_toml(path)
    assert sys.bodies == ["cam", "follower"]
    angles = np.arange(0.0, 360.0, 15.0)
    r = sys.analyze(angles)
    cli = csv_columns(run_cli("analyze", path, "--system", "--angles", "0:360:15"))
    assert list(r) == list(cli)
    assert list(r)[0] == "angle_deg"
    same_as_the_command(r, cli)
    cam = camkin.Mechanism.from_toml(path).analyze(angles)
    w = 600.0 * 2.0 * np.pi / 60.0
    size = 5.0
    # the roller travels along +y from x = -0.5: its frame's y is the cam path's position
    assert np.max(np.abs(r["follower_y_cm"] - cam["position_cm"])) <= 1e-12 * size
    assert np.max(np.abs(r["follower_vy_cm_s"] - cam["velocity_cm_s"])) <= 1e-12 * w * size
    assert np.max(np.abs(r["follower_ay_cm_s2"] - cam["acceleration_cm_s2"])) <= 1e-12 * w * w * size
    # the jerk, from the system's rows in time and from the cam path's tangency in the angle
    j, cj = r["follower_jerk_y_cm_s3"], cam["jerk_cm_s3"]
    assert np.array_equal(np.isnan(j), np.isnan(cj))
    assert np.nanmax(np.abs(j - cj)) <= 1e-12 * w**3 * size
    # the clockwise cam's body turns clockwise
    assert np.all(r["cam_omega_deg_s"] == -3600.0) or np.allclose(r["cam_omega_deg_s"], -3600.0, rtol=1e-15)


def test_a_form_closed_follower_as_a_system_warns_in_python():
    """Its second curve is left out of the system: a CamkinWarning says so, as the command does."""
    with pytest.warns(camkin.CamkinWarning, match="second curve is left out"):
        sys = camkin.System.from_toml(EXAMPLES / "conjugate-yoke.toml")
    assert sys.contacts == ["cam on follower"]


def test_a_long_analysis_holds_little_more_than_the_arrays_it_returns():
    """Issue 47: `analyze` of 10⁶ angles peaks at most 1.5 times the arrays it returns
    (it held 1.75 times: a string per row in each text column), measured in a fresh process."""
    import subprocess
    import sys
    import textwrap

    code = textwrap.dedent(
        """
        import resource, numpy as np, camkin
        from pathlib import Path
        m = camkin.Mechanism.from_toml(Path(%r).read_text())
        angles = np.linspace(0, 360, 1_000_000, endpoint=False)
        base = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss
        r = m.analyze(angles, large=True)
        peak = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss
        size = sum(v.nbytes for v in r.values() if hasattr(v, "nbytes"))
        print((peak - base) * 1024 / size)
        """
        % str(EXAMPLES / "paper.toml")
    )
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    ratio = float(out.stdout.strip())
    assert ratio <= 1.5, ratio


def test_a_gear_pairs_handover_is_not_called_impulsive():
    # issue 49: an ideal pair's first contact passes to the next tooth pair; its acceleration is
    # zero, so the warning names the handover, not an impulse
    import warnings
    import numpy as np
    m = camkin.Mechanism.from_toml(EXAMPLES / "gear-pair-20-42.toml")
    with warnings.catch_warnings(record=True) as w:
        warnings.simplefilter("always")
        m.analyze(np.arange(0.0, 36.0, 0.5))
    texts = [str(x.message) for x in w]
    assert any("next tooth pair" in t for t in texts), texts
    assert not any("impulsive" in t for t in texts), texts


@pytest.mark.parametrize("direction", ["ccw", "cw"])
@pytest.mark.parametrize("offset", [-10.0, 10.0])
def test_the_offset_moves_the_pressure_angle_peak_as_the_docs_say(offset, direction):
    """docs/mechanism-files.md: on a ccw cam with its follower along +y, a negative offset (the line
    of travel right of the axis) moves the peak pressure angle to the return, a positive one to
    the rise; a cw cam mirrors this."""
    program = [
        {"law": "cycloidal", "rise": 12.0, "degrees": 120},
        {"law": "dwell", "degrees": 60},
        {"law": "3-4-5", "rise": -12.0, "degrees": 120},
        {"law": "dwell", "degrees": 60},
    ]
    m = camkin.synthesize(
        segments=program, base_radius=40.0, speed_rpm=600.0, length_unit="mm", direction=direction,
        follower={"kind": "translating-roller", "direction": [0.0, 1.0], "offset": offset, "roller_radius": 10.0},
    )
    r = m.analyze(np.arange(0.0, 360.0, 0.5))
    a, pa = r["angle_deg"], np.abs(r["pressure_angle_deg"])
    rise, ret = pa[a < 120].max(), pa[(a >= 180) & (a < 300)].max()
    on_rise = (offset > 0) == (direction == "ccw")
    assert (rise > ret + 5.0) if on_rise else (ret > rise + 5.0), (rise, ret)
