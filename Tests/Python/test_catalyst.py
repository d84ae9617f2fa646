"""Simulation.run(catalyst=[...]): a Catalyst script runs in situ from Python
as from `soak run --catalyst` (Doc/paraview.md, "In situ and live"). The
script writes CSV extracts only, so no display is needed; it fails where
ParaView's Catalyst (python3-paraview) is missing.
"""
import csv
import os

import soak

SOURCE = os.environ.get("SOAK_SOURCE_DIR", os.path.join(os.path.dirname(__file__), "..", ".."))

CSV_SCRIPT = """
import os
from paraview.simple import *
from paraview import catalyst
options = catalyst.Options()
options.ExtractsOutputDirectory = os.path.join(os.environ["SOAK_OUTPUT"], "catalyst")
sheet = TrivialProducer(registrationName="cloth_sheet.pvd")  # the name a GUI-made script gives it
extract = CreateExtractor("CSV", sheet, registrationName="SheetCsv")
extract.Trigger = "TimeStep"
extract.Writer.FileName = "sheet_{timestep:06d}.csv"
"""


def test_run_with_a_catalyst_script_writes_its_extracts_every_other_frame(tmp_path):
    script = tmp_path / "sheet_csv.py"
    script.write_text(CSV_SCRIPT)
    out = tmp_path / "run"
    sim = soak.Simulation(os.path.join(SOURCE, "Scenes", "fig7_small.xml"), device="cpu")
    result = sim.run(str(out), frames=4, catalyst=[str(script)], catalyst_every=2)
    assert result["frames_written"] == 5
    extracts = sorted(os.listdir(out / "catalyst"))
    assert len(extracts) == 3, extracts  # frames 0, 2 and 4
    with open(out / "catalyst" / extracts[-1], newline="") as f:
        rows = list(csv.reader(f))
    header = [h.strip('"') for h in rows[0]]
    assert "saturation" in header and "held_water" in header
    assert len(rows) - 1 == 2500
