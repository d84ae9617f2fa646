#!/usr/bin/env python3
"""The include structure between Core's folders and the plugins, as a graph.

    python3 Demos/scripts/include_graph.py [ROOT] [--dot FILE]

Prints one line per edge "from -> to (files)" where a file in folder `from`
includes a header of folder `to` (Core/<folder>/..., Plugin/<name>/...), and
lists the edges that run from Fluid, Cloth, Output or Checkpoint up to
Simulation (the wiring layer). With --dot, writes the graph for Graphviz.
"""
import os
import re
import sys
from collections import defaultdict

LOW = {"Fluid", "Cloth", "Output", "Checkpoint"}


def folder_of(root, path):
    rel = os.path.relpath(path, root).split(os.sep)
    if rel[0] == "Core":
        return rel[1]
    if rel[0] == "Plugin":
        return "Plugin/" + rel[1]
    return None


def main():
    args = sys.argv[1:]
    dot = None
    if "--dot" in args:
        i = args.index("--dot")
        dot = args[i + 1]
        del args[i:i + 2]
    root = args[0] if args else "."
    core_folders = set(os.listdir(os.path.join(root, "Core")))
    edges = defaultdict(set)
    for top in ("Core", "Plugin"):
        for dirpath, _, files in os.walk(os.path.join(root, top)):
            for name in files:
                if not name.endswith((".h", ".cpp", ".cu")):
                    continue
                path = os.path.join(dirpath, name)
                src = folder_of(root, path)
                if src is None:
                    continue
                with open(path, encoding="utf-8", errors="replace") as f:
                    for line in f:
                        m = re.match(r'\s*#include\s+"([^"]+)"', line)
                        if not m:
                            continue
                        first = m.group(1).split("/")[0]
                        if first in core_folders and first != src:
                            edges[(src, first)].add(os.path.relpath(path, root))
    for (a, b), files in sorted(edges.items()):
        print(f"{a} -> {b} ({len(files)})")
    up = [(a, b, sorted(f)) for (a, b), f in sorted(edges.items()) if a in LOW and b == "Simulation"]
    print(f"\nup to Simulation from {', '.join(sorted(LOW))}: {len(up)} edges")
    for a, b, files in up:
        print(f"  {a} -> {b}: {', '.join(files)}")
    if dot:
        with open(dot, "w") as f:
            f.write("digraph includes {\n  rankdir=BT;\n  node [shape=box, fontsize=10];\n")
            for (a, b), files in sorted(edges.items()):
                colour = "red" if a in LOW and b == "Simulation" else "gray40"
                f.write(f'  "{a}" -> "{b}" [color={colour}, label="{len(files)}", fontsize=8];\n')
            f.write("}\n")


if __name__ == "__main__":
    main()
