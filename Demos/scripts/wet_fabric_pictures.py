#!/usr/bin/env python3
"""The pictures of Doc/model.md's wet fabric terms beyond the paper, from
their scenes (the Python module, CPU):

  Doc/images/wet_stiffness.png   Scenes/wet_strip_droop.xml and
                                 Scenes/wet_slope.xml, wet against dry
  Doc/images/anisotropic_spot.png  Scenes/anisotropic_spot.xml, top view

usage: PYTHONPATH=build/release/python python3 Demos/scripts/wet_fabric_pictures.py [OUTDIR]
"""
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np
import soak


def track(scene, overrides, seconds, measure):
    with soak.Simulation(scene, device="cpu", overrides=overrides) as sim:
        t, values = [], []
        while sim.time < seconds - 1e-9:
            sim.step()
            t.append(sim.time)
            values.append(measure(sim))
        return np.array(t), np.array(values)


def tip_height(sim):
    return sim.cloth("strip")["position"][1 * 11 + 10][1]


def slide(sim):
    down = np.array([0.9397, -0.3420, 0.0])
    return float(sim.cloth("sheet")["position"].mean(axis=0) @ down)


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else "Doc/images"
    fig, ax = plt.subplots(1, 2, figsize=(9, 3.4))
    for label, sat in (("dry", 0.0), ("wet", 0.3)):
        t, y = track("Scenes/wet_strip_droop.xml", {"WetCloth.initialSaturation": sat}, 2.5, tip_height)
        ax[0].plot(t, y, label=f"{label}: mean {y[t >= 1.0].mean():.3f} m from 1 s")
        t, s = track("Scenes/wet_slope.xml", {"WetCloth.initialSaturation": sat}, 1.0, slide)
        ax[1].plot(t, s - s[0], label=f"{label}: {s[-1] - s[0]:.3f} m in 1 s")
    ax[0].set_title("wet_strip_droop: free end of a clamped strip")
    ax[0].set_xlabel("time (s)")
    ax[0].set_ylabel("height (m), root at 1 m")
    ax[0].legend()
    ax[1].set_title("wet_slope: a sheet on a 20 degree slope")
    ax[1].set_xlabel("time (s)")
    ax[1].set_ylabel("slid down the slope (m)")
    ax[1].legend()
    fig.suptitle("Wet weight off: the wet strip is softer (wetBendSoftening 0.8), the wet sheet grips (wetFriction 3)")
    fig.tight_layout()
    fig.savefig(f"{out}/wet_stiffness.png", dpi=90)

    with soak.Simulation("Scenes/anisotropic_spot.xml", device="cpu") as sim:
        sim.advance(3.0)
        cloth = sim.cloth("sheet")
        x, s = cloth["position"], cloth["saturation"]
    fig, axis = plt.subplots(figsize=(5, 4.4))
    points = axis.scatter(x[:, 0], x[:, 2], c=s, s=12, cmap="Blues", vmin=0.0, vmax=max(float(s.max()), 1e-6))
    wet = x[s > 0.005]
    axis.set_title(f"anisotropic_spot, 3 s: wet patch {np.ptp(wet[:, 0]):.2f} x {np.ptp(wet[:, 2]):.2f} m", fontsize=10)
    axis.set_xlabel("x, warp (m)")
    axis.set_ylabel("z, weft (m)")
    axis.set_aspect("equal")
    fig.colorbar(points, label="saturation")
    fig.tight_layout()
    fig.savefig(f"{out}/anisotropic_spot.png", dpi=90)


if __name__ == "__main__":
    main()
