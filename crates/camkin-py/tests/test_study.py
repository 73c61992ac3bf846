"""Design studies: parallel inside one call, equal to analyze, independent of the thread count,
Dask equal to serial; the GIL is released during sweeps; motion laws, synthesis, checks, the
paper's study and simulation against the command."""

import math
import threading
import time

import numpy as np
import pytest

import camkin
from conftest import EXAMPLES, csv_columns, run_cli


def perturbed(n_designs, sigma=0.01, seed=1):
    base = np.array(camkin.paper_cam().to_dict()["cam"]["profile"]["points"])
    rng = np.random.default_rng(seed)
    return base + rng.normal(0.0, sigma, (n_designs,) + base.shape)


def test_spline_variants_equal_analyze_and_do_not_depend_on_threads():
    m = camkin.paper_cam()
    nodes = perturbed(12)
    one = camkin.spline_variants(m, nodes, threads=1)
    two = camkin.spline_variants(m, nodes, threads=2)
    for k in one:
        if k == "error":
            assert list(one[k]) == list(two[k])
        else:
            assert np.array_equal(one[k], two[k], equal_nan=True), k
    for d in (0, 5, 11):
        r = m.with_nodes(nodes[d]).analyze(np.arange(0.0, 360.0, 1.0))
        acc = r["acceleration_cm_s2"]
        k = int(np.argmax(np.abs(acc)))
        assert one["peak_acceleration_cm_s2"][d] == acc[k]
        assert one["peak_acceleration_angle_deg"][d] == r["angle_deg"][k]
        assert one["max_position_cm"][d] == r["position_cm"].max()
        assert one["peak_pressure_angle_deg"][d] == r["pressure_angle_deg"][np.argmax(np.abs(r["pressure_angle_deg"]))]


def test_a_design_that_cannot_be_built_says_why():
    m = camkin.paper_cam()
    nodes = perturbed(3)
    nodes[1, 2] = nodes[1, 1]  # two coincident nodes
    r = camkin.spline_variants(m, nodes)
    assert r["error"][0] is None and r["error"][2] is None
    assert "coincide" in r["error"][1] or "points" in r["error"][1]
    assert math.isnan(r["peak_acceleration_cm_s2"][1])


def test_summarize_a_list_of_mechanisms():
    base = camkin.Mechanism.from_toml(EXAMPLES / "eccentric-roller.toml")
    mechs = []
    for r in (2.0, 4.0, 6.0):
        d = base.to_dict()
        d["follower"]["roller_radius"] = r
        mechs.append(camkin.Mechanism.from_dict(d))
    s = camkin.summarize(mechs, angles_deg=np.arange(0, 360, 2.0))
    u = base.length_unit
    for k, m in enumerate(mechs):
        a = m.analyze(np.arange(0, 360, 2.0))[f"acceleration_{u}_s2"]
        assert s[f"peak_acceleration_{u}_s2"][k] == a[np.argmax(np.abs(a))]
    with pytest.raises(camkin.InputError):
        camkin.summarize([base, camkin.Mechanism.from_toml(EXAMPLES / "oscillating-roller.toml")])


def test_dask_local_cluster_equals_serial():
    distributed = pytest.importorskip("dask.distributed")
    m = camkin.paper_cam()
    nodes = perturbed(40, seed=7)
    serial = camkin.spline_variants(m, nodes, threads=1)
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None) as cluster, distributed.Client(cluster) as client:
        mf = client.scatter(m, broadcast=True)
        futures = [client.submit(camkin.spline_variants, mf, chunk, threads=1) for chunk in np.array_split(nodes, 4)]
        parts = client.gather(futures)
    key = "peak_acceleration_cm_s2"
    assert np.array_equal(np.concatenate([p[key] for p in parts]), serial[key])


def test_sweeps_release_the_gil():
    m = camkin.paper_cam()
    angles = np.arange(0, 360, 0.0005)  # 720 000 angles: about a second
    done = threading.Event()
    ticks = []

    def sweep():
        m.analyze(angles)
        done.set()

    t = threading.Thread(target=sweep)
    t0 = time.perf_counter()
    t.start()
    while not done.is_set():
        ticks.append(time.perf_counter())
        time.sleep(0.001)
    t.join()
    # the main thread kept running Python while the sweep ran: with the GIL held it would have
    # had no turn at all until the sweep returned
    assert len(ticks) > 50, len(ticks)
    assert time.perf_counter() - t0 > 0.1


def test_motion_laws_against_closed_forms():
    x = np.linspace(0, 1, 11)
    c = camkin.motion_law("cycloidal", x)
    assert np.allclose(c["y"], x - np.sin(2 * np.pi * x) / (2 * np.pi), atol=1e-15)
    p = camkin.motion_law("3-4-5", x)
    assert np.allclose(p["y"], 10 * x**3 - 15 * x**4 + 6 * x**5, atol=1e-15)
    for name in camkin.motion_laws():
        v = camkin.motion_law(name, np.array([0.0, 1.0]))
        if name != "dwell":
            assert v["y"][0] == 0.0 and v["y"][1] == pytest.approx(1.0)
        # y' by finite differences of y
        h = 1e-6
        y = camkin.motion_law(name, np.array([0.3 - h, 0.3 + h]))["y"]
        assert camkin.motion_law(name, 0.3)["dy"] == pytest.approx((y[1] - y[0]) / (2 * h), abs=1e-6)


def test_synthesize_round_trip_and_checks():
    m = camkin.synthesize(
        segments=[
            {"law": "cycloidal", "rise": 12.0, "degrees": 120},
            {"law": "dwell", "degrees": 60},
            {"law": "3-4-5", "rise": -12.0, "degrees": 120},
            {"law": "dwell", "degrees": 60},
        ],
        base_radius=40.0,
        follower={"kind": "translating-roller", "direction": [0.0, 1.0], "offset": 5.0, "roller_radius": 10.0},
        speed_rpm=600.0,
        length_unit="mm",
    )
    assert m.to_dict() == camkin.Mechanism.from_toml(EXAMPLES / "motion-roller.toml").to_dict()
    ch = m.checks()
    assert ch["passed"] and ch["failures"] == []
    assert ch["round_trip"]["acceleration"] <= 1e-6 * ch["round_trip"]["scale"]
    # the lift follows the program: 12 mm of cycloidal rise over 120°: at 60°, half of it
    r = m.analyze(60.0)
    assert r["lift_mm"] == pytest.approx(6.0, abs=1e-9)
    # a roller larger than the concave radius: undercut, named
    bad = m.to_dict()
    bad["follower"]["roller_radius"] = 38.0
    chk = camkin.Mechanism.from_dict(bad).checks(pressure_limit_deg=10.0)
    assert not chk["passed"] and "pressure angle" in chk["failures"]
    assert abs(chk["pressure_peak"][0]) > 10.0


def test_checks_equal_the_command_synth_report(tmp_path):
    import re

    m = camkin.Mechanism.from_toml(EXAMPLES / "motion-roller.toml")
    ch = m.checks()
    out = run_cli("synth", EXAMPLES / "motion-roller.toml", "--out", tmp_path)
    peak, at = map(float, re.search(r"pressure angle: peak (-?[0-9.]+)° at ([0-9.]+)°", out).groups())
    assert abs(peak - ch["pressure_peak"][0]) <= 0.005 and abs(at - ch["pressure_peak"][1]) <= 0.005
    rho, at = map(float, re.search(r"smallest convex radius of curvature of the profile: ([0-9.]+) mm at ([0-9.]+)°", out).groups())
    # the command prints six significant digits of the refined extreme
    assert rho == pytest.approx(ch["convex_min"][0], rel=1e-5) and at == pytest.approx(ch["convex_min"][1], abs=1e-4)
    # the words are the library's design report, written once: the command prints them first
    assert ch["text"] and out.startswith(ch["text"]), (ch["text"], out)
    assert [v["check"] for v in ch["verdicts"]] == ["round-trip", "curvature", "undercut", "pressure-angle"]
    assert all(v["passed"] and v["lines"] for v in ch["verdicts"])


def test_compare_is_the_papers_study():
    m = camkin.paper_cam()
    c = m.compare(nodes=[100, 1000], step_deg=0.5)
    assert c["angle_deg"].shape == (720,)
    exact = c["contact_method_cm_s2"]
    r = m.analyze(c["angle_deg"])
    assert np.allclose(exact, r["acceleration_cm_s2"], rtol=0, atol=1e-9 * np.abs(exact).max())
    # interpolation converges towards the exact curve as N grows (the paper's Figure 4)
    assert c["max_rel_error"][1000] < c["max_rel_error"][100] < 1.0
    rel = np.abs(c["interpolated_cm_s2"][100] - exact) / np.abs(exact).max()
    assert np.allclose(rel, c["rel_error"][100], rtol=1e-12, atol=1e-15)


def test_simulate_equals_the_command_csv():
    path = EXAMPLES / "eccentric-flat-dynamics.toml"
    m = camkin.Mechanism.from_toml(path)
    s = m.simulate(revolutions=1.0, step_deg=2.0)
    cli = csv_columns(run_cli("simulate", path, "--revolutions", "1", "--step", "2"))
    assert list(s["samples"]) == list(cli)
    for col, cells in cli.items():
        v = s["samples"][col]
        if col == "in_contact":
            assert [("1" if x else "0") for x in v] == cells
        else:
            assert [float(c) for c in cells] == list(v), col
    assert isinstance(s["events"], list)


def test_no_designs_is_an_empty_study_not_a_crash():
    r = camkin.spline_variants(camkin.paper_cam(), np.zeros((0, 9, 2)))
    assert r["peak_acceleration_cm_s2"].shape == (0,)
    with pytest.raises(camkin.InputError) as e:
        camkin.spline_variants(camkin.Mechanism.from_toml(EXAMPLES / "motion-roller.toml"), np.zeros((0, 9, 2)))
    assert e.value.field == "cam.profile.kind"
