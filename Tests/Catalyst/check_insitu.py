# Checks what Tests/Catalyst/picture_and_csv.py wrote in situ during a run
# against the run's own files (pvpython or any Python with VTK):
#   every frame has a picture, whose middle (where the sheet is, seen from
#   fig7's <Camera>) is the cloth's red-to-black, not the white background;
#   every frame's cloth CSV has the .vtp's point count and held water, and
#   its water CSV the .vtu's point count.
# usage: check_insitu.py RUN_DIR FRAMES
import csv
import math
import os
import sys

from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkIOImage import vtkPNGReader
from vtkmodules.vtkIOXML import vtkXMLPolyDataReader, vtkXMLUnstructuredGridReader

run, frames = sys.argv[1], int(sys.argv[2])
extracts = os.path.join(run, "catalyst")
failures = []


def read(reader_type, path):
    reader = reader_type()
    reader.SetFileName(path)
    reader.Update()
    return reader.GetOutput()


def csv_columns(path):
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    header = [h.strip('"') for h in rows[0]]
    return {name: [float(r[i]) for r in rows[1:]] for i, name in enumerate(header)}, len(rows) - 1


with open(os.path.join(run, "stats.csv"), newline="") as f:
    stats = list(csv.DictReader(f))
if len(stats) != frames + 1:
    failures.append("stats.csv lists %d frames, expected %d" % (len(stats), frames + 1))

for row in stats:
    frame, step = int(row["frame"]), int(float(row["step"]))
    cloth = read(vtkXMLPolyDataReader, os.path.join(run, "cloth_sheet", "cloth_sheet_%06d.vtp" % frame))
    water = read(vtkXMLUnstructuredGridReader, os.path.join(run, "water", "water_%06d.vtu" % frame))
    held = float(vtk_to_numpy(cloth.GetPointData().GetArray("held_water")).astype("float64").sum())
    cloth_csv = os.path.join(extracts, "cloth_%06d.csv" % step)
    water_csv = os.path.join(extracts, "water_%06d.csv" % step)
    picture = os.path.join(extracts, "sheet_%06d.png" % step)
    missing = [path for path in (cloth_csv, water_csv, picture) if not os.path.exists(path)]
    for path in missing:
        failures.append("frame %d (step %d): %s was not written" % (frame, step, path))
    if missing:
        continue
    columns, points = csv_columns(cloth_csv)
    if points != cloth.GetNumberOfPoints():
        failures.append("frame %d: cloth CSV has %d points, the .vtp %d" % (frame, points, cloth.GetNumberOfPoints()))
    csv_held = math.fsum(columns["held_water"])
    if not math.isclose(csv_held, held, rel_tol=1e-5, abs_tol=1e-9):
        failures.append("frame %d: held water %.9g in the CSV, %.9g in the .vtp" % (frame, csv_held, held))
    _, water_points = csv_columns(water_csv)
    if water_points != water.GetNumberOfPoints():
        failures.append("frame %d: water CSV has %d points, the .vtu %d" % (frame, water_points, water.GetNumberOfPoints()))
    image = read(vtkPNGReader, picture)
    nx, ny, _ = image.GetDimensions()
    pixels = vtk_to_numpy(image.GetPointData().GetScalars()).reshape(ny, nx, -1)[:, :, :3].astype(int)
    # Where the sheet is, seen from fig7's <Camera>: the band across the
    # picture's middle. The cloth's colours are red (dry) to black (wet):
    # red never below green or blue, and far from the white background.
    band = pixels[ny * 45 // 100: ny * 58 // 100, nx // 5: nx * 4 // 5]
    not_white = band.sum(axis=2) < 600
    cloth_like = not_white & (band[:, :, 0] >= band[:, :, 1]) & (band[:, :, 0] >= band[:, :, 2])
    share = cloth_like.mean()
    if not_white.mean() < 0.5 or share < 0.25:
        failures.append("frame %d: the sheet's band of the picture is %.0f %% background and %.0f %% cloth (%s)"
                        % (frame, 100 * (1 - not_white.mean()), 100 * share, picture))
    print("frame %2d step %3d: cloth %d points, held water %.6g kg, water %d points, sheet band %.0f %% cloth"
          % (frame, step, points, csv_held, water_points, 100 * share))

if failures:
    print("FAILED:\n  " + "\n  ".join(failures))
    sys.exit(1)
print("in situ picture and CSV extracts agree with the run's files for %d frames" % (frames + 1))
