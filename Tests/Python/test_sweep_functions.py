"""soak.sweep_plan, sweep_run, sweep_status and sweep_collect: `soak sweep` from Python."""
import csv
import os

import soak

SOURCE = os.environ.get("SOAK_SOURCE_DIR", os.path.join(os.path.dirname(__file__), "..", ".."))
SCENE = os.path.join(SOURCE, "Tests", "Sweep", "wet_sheet.xml")


def test_a_sweep_planned_run_and_collected_from_python(tmp_path):
    folder = str(tmp_path / "sweep")
    plan = soak.sweep_plan(folder, scene=SCENE, vary={"WetCloth.initialSaturation": [0.1, 0.3]},
                           set={"Nozzle.speed": 1.5}, frames=3, device="cpu")
    assert plan == {"points": 2, "added": 2, "invalid": 0}
    assert [r["status"] for r in soak.sweep_status(folder)] == ["planned", "planned"]

    summary = soak.sweep_run(folder, jobs=2, threads=1, soak_program=os.environ["SOAK_BINARY"])
    assert summary["exit_code"] == 0 and summary["done"] == 2 and summary["started"] == 2
    rows = soak.sweep_status(folder)
    assert [r["status"] for r in rows] == ["done", "done"]
    assert [r["WetCloth.initialSaturation"] for r in rows] == ["0.1", "0.3"]

    # Planned again from the same arguments: the same points, nothing to run.
    assert soak.sweep_plan(folder, scene=SCENE, vary={"WetCloth.initialSaturation": [0.1, 0.3]},
                           set={"Nozzle.speed": 1.5}, frames=3, device="cpu")["added"] == 0
    assert soak.sweep_run(folder, jobs=2, soak_program=os.environ["SOAK_BINARY"])["started"] == 0

    collected = soak.sweep_collect(folder, figures=["held", "steps"], plot="held",
                                   against="WetCloth.initialSaturation")
    assert collected[1]["held"] > 2 * collected[0]["held"] > 0
    assert collected[0]["steps"] == collected[1]["steps"] == 7  # 0.1 s at dt = 0.015 s
    with open(os.path.join(folder, "collect.csv")) as f:
        assert [r["status"] for r in csv.DictReader(f)] == ["done", "done"]
    assert open(os.path.join(folder, "plot-held.svg")).read().count("<circle") == 2


def test_a_bad_description_names_its_line(tmp_path):
    description = tmp_path / "bad.txt"
    description.write_text(f"scene = {SCENE}\nframes = 3\nvary WetCloth.initialSaturation = linear 0.1 0.3\n")
    try:
        soak.sweep_plan(str(tmp_path / "sweep"), str(description))
    except soak.InputError as e:
        assert str(e).startswith(f"{description}:3: 'linear' takes FROM TO COUNT")
    else:
        raise AssertionError("a range without its count was planned")
