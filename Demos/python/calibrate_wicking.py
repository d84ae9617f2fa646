#!/usr/bin/env python3
"""Fit the wicking strip's diffusivity to a measured uptake, with soak.sweep_*.

Plans Scenes/sweeps/wicking_diffusivity.txt (six diffusivities, 5 s of the
strip of Scenes/wicking_strip.xml each), runs the points not done on this
machine, collects the water each strip holds at the end and interpolates, in
log D, the diffusivity whose uptake equals the measured one.

    python3 Demos/python/calibrate_wicking.py --measured 0.18 --folder soak-sweeps/wicking

Doc/sweeps.md walks through it; the same sweep runs on Slurm with
`soak sweep run FOLDER --executor slurm`, and this script then only collects.
"""
import argparse
import math
import os
import sys

import soak

HERE = os.path.dirname(os.path.abspath(__file__))
DESCRIPTION = os.path.join(HERE, "..", "..", "Scenes", "sweeps", "wicking_diffusivity.txt")


def fit(points, measured):
    """The diffusivity whose held water is `measured`, interpolated in log D
    between the two neighbouring points; None outside the swept range."""
    points = sorted(points)
    for (d0, h0), (d1, h1) in zip(points, points[1:]):
        if min(h0, h1) <= measured <= max(h0, h1) and h1 != h0:
            s = (measured - h0) / (h1 - h0)
            return math.exp(math.log(d0) + s * (math.log(d1) - math.log(d0)))
    return None


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--measured", type=float, default=0.18, help="water held after 5 s (kg)")
    parser.add_argument("--folder", default="soak-sweeps/wicking_diffusivity")
    parser.add_argument("--jobs", type=int, default=0, help="points at once (0: one per core)")
    parser.add_argument("--collect-only", action="store_true", help="the points ran elsewhere (Slurm)")
    args = parser.parse_args(argv)

    soak.sweep_plan(args.folder, DESCRIPTION)
    if not args.collect_only:
        summary = soak.sweep_run(args.folder, jobs=args.jobs, threads=1)
        if summary["exit_code"] != 0:
            sys.exit(f"sweep ended with {summary}; see {args.folder}/manifest.csv")
    rows = soak.sweep_collect(args.folder, figures=["held"], plot="held", against="WetCloth.diffusivity")
    points = [(float(r["WetCloth.diffusivity"]), r["held"]) for r in rows if r["held"] is not None]
    for d, held in sorted(points):
        print(f"D = {d:.5g} m^2/s: {held:.4f} kg held after 5 s")
    d = fit(points, args.measured)
    if d is None:
        sys.exit(f"{args.measured} kg is outside the swept uptakes: widen the range in {DESCRIPTION}")
    print(f"measured {args.measured} kg -> diffusivity {d:.4g} m^2/s (plot: {args.folder}/plot-held.svg)")


if __name__ == "__main__":
    main()
