#!/usr/bin/env python3
"""Density error and fluid.solve time against the density iterations.

    python3 Demos/scripts/density_vs_iterations.py collect DIR OUT.csv   # from the runs below
    python3 Demos/scripts/density_vs_iterations.py plot IN.csv OUT.png

`collect` reads, for each K, DIR/iter_fig9b_K.csv (stats.csv of
`soak run Scenes/fig9b_ball_sticky.xml --time 3 --set Water.iterations=K`) and
DIR/iterbench_fig9b_K.txt (`soak-bench --only fig9b_ball_sticky --set
Water.iterations=K`), skipping the first 0.3 s (the water still falling
apart from its block). Doc/performance.md, "Density iterations", has the
numbers and the commands.
"""
import csv
import glob
import os
import re
import sys


def collect(folder, out):
    ks = sorted(int(re.search(r"_(\d+)\.csv$", f).group(1)) for f in glob.glob(os.path.join(folder, "iter_fig9b_*.csv")))
    with open(out, "w") as o:
        o.write("iterations,frames,mean_of_mean_density_error,worst_mean_density_error,worst_max_density_error,"
                "fluid_solve_ms,step_ms\n")
        for k in ks:
            rows = [r for r in csv.DictReader(open(os.path.join(folder, f"iter_fig9b_{k}.csv"))) if float(r["time"]) > 0.3]
            mean = [float(r["mean_density_error"]) for r in rows]
            worst = max(float(r["max_density_error"]) for r in rows)
            text = open(os.path.join(folder, f"iterbench_fig9b_{k}.txt")).read()
            solve = re.search(r"^\| fluid.solve \| ([0-9.]+) \|", text, re.M).group(1)
            step = re.search(r"^\| fig9b_ball_sticky \| [^|]+\| [^|]+\| [^|]+\| ([0-9.]+) \|", text, re.M).group(1)
            o.write(f"{k},{len(rows)},{sum(mean) / len(mean):.5f},{max(mean):.5f},{worst:.4f},{solve},{step}\n")


def plot(path, out):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    rows = list(csv.DictReader(open(path)))
    k = [int(r["iterations"]) for r in rows]
    fig, ax = plt.subplots(figsize=(6, 3.6))
    ax.plot(k, [100 * float(r["mean_of_mean_density_error"]) for r in rows], "o-", label="mean over frames")
    ax.plot(k, [100 * float(r["worst_mean_density_error"]) for r in rows], "s--", label="worst frame")
    ax.set_xlabel("density iterations per step (Water.iterations)")
    ax.set_ylabel("mean compression of the water (%)")
    ax.set_ylim(bottom=0)
    ax2 = ax.twinx()
    ax2.plot(k, [float(r["fluid_solve_ms"]) for r in rows], "^:", color="gray", label="fluid.solve (ms)")
    ax2.set_ylabel("fluid.solve, H100 (ms)")
    ax2.set_ylim(bottom=0)
    lines = ax.get_legend_handles_labels()
    lines2 = ax2.get_legend_handles_labels()
    ax.legend(lines[0] + lines2[0], lines[1] + lines2[1], fontsize=8, loc="upper center")
    ax.set_title("fig9b_ball_sticky, 3 s: density error against iterations", fontsize=9)
    fig.tight_layout()
    fig.savefig(out, dpi=120)


if __name__ == "__main__":
    if len(sys.argv) != 4 or sys.argv[1] not in ("collect", "plot"):
        sys.exit(__doc__)
    (collect if sys.argv[1] == "collect" else plot)(sys.argv[2], sys.argv[3])
