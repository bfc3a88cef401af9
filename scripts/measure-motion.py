#!/usr/bin/env python3
"""Motion and size of a packing's elements, measured on its SVG frames alone (docs/quality.md, "Motion").

    scripts/measure-motion.py DIR [--slices N] [--no-loop] [--loop-to A:B,...]

DIR holds frames/frame_NNNN.svg (animpak pack or render with --format svg). Each element is one <g id=...>
of straight path segments. Per element and frame: the centroid of its points and the area its paths
enclose. Printed:
  - acceleration: the centroid's frame-to-frame second difference (cyclic when the scene loops), in
    container widths: its median and 99th percentile over every element and frame, and their ratio (a
    jolt at every slice shows as a 99th percentile far above the median). Across the loop's seam an
    element continues as the element it loops into (--loop-to A:B: A's last frame is followed by B's
    first), as two guided elements that swap places do;
  - with --slices N (slices evenly spaced in t): the mean acceleration at the frames next to a slice time
    over the mean elsewhere (1 when the slices do not show);
  - size: per element, its largest area over its smallest over the loop; the median and the worst.
It reads nothing but the frames, so it measures what a viewer sees, independently of the solver.
"""
import argparse
import glob
import math
import os
import re
import statistics
import sys
import xml.etree.ElementTree as ET

NUMBER = re.compile(r"[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?")


def subpaths(d):
    """The point lists of a path of M, L and Z commands (what animpak writes)."""
    out, current = [], []
    for command, args in re.findall(r"([MLZmlz])([^MLZmlz]*)", d):
        values = [float(v) for v in NUMBER.findall(args)]
        points = list(zip(values[0::2], values[1::2]))
        if command in "Mm":
            if current:
                out.append(current)
            current = points
        elif command in "Ll":
            current.extend(points)
        else:
            if current:
                out.append(current)
            current = []
    if current:
        out.append(current)
    return out


def shoelace(points):
    return 0.5 * sum(a[0] * b[1] - b[0] * a[1] for a, b in zip(points, points[1:] + points[:1]))


def read_frame(path):
    root = ET.parse(path).getroot()
    ns = root.tag[: root.tag.index("}") + 1] if root.tag.startswith("{") else ""
    width = float(root.get("viewBox").split()[2])
    container = root.find(f".//{ns}path[@id='container']")
    if container is not None:
        xs = [p[0] for s in subpaths(container.get("d")) for p in s]
        width = max(xs) - min(xs)
    elements = {}
    for g in root.iter(f"{ns}g"):
        name = g.get("id")
        if not name:
            continue
        points, area = [], 0.0
        for p in g.iter(f"{ns}path"):
            for s in subpaths(p.get("d") or ""):
                points.extend(s)
                area += abs(shoelace(s))
        if points:
            cx = sum(p[0] for p in points) / len(points)
            cy = sum(p[1] for p in points) / len(points)
            elements[name] = (cx, cy, area)
    return width, elements


def percentile(values, q):
    values = sorted(values)
    return values[min(len(values) - 1, int(q * (len(values) - 1) + 0.5))]


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("dir")
    parser.add_argument("--slices", type=int, default=0, help="slices of the scene, evenly spaced in t")
    parser.add_argument("--no-loop", action="store_true", help="the scene does not loop")
    parser.add_argument("--loop-to", default="", help="A:B,... element A loops into element B at the seam")
    args = parser.parse_args()
    files = sorted(glob.glob(os.path.join(args.dir, "frames", "frame_*.svg")))
    if len(files) < 3:
        sys.exit(f"measure-motion: {args.dir}/frames: fewer than 3 SVG frames (render with --format svg)")
    frames = [read_frame(f) for f in files]
    width = frames[0][0]
    names = sorted(set.intersection(*[set(e) for _, e in frames]))
    n = len(frames)
    loop = not args.no_loop
    into = {name: name for name in names}
    for pair in filter(None, args.loop_to.split(",")):
        a, b = pair.split(":")
        into[a] = b
    came_from = {b: a for a, b in into.items()}
    accel, at_slice, elsewhere, sizes = [], [], [], []
    for name in names:
        c = [(e[name][0], e[name][1]) for _, e in frames]
        areas = [e[name][2] for _, e in frames]
        sizes.append(max(areas) / max(min(areas), 1e-12))
        for i in range(n) if loop else range(1, n - 1):
            a = (frames[-1][1][came_from[name]][:2] if i == 0 else c[i - 1])
            b = c[i]
            d = (frames[0][1][into[name]][:2] if i == n - 1 else c[i + 1])
            value = math.hypot(a[0] - 2 * b[0] + d[0], a[1] - 2 * b[1] + d[1]) / width
            accel.append(value)
            if args.slices > 1:
                # Frame i is t = i/n (looping) or i/(n-1); a slice time between frames i-1 and i+1 bends there.
                t = i / n if loop else i / (n - 1)
                step = 1 / n if loop else 1 / (n - 1)
                interval = 1 / (args.slices - 1)
                near = any(abs(t - k * interval) < step for k in range(args.slices))
                (at_slice if near else elsewhere).append(value)
    median, p99 = statistics.median(accel), percentile(accel, 0.99)
    print(f"elements {len(names)}, frames {n}")
    print(f"acceleration: median {median:.3g}, 99th percentile {p99:.3g} container widths, ratio {p99 / median:.1f}")
    if at_slice and elsewhere:
        ratio = statistics.mean(at_slice) / statistics.mean(elsewhere)
        print(f"slices: mean acceleration next to a slice time over elsewhere {ratio:.2f}")
    print(f"size (largest area over smallest over the loop): median {statistics.median(sizes):.3f}, "
          f"worst {max(sizes):.3f}")


if __name__ == "__main__":
    main()
