#!/usr/bin/env python3
"""The worst frame of each run's cloth strain, from its stats.csv.

    worst_strain.py RUN_FOLDER ...

For each run folder (soak run -o FOLDER), one line: the largest per-frame
99th percentile of edge strain over the run's cloths (strain_p99_*
columns) and its time, the mean strain in that frame, the largest
per-frame mean, how many frames pass 3 % at the 99th percentile (issue
49's target), the same for stretch and compression apart (where the
run wrote stretch_p99_* and compression_p99_*), the cloth sub-steps a
step (mean and most) and the frames' step time (median and mean of
step_ms). Python's standard library only, so it runs on the lent GPU
machine as well.
"""
import csv
import statistics
import sys


def summarize(folder):
    with open(folder + "/stats.csv", newline="") as f:
        rows = list(csv.DictReader(f))
    frames = rows[1:]  # frame 0 is the scene as set up
    if not frames:
        return f"{folder}: no frames after frame 0"
    p99 = [k for k in rows[0] if k.startswith("strain_p99_")]
    mean = [k for k in rows[0] if k.startswith("strain_mean_")]
    if not p99:
        return f"{folder}: no cloth strain columns"
    worst, worst_time, mean_at_worst, worst_mean, over = -1.0, "", 0.0, 0.0, 0
    for r in frames:
        v = max(float(r[k]) for k in p99)
        m = max(float(r[k]) for k in mean)
        worst_mean = max(worst_mean, m)
        over += v > 0.03
        if v > worst:
            worst, worst_time, mean_at_worst = v, r["time"], m
    # Stretch and compression apart (stretch_p99_*, compression_p99_*), where the run wrote them.
    sides = ""
    for side in ("stretch", "compression"):
        cols = [k for k in rows[0] if k.startswith(side + "_p99_")]
        if cols:
            w = max(max(float(r[k]) for k in cols) for r in frames)
            n = sum(max(float(r[k]) for k in cols) > 0.03 for r in frames)
            sides += f", worst {side} p99 {100 * w:.2f} % (frames>3% {n})"
    cols = [k for k in rows[0] if k.startswith("stretch_mean_")]
    if cols:
        sides += f", worst stretch mean {100 * max(max(float(r[k]) for k in cols) for r in frames):.2f} %"
    sub = [float(r["cloth_substeps"]) for r in frames]
    ms = [float(r["step_ms"]) for r in frames]
    return (f"{folder}: frames {len(frames)} worst p99 {100 * worst:.2f} % at t {worst_time} "
            f"(mean {100 * mean_at_worst:.2f} %), worst mean {100 * worst_mean:.2f} %, frames>3% {over}{sides}, "
            f"substeps mean {statistics.mean(sub):.1f} max {max(sub):.0f}, "
            f"step ms median {statistics.median(ms):.2f} mean {statistics.mean(ms):.2f}")


def main(argv):
    if not argv or argv[0] in ("-h", "--help"):
        print(__doc__.strip())
        return 0 if argv else 2
    status = 0
    for folder in argv:
        try:
            print(summarize(folder))
        except (OSError, KeyError, ValueError) as e:
            print(f"{folder}: cannot read stats.csv ({e})", file=sys.stderr)
            status = 1
    return status


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
