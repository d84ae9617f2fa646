#!/usr/bin/env python3
"""Sweep a wetting parameter and plot the wet area of a sheet against time.

A sheet hangs with its lower edge in a tank (Figure 5(b)'s set-up, small).
For each value of the parameter (by default WetCloth.diffusionRate, kappa^d
of Eq. 12) it is simulated and its wet area (the rest area of the vertices
whose saturation passes --wet) is sampled. Writes a PNG plot and,
optionally, a CSV of the curves.

    python3 Demos/python/sweep_diffusion.py --out sweep.png
    python3 Demos/python/sweep_diffusion.py --values 0 0.1 0.5 2 --time 1.5 --device cpu
    python3 Demos/python/sweep_diffusion.py --parameter WetCloth.smoothingRate --values 5 20 53.3

What the default sweep shows: diffusion (any kappa^d > 0) against none
(kappa^d = 0), and curves that coincide for every kappa^d > 0. With the
relative epsilon of Eq. 15, kappa^d cancels out of Eq. 17 and the speed of
the spread is smoothingRate's (kappa^s; Doc/model.md, on epsilon of Eq. 15).
"""
import argparse
import csv
import sys

import numpy as np

import soak

SCENE = """<Scene>
  <Simulation timeStep="0.015" duration="2" frameRate="30"/>
  <Water spacing="0.04"/>
  <Box min="-0.42 0 -0.22" max="0.42 2 0.22" inside="true"/>
  <WaterBlock min="-0.4 0 -0.2" max="0.4 0.2 0.2"/>
  <Cloth name="sheet" origin="-0.3 0.75 0" axisU="1 0 0" axisV="0 -1 0" width="0.6" height="0.6"
         cellsU="{cells}" cellsV="{cells}" pinCorners="u0v0 u1v0"/>
  <WetCloth diffusionGravity="0" emission="false"/>
</Scene>"""


def wet_area(sim, threshold, vertex_area):
    saturation = sim.cloth("sheet")["saturation"]
    return float(np.count_nonzero(saturation > threshold)) * vertex_area


def sweep(parameter, values, seconds, samples, device, cells, threshold):
    """Returns {value: (times, wet areas in m^2)}."""
    curves = {}
    vertex_area = 0.6 * 0.6 / float((cells + 1) ** 2)
    for rate in values:
        with soak.Simulation(xml=SCENE.format(cells=cells), device=device, overrides={parameter: rate}) as sim:
            times, areas = [0.0], [wet_area(sim, threshold, vertex_area)]
            for _ in range(samples):
                sim.advance(seconds / samples)
                times.append(sim.time)
                areas.append(wet_area(sim, threshold, vertex_area))
            curves[rate] = (times, areas)
        print(f"{parameter} = {rate:g}: wet area {curves[rate][1][-1]:.4f} m^2 at {curves[rate][0][-1]:.2f} s",
              file=sys.stderr)
    return curves


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--parameter", default="WetCloth.diffusionRate", help="a scene value, as --set names it")
    parser.add_argument("--values", type=float, nargs="+", default=[0.0, 0.1, 0.5, 2.0])
    parser.add_argument("--time", type=float, default=1.5, help="simulated seconds per rate")
    parser.add_argument("--samples", type=int, default=15)
    parser.add_argument("--cells", type=int, default=24, help="sheet cells per side")
    parser.add_argument("--wet", type=float, default=0.02, help="saturation above which a vertex is wet")
    parser.add_argument("--device", default="auto")
    parser.add_argument("--out", default="diffusion_sweep.png")
    parser.add_argument("--csv", default=None, help="also write the curves (rate, time, wet area)")
    args = parser.parse_args(argv)

    curves = sweep(args.parameter, args.values, args.time, args.samples, args.device, args.cells, args.wet)

    if args.csv:
        with open(args.csv, "w", newline="") as f:
            w = csv.writer(f)
            w.writerow([args.parameter, "time_s", "wet_area_m2"])
            for rate, (times, areas) in curves.items():
                for t, a in zip(times, areas):
                    w.writerow([rate, t, a])

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(6, 4))
    for rate, (times, areas) in curves.items():
        ax.plot(times, areas, marker="o", markersize=3, label=f"{args.parameter} = {rate:g}")
    ax.set_xlabel("time (s)")
    ax.set_ylabel(f"wet area (m$^2$, saturation > {args.wet:g})")
    ax.set_title("Sheet dipped in water: wet area against time")
    ax.legend()
    fig.tight_layout()
    fig.savefig(args.out, dpi=120)
    print(f"wrote {args.out}", file=sys.stderr)


if __name__ == "__main__":
    main()
