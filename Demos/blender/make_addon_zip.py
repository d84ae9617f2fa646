#!/usr/bin/env python3
"""Zips the soak_blender add-on for Blender's Preferences > Add-ons > Install.

    python3 Demos/blender/make_addon_zip.py [OUT.zip]     (default: soak_blender.zip here)

The zip holds the folder soak_blender/ with its .py files, which is what
Blender's installer unpacks into its add-ons folder.
"""
import os
import sys
import zipfile

HERE = os.path.dirname(os.path.abspath(__file__))
PACKAGE = "soak_blender"


def make(out):
    source = os.path.join(HERE, PACKAGE)
    names = sorted(n for n in os.listdir(source) if n.endswith(".py"))
    with zipfile.ZipFile(out, "w", zipfile.ZIP_DEFLATED) as z:
        for name in names:
            z.write(os.path.join(source, name), f"{PACKAGE}/{name}")
    return names


if __name__ == "__main__":
    out = os.path.abspath(sys.argv[1] if len(sys.argv) > 1 else f"{PACKAGE}.zip")
    names = make(out)
    print(f"{out}: {PACKAGE}/ with {', '.join(names)}")
