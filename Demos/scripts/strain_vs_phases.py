#!/usr/bin/env python3
"""Strain against dependent cloth phases per step, for each cloth solver.

Two commands (Python's standard library only, so the sweep also runs on a
machine without our Debian packages, such as the lent GPU machine):

  strain_vs_phases.py sweep --soak COMMAND --scene FILE --time SECONDS --out FILE.csv
                            [--set Element.attr=value ...] CONFIG ...
      runs `COMMAND run` (COMMAND: soak's path, or e.g. ".device/run soak")
      once per CONFIG (model:substeps:iterations[:rho], e.g.
      pbd:8:4 or chebyshev:8:12:0.6) and writes one row per run: the
      dependent phases per step soak reports, the largest per-frame mean and
      99th-percentile edge strain of the first cloth (stats.csv), the last
      frame's kinetic energy over its peak, and soak's exit status.

  strain_vs_phases.py plot --out FILE.svg CSV ...
      draws one panel per CSV: worst 99th percentile (solid) and worst mean
      (dashed) strain against phases per step, a line per solver, log axes.

Doc/design.md, "Cloth solver", shows the plot and the commands that made it.
"""
import argparse
import csv
import math
import os
import re
import shlex
import subprocess
import sys
import tempfile

FIELDS = ["scene", "model", "substeps", "iterations", "rho", "phases", "worst_mean", "worst_p99",
          "final_ke_over_peak", "exit"]


def run_one(soak, scene, seconds, sets, config):
    parts = config.split(":")
    model, substeps, iterations = parts[0], int(parts[1]), int(parts[2])
    rho = parts[3] if len(parts) > 3 else ""
    with tempfile.TemporaryDirectory() as out:
        cmd = shlex.split(soak) + ["run", scene, "-o", os.path.join(out, "run"), "--time", str(seconds),
               "--set", f"Cloth.model={model}", "--set", f"Simulation.clothSubsteps={substeps}",
               "--set", f"Simulation.clothIterations={iterations}"]
        if rho:
            cmd += ["--set", f"Simulation.clothSpectralRadius={rho}"]
        if model == "pbd":  # fixed sub-steps: pbd's stiffness is per iteration
            cmd += ["--set", "Simulation.clothSubstepTravel=0"]
        for s in sets:
            cmd += ["--set", s]
        proc = subprocess.run(cmd, capture_output=True, text=True)
        match = re.search(r"cloth solve: (\d+) dependent phases", proc.stderr)
        row = {"scene": os.path.basename(scene), "model": model, "substeps": substeps,
               "iterations": iterations, "rho": rho, "phases": int(match.group(1)) if match else "",
               "worst_mean": "", "worst_p99": "", "final_ke_over_peak": "", "exit": proc.returncode}
        stats = os.path.join(out, "run", "stats.csv")
        if os.path.exists(stats):
            with open(stats) as f:
                rows = list(csv.DictReader(f))
            mean_key = next((k for k in rows[0] if k.startswith("strain_mean_")), None) if rows else None
            if mean_key:
                p99_key = "strain_p99_" + mean_key[len("strain_mean_"):]
                row["worst_mean"] = max(float(r[mean_key]) for r in rows)
                row["worst_p99"] = max(float(r[p99_key]) for r in rows)
                peak = max(float(r["kinetic_energy"]) for r in rows)
                row["final_ke_over_peak"] = float(rows[-1]["kinetic_energy"]) / peak if peak > 0 else 0.0
        return row


def sweep(args):
    with open(args.out, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=FIELDS)
        w.writeheader()
        for config in args.configs:
            row = run_one(args.soak, args.scene, args.time, args.set or [], config)
            w.writerow(row)
            f.flush()
            print(", ".join(f"{k}={row[k]}" for k in FIELDS), file=sys.stderr)


COLOURS = {"pbd": "#d62728", "xpbd": "#ff7f0e", "chebyshev": "#1f77b4"}


def plot(args):
    panels = []
    for path in args.csvs:
        with open(path) as f:
            rows = [r for r in csv.DictReader(f) if r["phases"] and r["worst_p99"]]
        panels.append((os.path.basename(path), rows))
    width, height, margin = 460, 340, 60
    svg = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{width * len(panels)}" height="{height}" '
           f'font-family="sans-serif" font-size="11">']
    for index, (name, rows) in enumerate(panels):
        x0 = index * width
        xs = [float(r["phases"]) for r in rows]
        ys = [float(r[k]) for r in rows for k in ("worst_p99", "worst_mean") if float(r[k]) > 0]
        if not xs or not ys:
            continue
        lx = (math.floor(math.log10(min(xs))), math.ceil(math.log10(max(xs))))
        ly = (math.floor(math.log10(min(ys))), math.ceil(math.log10(max(ys))))

        def px(v):
            return x0 + margin + (math.log10(v) - lx[0]) / max(lx[1] - lx[0], 1) * (width - 1.6 * margin)

        def py(v):
            return height - margin + (math.log10(max(v, 10.0 ** ly[0])) - ly[0]) / max(ly[1] - ly[0], 1) * \
                (2 * margin - height)

        svg.append(f'<text x="{x0 + width / 2}" y="20" text-anchor="middle">{name}</text>')
        svg.append(f'<rect x="{x0 + margin}" y="{margin}" width="{width - 1.6 * margin}" '
                   f'height="{height - 2 * margin}" fill="none" stroke="#888"/>')
        for e in range(lx[0], lx[1] + 1):
            svg.append(f'<text x="{px(10.0 ** e)}" y="{height - margin + 15}" text-anchor="middle">{10 ** e}</text>')
        for e in range(ly[0], ly[1] + 1):
            svg.append(f'<text x="{x0 + margin - 5}" y="{py(10.0 ** e) + 4}" text-anchor="end">'
                       f'{100 * 10.0 ** e:g} %</text>')
            svg.append(f'<line x1="{x0 + margin}" x2="{x0 + width - 0.6 * margin}" y1="{py(10.0 ** e)}" '
                       f'y2="{py(10.0 ** e)}" stroke="#eee"/>')
        svg.append(f'<text x="{x0 + width / 2}" y="{height - 20}" text-anchor="middle">dependent cloth phases '
                   f'per step</text>')
        svg.append(f'<line x1="{x0 + margin}" x2="{x0 + width - 0.6 * margin}" y1="{py(0.03)}" y2="{py(0.03)}" '
                   f'stroke="#2ca02c" stroke-dasharray="2,3"/>')
        svg.append(f'<text x="{x0 + width - 0.6 * margin}" y="{py(0.03) - 3}" text-anchor="end" fill="#2ca02c">'
                   f'3 % target</text>')
        legend_y = margin + 14
        for model in sorted({r["model"] for r in rows}):
            mine = sorted((r for r in rows if r["model"] == model), key=lambda r: float(r["phases"]))
            colour = COLOURS.get(model, "#555")
            for key, dash in (("worst_p99", ""), ("worst_mean", ' stroke-dasharray="5,3"')):
                points = " ".join(f"{px(float(r['phases'])):.1f},{py(float(r[key])):.1f}" for r in mine)
                svg.append(f'<polyline points="{points}" fill="none" stroke="{colour}"{dash}/>')
            for r in mine:
                label = f"{r['substeps']}x{r['iterations']}" + (" diverged" if r["exit"] not in ("0", "") else "")
                svg.append(f'<circle cx="{px(float(r["phases"])):.1f}" cy="{py(float(r["worst_p99"])):.1f}" r="3" '
                           f'fill="{colour}"/>')
                svg.append(f'<text x="{px(float(r["phases"])) + 4:.1f}" y="{py(float(r["worst_p99"])) - 4:.1f}" '
                           f'font-size="9" fill="{colour}">{label}</text>')
            svg.append(f'<text x="{x0 + margin + 8}" y="{legend_y}" fill="{colour}">{model}: p99 solid, '
                       f'mean dashed</text>')
            legend_y += 14
    svg.append("</svg>")
    with open(args.out, "w") as f:
        f.write("\n".join(svg) + "\n")


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    sub = parser.add_subparsers(dest="command", required=True)
    s = sub.add_parser("sweep")
    s.add_argument("--soak", required=True)
    s.add_argument("--scene", required=True)
    s.add_argument("--time", type=float, required=True)
    s.add_argument("--out", required=True)
    s.add_argument("--set", action="append")
    s.add_argument("configs", nargs="+")
    p = sub.add_parser("plot")
    p.add_argument("--out", required=True)
    p.add_argument("csvs", nargs="+")
    args = parser.parse_args()
    sweep(args) if args.command == "sweep" else plot(args)


if __name__ == "__main__":
    main()
