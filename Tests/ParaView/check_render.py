"""Checks a picture from Doc/render.py: not blank, and it shows the
saturation colours (red dry cloth, near-black wet cloth) and blue water.
usage: pvpython check_render.py FRAME.png PLOT.png"""
import sys

from PIL import Image

frame, plot = sys.argv[1], sys.argv[2]
img = Image.open(frame).convert("RGB")
w, h = img.size
pixels = list(img.getdata())
n = len(pixels)
drawn = sum(1 for r, g, b in pixels if not (r > 245 and g > 245 and b > 245))
red = sum(1 for r, g, b in pixels if r > 120 and g < 80 and b < 80)          # dry cloth
dark = sum(1 for r, g, b in pixels if r < 40 and g < 40 and b < 40)          # wet cloth
blue = sum(1 for r, g, b in pixels if b > 150 and r < 130 and b > r + 60)    # water
print(f"{frame}: {w}x{h}, drawn {drawn / n:.3%}, red (dry) {red / n:.3%}, dark (wet) {dark / n:.3%}, "
      f"blue (water) {blue / n:.3%}")
failures = []
if drawn < 0.02 * n:
    failures.append("the picture is (nearly) blank")
if red < 0.001 * n:
    failures.append("no dry (red) cloth")
if dark < 0.001 * n:
    failures.append("no wet (dark) cloth")
if blue < 0.0005 * n:
    failures.append("no water")
plot_img = Image.open(plot).convert("L")
if plot_img.getextrema()[0] > 100:
    failures.append(f"{plot} looks empty")
if failures:
    sys.exit("check_render: " + "; ".join(failures))
print("check_render: ok")
