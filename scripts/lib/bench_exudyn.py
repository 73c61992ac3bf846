"""Public multibody benchmarks in camkin and in Exudyn, in one run on this machine.

Each problem is camkin's example file; the Exudyn model is built from the same file (its bodies,
revolute joints, springs, torques and gravity, each body's node at its centre of mass) and starts
from the state camkin starts from (the first sample's rates, which camkin made consistent with the
joints). Each tool runs a ladder of settings (camkin: its tolerances; Exudyn: its generalized-alpha
steps, its default solver, sparse, told to go on at a singular Jacobian); each run's error is
measured against the problem's reference, and its wall time (camkin's the whole command, CSV
written; Exudyn's its solver alone). Called by scripts/bench-exudyn; writes
target/bench-exudyn.json.

- IFToMM A02, the N-four-bar (N = 40, 20 s): B0's largest distance from the one-coordinate
  reference (J θ'' = -C cos θ, RK4 at 1e-4 s) at the 400 outputs; the benchmark's high precision
  is 1e-3 m.
- IFToMM A03, Andrews' squeezing mechanism (0.03 s): the largest error of the seven angles at
  0.03 s against the Test Set for IVP Solvers' published solution.
"""
import csv
import io
import json
import math
import subprocess
import sys
import time
import tomllib


def read_camkin(binary, example, tol):
    start = time.perf_counter()
    done = subprocess.run([binary, "simulate", example, "--rtol", str(tol), "--atol", str(tol)],
                          capture_output=True, text=True)
    wall = time.perf_counter() - start
    if done.returncode != 0:
        return None, wall, done.stderr.strip().splitlines()[-1]
    return list(csv.DictReader(io.StringIO(done.stdout))), wall, ""


def key(name):
    return "".join(c if c.isalnum() else "_" for c in name.lower())


def rotate(a, p):
    c, s = math.cos(a), math.sin(a)
    return (c * p[0] - s * p[1], s * p[0] + c * p[1])


def exudyn_run(spec, first, steps, t_end, outputs):
    """The file `spec` in Exudyn from camkin's first sample `first`: each body's (x, y, angle) at
    the outputs, and the wall time of its solver."""
    import exudyn as exu
    from exudyn.itemInterface import (NodeRigidBody2D, ObjectRigidBody2D, ObjectGround,
                                      MarkerBodyPosition, MarkerBodyRigid, MarkerNodePosition,
                                      ObjectJointRevolute2D, ObjectConnectorSpringDamper, Force,
                                      Torque, SensorNode)
    SC = exu.SystemContainer()
    mbs = SC.AddSystem()
    ground = mbs.AddObject(ObjectGround())
    bodies = {}
    for b in spec["body"]:
        k = key(b["name"])
        a = math.radians(float(first[f"{k}_angle_deg"]))
        o = (float(first[f"{k}_x_m"]), float(first[f"{k}_y_m"]))
        c = b.get("centre_of_mass", [0.0, 0.0])
        rc = rotate(a, c)
        w = math.radians(float(first[f"{k}_omega_deg_s"]))
        v = (float(first[f"{k}_vx_m_s"]) - w * rc[1], float(first[f"{k}_vy_m_s"]) + w * rc[0])
        n = mbs.AddNode(NodeRigidBody2D(referenceCoordinates=[o[0] + rc[0], o[1] + rc[1], a],
                                        initialVelocities=[v[0], v[1], w]))
        body = mbs.AddObject(ObjectRigidBody2D(physicsMass=b["mass"], physicsInertia=b["inertia"],
                                               nodeNumber=n))
        bodies[b["name"]] = (n, body, c, a)

    def marker(name, at):
        if name == "ground":
            return mbs.AddMarker(MarkerBodyPosition(bodyNumber=ground, localPosition=[at[0], at[1], 0]))
        n, body, c, _ = bodies[name]
        return mbs.AddMarker(MarkerBodyPosition(bodyNumber=body,
                                                localPosition=[at[0] - c[0], at[1] - c[1], 0]))

    for j in spec.get("joint", []):
        assert j["kind"] == "revolute", j
        (a, b), (pa, pb) = j["bodies"], j["at"]
        mbs.AddObject(ObjectJointRevolute2D(markerNumbers=[marker(a, pa), marker(b, pb)]))
    for s in spec.get("spring", []):
        (a, b), (pa, pb) = s["bodies"], s["at"]
        mbs.AddObject(ObjectConnectorSpringDamper(markerNumbers=[marker(a, pa), marker(b, pb)],
                                                  stiffness=s["stiffness"], damping=0,
                                                  referenceLength=s["free_length"],
                                                  force=s.get("preload", 0.0)))
    for load in spec.get("load", []):
        n, body, c, _ = bodies[load["body"]]
        if "torque" in load:
            m = mbs.AddMarker(MarkerBodyRigid(bodyNumber=body, localPosition=[0, 0, 0]))
            mbs.AddLoad(Torque(markerNumber=m, loadVector=[0, 0, load["torque"]]))
    g = spec.get("dynamics", {}).get("gravity", [0.0, 0.0])
    if g != [0.0, 0.0]:
        for b in spec["body"]:
            n = bodies[b["name"]][0]
            mbs.AddLoad(Force(markerNumber=mbs.AddMarker(MarkerNodePosition(nodeNumber=n)),
                              loadVector=[b["mass"] * g[0], b["mass"] * g[1], 0]))
    sensors = {name: mbs.AddSensor(SensorNode(nodeNumber=n, storeInternal=True, writeToFile=False,
                                              outputVariableType=exu.OutputVariableType.Coordinates))
               for name, (n, _, _, _) in bodies.items()}
    mbs.Assemble()
    s = exu.SimulationSettings()
    s.timeIntegration.numberOfSteps = steps
    s.timeIntegration.endTime = t_end
    s.timeIntegration.verboseMode = 0
    s.solution.file.write = False
    s.solution.sensors.writePeriod = t_end / outputs
    s.linearSolver.ignoreSingularJacobian = True
    s.linearSolver.solverType = exu.LinearSolverType.EigenSparse
    start = time.perf_counter()
    try:
        mbs.SolveDynamic(s)
    except Exception as e:  # its solver gives up: said, as camkin's refusal is said
        return None, time.perf_counter() - start, str(e).splitlines()[0][:60]
    wall = time.perf_counter() - start
    # each body's frame: its node (the centre) less its centre's offset; its angle
    frames = {}
    for name, (n, body, c, a0) in bodies.items():
        data = mbs.GetSensorStoredData(sensors[name])[: outputs + 1]
        ref = mbs.GetNodeParameter(n, "referenceCoordinates")
        out = []
        for row in data:
            a = ref[2] + row[3]
            rc = rotate(a, c)
            out.append((ref[0] + row[1] - rc[0], ref[1] + row[2] - rc[1], a))
        frames[name] = out
    if any(len(f) != outputs + 1 for f in frames.values()):
        return None, wall, "fewer outputs than asked"
    return frames, wall, ""


def camkin_frames(rows, spec):
    return {b["name"]: [(float(r[f"{key(b['name'])}_x_m"]), float(r[f"{key(b['name'])}_y_m"]),
                         math.radians(float(r[f"{key(b['name'])}_angle_deg"]))) for r in rows]
            for b in spec["body"]}


# --- IFToMM A02: the N-four-bar ---------------------------------------------------------------
def n_four_bar_error(frames):
    n, g = 40, 9.81
    j = (n + 1) / 3 + n
    c = g * ((n + 1) / 2 + n)

    def f(y):
        return (y[1], -(c / j) * math.cos(y[0]))

    crank = frames["crank 0"]
    y, t, h = (math.pi / 2, -1.0), 0.0, 1e-4
    worst = 0.0
    for k, (x0, y0, a) in enumerate(crank):
        until = 20.0 * k / (len(crank) - 1)
        while t < until - 1e-12:
            s = min(h, until - t)
            k1 = f(y)
            k2 = f((y[0] + s / 2 * k1[0], y[1] + s / 2 * k1[1]))
            k3 = f((y[0] + s / 2 * k2[0], y[1] + s / 2 * k2[1]))
            k4 = f((y[0] + s * k3[0], y[1] + s * k3[1]))
            y = (y[0] + s / 6 * (k1[0] + 2 * k2[0] + 2 * k3[0] + k4[0]),
                 y[1] + s / 6 * (k1[1] + 2 * k2[1] + 2 * k3[1] + k4[1]))
            t += s
        b0 = (x0 + 0.5 * math.cos(a), y0 + 0.5 * math.sin(a))
        worst = max(worst, abs(b0[0] - math.cos(y[0])), abs(b0[1] - math.sin(y[0])))
    return worst


# --- IFToMM A03: Andrews' squeezing mechanism ------------------------------------------------
ANDREWS = [0.1581077119629904e2, -0.1575637105984298e2, 0.4082224013073101e-1,
           -0.5347301163226948, 0.5244099658805304, 0.5347301163226948, 0.1048080741042263e1]


def andrews_error(frames):
    p = [frames[n][-1][2] for n in ("crank", "connecting rod", "lever B", "link E", "triangle A",
                                     "link G", "triangle A2")]
    got = [p[0], p[1] - p[0], p[2], p[3] - p[4], p[4], p[5] - p[6], p[6]]
    return max(abs(a - b) for a, b in zip(got, ANDREWS))


PROBLEMS = [
    ("IFToMM A02 N-four-bar", "examples/n-four-bar.toml", n_four_bar_error, "m (B0)", 1e-3,
     (2000, 8000, 32000)),
    ("IFToMM A03 Andrews", "examples/andrews-squeezer.toml", andrews_error, "rad", None,
     (1000, 4000, 16000)),
]


def main():
    import warnings
    warnings.simplefilter("ignore", DeprecationWarning)
    binary = sys.argv[1]
    results = []
    for title, example, error, unit, high, ladder in PROBLEMS:
        spec = tomllib.load(open(example, "rb"))
        t_end, interval = spec["simulation"]["duration"], spec["simulation"]["interval"]
        outputs = round(t_end / interval)
        rows = []
        first = None
        for tol in (1e-6, 1e-8, 1e-10):
            table, wall, why = read_camkin(binary, example, tol)
            if table:
                first = first or table[0]
            err = error(camkin_frames(table, spec)) if table else None
            rows.append(("camkin", f"rtol = atol = {tol:g}", err, wall, why))
        for steps in ladder:
            frames, wall, why = exudyn_run(spec, first, steps, t_end, outputs)
            err = error(frames) if frames else None
            rows.append(("Exudyn", f"generalized-α, {steps} steps (h = {t_end / steps:.3g} s)",
                         err, wall, why))
        print(f"\n{title} ({example}): error in {unit}")
        print(f"  {'tool':8} {'settings':44} {'error':>10} {'time (s)':>9}")
        for tool, what, err, wall, why in rows:
            e = f"{err:.2e}" if err is not None else "failed"
            print(f"  {tool:8} {what:44} {e:>10} {wall:9.2f}  {why}")
        done = [r for r in rows if r[2] is not None]
        if high is not None:
            best = {}
            for tool, what, err, wall, _ in done:
                if err <= high and (tool not in best or wall < best[tool][1]):
                    best[tool] = (what, wall, err)
            if len(best) == 2:
                print(f"  at the benchmark's high precision ({high:g} {unit.split()[0]}): Exudyn / camkin "
                      f"time {best['Exudyn'][1] / best['camkin'][1]:.1f}")
        exu_best = min((r for r in done if r[0] == "Exudyn"), key=lambda r: r[2], default=None)
        if exu_best:
            match = [r for r in done if r[0] == "camkin" and r[2] <= exu_best[2]]
            if match:
                c = min(match, key=lambda r: r[3])
                print(f"  at Exudyn's best error ({exu_best[2]:.1e}, {exu_best[3]:.2f} s) camkin's "
                      f"cheapest run as accurate ({c[2]:.1e}, {c[1]}): {c[3]:.2f} s, "
                      f"Exudyn / camkin {exu_best[3] / c[3]:.1f}")
        results.append({"problem": title, "unit": unit,
                        "runs": [dict(zip(("tool", "settings", "error", "time_s", "note"), r))
                                 for r in rows]})
    json.dump(results, open("target/bench-exudyn.json", "w"), indent=1)


main()
