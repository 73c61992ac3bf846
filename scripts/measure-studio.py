#!/usr/bin/env python3
"""Measures the studio's edit-to-screen time in headless Chromium: drags a node of the paper cam
(and of a 10 000-node profile) in small steps, each step waiting for the updated plots, and
prints the medians of the server's time, the time to the answer's arrival (request, analysis,
JSON parse) and the time to the redrawn screen. Run by hand (needs scripts/test-browser's
virtualenv and Chromium): target/pyenv/bin/python scripts/measure-studio.py"""

import math
import os
import shutil
import statistics
import subprocess
import sys
import tempfile
from pathlib import Path

from playwright.sync_api import sync_playwright

ROOT = Path(__file__).resolve().parents[1]
CAMKIN = os.environ.get("CAMKIN_BIN", str(ROOT / "target" / "release" / "camkin"))
ARGS = ["--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
        "--disable-background-networking", "--disable-component-update", "--disable-sync"]


def big_profile(path, n):
    """An n-node spline through an eccentric ellipse the size of the paper's cam (convex)."""
    # a smooth convex closed curve near the paper's: an ellipse shifted along x
    pts = [[1.1 + 3.9 * math.cos(t), 3.45 * math.sin(t)] for t in
           (2 * math.pi * k / n for k in range(n))]
    body = ",\n".join(f"  [{x:.9f}, {y:.9f}]" for x, y in pts)
    path.write_text(
        'length_unit = "cm"\n[cam]\nspeed_rpm = 1000.0\n[cam.profile]\nkind = "spline"\n'
        f"points = [\n{body}\n]\n[follower]\nkind = \"translating-flat\"\n")


def measure(browser, url, steps, node):
    """`steps` edits: drags of node `node` by a pixel, or (node None) new cam speeds typed into
    the file (a drag on a 10 000-node profile makes a kink, which is not convex and is refused
    as too much work for one request)."""
    page = browser.new_page(viewport={"width": 1400, "height": 1000})
    page.goto(url)
    page.wait_for_function("window.studio && window.studio.result && window.studio.idle()", timeout=120000)
    page.evaluate("window.studio.timings.length = 0")
    if node is not None:
        x, y = page.evaluate(f"window.studio.nodeScreen({node})")
        page.mouse.move(x, y)
        page.mouse.down()
        for k in range(1, steps + 1):
            page.mouse.move(x + 0.6 * k, y - 0.4 * k)
            page.wait_for_function(f"window.studio.timings.length >= {k} && !window.studio.inflight", timeout=120000)
        page.mouse.up()
    else:
        text = page.locator("#editor").input_value()
        for k in range(1, steps + 1):
            # as a paste: the new text set at once, then the input event
            page.evaluate(
                "t => { const e = document.querySelector('#editor'); e.value = t;"
                " e.dispatchEvent(new Event('input')); }",
                text.replace("speed_rpm = 1000.0", f"speed_rpm = {1000 + k}.0"),
            )
            page.wait_for_function(f"window.studio.timings.length >= {k} && !window.studio.inflight", timeout=120000)
    t = page.evaluate("window.studio.timings")
    assert page.evaluate("window.studio.lastError") is None
    page.close()
    med = lambda key: statistics.median(x[key] for x in t)
    return len(t), med("server_ms"), med("network_ms"), med("total_ms")


def main():
    with tempfile.TemporaryDirectory() as d, sync_playwright() as p:
        d = Path(d)
        shutil.copy(ROOT / "examples" / "paper.toml", d / "paper.toml")
        big_profile(d / "big.toml", 10_000)
        browser = p.chromium.launch(executable_path=shutil.which("chromium") or "/usr/bin/chromium", args=ARGS)
        for name, steps, node in [("paper.toml", 40, 1), ("paper.toml", 20, None), ("big.toml", 10, None)]:
            proc = subprocess.Popen([CAMKIN, "serve", str(d / name), "--port", "0"],
                                    stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, text=True)
            url = proc.stdout.readline().strip()
            n, server, net, total = measure(browser, url, steps, node)
            how = "node drags" if node is not None else "typed edits"
            print(f"{name}: {n} {how}, median server {server:.2f} ms, answer in the page "
                  f"{net:.2f} ms, on screen {total:.2f} ms")
            proc.kill()
        browser.close()


if __name__ == "__main__":
    sys.exit(main())
