"""The studio in a real browser (headless Chromium): it loads without console errors, draws,
follows the slider, reacts to a dragged node with the numbers `camkin analyze` gives for the
edited file, shows a bad edit's line and column while keeping the last good result, and its
report renders offline."""

import csv
import shutil

from conftest import ROOT, camkin

EXAMPLES = ROOT / "examples"


def loaded(page, url):
    page.goto(url)
    # a system file has no interpolation study; a gear pair's is refused (its motion does not repeat)
    try:
        page.wait_for_function(
            "window.studio && window.studio.result"
            " && (window.studio.compare || window.studio.result.system || window.studio.compareFor !== undefined)"
            " && window.studio.idle()"
        )
    except Exception as e:
        # say what the page says (a refused request shows its message)
        said = page.evaluate(
            "['status', 'compare-summary', 'error'].map(id => id + ': ' + (document.getElementById(id) || {}).textContent)"
        )
        raise AssertionError(f"the page did not settle: {said}; errors {page.errors}") from e
    return page


def inked(page, selector):
    """How many pixels of the canvas are not white."""
    return page.evaluate(
        """(sel) => { const c = document.querySelector(sel);
            const d = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
            let n = 0; for (let i = 0; i < d.length; i += 4) if (d[i] < 240 || d[i+1] < 240 || d[i+2] < 240) n++;
            return n; }""",
        selector,
    )


def series(page, key):
    return page.evaluate(f"window.studio.result.series.find(s => s.key === '{key}').values")


def at_page_precision(page_values, file_values, resolution=None):
    """The page's series are the command's to the page's precision: within 1e-7 of the column's
    largest magnitude, or of its motion's scale (1e9 times the series' resolution) where that is
    larger (`studio::page_precision`: rounding noise reads 0; the downloads keep every digit),
    absent where the command's cell is."""
    top = max((abs(v) for v in file_values if v is not None), default=0.0)
    tol = max(1e-7 * top, 100.0 * (resolution or 0.0))
    return len(page_values) == len(file_values) and all(
        (a is None) == (b is None) and (a is None or abs(a - b) <= tol)
        for a, b in zip(page_values, file_values))


def test_page_loads_without_errors_and_draws_everything(serve, page):
    loaded(page, serve())
    assert page.errors == []
    for sel in ["#drawing", "#compare-acc", "#compare-err"] + [
        f'#plots canvas[data-key="{k}"]'
        for k in ["lift", "velocity", "acceleration", "jerk", "pressure_angle", "radius_of_curvature"]
    ]:
        assert inked(page, sel) > 2000, sel
    checks = page.locator("#checks li")
    assert checks.count() >= 3
    assert "paper.toml" in page.title() or "paper.toml" in page.locator("#title").inner_text()


def test_the_slider_moves_the_contact_point(serve, page):
    loaded(page, serve())
    before = page.evaluate("window.studio.result.frames[window.studio.index].contact")
    shot = page.locator("#drawing").screenshot()
    page.locator("#angle").fill("180")
    assert page.evaluate("window.studio.index") == 180
    assert page.locator("#angle-readout").inner_text() == "90°"
    after = page.evaluate("window.studio.result.frames[window.studio.index].contact")
    assert abs(after[0] - before[0]) + abs(after[1] - before[1]) > 0.5  # cm, on a 5 cm cam
    assert page.locator("#drawing").screenshot() != shot
    assert page.errors == []


def drag_node(page, i, dx, dy):
    x, y = page.evaluate(f"window.studio.nodeScreen({i})")
    page.mouse.move(x, y)
    page.mouse.down()
    for k in range(1, 11):
        page.mouse.move(x + dx * k / 10, y + dy * k / 10)
    page.mouse.up()
    page.wait_for_function("window.studio.idle()")


def test_dragging_a_node_gives_the_numbers_of_camkin_analyze_on_the_edited_file(serve, page, tmp_path):
    shutil.copy(EXAMPLES / "paper.toml", tmp_path / "cam.toml")
    loaded(page, serve(tmp_path / "cam.toml"))
    acc0 = series(page, "acceleration")
    drag_node(page, 1, 25, -18)
    acc1 = series(page, "acceleration")
    assert acc1 != acc0
    # the comparison follows the edit: its exact curve is the new one
    assert page.evaluate("window.studio.compare.exact") == acc1
    assert max(abs(a - b) for a, b in zip(acc0, acc1)) > 1000  # cm/s², of a 27 000 cm/s² peak
    text = page.locator("#editor").input_value()
    assert text == page.evaluate("window.studio.toml")
    assert "[3.4, 2.8]" not in text  # the dragged node was written into the file
    (tmp_path / "edited.toml").write_text(text)
    out = tmp_path / "out.csv"
    camkin("analyze", tmp_path / "edited.toml", "--angles", "0:360:0.5", "-o", out)
    rows = list(csv.DictReader(out.open()))
    assert len(rows) == 720
    for key, col in [
        ("lift", "lift_cm"),
        ("velocity", "velocity_cm_s"),
        ("acceleration", "acceleration_cm_s2"),
        ("jerk", "jerk_cm_s3"),
        ("pressure_angle", "pressure_angle_deg"),
        ("radius_of_curvature", "radius_of_curvature_cm"),
    ]:
        page_values = series(page, key)
        file_values = [float(r[col]) if r[col] not in ("", "inf", "-inf") else None for r in rows]
        resolution = page.evaluate(f"window.studio.result.series.find(s => s.key === '{key}').resolution")
        assert at_page_precision(page_values, file_values, resolution), key
    assert page.errors == []


def test_a_bad_edit_shows_line_and_column_and_keeps_the_last_result(serve, page):
    loaded(page, serve())
    acc = series(page, "acceleration")
    good = page.locator("#editor").input_value()
    page.locator("#editor").fill(good.replace("speed_rpm = 1000.0", "speed_rpm = -5.0"))
    page.wait_for_selector("#error:not([hidden])")
    msg = page.locator("#error").inner_text()
    assert "line 6, column 13" in msg and "speed_rpm" in msg, msg
    assert series(page, "acceleration") == acc
    # a syntax error, placed by the TOML parser
    page.locator("#editor").fill(good.replace("[follower]", "[follower"))
    page.wait_for_function("document.querySelector('#error').innerText.includes('line 15, column')")
    assert series(page, "acceleration") == acc
    # mended: the error goes, the result is the file's again
    page.locator("#editor").fill(good)
    page.wait_for_selector("#error", state="hidden")
    page.wait_for_function("window.studio.idle()")
    assert series(page, "acceleration") == acc
    # the console reports the refused requests (422) and nothing else
    assert all("422" in e for e in page.errors), page.errors


def test_the_report_opens_offline_and_renders(page, tmp_path):
    report = tmp_path / "report.html"
    camkin("report", EXAMPLES / "paper-dynamics.toml", "-o", report)
    requests = []

    def offline(route):
        requests.append(route.request.url)
        if route.request.url.startswith("file:"):
            route.continue_()
        else:
            route.abort()

    page.context.route("**/*", offline)
    page.goto(report.as_uri())
    page.wait_for_function("window.studio && window.studio.result")
    assert [u for u in requests if not u.startswith("file:")] == []
    assert page.errors == []
    assert inked(page, "#drawing") > 2000
    assert inked(page, '#plots canvas[data-key="acceleration"]') > 2000
    assert inked(page, "#force") > 2000
    assert page.locator("#dynamics-panel").is_visible()
    page.locator("#angle").fill("90")
    assert page.evaluate("window.studio.index") == 90
    assert page.locator("#editor").input_value().startswith("#")
    # a design review document (issue 49): titled, dated, its verdict and the profile's extent
    import datetime
    import re
    assert page.title() == "Design review — paper-dynamics.toml"
    status = page.locator("#status").inner_text()
    today = datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%d")
    assert today in status and "design check" in status, status
    # its manufacturing summary: camkin profile's polar table (the paper's cam: 3.4 to 5 cm) and DXF
    assert "Shop (camkin profile): polar table (1°) radius" in status and "DXF of" in status, status
    m = re.search(r"radius ([\d.]+) to ([\d.]+) cm", status)
    assert m and abs(float(m.group(2)) - 5.0) < 1e-4, status
    # the readouts are rounded for people at every angle: no rounding noise such as 1.7e-16
    for a in ("0", "45", "90", "180"):
        page.locator("#angle").fill(a)
        values = page.locator("#values").inner_text()
        assert not re.search(r"e-1\d", values), values


def test_the_speed_slider_shows_where_the_follower_jumps(serve, page):
    loaded(page, serve(EXAMPLES / "paper-dynamics.toml"))
    jump = page.evaluate("window.studio.result.dynamics.jump_rpm")
    assert jump and jump > 0
    page.locator("#rpm").fill(str(int(jump * 0.9)))
    assert "holds" in page.locator("#dynamics-summary").inner_text()
    page.locator("#rpm").fill(str(int(jump * 1.1) + 1))
    assert "jumps" in page.locator("#dynamics-summary").inner_text()
    assert page.errors == []


def test_a_lubrication_section_is_drawn_in_the_force_panel(serve, page, tmp_path):
    # the eccentric disc at 1000 rpm (it stays on the cam) with SAE 30 at 100 °C: λ, shaded by
    # regime, the command's numbers to the page's precision
    text = (EXAMPLES / "eccentric-flat-dynamics.toml").read_text().replace(
        "speed_rpm = 1380.0", "speed_rpm = 1000.0")
    path = tmp_path / "lub.toml"
    path.write_text(text + '\n[lubrication]\noil = "sae-30@100c"\nroughness_um = [0.2, 0.3]\nface_width = 10.0\n')
    loaded(page, serve(path))
    assert page.errors == []
    assert page.locator("#lubrication-box").is_visible()
    summary = page.locator("#lubrication-summary").inner_text()
    assert "λ min" in summary and "flash temperature max" in summary, summary
    assert inked(page, "#lubrication") > 2000
    out = tmp_path / "out"
    camkin("forces", path, "--step", str(page.evaluate("window.studio.result.step_deg")), "--out", out)
    with open(out / "lubrication.csv") as f:
        rows = list(csv.DictReader(f))
    cli = [float(r["lambda"]) if r["lambda"] else None for r in rows]
    assert at_page_precision(page.evaluate("window.studio.result.dynamics.lubrication.lambda"), cli)
    page.locator("#dynamics-panel").screenshot(path=str(ROOT / "target" / "studio-lubrication.png"))
    # without the section there is no lubrication box
    loaded(page, serve(EXAMPLES / "paper-dynamics.toml"))
    assert not page.locator("#lubrication-box").is_visible()


def test_a_gear_pairs_loads_are_drawn_along_its_path_of_contact(serve, page, tmp_path):
    # the FZG C pair with [gear_loads] and [lubrication]: Hertz, the specific sliding and λ over
    # the driver's contact radius, the command's gear_loads.csv to the last digit
    shutil.copy(EXAMPLES / "fzg-c.toml", tmp_path / "fzg.toml")
    loaded(page, serve(tmp_path / "fzg.toml"))
    assert page.errors == []
    assert page.locator("#gear-panel").is_visible()
    summary = page.locator("#gear-summary").inner_text()
    assert "302 N·m" in summary and "Hertz max" in summary and "λ min" in summary, summary
    for c in ("#gear-hertz", "#gear-sliding", "#gear-lambda"):
        assert inked(page, c) > 2000, c
    out = tmp_path / "out"
    camkin("forces", tmp_path / "fzg.toml", "--out", out)
    with open(out / "gear_loads.csv") as f:
        rows = list(csv.DictReader(f))
    g = page.evaluate("window.studio.result.gear_loads")
    assert len(g["hertz_mpa"]) == len(rows)
    for got, row in zip(g["hertz_mpa"], rows):
        assert got == float(row["hertz_MPa"])
    for got, row in zip(g["radius"], rows):
        assert abs(got - 1e3 * float(row["driver_radius_m"])) <= 1e-12 * got
    for got, row in zip(g["lambda"], rows):
        assert got == float(row["lambda"])
    # the cursor: the contact drawn lies on the path (its radius between the ends)
    r = page.evaluate("(() => { const s = window.studio, f = s.result.frames[s.index];"
                      " return Math.hypot(f.contact[0] - s.result.pivot[0], f.contact[1] - s.result.pivot[1]); })()")
    assert g["radius"][0] - 1e-9 <= r <= g["radius"][-1] + 1e-9, r
    page.locator("#gear-panel").screenshot(path=str(ROOT / "target" / "studio-gear-loads.png"))
    # a gear pair without the section has no panel
    loaded(page, serve(EXAMPLES / "gear-pair-20-42.toml"))
    assert not page.locator("#gear-panel").is_visible()


import pytest  # noqa: E402


# every mechanism file (system files below)
@pytest.mark.parametrize(
    "example",
    sorted(p.name for p in EXAMPLES.glob("*.toml") if "[[body]]" not in p.read_text()),
)
def test_every_example_opens_and_draws(serve, page, example, tmp_path):
    shutil.copytree(EXAMPLES, tmp_path / "ex")
    loaded(page, serve(tmp_path / "ex" / example))
    assert page.errors == []
    assert page.evaluate("window.studio.lastError") is None
    assert inked(page, "#drawing") > 2000
    assert inked(page, '#plots canvas[data-key="acceleration"]') > 2000
    n = page.evaluate("window.studio.result.frames.length")
    page.locator("#angle").fill(str(n // 3))
    assert page.evaluate("window.studio.result.frames[window.studio.index].contact") is not None
    if "gear" in example or example == "fzg-c.toml":
        # the interpolation study does not apply to a gear pair, and the page says why
        assert "does not repeat" in page.locator("#compare-summary").inner_text()
    page.screenshot(path=str(ROOT / "target" / f"studio-{example}.png"))


def test_hover_shows_values_with_units_and_play_turns_the_cam(serve, page):
    loaded(page, serve())
    box = page.locator('#plots canvas[data-key="acceleration"]').bounding_box()
    page.mouse.move(box["x"] + box["width"] / 2, box["y"] + box["height"] / 2)
    tip = page.locator("#tooltip")
    assert tip.is_visible()
    assert "cam angle" in tip.inner_text() and "cm/s²" in tip.inner_text()
    page.locator("#play").click()
    page.wait_for_function("window.studio.index > 10")
    page.locator("#play").click()
    stopped = page.evaluate("window.studio.index")
    page.wait_for_timeout(200)
    assert page.evaluate("window.studio.index") == stopped
    assert page.errors == []


def test_a_file_with_an_error_opens_to_be_mended(serve, page, tmp_path):
    good = (EXAMPLES / "paper.toml").read_text()
    (tmp_path / "cam.toml").write_text(good.replace('kind = "spline"', 'kind = "splin"'))
    page.goto(serve(tmp_path / "cam.toml"))
    page.wait_for_selector("#error:not([hidden])")
    assert "line 11, column 8" in page.locator("#error").inner_text()
    page.evaluate(
        "t => { const e = document.querySelector('#editor'); e.value = t; e.dispatchEvent(new Event('input')); }",
        good,
    )
    page.wait_for_function("window.studio.result && window.studio.idle()")
    assert page.locator("#error").is_hidden()
    assert [e for e in page.errors if "422" not in e] == []


# every system file: bodies, joints and contacts drawn, the slider turning the first driver
@pytest.mark.parametrize(
    "example",
    # the kinematic ones: a file with [dynamics] is simulated (`camkin simulate`)
    sorted(
        p.name
        for p in EXAMPLES.glob("*.toml")
        if "[[body]]" in p.read_text() and "[dynamics]" not in p.read_text()
    ),
)
def test_every_system_example_opens_draws_and_turns_with_the_slider(serve, page, example, tmp_path):
    shutil.copytree(EXAMPLES, tmp_path / "ex")
    loaded(page, serve(tmp_path / "ex" / example))
    assert page.errors == []
    assert page.evaluate("window.studio.lastError") is None
    assert page.evaluate("window.studio.result.system") is True
    assert page.locator("#compare-panel").is_hidden()
    assert inked(page, "#drawing") > 2000
    keys = page.evaluate("window.studio.result.series.map(s => s.key)")
    assert keys, example
    for k in keys:
        assert inked(page, f'#plots canvas[data-key="{k}"]') > 1000, k
    shot = page.locator("#drawing").screenshot()
    n = page.evaluate("window.studio.result.frames.length")
    page.locator("#angle").fill(str(n // 3))
    assert page.locator("#drawing").screenshot() != shot
    assert page.evaluate("window.studio.result.failed") == 0
    page.screenshot(path=str(ROOT / "target" / f"studio-{example}.png"))


def test_a_systems_numbers_on_screen_are_the_commands(serve, page, tmp_path):
    """The valve train in the studio: each plotted series at every angle is the column of
    `camkin analyze FILE --angles 0:360:0.5` for that body (angles in degrees)."""
    loaded(page, serve(EXAMPLES / "valve-train-kinematics.toml"))
    rows = list(csv.DictReader(camkin("analyze", EXAMPLES / "valve-train-kinematics.toml", "--angles", "0:360:0.5").stdout.splitlines()))
    assert page.evaluate("window.studio.result.angles_deg.length") == len(rows) == 720
    finger = series(page, "finger_angle")
    valve = series(page, "valve_y")
    valve_a = series(page, "valve_y_acceleration")
    for values, col in [(finger, "finger_angle_deg"), (valve, "valve_y_mm"), (valve_a, "valve_ay_mm_s2")]:
        assert at_page_precision(values, [float(r[col]) for r in rows]), col
    assert "valve y" in page.locator("#values").inner_text()
