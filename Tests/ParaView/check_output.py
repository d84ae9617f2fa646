"""Opens a soak run's .pvd files with ParaView's reader and checks what ParaView sees.

usage: pvpython check_output.py OUTDIR FRAMES FRAMERATE
"""
import sys

from paraview import simple

out, frames, rate = sys.argv[1], int(sys.argv[2]), float(sys.argv[3])
failures = []


def check(cond, what):
    if not cond:
        failures.append(what)


reader = simple.PVDReader(FileName=out + "/water.pvd")
reader.UpdatePipelineInformation()
times = list(reader.TimestepValues)
check(len(times) == frames + 1, "expected %d time steps, ParaView sees %d" % (frames + 1, len(times)))
dt = 0.015
for k, t in enumerate(times):
    # Frame k is written at the first step at or past k / rate.
    check(abs(t - k / rate) < dt + 1e-9 and t >= k / rate - 1e-9, "frame %d has time %g" % (k, t))

for t in times:
    reader.UpdatePipeline(t)
    data = simple.servermanager.Fetch(reader)
    names = [data.GetPointData().GetArrayName(i) for i in range(data.GetPointData().GetNumberOfArrays())]
    for name in ("velocity", "mass", "radius", "id"):
        check(name in names, "point array %r missing at t=%g (have %s)" % (name, t, names))
    check(data.GetNumberOfPoints() > 0, "no points at t=%g" % t)
    check(data.GetNumberOfCells() == data.GetNumberOfPoints(), "expected one vertex cell per particle")

# Particles fall: the mean height at the last frame is below the first.
def mean_y(t):
    reader.UpdatePipeline(t)
    d = simple.servermanager.Fetch(reader)
    pts = d.GetPoints()
    return sum(pts.GetPoint(i)[1] for i in range(d.GetNumberOfPoints())) / d.GetNumberOfPoints()

check(mean_y(times[-1]) < mean_y(times[0]), "particles did not fall")

if failures:
    print("FAILED:\n  " + "\n  ".join(failures))
    sys.exit(1)
print("ParaView read %d frames, times %s, arrays OK" % (len(times), ["%.4f" % t for t in times]))
