#!/usr/bin/env python3
"""Memory of a long run: resident memory (VmRSS) against the step count.

Runs `soak run SCENE -o OUT --time T ...`, samples the process's VmRSS (and,
on the GPU, the device memory in use as nvidia-smi reports it, when present)
every --every seconds against the last step in OUT/stats.csv, and prints the
RSS after the first --early steps and at the end, and their ratio. A run
whose memory grows with its length would show a ratio above 1. Needs only
Python's standard library (the device machine has no Debian packages).

  Demos/scripts/long_run_memory.py --soak build/release/bin/soak \
      Scenes/small/sheet_swing_40.xml --time 1500 -o /tmp/long --csv rss.csv \
      -- --device cpu --checkpoint-every 100 --set Simulation.frameRate=2

Doc/reliability.md ("Long runs") gives the measurements.
"""
import argparse
import csv
import os
import shlex
import subprocess
import sys
import time


def rss_bytes(pid):
    try:
        with open(f"/proc/{pid}/status") as f:
            for line in f:
                if line.startswith("VmRSS:"):
                    return int(line.split()[1]) * 1024
    except OSError:
        return None
    return None


def gpu_bytes(pid):
    """Device memory the process holds (nvidia-smi), or None."""
    try:
        out = subprocess.run(["nvidia-smi", "--query-compute-apps=pid,used_memory", "--format=csv,noheader,nounits"],
                             capture_output=True, text=True, timeout=10).stdout
    except (OSError, subprocess.SubprocessError):
        return None
    for line in out.splitlines():
        parts = [p.strip() for p in line.split(",")]
        if len(parts) == 2 and parts[0] == str(pid):
            return int(parts[1]) * 1024 * 1024
    return None


def last_step(stats_path):
    try:
        with open(stats_path, "rb") as f:
            f.seek(0, os.SEEK_END)
            size = f.tell()
            f.seek(max(0, size - 4096))
            lines = f.read().decode(errors="replace").strip().splitlines()
    except OSError:
        return None
    for line in reversed(lines):
        fields = line.split(",")
        if len(fields) > 2 and fields[2].isdigit():
            return int(fields[2])
    return None


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("scene")
    ap.add_argument("--soak", default="soak", help="the soak program (a command line: split as a shell would)")
    ap.add_argument("--time", type=float, required=True, help="simulated seconds (steps = time / timeStep)")
    ap.add_argument("-o", "--output", required=True)
    ap.add_argument("--every", type=float, default=1.0, help="seconds between samples")
    ap.add_argument("--early", type=int, default=1000, help="the step the end is compared with")
    ap.add_argument("--csv", help="write the samples here (seconds, step, rss_bytes, gpu_bytes)")
    a, extra = ap.parse_known_args()
    a.soak_args = [x for x in extra if x != "--"]  # after --: further `soak run` options

    cmd = shlex.split(a.soak) + ["run", a.scene, "-o", a.output, "--time", str(a.time), "--quiet", "--overwrite"] + a.soak_args
    start = time.monotonic()
    proc = subprocess.Popen(cmd)
    samples = []
    while proc.poll() is None:
        rss = rss_bytes(proc.pid)
        step = last_step(os.path.join(a.output, "stats.csv"))
        if rss is not None and step is not None:
            samples.append((time.monotonic() - start, step, rss, gpu_bytes(proc.pid)))
        time.sleep(a.every)
    wall = time.monotonic() - start
    if proc.returncode != 0:
        print(f"soak exited with {proc.returncode}", file=sys.stderr)
        return proc.returncode
    if a.csv:
        with open(a.csv, "w", newline="") as f:
            w = csv.writer(f)
            w.writerow(["seconds", "step", "rss_bytes", "gpu_bytes"])
            w.writerows(samples)
    early = [s for s in samples if s[1] >= a.early]
    if not early:
        print("the run ended before the early step was sampled", file=sys.stderr)
        return 1
    first, last = early[0], samples[-1]
    peak = max(s[2] for s in samples)
    print(f"steps {last[1]}, wall {wall:.0f} s, samples {len(samples)}")
    print(f"rss at step {first[1]}: {first[2] / 2**20:.1f} MiB; at step {last[1]}: {last[2] / 2**20:.1f} MiB; "
          f"peak {peak / 2**20:.1f} MiB; end/early {last[2] / first[2]:.4f}")
    if first[3] is not None and last[3] is not None:
        print(f"gpu memory at step {first[1]}: {first[3] / 2**20:.0f} MiB; at step {last[1]}: "
              f"{last[3] / 2**20:.0f} MiB; end/early {last[3] / first[3]:.4f}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
