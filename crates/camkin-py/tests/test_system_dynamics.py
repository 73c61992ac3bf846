"""Issue 46: camkin.System.simulate — a system's dynamics from Python, the command's columns to
the last bit, its events, and bad input naming its argument."""

import numpy as np
import pytest

import camkin
from conftest import EXAMPLES, csv_columns, run_cli


def test_simulate_equals_the_command_to_the_last_bit(tmp_path):
    sys = camkin.System.from_toml(EXAMPLES / "valve-train.toml")
    samples, events = sys.simulate(revolutions=0.5, step_deg=1.0, rtol=1e-9)
    out = tmp_path / "vt"
    run_cli(
        "simulate", EXAMPLES / "valve-train.toml", "--revolutions", "0.5", "--step", "1",
        "--rtol", "1e-9", "--out", out,
    )
    cli = csv_columns((out / "time_series.csv").read_text())
    assert list(samples) == list(cli)
    assert len(samples["time_s"]) == 181
    for key, cells in cli.items():
        if key.endswith("_in_contact"):
            assert [bool(x) for x in samples[key]] == [c == "true" for c in cells], key
        else:
            assert list(samples[key]) == [float(c) for c in cells], key
    cli_events = csv_columns((out / "events.csv").read_text())
    assert list(events) == list(cli_events)
    assert list(events["contact"]) == cli_events["contact"]
    assert list(events["time_s"]) == [float(c) for c in cli_events["time_s"]]
    # the valve leaves its seat at once and is back on it by 160°
    assert events["event"][0] == "lift-off" and events["contact"][0] == "seat"
    assert "impact" in list(events["event"])


def test_simulate_takes_any_step_and_refuses_tolerances_out_of_range():
    # issue 64: no step is refused (the lash adjuster's damper once asked for substeps=3 at
    # 2°): the steps are chosen by the tolerances
    sys = camkin.System.from_toml(EXAMPLES / "valve-train.toml")
    samples, _ = sys.simulate(revolutions=0.1, step_deg=2.0)
    assert len(samples["time_s"]) == 19
    for key, value in [("rtol", 0.0), ("atol", 0.5), ("rtol", 1e-14)]:
        with pytest.raises(camkin.InputError, match=key) as e:
            sys.simulate(revolutions=0.1, **{key: value})
        assert e.value.field == key
    with pytest.raises(camkin.InputError, match="integrator") as e:
        sys.simulate(revolutions=0.1, integrator="stiff")
    assert e.value.field == "integrator"
    # the implicit integrator gives the explicit one's motion (docs/systems.md, stiff systems)
    a, _ = sys.simulate(revolutions=0.1, step_deg=2.0, integrator="explicit")
    b, _ = sys.simulate(revolutions=0.1, step_deg=2.0, integrator="implicit")
    assert np.allclose(a["valve_y_mm"], b["valve_y_mm"], rtol=0, atol=1e-6)
    with pytest.raises(camkin.InputError, match="revolutions"):
        sys.simulate(revolutions=-1.0)
    with pytest.raises(camkin.InputError, match="step_deg"):
        sys.simulate(step_deg=0.0)


def test_lubrication_equals_the_command_to_the_last_bit(tmp_path):
    # the valve train's [lubrication]: the roller rolls on the cam (nothing slides), the pad
    # slides on the valve's tip; Python's columns are lubrication.csv's to the last bit
    path = EXAMPLES / "valve-train.toml"
    r = camkin.System.from_toml(path).lubrication(step_deg=1.0)
    out = tmp_path / "vt"
    run_cli("forces", path, "--step", "1", "--out", out)
    cli = csv_columns((out / "lubrication.csv").read_text())
    assert list(r["columns"]) == list(cli)
    for key, cells in cli.items():
        got = list(r["columns"][key])
        if key in ("contact", "regime"):
            assert [g if g is not None else "" for g in got] == cells, key
        else:
            want = [float(c) if c != "" else None for c in cells]
            assert [None if (g is None or g != g) else g for g in got] == want, key
    names = [c["name"] for c in r["report"]["contacts"]]
    assert names == ["cam on roller", "pad on valve"]
    roller = r["report"]["contacts"][0]
    assert roller["lubrication"]["rolls"] == 1 and roller["mean_friction_power"] == 0.0


def test_lubrication_without_the_table_names_it():
    with pytest.raises(camkin.InputError) as e:
        camkin.System.from_toml(EXAMPLES / "cam-four-bar.toml").lubrication()
    assert e.value.field == "lubrication"


def test_two_contacts_of_one_name_and_an_oil_no_contact_takes_are_refused():
    # the one reader refuses what the command refuses: a second contact of the valve train's
    # name (its columns would appear twice, and one would be kept), and a [lubrication] table
    # where no contact has a face_width (nothing would be lubricated, without a word)
    text = (EXAMPLES / "valve-train.toml").read_text()
    first = text.index("[[contact]]")
    block = text[first : text.index("[[", first + 3)]
    with pytest.raises(camkin.InputError) as e:
        camkin.System.from_toml(text + "\n" + block)
    assert "contact" in e.value.field and "name" in e.value.field, e.value.field
    keys = ("face_width", "rolls", "materials")
    dry = "\n".join(l for l in text.splitlines() if not l.strip().startswith(keys))
    with pytest.raises(camkin.InputError) as e:
        camkin.System.from_toml(dry)
    assert e.value.field == "lubrication", e.value.field
    assert "no contact takes this oil" in str(e.value)


PENDULUM = """length_unit = "mm"
[dynamics]
gravity = [0.0, -9.81]
[[body]]
name = "bar"
mass = 2.0
inertia = 0.06
position = [300.0, 3.0]
angular_velocity = 2.0
[[joint]]
name = "pin"
kind = "revolute"
bodies = ["ground", "bar"]
at = [[0.0, 0.0], [-300.0, 0.0]]
"""


def test_a_driverless_system_runs_for_a_duration_as_the_command(tmp_path):
    # issue 64: a run in time, the command's columns to the last bit; the start's assembly
    # warned of; the settings refused by keyword
    path = tmp_path / "pendulum.toml"
    path.write_text(PENDULUM)
    sys = camkin.System.from_toml(path)
    with pytest.warns(camkin.errors.CamkinWarning, match="assembled onto the joints"):
        samples, events = sys.simulate(duration=2.0, interval=0.25)
    assert list(samples)[0] == "time_s"
    assert len(samples["time_s"]) == 9 and samples["time_s"][-1] == 2.0
    out = tmp_path / "run"
    run_cli("simulate", path, "--duration", "2", "--interval", "0.25", "--out", out)
    cli = csv_columns((out / "time_series.csv").read_text())
    assert list(samples) == list(cli)
    for key, cells in cli.items():
        assert list(samples[key]) == [float(c) for c in cells], key
    with pytest.raises(camkin.errors.InputError) as e:
        sys.simulate()
    assert e.value.field == "duration"
    with pytest.raises(camkin.errors.InputError) as e:
        sys.simulate(duration=1.0, revolutions=1.0)
    assert e.value.field == "duration"
    with pytest.raises(camkin.errors.InputError) as e:
        sys.simulate(duration=-1.0)
    assert e.value.field == "duration" and e.value.value == "-1"


def test_lash_sweep_equals_the_command_to_the_last_bit(tmp_path):
    # issue 65: the lash sweep's table as `camkin simulate --lash`, and the ramp's closed form
    # (a 0.1 mm lash taken up at 11.25°, seated at 248.75°, both at 120 mm/s)
    sys = camkin.System.from_toml(EXAMPLES / "bucket-lash.toml")
    table = sys.lash_sweep([0.05, 0.1, 0.15], step_deg=0.5)
    out = tmp_path / "lash"
    run_cli(
        "simulate", EXAMPLES / "bucket-lash.toml", "--lash", "0.05:0.15:0.05", "--step", "0.5",
        "--out", out,
    )
    cli = csv_columns((out / "lash.csv").read_text())
    assert list(table) == list(cli)
    for key, cells in cli.items():
        if key in ("contact", "seat"):
            assert list(table[key]) == cells, key
        else:
            assert list(table[key]) == [float(c) for c in cells], key
    assert abs(table["take_up_angle_deg"][1] - 11.25) < 1e-8
    assert abs(table["seating_angle_deg"][1] - 248.75) < 1e-8
    assert abs(table["seating_speed_mm_s"][1] - 120.0) < 1e-9 * 120.0
    with pytest.raises(camkin.InputError, match="lashes: a lash of -0.1") as e:
        sys.lash_sweep([0.1, -0.1])
    assert e.value.field == "lashes" and e.value.value == "-0.1"
    with pytest.raises(camkin.InputError, match="no contact has a lash") as e:
        camkin.System.from_toml(EXAMPLES / "valve-train.toml").lash_sweep([0.1])
    assert e.value.field == "lashes"
    with pytest.raises(camkin.InputError, match="step_deg"):
        sys.lash_sweep([0.1], step_deg=0.0)
