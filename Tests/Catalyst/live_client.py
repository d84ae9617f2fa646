# Catalyst Live with pvpython as the client (what ParaView's Catalyst >
# Connect does): listens on a free port, starts `soak run --live` on a
# short fig7_small run, extracts the cloth over the live connection twice
# and checks its point count and that its saturation rises, pauses the run
# from here and checks that it stops, continues it and lets it finish.
# usage: pvpython live_client.py SOAK SCENE OUTDIR
import os
import socket
import subprocess
import sys
import time

from paraview import live, servermanager
from paraview.simple import *

soak, scene, out = sys.argv[1:4]
frames = 60


def fail(message):
    print("FAILED: " + message)
    sys.exit(1)


def free_port():
    with socket.socket() as s:
        s.bind(("localhost", 0))
        return s.getsockname()[1]


port = free_port()
link = live.ConnectToCatalyst("localhost", port)
run = subprocess.Popen([soak, "run", scene, "-o", os.path.join(out, "run"), "--frames", str(frames), "--device",
                        "cpu", "--quiet", "--live", "localhost:%d" % port])


def pump(seconds, until=lambda: False):
    end = time.time() + seconds
    while time.time() < end:
        live.ProcessServerNotifications()
        if until():
            return True
        if run.poll() is not None:
            fail("soak ended (exit %s) before the test was done" % run.returncode)
        time.sleep(0.02)
    return until()


def simulation_has(name):
    pxm = link.GetInsituProxyManager()
    return pxm is not None and pxm.GetProxy("sources", name) is not None


if not pump(120, lambda: simulation_has("cloth_sheet")):
    fail("no simulation connected and offered 'cloth_sheet' within 120 s")
cloth = live.ExtractCatalystData(link, "cloth_sheet")


# The saturation summed over the sheet's area, as the client computes it
# from what came over the live connection.
integral = IntegrateVariables(Input=cloth)


def saturation_sum():
    """The extract's point count and its saturation integrated over the sheet."""
    cloth.UpdatePipeline()
    points = cloth.GetDataInformation().GetNumberOfPoints()
    if points == 0:
        return None, 0.0
    integral.UpdatePipeline()
    return points, integral.PointData["saturation"].GetRange()[0]


samples = []
deadline = time.time() + 240
while time.time() < deadline and len(samples) < 2:
    pump(0.5)
    points, total = saturation_sum()
    if points and total > 0 and (not samples or total > samples[-1][1]):
        samples.append((points, total))
        print("extract %d: %d points, saturation integrated over the sheet %.6f m^2" % (len(samples), points, total))
if len(samples) < 2:
    fail("the cloth's saturation did not rise over the live connection (extracts: %r)" % samples)
if any(p != 2500 for p, _ in samples):
    fail("the cloth has %r points over the live connection, the scene 2500" % [p for p, _ in samples])

# Pause from here: the run stops once the frames already queued (the
# writer's and the adaptor's queues) are written.
live.PauseCatalyst(link, True)
stats = os.path.join(out, "run", "stats.csv")
pump(10)
before = open(stats).read().count("\n")
pump(5)
after = open(stats).read().count("\n")
print("paused: stats.csv has %d lines, 5 s later %d (of %d)" % (before, after, frames + 2))
if after != before or after >= frames + 2:
    fail("the run went on while paused from the live client")
live.PauseCatalyst(link, False)
if not pump(240, lambda: run.poll() is not None) and run.poll() is None:
    run.kill()
    fail("the run did not finish after it was continued")
if run.returncode != 0:
    fail("soak exited with %d" % run.returncode)
print("live: cloth extracted twice (2500 points, saturation rising), pause and continue obeyed, run finished")
