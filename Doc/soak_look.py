"""ParaView GUI macro: shows a Soak run with the look of Doc/render.py
(cloth coloured by saturation from red to black, water as spheres, the
colliders, the scene's camera) in the active view.

Install once: Macros > Import new macro... > this file (keep render.py in
the same folder as this file). Then open a run's water.pvd (File > Open),
or set SOAK_RUN=/path/to/run before starting ParaView, and click the macro.
"""
import os
import sys

from paraview.simple import GetActiveViewOrCreate, GetSources, Render

here = os.path.dirname(os.path.abspath(__file__)) if "__file__" in globals() else os.getcwd()
for folder in (here, os.path.join(os.environ.get("SOAK_SOURCE_DIR", ""), "Doc")):
    if os.path.exists(os.path.join(folder, "render.py")) and folder not in sys.path:
        sys.path.insert(0, folder)
import render  # noqa: E402  (Doc/render.py)


def find_run():
    """The folder of an opened water.pvd, else $SOAK_RUN."""
    for (name, _), proxy in GetSources().items():
        fname = getattr(proxy, "FileName", "") or ""
        if isinstance(fname, str) and fname.endswith("water.pvd"):
            return os.path.dirname(fname), proxy
    return os.environ.get("SOAK_RUN"), None


run, opened = find_run()
if not run or not os.path.isdir(run):
    print("soak_look: open a run's water.pvd first, or start ParaView with SOAK_RUN=/path/to/run")
else:
    import paraview.simple
    paraview.simple._DisableFirstRenderCameraReset()  # keep the scene's camera
    view = GetActiveViewOrCreate("RenderView")
    if opened is not None:
        from paraview.simple import Hide
        Hide(opened, view)   # the macro draws the water itself
    look = render.Look(run, view=view)
    look.set_time(look.times[0] if look.times else 0.0)
    Render(view)
    print(f"soak_look: {run}")
