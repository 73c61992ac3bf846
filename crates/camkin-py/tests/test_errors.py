"""Errors are camkin's classes and carry the field and the value."""

import subprocess

import numpy as np
import pytest

import camkin
from conftest import EXAMPLES, camkin_bin

PAPER = (EXAMPLES / "paper.toml").read_text()


def spec(**changes):
    d = camkin.paper_cam().to_dict()
    for path, value in changes.items():
        node = d
        keys = path.split("__")
        for k in keys[:-1]:
            node = node[k]
        node[keys[-1]] = value
    return d


@pytest.mark.parametrize(
    "change,field,value,words",
    [
        ({"cam__speed_rpm": -5.0}, "cam.speed_rpm", "-5", "must be positive"),
        ({"cam__profile__kind": "blob"}, "cam.profile.kind", "blob", "is not"),
        ({"length_unit": "furlong"}, "length_unit", "furlong", "is not"),
        ({"follower__kind": "translating-roller"}, "follower.roller_radius", None, "needs"),
        ({"cam__profile__points": [[1, 0], [0, 1]]}, "cam.profile.points", None, "at least"),
    ],
)
def test_spec_errors_name_field_and_value(change, field, value, words):
    with pytest.raises(camkin.InputError) as e:
        camkin.Mechanism.from_dict(spec(**change))
    assert e.value.field == field, (e.value.field, str(e.value))
    assert e.value.value == value
    assert words in str(e.value)
    assert isinstance(e.value, camkin.CamkinError) and isinstance(e.value, ValueError)


def test_missing_length_unit_is_named():
    d = spec()
    del d["length_unit"]
    with pytest.raises(camkin.InputError) as e:
        camkin.Mechanism.from_dict(d)
    assert e.value.field == "length_unit"


def test_toml_errors_give_line_and_key():
    with pytest.raises(camkin.InputError) as e:
        camkin.Mechanism.from_toml(PAPER.replace("speed_rpm = 1000.0", 'speed_rpm = "fast"'))
    assert e.value.field == "cam.speed_rpm" and "line 6" in str(e.value)
    # the value of the wrong type as written (it used to be None)
    assert e.value.value == "fast"
    with pytest.raises(camkin.InputError) as e:
        camkin.Mechanism.from_toml(PAPER + "\nnonsense = \n")
    assert "line" in str(e.value)
    with pytest.raises(camkin.InputError) as e:
        camkin.Mechanism.from_toml(EXAMPLES / "no-such-file.toml")
    assert e.value.field == "source" and "no-such-file.toml" in e.value.value
    with pytest.raises(camkin.InputError):
        camkin.Mechanism.from_dict([1, 2])
    with pytest.raises(camkin.InputError):
        camkin.Mechanism.from_dict({"length_unit": "mm", "cam": {}, "follower": {}, "extra": 1})


def test_argument_errors():
    m = camkin.paper_cam()
    with pytest.raises(camkin.InputError) as e:
        m.analyze([0.0, float("nan")])
    assert e.value.field == "angles_deg" and e.value.value == "NaN"
    with pytest.raises(camkin.InputError) as e:
        m.analyze(np.zeros((2, 2)))
    assert e.value.field == "angles_deg"
    with pytest.raises(camkin.InputError) as e:
        m.analyze(["a"])
    assert e.value.field == "angles_deg"
    with pytest.raises(camkin.InputError) as e:
        m.analyze(1.0, per="minute")
    assert (e.value.field, e.value.value) == ("per", "minute")
    with pytest.raises(camkin.InputError) as e:
        m.checks(pressure_limit_deg=95.0)
    assert e.value.field == "pressure_limit_deg"
    with pytest.raises(camkin.InputError) as e:
        m.simulate()
    assert e.value.field == "dynamics"
    with pytest.raises(camkin.InputError) as e:
        camkin.Circle((0, 0), -1.0)
    assert e.value.field == "radius"
    with pytest.raises(camkin.InputError) as e:
        camkin.Spline([[0, 0], [1, 0]])
    assert e.value.field == "points"
    with pytest.raises(camkin.InputError) as e:
        camkin.Body(position=(0, float("inf")))
    assert e.value.field == "position"
    with pytest.raises(camkin.InputError) as e:
        camkin.motion_law("bouncy", 0.5)
    assert (e.value.field, e.value.value) == ("law", "bouncy")


def test_work_is_refused_up_front_with_the_estimate():
    m = camkin.paper_cam()
    with pytest.raises(camkin.ResourceError, match="large=True"):
        m.analyze(np.zeros(camkin.MAX_ANGLES + 1))
    with pytest.raises(camkin.ResourceError, match="large=True"):
        m.simulate(revolutions=5000) if m.has_dynamics else camkin.Mechanism.from_toml(
            EXAMPLES / "paper-dynamics.toml"
        ).simulate(revolutions=5000)


def test_a_long_gear_simulation_is_refused_with_the_librarys_estimate():
    # the gear pair with backlash (coast flanks) and a load: the one-coordinate model, whose
    # estimate (the library's, as the command's) is six cold searches of 1 ms a step and curve
    # (432 s), and the kinematic sweep beside the rows (37 441 angles, a carried curve's warm
    # step timed on this machine: 440 s on an idle one, 462 s beside a build): the same
    # sentence as the command's
    m = camkin.Mechanism.from_toml(EXAMPLES / "gear-pair-backlash.toml")
    with pytest.raises(camkin.ResourceError, match="36000 steps of this mechanism would take about 4[3-9][0-9] s"):
        m.simulate(revolutions=100)


def test_contact_errors_say_why():
    body = camkin.Body()
    with pytest.raises(camkin.ContactError, match="unbounded"):
        camkin.contact(camkin.Line((0, 0), (1, 0)), body, camkin.Line((0, 1), (1, 0)), body)
    # a pin in a hole of its own size: conformal, the contact point is not determined
    hole_curve = camkin.Circle((0, 0), 1.0)
    with pytest.raises(camkin.ContactError, match="conformal"):
        camkin.contact(hole_curve, body, camkin.Circle((0, 0), 1.0), body, at=(0.0, 0.0))


@pytest.mark.parametrize(
    "kw, field",
    [
        ({"at": (float("nan"), 0.0)}, "at"),
        ({"at": (0.0, float("inf"))}, "at"),
        ({"guess": (float("nan"), 0.0)}, "guess"),
    ],
)
def test_a_contact_parameter_that_is_not_on_its_curve_is_bad_input(kw, field):
    # issue 63: it was a ContactError ("zero-length tangent at u = NaN")
    body = camkin.Body()
    line = camkin.Line((0.0, 2.0), (1.0, 0.0))
    with pytest.raises(camkin.InputError, match="is not a parameter of") as e:
        camkin.contact(camkin.Circle((0, 0), 1.0), body, line, body, **kw)
    assert e.value.field == field


def test_errors_pickle():
    import pickle

    e = camkin.InputError("x = 1: bad", "x", "1")
    e2 = pickle.loads(pickle.dumps(e))
    assert (e2.field, e2.value, str(e2)) == ("x", "1", "x = 1: bad")


def test_file_errors_carry_the_line_and_column_the_command_prints(tmp_path):
    # the library's one reader places the error: the same file:line:column as `camkin analyze`
    text = (EXAMPLES / "paper.toml").read_text().replace("speed_rpm = 1000.0", "speed_rpm = -5.0")
    path = tmp_path / "bad.toml"
    path.write_text(text)
    with pytest.raises(camkin.InputError) as e:
        camkin.Mechanism.from_toml(path)
    assert (e.value.line, e.value.column) == (6, 13), e.value
    assert e.value.field == "cam.speed_rpm" and e.value.value == "-5"
    assert str(e.value).startswith(f"{path}:6:13:"), str(e.value)
    r = subprocess.run([camkin_bin(), "analyze", str(path)], capture_output=True, text=True)
    assert r.returncode == 2 and f"{path}:6:13:" in r.stderr, r.stderr
    # a type error too, and TOML text
    with pytest.raises(camkin.InputError) as e:
        camkin.Mechanism.from_toml(text.replace("speed_rpm = -5.0", 'speed_rpm = "fast"'))
    assert e.value.line == 6 and e.value.field == "cam.speed_rpm", e.value
    # a dict has no lines
    with pytest.raises(camkin.InputError) as e:
        camkin.Mechanism.from_dict({"length_unit": "cm", "cam": {"speed_rpm": "fast"}})
    assert e.value.line is None and e.value.field == "cam.speed_rpm", e.value


def test_a_path_with_an_equals_sign_is_a_path(tmp_path):
    d = tmp_path / "a=b"
    d.mkdir()
    path = d / "cam.toml"
    path.write_text((EXAMPLES / "paper.toml").read_text())
    m = camkin.Mechanism.from_toml(str(path))
    assert m.name == "cam"
    with pytest.raises(camkin.InputError, match="cannot read mechanism file"):
        camkin.Mechanism.from_toml(str(d / "missing.toml"))


def test_the_bound_on_a_file_counts_the_bytes_read_not_its_reported_size():
    # a device reports size 0; reading it must still stop at the bound
    with pytest.raises(camkin.InputError, match="more than 8388608 bytes"):
        camkin.Mechanism.from_toml("/dev/zero")


@pytest.mark.parametrize(
    "angles,words",
    [
        (45 + 2j, "complex"),
        ([0.0, 1j], "complex"),
        ("45", "text"),
        (["0", "90"], "text"),
        ([True, False], "booleans"),
        ([1.0, None], "mixed"),
    ],
)
def test_angles_that_are_not_real_numbers_are_refused(angles, words):
    # a complex angle used to lose its imaginary part, a string to be read as a number
    with pytest.raises(camkin.InputError) as e:
        camkin.paper_cam().analyze(angles)
    assert e.value.field == "angles_deg" and words in str(e.value), str(e.value)


def test_numpy_integer_and_real_angles_are_angles():
    m = camkin.paper_cam()
    a = m.analyze(np.array([0, 45], dtype=np.int32))
    b = m.analyze(np.array([0.0, 45.0], dtype=np.float32))
    assert np.array_equal(a["acceleration_cm_s2"], b["acceleration_cm_s2"])


@pytest.mark.parametrize("bad", [float("nan"), float("inf"), -float("inf")])
def test_a_non_finite_number_in_a_dict_names_its_field(bad):
    # it used to be "expected value at line 1 column 44" of JSON the user never wrote
    with pytest.raises(camkin.InputError) as e:
        camkin.Mechanism.from_dict(spec(cam__speed_rpm=bad))
    assert e.value.field == "cam.speed_rpm", str(e.value)
    assert "line 1" not in str(e.value) and "must be positive and finite" in str(e.value)


@pytest.mark.parametrize(
    "change,field,value",
    [
        ({"cam__speed_rpm": "fast"}, "cam.speed_rpm", "fast"),
        ({"cam__profile__points": [[1, 0], [0, "x"], [-1, 0]]}, "cam.profile.points[1][1]", "x"),
        ({"follower__kind": 3}, "follower.kind", "3"),
        ({"cam__speed_rpm": 2j}, "cam.speed_rpm", "2j"),
    ],
)
def test_a_value_of_the_wrong_type_in_a_dict_is_named_with_its_value(change, field, value):
    with pytest.raises(camkin.InputError) as e:
        camkin.Mechanism.from_dict(spec(**change))
    assert e.value.field == field and e.value.value == value, (e.value.field, e.value.value, str(e.value))


def test_a_dict_may_hold_numpy_arrays_and_leave_out_none():
    d = spec()
    d["cam"]["profile"]["points"] = np.array(d["cam"]["profile"]["points"])
    d["cam"]["speed_rpm"] = np.float64(1000.0)
    d["cam"]["angular_acceleration_deg_s2"] = None
    m = camkin.Mechanism.from_dict(d)
    assert m.to_dict() == camkin.paper_cam().to_dict()


# every real-number argument: text, a complex number, a bool, an array or None (where a number is
# needed) is an InputError naming the argument and the value; NumPy scalars are numbers
REAL_ARGS = [
    (lambda m, v: m.checks(step_deg=v), "step_deg"),
    (lambda m, v: m.checks(pressure_limit_deg=v), "pressure_limit_deg"),
    (lambda m, v: m.forces(step_deg=v), "step_deg"),
    (lambda m, v: m.forces(margin=v), "margin"),
    (lambda m, v: m.forces(face_width=v), "face_width"),
    (lambda m, v: m.forces(target_rpm=v), "target_rpm"),
    (lambda m, v: m.shop(tool_radius=v), "tool_radius"),
    (lambda m, v: m.shop(tolerance=v), "tolerance"),
    (lambda m, v: m.shop(step_deg=v), "step_deg"),
    (lambda m, v: m.simulate(revolutions=v), "revolutions"),
    (lambda m, v: m.simulate(start_angle_deg=v), "start_angle_deg"),
    (lambda m, v: m.compare(step_deg=v), "step_deg"),
    (lambda m, v: camkin.Body(angle=v), "angle"),
    (lambda m, v: camkin.Body(angular_velocity=v), "angular_velocity"),
]


@pytest.mark.parametrize("call,field", REAL_ARGS, ids=lambda x: x if isinstance(x, str) else "")
@pytest.mark.parametrize("bad", ["10mm", 1 + 2j, True, np.array([1.0, 2.0])], ids=["text", "complex", "bool", "array"])
def test_a_real_argument_refuses_what_is_not_a_real_number(call, field, bad):
    mech = camkin.Mechanism.from_toml(EXAMPLES / "paper-dynamics.toml")
    with pytest.raises(camkin.InputError) as e:
        call(mech, bad)
    assert e.value.field == field, (e.value.field, str(e.value))
    assert str(e.value).startswith(field) and repr(bad)[:6] in str(e.value), str(e.value)


def test_numpy_scalars_are_numbers():
    mech = camkin.paper_cam()
    a = mech.shop(step_deg=np.float32(2.0), tool_radius=np.int64(1))
    b = mech.shop(step_deg=2.0, tool_radius=1.0)
    assert a["dxf"] == b["dxf"]


COUNT_ARGS = [
    (lambda m, v: m.profile(v), "n"),
    (lambda m, v: camkin.summarize([m], threads=v), "threads"),
]


@pytest.mark.parametrize("call,field", COUNT_ARGS, ids=lambda x: x if isinstance(x, str) else "")
@pytest.mark.parametrize("bad", ["10", 2.5, -3, True], ids=["text", "float", "negative", "bool"])
def test_a_count_argument_refuses_what_is_not_a_whole_number(call, field, bad):
    mech = camkin.Mechanism.from_toml(EXAMPLES / "paper-dynamics.toml")
    with pytest.raises(camkin.InputError) as e:
        call(mech, bad)
    assert e.value.field == field and str(e.value).startswith(field), (e.value.field, str(e.value))


def test_warnings_carry_the_field_and_the_place(tmp_path):
    text = (EXAMPLES / "paper.toml").read_text()
    start = text.index("points = [")
    end = text.index("]]", start) + 2
    text = text[:start] + "points = [[5, 0], [4.9, 1], [0, 4], [-4, 0], [0, -4]]" + text[end:]
    line = text[:start].count("\n") + 1
    with pytest.warns(camkin.CamkinWarning) as rec:
        camkin.Mechanism.from_toml(text)
    w = rec[0].message
    assert w.field == "cam.profile.points" and "unevenly spaced" in str(w)
    assert w.line == line, (w.line, w.column, line)
    # from a dict: the field, no place
    d = camkin.paper_cam().to_dict()
    d["cam"]["profile"]["points"] = [[5, 0], [4.9, 1], [0, 4], [-4, 0], [0, -4]]
    with pytest.warns(camkin.CamkinWarning) as rec:
        camkin.Mechanism.from_dict(d)
    w = rec[0].message
    assert w.field == "cam.profile.points" and w.line is None
    # a result's warning names the argument
    with pytest.warns(camkin.CamkinWarning) as rec:
        camkin.Mechanism.from_toml(EXAMPLES / "gear-pair-20-42.toml").analyze(np.arange(0.0, 60.0, 0.5))
    assert rec[0].message.field == "angles_deg"


@pytest.mark.parametrize(
    "call,field",
    [
        (lambda v: camkin.Circle(v, 1.0), "center"),
        (lambda v: camkin.Line((0.0, 0.0), v), "direction"),
        (lambda v: camkin.Point(v), "at"),
        (lambda v: camkin.Body(position=v), "position"),
    ],
    ids=["Circle.center", "Line.direction", "Point.at", "Body.position"],
)
@pytest.mark.parametrize("bad", ["1,2", (1.0, "2"), (1.0, None), (1j, 0.0)], ids=["text", "text-item", "None-item", "complex-item"])
def test_a_point_argument_refuses_what_is_not_real_numbers(call, field, bad):
    with pytest.raises(camkin.InputError) as e:
        call(bad)
    assert e.value.field == field and str(e.value).startswith(field), (e.value.field, str(e.value))


def test_the_widget_refuses_what_it_cannot_show(tmp_path):
    from camkin.widget import Studio

    with pytest.raises(camkin.InputError) as e:
        Studio.from_toml(tmp_path / "a=b" / "cam.toml")
    assert e.value.field == "source" and "a=b" in str(e.value)
    with pytest.raises(camkin.InputError) as e:
        Studio(camkin.System.from_toml(EXAMPLES / "valve-train.toml"))
    assert e.value.field == "mechanism" and "from_toml" in str(e.value)
    # a path with `=` in it is a path
    d = tmp_path / "x=1"
    d.mkdir()
    (d / "cam.toml").write_text((EXAMPLES / "paper.toml").read_text())
    w = Studio.from_toml(d / "cam.toml")
    assert w.mechanism.name == "cam"


def test_the_interpolation_study_refuses_a_gear_pair_saying_why():
    import warnings

    with warnings.catch_warnings():
        warnings.simplefilter("ignore", camkin.CamkinWarning)
        g = camkin.Mechanism.from_toml(EXAMPLES / "gear-pair-20-42.toml")
    with pytest.raises(camkin.InputError) as e:
        g.compare([100])
    assert e.value.field == "mechanism" and "does not repeat" in str(e.value)


def test_the_widget_refuses_a_file_larger_than_a_mechanism(tmp_path):
    from camkin.widget import Studio

    big = tmp_path / "big.toml"
    big.write_text("# " + "x" * (9 << 20) + "\n")
    with pytest.raises(camkin.InputError) as e:
        Studio.from_toml(big)
    assert e.value.field == "source" and "MiB" in str(e.value)
