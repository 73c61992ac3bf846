"""`Mechanism.forces()` is the command's `camkin forces`: the same columns to the last bit, the
jump speed of the closed form, and bad input refused naming the argument."""

import math
import subprocess

import numpy as np
import pytest

import camkin
from conftest import EXAMPLES, camkin_bin, csv_columns
from test_mechanism import same_cells

DYNAMICS = sorted(
    p.name
    for p in EXAMPLES.glob("*.toml")
    if "[dynamics]" in p.read_text() and "[[body]]" not in p.read_text()
)


def cli_forces(path, out, *args):
    r = subprocess.run(
        [camkin_bin(), "forces", str(path), "--out", str(out), *map(str, args)],
        capture_output=True, text=True,
    )
    # 3: a check failed (the eccentric example leaves its cam at its own speed); files are written
    assert r.returncode in (0, 3), r.stderr
    return (
        csv_columns((out / "forces.csv").read_text()),
        csv_columns((out / "force_speed.csv").read_text()),
    )


def check_same(py, cli):
    assert list(py) == list(cli), "the same columns in the same order"
    for col, cells in cli.items():
        same_cells(py[col], cells, col)


@pytest.mark.parametrize("name", DYNAMICS)
@pytest.mark.parametrize("hertz", [False, True])
def test_forces_equal_the_command_csv_bit_for_bit(tmp_path, name, hertz):
    path = EXAMPLES / name
    args = ["--face-width", "10", "--materials", "steel,bronze"] if hertz else []
    cli, cli_speed = cli_forces(path, tmp_path, "--step", "1", *args)
    kw = {"face_width": 10.0, "materials": ("steel", "bronze")} if hertz else {}
    r = camkin.Mechanism.from_toml(path).forces(step_deg=1.0, **kw)
    check_same(r["columns"], cli)
    check_same(r["force_speed"], cli_speed)
    assert len(r["columns"]["angle_deg"]) == 360


def test_a_form_closed_follower_reports_each_curve(tmp_path):
    text = (EXAMPLES / "conjugate-yoke.toml").read_text()
    path = tmp_path / "yoke.toml"
    path.write_text(text + "\n[dynamics]\nmass = 0.5\nspring_stiffness = 0.0\nspring_preload = 0.0\n")
    cli, cli_speed = cli_forces(path, tmp_path / "out", "--face-width", "10")
    r = camkin.Mechanism.from_toml(path).forces(face_width=10.0)
    check_same(r["columns"], cli)
    check_same(r["force_speed"], cli_speed)
    fc = r["report"]["form_closed"]
    # the load passes between the rollers where the cycloidal accelerations change sign
    assert [round(math.degrees(t), 6) for t in fc["reversals"]] == [90.0, 270.0]
    assert r["report"]["spring"] is None and r["report"]["failures"] == []


def test_the_jump_speed_is_the_closed_form_of_the_eccentric_disc():
    # eccentric disc (e = 10 mm) under a flat face: the contact force m e ω² cos θ short of the
    # spring's F₀ + k e (1 + cos θ) first reaches 0 at θ = 0, at ω² = (F₀ + 2 k e) / (m e)
    d = camkin.Mechanism.from_toml(EXAMPLES / "eccentric-flat-dynamics.toml").to_dict()
    m, k, f0 = d["dynamics"]["mass"], d["dynamics"]["spring_stiffness"], d["dynamics"]["spring_preload"]
    e = 0.01
    r = camkin.Mechanism.from_toml(EXAMPLES / "eccentric-flat-dynamics.toml").forces(target_rpm=100.0)
    rep = r["report"]
    assert rep["jump"]["speed"] == pytest.approx(math.sqrt((f0 + 2 * k * e) / (m * e)), rel=1e-9)
    assert rep["jump"]["cam_angle"] == 0.0
    # below the file's speed: the margin check fails, the target check passes
    assert [f["check"] for f in rep["failures"]] == ["below_margin"]
    # the force at 0° is the closed form at the file's speed
    w = d["cam"]["speed_rpm"] * 2 * math.pi / 60
    f = r["columns"]["contact_force_N"]
    assert f[0] == pytest.approx(-m * e * w * w + f0 + 2 * k * e, rel=1e-12)


@pytest.mark.parametrize(
    "kw, field, needle",
    [
        ({"face_width": 10.0, "materials": "E=210:nu=0.3,steel"}, "materials", "did you mean GPa"),
        ({"face_width": 10.0, "materials": ("steel", "E=210e9:nu=-1")}, "materials", "nu = -1"),
        ({"face_width": 10.0, "materials": "steel,E=210e9:nu=0.3:rho=7800"}, "materials", "rho"),
        ({"face_width": 10.0, "materials": 3}, "materials", "CAM,FOLLOWER"),
        ({"face_width": 1e-300}, "face_width", "not plausible"),
        ({"face_width": -1.0}, "face_width", "must be positive"),
        ({"margin": -1.0}, "margin", "≥ 0"),
        ({"margin": float("nan")}, "margin", "finite"),
        ({"target_rpm": 0.0}, "target_rpm", "(0, 1e7]"),
        ({"allowable_mpa": -5.0}, "allowable_mpa", "positive"),
        ({"step_deg": 7.0}, "step_deg", "divide 360"),
    ],
)
def test_bad_force_input_names_the_argument(kw, field, needle):
    mech = camkin.Mechanism.from_toml(EXAMPLES / "eccentric-flat-dynamics.toml")
    with pytest.raises(camkin.InputError) as e:
        mech.forces(**kw)
    assert e.value.field == field, e.value
    assert needle in str(e.value), str(e.value)


def test_forces_need_a_dynamics_section():
    with pytest.raises(camkin.InputError, match=r"\[dynamics\]"):
        camkin.paper_cam().forces()
    assert np.isfinite(
        camkin.Mechanism.from_toml(EXAMPLES / "paper-dynamics.toml").forces()["columns"]["camshaft_torque_N_m"]
    ).all()


LUB = ["--face-width", "10", "--oil", "sae-30@100c", "--roughness", "0.2,0.3"]


@pytest.mark.parametrize("name", DYNAMICS)
def test_lubrication_equals_the_command_csv_bit_for_bit(tmp_path, name):
    path = EXAMPLES / name
    cli_forces(path, tmp_path, "--step", "1", *LUB, "--friction", "0.06")
    cli = csv_columns((tmp_path / "lubrication.csv").read_text())
    r = camkin.Mechanism.from_toml(path).forces(
        step_deg=1.0, face_width=10.0, oil="sae-30@100c", roughness_um=(0.2, 0.3), friction=0.06
    )
    py = r["lubrication"]
    assert list(py) == list(cli)
    for col, cells in cli.items():
        if col.endswith("regime"):
            # text: the regime's name, empty (None) where the contact carries nothing
            assert [x if x is not None else "" for x in py[col]] == cells, col
        else:
            same_cells(py[col], cells, col)
    rep = r["report"]["lubrication"]
    assert rep["request"]["friction"] == {"Constant": 0.06}
    assert rep["composite_roughness"] == pytest.approx(math.hypot(0.2e-6, 0.3e-6), rel=1e-15)


@pytest.mark.parametrize(
    "kw,field,needle",
    [
        ({"oil": "eta=-0.01:alpha=2e-8"}, "oil", "eta = -0.01"),
        ({"oil": "eta=9000:alpha=2e-8"}, "oil", "mPa·s"),
        ({"oil": 0.009}, "oil", "is not a lubricant's name"),
        ({"oil": "castor"}, "oil", "is not a lubricant"),
        ({"roughness_um": (0.0, 0.3)}, "roughness_um", "0.0 µm is not a plausible roughness"),
        ({"roughness_um": ("0.2", 0.3)}, "roughness_um", "'0.2' is not a number"),
        ({"roughness_um": (1j, 0.3)}, "roughness_um", "1j is not a number"),
        ({"roughness_um": (None, 0.3)}, "roughness_um", "None is not a number"),
        ({"roughness_um": (True, 0.3)}, "roughness_um", "True is not a number"),
        ({"roughness_um": 0.2}, "roughness_um", "is not a pair"),
        ({"roughness_um": None}, "roughness_um", "needs each surface's RMS roughness"),
        ({"friction": 1.5}, "friction", "not a friction coefficient"),
        ({"friction": "0.1"}, "friction", "is not a number"),
        ({"film": "grubin"}, "film", "is not a film formula"),
        ({"face_width": None}, "face_width", "lubrication needs the contact's face width"),
    ],
)
def test_bad_lubrication_input_names_the_argument(kw, field, needle):
    mech = camkin.Mechanism.from_toml(EXAMPLES / "eccentric-flat-dynamics.toml")
    args = {"face_width": 10.0, "oil": "sae-30@100c", "roughness_um": (0.2, 0.3), **kw}
    if args["roughness_um"] is None:
        del args["roughness_um"]
    with pytest.raises(camkin.InputError) as e:
        mech.forces(**args)
    assert e.value.field == field, e.value
    assert needle in str(e.value), str(e.value)


def test_roughness_without_an_oil_is_refused():
    mech = camkin.Mechanism.from_toml(EXAMPLES / "eccentric-flat-dynamics.toml")
    with pytest.raises(camkin.InputError) as e:
        mech.forces(face_width=10.0, roughness_um=(0.2, 0.3))
    assert e.value.field == "roughness_um"


def test_a_lubrication_section_is_the_default_of_the_keywords(tmp_path):
    text = (EXAMPLES / "eccentric-flat-dynamics.toml").read_text().replace(
        "speed_rpm = 1380.0", "speed_rpm = 1000.0"
    )
    plain = tmp_path / "plain.toml"
    plain.write_text(text)
    with_section = tmp_path / "with.toml"
    with_section.write_text(
        text
        + '\n[lubrication]\noil = "sae-30@100c"\nroughness_um = [0.2, 0.3]\nface_width = 10.0\n'
        + 'friction = 0.07\nmaterials = "steel,bronze"\n'
    )
    kw = dict(face_width=10.0, oil="sae-30@100c", roughness_um=(0.2, 0.3), friction=0.07,
              materials="steel,bronze")
    a = camkin.Mechanism.from_toml(with_section).forces()["lubrication"]
    b = camkin.Mechanism.from_toml(plain).forces(**kw)["lubrication"]
    assert list(a) == list(b)
    for col in a:
        assert list(a[col]) == list(b[col]) or all(
            (x != x and y != y) or x == y for x, y in zip(a[col], b[col])
        ), col
    # a keyword replaces the file's value
    c = camkin.Mechanism.from_toml(with_section).forces(roughness_um=(0.4, 0.4))["lubrication"]
    d = camkin.Mechanism.from_toml(plain).forces(**{**kw, "roughness_um": (0.4, 0.4)})["lubrication"]
    assert np.array_equal(c["lambda"], d["lambda"], equal_nan=True)
    assert not np.array_equal(a["lambda"], c["lambda"], equal_nan=True)


def test_gear_loads_equal_the_command_csv_bit_for_bit(tmp_path):
    path = EXAMPLES / "gear-pair-20-42.toml"
    r = subprocess.run(
        [camkin_bin(), "forces", str(path), "--torque", "50", "--face-width", "20",
         "--oil", "iso-vg-220@40c", "--roughness", "0.4,0.4", "--out", str(tmp_path)],
        capture_output=True, text=True,
    )
    assert r.returncode == 0, r.stderr
    cli = csv_columns((tmp_path / "gear_loads.csv").read_text())
    py = camkin.Mechanism.from_toml(path).gear_loads(
        torque=50, face_width=20.0, oil="iso-vg-220@40c", roughness_um=(0.4, 0.4)
    )
    assert list(py["columns"]) == list(cli)
    for col, cells in cli.items():
        if col in ("regime", "point"):
            assert [x if x is not None else "" for x in py["columns"][col]] == cells
        else:
            same_cells(py["columns"][col], cells, col)
    rb1 = 0.020 * math.cos(math.radians(20))
    assert py["report"]["normal_force"] == pytest.approx(50 / rb1, rel=1e-13)


@pytest.mark.parametrize(
    "file,kw,field",
    [
        ("paper-dynamics.toml", {"torque": 5.0, "face_width": 1.0}, "torque"),
        ("gear-pair-20-42.toml", {"torque": -5.0, "face_width": 20.0}, "torque"),
        ("gear-pair-20-42.toml", {"torque": "5", "face_width": 20.0}, "torque"),
        ("gear-pair-20-42.toml", {"torque": 5.0}, "face_width"),
        ("gear-pair-20-42.toml", {"torque": 5.0, "face_width": 0.0}, "face_width"),
        ("gear-pair-20-42.toml", {"face_width": 20.0}, "torque"),
        ("gear-pair-20-42.toml", {"power_kw": -1.0, "face_width": 20.0}, "power_kw"),
        ("gear-pair-20-42.toml", {"power_kw": 1j, "face_width": 20.0}, "power_kw"),
        ("gear-pair-20-42.toml", {"torque": 1.0, "power_kw": 1.0, "face_width": 20.0}, "power_kw"),
        ("paper-dynamics.toml", {"power_kw": 5.0, "face_width": 1.0}, "power_kw"),
    ],
)
def test_bad_gear_loads_name_the_argument(file, kw, field):
    with pytest.raises(camkin.InputError) as e:
        camkin.Mechanism.from_toml(EXAMPLES / file).gear_loads(**kw)
    assert e.value.field == field, e.value


def test_gear_loads_from_the_file_equal_the_command_csv_bit_for_bit(tmp_path):
    # the FZG pair's [gear_loads] and [lubrication] with no keyword, as `camkin forces FILE`
    path = EXAMPLES / "fzg-c.toml"
    r = subprocess.run([camkin_bin(), "forces", str(path), "--out", str(tmp_path)],
                       capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    cli = csv_columns((tmp_path / "gear_loads.csv").read_text())
    py = camkin.Mechanism.from_toml(path).gear_loads()
    assert list(py["columns"]) == list(cli)
    for col, cells in cli.items():
        if col in ("regime", "point"):
            assert [x if x is not None else "" for x in py["columns"][col]] == cells
        else:
            same_cells(py["columns"][col], cells, col)
    # a power is P/ω at the file's 2170 rpm: the same loads as its torque
    w = 2170 * math.pi / 30
    by_power = camkin.Mechanism.from_toml(path).gear_loads(power_kw=302.0 * w / 1e3)
    assert by_power["report"]["normal_force"] == pytest.approx(py["report"]["normal_force"], rel=1e-14)
