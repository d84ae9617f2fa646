#!/usr/bin/env pvpython
"""Pictures of a Soak run with ParaView: PNG frames, an animated GIF, and
plots of the water budget and of the largest saturation.

    pvpython Doc/render.py OUT                 # every frame, animation, plots
    pvpython Doc/render.py OUT --frame -1      # the last frame only
    xvfb-run -a pvpython Doc/render.py OUT     # on a machine without a display

OUT is a folder written by `soak run`. Pictures go to OUT/render/ (or
--to DIR). The cloth is coloured by saturation from dry (red) to wet
(black), as in the paper's figures; water particles are spheres of radius
h/4 (r0/2 for a full particle, smaller for partly absorbed ones and drips);
the scene's colliders are drawn (moving ones where their path puts them);
the camera is the scene's <Camera> element, or a view of everything in the
first frame. Doc/paraview.md shows the results and how to get the same look
in the ParaView GUI (Doc/soak_look.py).
"""
import argparse
import csv
import glob
import os
import sys
import xml.etree.ElementTree as ET

# ParaView's modules; pvpython provides them.
import paraview.simple
from paraview.simple import (CreateView, PVDReader, Show, Hide, ColorBy, GetColorTransferFunction, Glyph,
                             Sphere, Plane, Box, SaveScreenshot, Render, ResetCamera)

DRY_RGB = (0.85, 0.18, 0.12)    # red: dry cloth (S = 0)
WET_RGB = (0.04, 0.04, 0.04)    # black: saturated cloth (S = S^MAX)
WATER_RGB = (0.25, 0.55, 0.95)
COLLIDER_RGB = (0.75, 0.75, 0.72)


def vec(text, default):
    try:
        v = [float(x) for x in (text or default).split()]
        return v if len(v) == 3 else [float(x) for x in default.split()]
    except ValueError:
        return [float(x) for x in default.split()]


def parse_path(text):
    """'t x y z; t x y z' -> [(t, [x, y, z]), ...] (offsets, linear in between)."""
    keys = []
    for part in (text or "").split(";"):
        nums = part.split()
        if len(nums) == 4:
            keys.append((float(nums[0]), [float(x) for x in nums[1:]]))
    return sorted(keys)


def offset_at(keys, t):
    if not keys:
        return [0.0, 0.0, 0.0]
    if t <= keys[0][0]:
        return keys[0][1]
    for (t0, a), (t1, b) in zip(keys, keys[1:]):
        if t <= t1:
            u = (t - t0) / (t1 - t0) if t1 > t0 else 1.0
            return [a[k] + u * (b[k] - a[k]) for k in range(3)]
    return keys[-1][1]


class Look:
    """Builds the pipeline once; set_time() moves it to a frame."""

    def __init__(self, run, size=None, surface=False, view=None):
        scene_file = os.path.join(run, "scene.xml")
        self.scene = ET.parse(scene_file).getroot() if os.path.exists(scene_file) else ET.Element("Scene")
        self.view = view or CreateView("RenderView")
        if size:
            self.view.ViewSize = list(size)
        self.view.Background = [1.0, 1.0, 1.0]
        try:
            self.view.UseColorPaletteForBackground = 0
        except AttributeError:
            pass
        self.view.OrientationAxesVisibility = 0
        self.times = []
        self.movers = []
        self.water = None
        wet = self.scene.find("WetCloth")
        self.s_max = float(wet.get("sMax", "0.4")) if wet is not None else 0.4
        self._water(run, surface)
        self._cloth(run)
        self._colliders()
        self._camera()

    def _water(self, run, surface):
        path = os.path.join(run, "water.pvd")
        if not os.path.exists(path):
            return
        self.water = PVDReader(FileName=path)
        self.times = list(self.water.TimestepValues or [0.0])
        surface_path = os.path.join(run, "water_surface.pvd")
        if surface and os.path.exists(surface_path):
            # The mesh written with <WaterSurface> instead of the particles.
            d = Show(PVDReader(FileName=surface_path), self.view)
            d.ColorArrayName = ['POINTS', '']
            d.AmbientColor = d.DiffuseColor = list(WATER_RGB)
            d.Opacity = 0.7
            d.Specular = 0.5
            return
        glyph = Glyph(Input=self.water, GlyphType="Sphere")
        glyph.ScaleArray = ["POINTS", "radius"]
        glyph.ScaleFactor = 0.5          # the unit sphere glyph has radius 0.5: drawn radius = h / 4
        glyph.GlyphMode = "All Points"
        glyph.GlyphType.ThetaResolution = 10
        glyph.GlyphType.PhiResolution = 8
        d = Show(glyph, self.view)
        d.ColorArrayName = ['POINTS', '']
        d.AmbientColor = d.DiffuseColor = list(WATER_RGB)
        d.Specular = 0.4

    def _cloth(self, run):
        lut = GetColorTransferFunction("saturation")
        lut.RGBPoints = [0.0, *DRY_RGB, self.s_max, *WET_RGB]
        lut.ColorSpace = "RGB"
        lut.AutomaticRescaleRangeMode = "Never"
        lut.RescaleTransferFunction(0.0, self.s_max)
        self.cloth = []
        for path in sorted(glob.glob(os.path.join(run, "cloth_*.pvd"))):
            reader = PVDReader(FileName=path)
            d = Show(reader, self.view)
            d.SetRepresentationType("Surface")
            names = [a.GetName() for a in reader.PointData]
            if "saturation" in names:
                ColorBy(d, ("POINTS", "saturation"))
                d.LookupTable = lut
            else:
                d.ColorArrayName = ['POINTS', '']
                d.AmbientColor = d.DiffuseColor = list(DRY_RGB)
            self.cloth.append(reader)
            if not self.times:
                self.times = list(reader.TimestepValues or [0.0])
        self.lut = lut

    def _colliders(self):
        lo = vec(self.scene.find("Simulation").get("domainMin") if self.scene.find("Simulation") is not None else None,
                 "-2 -1 -2")
        hi = vec(self.scene.find("Simulation").get("domainMax") if self.scene.find("Simulation") is not None else None,
                 "2 4 2")
        for e in self.scene:
            if e.tag == "Plane":
                p, n = vec(e.get("point"), "0 0 0"), vec(e.get("normal"), "0 1 0")
                if abs(n[1]) > 0.9:   # a floor: a square of the domain's width, at its height
                    half = min(1.5, 0.5 * max(hi[0] - lo[0], hi[2] - lo[2]))
                    src = Plane(Origin=[p[0] - half, p[1], p[2] - half], Point1=[p[0] + half, p[1], p[2] - half],
                                Point2=[p[0] - half, p[1], p[2] + half])
                    self._show_collider(src, opacity=0.35)
            elif e.tag == "Sphere":
                c, r = vec(e.get("center"), "0 0 0"), float(e.get("radius", "0.1"))
                src = Sphere(Center=c, Radius=r, ThetaResolution=48, PhiResolution=32)
                self._show_collider(src, opacity=0.2 if e.get("inside") == "true" else 1.0)
                self.movers.append((src, c, parse_path(e.get("path"))))
            elif e.tag == "Box":
                a, b = vec(e.get("min"), "-1 -1 -1"), vec(e.get("max"), "1 1 1")
                src = Box(Center=[(a[k] + b[k]) / 2 for k in range(3)], XLength=b[0] - a[0], YLength=b[1] - a[1],
                          ZLength=b[2] - a[2])
                d = self._show_collider(src, opacity=1.0)
                if e.get("inside") == "true":
                    d.SetRepresentationType("Outline")
                self.movers.append((src, [(a[k] + b[k]) / 2 for k in range(3)], parse_path(e.get("path"))))

    def _show_collider(self, src, opacity):
        d = Show(src, self.view)
        d.ColorArrayName = ['POINTS', '']
        d.AmbientColor = d.DiffuseColor = list(COLLIDER_RGB)
        d.Opacity = opacity
        return d

    def _camera(self):
        cam = self.scene.find("Camera")
        self.view.ViewTime = self.times[0] if self.times else 0.0
        if cam is not None:
            self.view.CameraPosition = vec(cam.get("position"), "0 1 4")
            self.view.CameraFocalPoint = vec(cam.get("focus"), "0 0.8 0")
            self.view.CameraViewUp = vec(cam.get("up"), "0 1 0")
            self.view.CameraViewAngle = float(cam.get("viewAngle", "30"))
        else:
            # A three-quarter view from above of everything in the first frame.
            ResetCamera(self.view)
            f = list(self.view.CameraFocalPoint)
            p = list(self.view.CameraPosition)
            dist = sum((p[k] - f[k]) ** 2 for k in range(3)) ** 0.5
            d = [0.55, 0.45, 0.70]
            n = sum(x * x for x in d) ** 0.5
            self.view.CameraPosition = [f[k] + dist * d[k] / n for k in range(3)]
            self.view.CameraViewUp = [0.0, 1.0, 0.0]
            ResetCamera(self.view)

    def set_time(self, t):
        self.view.ViewTime = t
        for src, centre, keys in self.movers:
            off = offset_at(keys, t)
            src.Center = [centre[k] + off[k] for k in range(3)]


def plot_stats(run, to):
    """Water budget and largest saturation against time, from stats.csv."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    path = os.path.join(run, "stats.csv")
    if not os.path.exists(path):
        return []
    with open(path) as f:
        rows = list(csv.DictReader(f))
    if not rows:
        return []
    t = [float(r["time"]) for r in rows]
    out = []
    fig, ax = plt.subplots(figsize=(7, 4))
    for col, label in [("free_water_mass", "free"), ("held_water_mass", "held by cloth"),
                       ("buffered_water_mass", "buffered"), ("drained_water_mass", "drained"),
                       ("total_water_mass", "total")]:
        if col in rows[0]:
            ax.plot(t, [float(r[col]) for r in rows], label=label, lw=2 if col == "total_water_mass" else 1.4)
    ax.set_xlabel("time (s)")
    ax.set_ylabel("water (kg)")
    ax.set_title("Water budget")
    ax.grid(alpha=0.3)
    ax.legend()
    fig.tight_layout()
    out.append(os.path.join(to, "water_budget.png"))
    fig.savefig(out[-1], dpi=110)
    plt.close(fig)
    if "max_saturation" in rows[0]:
        fig, ax = plt.subplots(figsize=(7, 3))
        ax.plot(t, [float(r["max_saturation"]) for r in rows], color="black")
        ax.set_xlabel("time (s)")
        ax.set_ylabel("largest saturation")
        ax.grid(alpha=0.3)
        fig.tight_layout()
        out.append(os.path.join(to, "max_saturation.png"))
        fig.savefig(out[-1], dpi=110)
        plt.close(fig)
    return out


def main(argv):
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("run", help="a folder written by soak run")
    ap.add_argument("--to", help="where pictures go (default RUN/render)")
    ap.add_argument("--frame", type=int, help="only this frame (negative counts from the end)")
    ap.add_argument("--size", default="1280x720", help="picture size WxH (default 1280x720)")
    ap.add_argument("--no-animation", action="store_true", help="no animated GIF")
    ap.add_argument("--no-plots", action="store_true", help="no plots from stats.csv")
    ap.add_argument("--surface", action="store_true",
                    help="draw the water surface mesh (scenes with <WaterSurface>) instead of particles")
    args = ap.parse_args(argv)
    if not os.path.isdir(args.run):
        sys.exit(f"render.py: {args.run} is not a folder written by soak run")
    to = args.to or os.path.join(args.run, "render")
    os.makedirs(to, exist_ok=True)
    w, h = (int(x) for x in args.size.lower().split("x"))
    paraview.simple._DisableFirstRenderCameraReset()  # keep the scene's camera
    look = Look(args.run, (w, h), surface=args.surface)
    if not look.times:
        sys.exit(f"render.py: no water.pvd or cloth_*.pvd in {args.run}")
    frames = list(range(len(look.times)))
    if args.frame is not None:
        frames = [frames[args.frame]]
    written = []
    for k in frames:
        look.set_time(look.times[k])
        Render(look.view)
        name = os.path.join(to, f"frame_{k:06d}.png")
        SaveScreenshot(name, look.view, ImageResolution=[w, h])
        written.append(name)
        print(f"render.py: {name} (t = {look.times[k]:.3f} s)", flush=True)
    if len(written) > 1 and not args.no_animation:
        from PIL import Image
        images = [Image.open(p).convert("P", palette=Image.ADAPTIVE) for p in written]
        gif = os.path.join(to, "animation.gif")
        step = look.times[1] - look.times[0] if len(look.times) > 1 else 1 / 30
        images[0].save(gif, save_all=True, append_images=images[1:], duration=max(20, int(1000 * step)), loop=0)
        print(f"render.py: {gif}")
    if not args.no_plots:
        for p in plot_stats(args.run, to):
            print(f"render.py: {p}")


if __name__ == "__main__":
    main(sys.argv[1:])
