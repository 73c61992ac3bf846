"""The paper's Figure 4: the follower's acceleration of the paper's cam over a revolution, exact by
the contact method, beside a cubic spline through 100 sampled positions differentiated twice.

    python examples/python/figure4.py [out.png]
"""
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

import camkin

cam = camkin.paper_cam()
exact = cam.analyze(np.arange(0, 360, 0.05))
study = cam.compare(nodes=[100], step_deg=0.05)
fig, ax = plt.subplots(figsize=(8, 4.5))
ax.plot(exact["angle_deg"], exact["acceleration_cm_s2"], label="contact method (exact)")
ax.plot(study["angle_deg"], study["interpolated_cm_s2"][100], "--", label="cubic spline through 100 positions")
ax.set(xlabel="cam angle (°)", ylabel="follower acceleration (cm/s²)", title="Paper's cam at 1000 rpm (Figure 4)")
ax.legend()
fig.savefig(sys.argv[1] if len(sys.argv) > 1 else "figure4.png", dpi=120, bbox_inches="tight")
