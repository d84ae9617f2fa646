#!/usr/bin/env python3
"""Whether whole runs of a hanging sheet tangled or flailed, from their stats.csv.

    python3 Demos/scripts/tangle_summary.py RUN/stats.csv ...

Per run: the frames in which some edge is over 20 % from its rest length
(`max_stretch` > 0.2: a layer held through another; a sheet that is not
tangled stays under 0.2), and, after the first second, the mean and most
kinetic energy, the fastest particle and the cloth sub-steps a step.
Doc/performance.md, "fig6b's tangles and the end velocity's limit (H100)",
calls a run tangled with 20 such frames or more and flailing with a mean
kinetic energy over 20 J after the first second (calm fig6b runs: 3-19 J).
"""
import csv
import os
import statistics
import sys


def summary(path):
    rows = list(csv.DictReader(open(path)))
    late = [r for r in rows if float(r["time"]) > 1.0] or rows[-1:]
    kinetic = [float(r["kinetic_energy"]) for r in late]
    return {
        "end": float(rows[-1]["time"]),
        "p99": 100 * max(float(r.get("strain_p99_sheet", 0) or 0) for r in rows),
        "tangled_frames": sum(float(r["max_stretch"]) > 0.2 for r in rows),
        "worst_edge": max(float(r["max_stretch"]) for r in rows),
        "kinetic_mean": statistics.mean(kinetic),
        "kinetic_most": max(kinetic),
        "fastest": max(float(r["max_speed"]) for r in late),
        "substeps": statistics.mean(float(r["cloth_substeps"]) for r in late),
    }


def main(paths):
    for path in paths:
        name = os.path.basename(os.path.dirname(path)) if path.endswith("stats.csv") else os.path.basename(path)[:-4]
        try:
            s = summary(path)
        except (OSError, KeyError, ValueError, statistics.StatisticsError) as e:
            print(f"{name}: unreadable ({e})")
            continue
        state = "flailing" if s["kinetic_mean"] > 20 else "tangled" if s["tangled_frames"] >= 20 else "calm"
        print(f"{name:16} to {s['end']:5.2f} s  p99 {s['p99']:5.2f} %  frames past 20 % {s['tangled_frames']:3}"
              f" (worst {s['worst_edge']:.2f})  after 1 s: sub-steps {s['substeps']:5.1f}, kinetic mean"
              f" {s['kinetic_mean']:6.1f} J most {s['kinetic_most']:7.1f} J, fastest {s['fastest']:5.1f} m/s  {state}")


if __name__ == "__main__":
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    main(sys.argv[1:])
