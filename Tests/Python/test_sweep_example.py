"""Demos/python/sweep_diffusion.py runs, writes its plot and CSV, and shows diffusion."""
import csv
import os
import subprocess
import sys

SOURCE = os.environ.get("SOAK_SOURCE_DIR", os.path.join(os.path.dirname(__file__), "..", ".."))


def test_sweep_plots_wet_area_and_diffusion_wets_more_than_none(tmp_path):
    png, table = tmp_path / "sweep.png", tmp_path / "sweep.csv"
    subprocess.run([sys.executable, os.path.join(SOURCE, "Demos", "python", "sweep_diffusion.py"), "--device", "cpu",
                    "--values", "0", "0.5", "--time", "0.6", "--samples", "4", "--cells", "16", "--out", str(png),
                    "--csv", str(table)], check=True)
    assert png.stat().st_size > 10000 and png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    rows = list(csv.DictReader(table.open()))
    final = {}
    for r in rows:
        final[float(r["WetCloth.diffusionRate"])] = float(r["wet_area_m2"])  # the last sample of each value wins
    assert set(final) == {0.0, 0.5}
    assert len(rows) == 2 * 5
    # Without diffusion only what touches the water is wet; with it the water climbs the sheet.
    assert final[0.5] > 1.3 * final[0.0] > 0.0
