"""Reads Soak's binary PLY cloth frames (Doc/output.md) with numpy.

A frame holds one `vertex` element (x y z, vx vy vz, one float per channel,
red green blue) and one `face` element whose `vertex_indices` lists are
triangles. Soak writes binary_little_endian; big-endian files are read too.
Nothing here needs Blender.
"""
import numpy as np

# PLY scalar type names (both spellings of the specification) -> numpy codes.
_TYPES = {
    "char": "i1", "int8": "i1", "uchar": "u1", "uint8": "u1",
    "short": "i2", "int16": "i2", "ushort": "u2", "uint16": "u2",
    "int": "i4", "int32": "i4", "uint": "u4", "uint32": "u4",
    "float": "f4", "float32": "f4", "double": "f8", "float64": "f8",
}


class PlyError(ValueError):
    pass


class Element:
    def __init__(self, name, count):
        self.name = name
        self.count = count
        self.properties = []   # (name, numpy code) for scalars
        self.list_property = None   # (name, count code, item code)


def read_header(f):
    """Reads the header from an open binary file; returns (elements, byte order)."""
    if f.readline().strip() != b"ply":
        raise PlyError("not a PLY file")
    elements, order = [], None
    while True:
        line = f.readline()
        if not line:
            raise PlyError("header has no end_header")
        words = line.decode("ascii", "replace").split()
        if not words or words[0] in ("comment", "obj_info"):
            continue
        if words[0] == "format":
            order = {"binary_little_endian": "<", "binary_big_endian": ">"}.get(words[1])
            if order is None:
                raise PlyError(f"format {words[1]} is not binary (Soak writes binary_little_endian)")
        elif words[0] == "element":
            elements.append(Element(words[1], int(words[2])))
        elif words[0] == "property":
            if not elements:
                raise PlyError("property before any element")
            if words[1] == "list":
                elements[-1].list_property = (words[4], _TYPES[words[2]], _TYPES[words[3]])
            else:
                elements[-1].properties.append((words[2], _TYPES[words[1]]))
        elif words[0] == "end_header":
            break
    if order is None:
        raise PlyError("header has no format line")
    return elements, order


def _read_triangles(f, element, order):
    _, count_code, index_code = element.list_property
    if element.properties:
        raise PlyError("face element with scalar properties besides its list")
    if element.count == 0:
        return np.zeros((0, 3), np.int32)
    # Soak's faces are all triangles: read them as fixed-size records and check the counts.
    record = np.dtype([("n", order + count_code), ("v", order + index_code, (3,))])
    data = np.fromfile(f, dtype=record, count=element.count)
    if len(data) != element.count or np.any(data["n"] != 3):
        raise PlyError("faces are not all triangles")
    return data["v"].astype(np.int32)


def read(path, faces=True):
    """Returns (vertex record array with one field per property, triangles or None)."""
    with open(path, "rb") as f:
        elements, order = read_header(f)
        vertices, triangles = None, None
        for element in elements:
            if element.name == "vertex":
                if element.list_property:
                    raise PlyError("vertex element with a list property")
                dtype = np.dtype([(name, order + code) for name, code in element.properties])
                vertices = np.fromfile(f, dtype=dtype, count=element.count)
                if len(vertices) != element.count:
                    raise PlyError(f"{path}: file ends inside the vertices")
            elif element.name == "face" and faces:
                triangles = _read_triangles(f, element, order)
            else:
                break   # the elements after are not needed
    if vertices is None:
        raise PlyError(f"{path}: no vertex element")
    for axis in ("x", "y", "z"):
        if axis not in vertices.dtype.names:
            raise PlyError(f"{path}: vertex has no '{axis}'")
    return vertices, triangles


# Properties that are not per-vertex channels: position, velocity and the display colour.
GEOMETRY_PROPERTIES = ("x", "y", "z", "vx", "vy", "vz", "red", "green", "blue", "alpha")


def channel_names(vertices):
    """The float channels (saturation, held_water, ...) of a vertex record array."""
    return [n for n in vertices.dtype.names
            if n not in GEOMETRY_PROPERTIES and vertices.dtype[n].kind == "f"]
