"""What a Soak run folder holds (Doc/output.md), read without Blender.

A run written by `soak run SCENE -o OUT` has OUT/scene.xml (the scene as
run, overrides applied), OUT/stats.csv (one row per frame, with its time),
with `Output.ply` OUT/cloth_NAME_ply/cloth_NAME_NNNNNN.ply per cloth and
frame, and with `Output.vdb` OUT/water_vdb/water_NNNNNN.vdb per frame.
"""
import csv
import os
import re
import xml.etree.ElementTree as ET

_PLY_FOLDER = re.compile(r"^cloth_(.+)_ply$")
_NUMBERED = re.compile(r"_(\d+)\.(ply|vdb)$")

# Default values of the scene attributes read here (`soak params`).
DEFAULTS = {
    "Simulation": {"frameRate": "30", "domainMin": "-1000 -1000 -1000", "domainMax": "1000 1000 1000"},
    "Camera": {"position": "0 1 4", "focus": "0 0.8 0", "up": "0 1 0", "viewAngle": "30"},
    "Plane": {"point": "0 0 0", "normal": "0 1 0", "path": ""},
    "Box": {"min": "-1 -1 -1", "max": "1 1 1", "inside": "false", "path": ""},
    "Sphere": {"center": "0 0 0", "radius": "0.1", "inside": "false", "path": ""},
    "WetCloth": {"sMax": "0.4"},
    "Water": {"spacing": "0.02", "restDensity": "1000"},
}


class RunError(Exception):
    pass


def attribute(element, name):
    """The attribute's text, or its default from `soak params` where the scene leaves it out."""
    value = element.get(name)
    return value if value is not None else DEFAULTS[element.tag][name]


def vector(element, name):
    numbers = [float(x) for x in attribute(element, name).replace(",", " ").split()]
    if len(numbers) != 3:
        raise RunError(f"<{element.tag} {name}=...> is not three numbers")
    return numbers


def number(element, name):
    return float(attribute(element, name))


def boolean(element, name):
    return attribute(element, name).strip().lower() in ("true", "1", "yes", "on")


def path_keys(element):
    """A collider's `path` ('t x y z; t x y z; ...', offsets, linear between) as sorted (t, [x, y, z])."""
    keys = []
    for part in attribute(element, "path").split(";"):
        numbers = part.replace(",", " ").split()
        if len(numbers) == 4:
            keys.append((float(numbers[0]), [float(x) for x in numbers[1:]]))
        elif numbers:
            raise RunError(f"<{element.tag} path=...>: '{part.strip()}' is not 'time x y z'")
    return sorted(keys, key=lambda k: k[0])


def offset_at(keys, t):
    """The path's offset at time t: linear between keys, held before the first and after the last."""
    if not keys:
        return [0.0, 0.0, 0.0]
    if t <= keys[0][0]:
        return list(keys[0][1])
    for (t0, a), (t1, b) in zip(keys, keys[1:]):
        if t <= t1:
            u = (t - t0) / (t1 - t0) if t1 > t0 else 1.0
            return [a[k] + u * (b[k] - a[k]) for k in range(3)]
    return list(keys[-1][1])


def numbered_files(folder):
    """{frame number: path} of the NNNNNN-numbered .ply/.vdb files in a folder."""
    frames = {}
    if os.path.isdir(folder):
        for name in os.listdir(folder):
            m = _NUMBERED.search(name)
            if m and not name.startswith("."):
                frames[int(m.group(1))] = os.path.join(folder, name)
    return frames


class Run:
    """The parts of a run folder the importer uses."""

    def __init__(self, folder):
        self.folder = os.path.abspath(folder)
        scene_path = os.path.join(self.folder, "scene.xml")
        if not os.path.isfile(scene_path):
            raise RunError(f"{self.folder} is not a Soak run folder: it has no scene.xml")
        self.scene = ET.parse(scene_path).getroot()
        self.cloths = {}   # name -> {frame: ply path}
        for entry in sorted(os.listdir(self.folder)):
            m = _PLY_FOLDER.match(entry)
            if m and os.path.isdir(os.path.join(self.folder, entry)):
                frames = numbered_files(os.path.join(self.folder, entry))
                if frames:
                    self.cloths[m.group(1)] = frames
        self.water_vdb = numbered_files(os.path.join(self.folder, "water_vdb"))
        self.times = self._read_times()

    def _read_times(self):
        """{frame: simulated time} from stats.csv (a frame's time is the step's that wrote it)."""
        times = {}
        path = os.path.join(self.folder, "stats.csv")
        if os.path.isfile(path):
            with open(path, newline="") as f:
                for row in csv.DictReader(f):
                    try:
                        times[int(row["frame"])] = float(row["time"])
                    except (KeyError, TypeError, ValueError):
                        pass
        return times

    def element(self, tag):
        return self.scene.find(tag)

    def elements(self, *tags):
        return [e for e in self.scene if e.tag in tags]

    @property
    def frame_rate(self):
        sim = self.element("Simulation")
        return number(sim, "frameRate") if sim is not None else float(DEFAULTS["Simulation"]["frameRate"])

    @property
    def saturation_max(self):
        wet = self.element("WetCloth")
        return number(wet, "sMax") if wet is not None else float(DEFAULTS["WetCloth"]["sMax"])

    def frames(self):
        """Every frame number some cloth, water or stats row has."""
        numbers = set(self.water_vdb) | set(self.times)
        for frames in self.cloths.values():
            numbers |= set(frames)
        return sorted(numbers)

    @property
    def last_frame(self):
        frames = self.frames()
        return frames[-1] if frames else 0

    def time_of(self, frame):
        """The frame's simulated time: stats.csv's, else frame / frameRate."""
        return self.times.get(frame, frame / self.frame_rate)
