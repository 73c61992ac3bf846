"""Tolerance study of the paper's cam: Monte-Carlo perturbations of its 9 spline nodes (a
manufacturing tolerance, normal with standard deviation SIGMA in each coordinate), the
distribution of the follower's peak acceleration over a revolution (1° steps), computed in
parallel inside camkin (one call, all cores) and across a local Dask cluster (the same calls on
workers: to go across machines, point the Client at a dask-scheduler instead). Prints designs per
second on one core, on two, and through Dask, and saves a histogram.

    python examples/python/tolerance_study.py [--designs 20000] [--sigma 0.005] [--out tolerance.png]
"""
import argparse
import time

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

import camkin


def variants(n, sigma, seed=2005):
    nodes = np.array(camkin.paper_cam().to_dict()["cam"]["profile"]["points"])
    rng = np.random.default_rng(seed)
    return nodes + rng.normal(0.0, sigma, (n,) + nodes.shape)


def rate(f, n):
    t = time.perf_counter()
    out = f()
    return out, n / (time.perf_counter() - t)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--designs", type=int, default=20000)
    ap.add_argument("--sigma", type=float, default=0.005, help="node tolerance, cm (1 sd)")
    ap.add_argument("--workers", type=int, default=2)
    ap.add_argument("--out", default="tolerance.png")
    a = ap.parse_args()

    cam = camkin.paper_cam()
    nodes = variants(a.designs, a.sigma)
    key = "peak_acceleration_cm_s2"

    one, r1 = rate(lambda: camkin.spline_variants(cam, nodes, threads=1), a.designs)
    two, r2 = rate(lambda: camkin.spline_variants(cam, nodes, threads=2), a.designs)
    assert np.array_equal(one[key], two[key]), "thread count changed a result"

    from dask.distributed import Client, LocalCluster

    with LocalCluster(n_workers=a.workers, threads_per_worker=1, dashboard_address=None) as cluster, Client(cluster) as client:
        base = client.scatter(cam, broadcast=True)
        chunks = np.array_split(nodes, 8 * a.workers)
        client.run(lambda: camkin.paper_cam())  # import camkin on every worker before timing

        def on_dask():
            futures = [client.submit(camkin.spline_variants, base, c, threads=1) for c in chunks]
            return np.concatenate([p[key] for p in client.gather(futures)])

        dask_peaks, rd = rate(on_dask, a.designs)
    assert np.array_equal(dask_peaks, one[key]), "Dask changed a result"

    peaks = np.abs(one[key])
    nominal = abs(camkin.spline_variants(cam, variants(1, 0.0))[key][0])
    print(f"{a.designs} designs, node tolerance {a.sigma} cm (1 sd), 360 angles each")
    print(f"designs per second: {r1:.0f} on one core, {r2:.0f} on two, {rd:.0f} through Dask ({a.workers} workers)")
    print(f"peak |acceleration|: nominal {nominal:.1f} cm/s², mean {peaks.mean():.1f}, sd {peaks.std():.1f}, "
          f"99th percentile {np.percentile(peaks, 99):.1f} cm/s² ({np.percentile(peaks, 99) / nominal - 1:+.1%})")
    print(f"designs that failed: {int(np.count_nonzero(one['failed_angles']))}")

    fig, ax = plt.subplots(figsize=(8, 4.5))
    ax.hist(peaks, bins=80)
    ax.axvline(nominal, color="k", ls="--", label=f"nominal {nominal:.0f} cm/s²")
    ax.set(xlabel="peak |follower acceleration| over a revolution (cm/s²)", ylabel="designs",
           title=f"Paper's cam, nodes ± {a.sigma} cm (1 sd): {a.designs} designs")
    ax.legend()
    fig.savefig(a.out, dpi=120, bbox_inches="tight")
    print(f"wrote {a.out}")


if __name__ == "__main__":
    main()
