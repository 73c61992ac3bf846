"""The studio as a Jupyter widget, tried as a user would: a notebook in JupyterLab (installed from
PyPI by the test script) in headless Chromium builds the paper's cam and shows `Studio`; a node
is dragged in the page; the plots change, and the kernel's `widget.mechanism` holds the moved
node."""

import json
import tomllib
from pathlib import Path

ROOT = Path(__file__).resolve().parents[3]

NOTEBOOK = {
    "cells": [
        {
            "cell_type": "code",
            "metadata": {},
            "execution_count": None,
            "outputs": [],
            "source": "import camkin\nfrom camkin.widget import Studio\nw = Studio(camkin.paper_cam())\nw",
        }
    ],
    "metadata": {
        "kernelspec": {"name": "python3", "display_name": "Python 3", "language": "python"}
    },
    "nbformat": 4,
    "nbformat_minor": 5,
}

# runs code in the notebook's own kernel and returns what it printed (an error's name and value)
RUN_IN_KERNEL = """async (code) => {
  const kernel = window.jupyterapp.shell.currentWidget.sessionContext.session.kernel;
  const future = kernel.requestExecute({ code });
  let out = "";
  future.onIOPub = (m) => {
    if (m.header.msg_type === "stream" && m.content.name === "stdout") out += m.content.text;
    if (m.header.msg_type === "error") out += `${m.content.ename}: ${m.content.evalue}`;
  };
  await future.done;
  return out;
}"""


def studio_frame(page):
    handle = page.wait_for_selector("iframe.camkin-studio", timeout=120_000)
    frame = handle.content_frame()
    frame.wait_for_function(
        "window.studio && window.studio.result && window.studio.compare && window.studio.idle()",
        timeout=120_000,
    )
    return handle, frame


def series(frame, key):
    return frame.evaluate(f"window.studio.result.series.find(s => s.key === '{key}').values")


def open_notebook(page, url, work, source, name="cam.ipynb"):
    """A notebook of one cell, `source`, opened in JupyterLab and run; returns the studio's
    frame element and frame once its first answers are in."""
    nb = json.loads(json.dumps(NOTEBOOK))
    nb["cells"][0]["source"] = source
    (work / name).write_text(json.dumps(nb))
    page.goto(f"{url}/lab/tree/{name}")
    page.wait_for_function(
        "window.jupyterapp && window.jupyterapp.shell.currentWidget"
        " && window.jupyterapp.shell.currentWidget.sessionContext"
        " && window.jupyterapp.shell.currentWidget.sessionContext.session"
        " && window.jupyterapp.shell.currentWidget.sessionContext.session.kernel"
        " && window.jupyterapp.shell.currentWidget.sessionContext.session.kernel.connectionStatus === 'connected'",
        timeout=120_000,
    )
    page.evaluate("window.jupyterapp.commands.execute('notebook:run-all-cells')")
    return studio_frame(page)


def inked(frame, selector):
    """How many pixels of a canvas in the frame are not white."""
    return frame.evaluate(
        """(sel) => { const c = document.querySelector(sel);
            const d = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
            let n = 0; for (let i = 0; i < d.length; i += 4) if (d[i] < 240 || d[i+1] < 240 || d[i+2] < 240) n++;
            return n; }""",
        selector,
    )


def test_a_node_dragged_in_the_notebook_widget_moves_the_kernels_mechanism(jupyterlab, page):
    url, work = jupyterlab
    handle, frame = open_notebook(page, url, work, NOTEBOOK["cells"][0]["source"])
    # the page drew the paper's cam from the kernel's answers
    before = series(frame, "acceleration")
    assert len(before) == 720
    assert max(map(abs, before)) > 20_000  # cm/s², the paper's cam peaks near 27 000
    handle.scroll_into_view_if_needed()
    box = handle.bounding_box()
    x, y = frame.evaluate("window.studio.nodeScreen(1)")
    x, y = box["x"] + x, box["y"] + y
    page.mouse.move(x, y)
    page.mouse.down()
    for k in range(1, 11):
        page.mouse.move(x + 25 * k / 10, y - 18 * k / 10)
    page.mouse.up()
    frame.wait_for_function("window.studio.idle()", timeout=60_000)
    after = series(frame, "acceleration")
    assert max(abs(a - b) for a, b in zip(before, after)) > 1000  # cm/s²: the plots changed
    page_points = tomllib.loads(frame.evaluate("window.studio.toml"))["cam"]["profile"]["points"]
    assert page_points[1] != [3.4, 2.8]  # the dragged node moved in the page's text
    out = page.evaluate(
        RUN_IN_KERNEL,
        "import json; print(json.dumps(w.mechanism.to_dict()['cam']['profile']['points']))",
    )
    kernel_points = json.loads(out)
    assert kernel_points == page_points, out
    # the kernel's mechanism analyses as the page shows it, to the page's precision
    out = page.evaluate(
        RUN_IN_KERNEL,
        "import json; r = w.mechanism.analyze([k * 0.5 for k in range(720)]);"
        " print(json.dumps([float(v) for v in r['acceleration_cm_s2']]))",
    )
    exact = json.loads(out)
    top = max(map(abs, exact))
    assert all(abs(a - b) <= 1e-7 * top for a, b in zip(after, exact))
    page.screenshot(path=str(ROOT / "target" / "widget-jupyterlab.png"))
    assert page.errors == []


def test_a_gear_pairs_mesh_and_loads_in_the_notebook_widget(jupyterlab, page):
    """The same widget on a gear pair file: the mesh drawn, its plots, and its [gear_loads]
    panel, computed in the kernel."""
    url, work = jupyterlab
    source = (
        "from camkin.widget import Studio\n"
        f"w = Studio.from_toml({str(ROOT / 'examples' / 'fzg-c.toml')!r})\n"
        "w"
    )
    handle, frame = open_notebook(page, url, work, source, name="gears.ipynb")
    assert frame.evaluate("document.getElementById('gear-panel').hidden") is False
    for sel in ["#drawing", "#gear-hertz", "#gear-sliding", "#gear-lambda"]:
        assert inked(frame, sel) > 2000, sel
    # the kernel's answer is the command's: the pitch-point Hertz pressure of load stage 9
    summary = frame.evaluate("document.getElementById('gear-summary').textContent")
    assert "MPa" in summary or "N/mm" in summary, summary
    handle.scroll_into_view_if_needed()
    page.screenshot(path=str(ROOT / "target" / "widget-jupyterlab-gears.png"))
    assert page.errors == []
