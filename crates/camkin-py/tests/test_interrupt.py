"""Ctrl-C during a long call raises KeyboardInterrupt promptly (not PanicException, not after the
call has finished): the work released the GIL checks for signals between chunks."""

import os
import signal
import threading
import time

import numpy as np
import pytest

import camkin
from conftest import EXAMPLES


def interrupt_after(seconds):
    def fire():
        time.sleep(seconds)
        os.kill(os.getpid(), signal.SIGINT)

    threading.Thread(target=fire, daemon=True).start()


@pytest.mark.parametrize(
    "call",
    [
        lambda: camkin.paper_cam().analyze(np.linspace(0.0, 360.0, 20_000_000), large=True),
        lambda: camkin.paper_cam().contacts(np.linspace(0.0, 360.0, 2_000_000), large=True),
        lambda: camkin.Mechanism.from_toml(EXAMPLES / "eccentric-flat-dynamics.toml").simulate(
            revolutions=5_000, large=True
        ),
        lambda: camkin.spline_variants(
            camkin.paper_cam(),
            np.array(camkin.paper_cam().to_dict()["cam"]["profile"]["points"])[None].repeat(20_000, 0),
            angles_deg=np.arange(0.0, 360.0, 0.1),
            large=True,
        ),
    ],
    ids=["analyze", "contacts", "simulate", "spline_variants"],
)
def test_ctrl_c_interrupts_a_long_call(call):
    interrupt_after(0.5)
    t0 = time.monotonic()
    with pytest.raises(KeyboardInterrupt):
        call()
    # within a couple of chunks of work, not at the end (each of these runs for tens of seconds)
    assert time.monotonic() - t0 < 5.0
