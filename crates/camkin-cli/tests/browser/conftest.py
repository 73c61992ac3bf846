"""Fixtures of the studio's browser tests: a `camkin serve` process per test and headless
Chromium (Debian's package) driven by Playwright over the DevTools protocol."""

import os
import shutil
import subprocess
from pathlib import Path

import pytest
from playwright.sync_api import sync_playwright

ROOT = Path(__file__).resolve().parents[4]
CAMKIN = os.environ.get("CAMKIN_BIN", str(ROOT / "target" / "release" / "camkin"))
CHROMIUM = os.environ.get("CAMKIN_CHROMIUM", shutil.which("chromium") or "/usr/bin/chromium")
# as the machine's network is closed, Chromium's own background connections are turned off
ARGS = [
    "--no-sandbox",
    "--disable-gpu",
    "--disable-quic",
    "--no-first-run",
    "--disable-background-networking",
    "--disable-component-update",
    "--disable-sync",
]


class Server:
    def __init__(self, args):
        self.proc = subprocess.Popen(
            [CAMKIN, "serve", *args, "--port", "0"],
            stdout=subprocess.PIPE,
            stderr=subprocess.PIPE,
            text=True,
        )
        self.url = self.proc.stdout.readline().strip()
        assert self.url.startswith("http://127.0.0.1:"), self.proc.stderr.read()

    def stop(self):
        self.proc.kill()
        self.proc.wait()


@pytest.fixture
def serve():
    servers = []

    def start(*args):
        s = Server([str(a) for a in args])
        servers.append(s)
        return s.url

    yield start
    for s in servers:
        s.stop()


@pytest.fixture(scope="session")
def browser():
    with sync_playwright() as p:
        b = p.chromium.launch(executable_path=CHROMIUM, args=ARGS)
        yield b
        b.close()


@pytest.fixture
def page(browser):
    """A page that records console errors and uncaught exceptions in `page.errors`."""
    ctx = browser.new_context(viewport={"width": 1400, "height": 1000})
    pg = ctx.new_page()
    pg.errors = []
    pg.on("console", lambda m: pg.errors.append(m.text) if m.type == "error" else None)
    pg.on("pageerror", lambda e: pg.errors.append(str(e)))
    yield pg
    ctx.close()


def camkin(*args):
    return subprocess.run([CAMKIN, *map(str, args)], capture_output=True, text=True, check=True)
