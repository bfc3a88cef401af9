#!/usr/bin/env python3
"""Writes an SVG with one star-shaped path of N points, the size of a bitmap tracer's output for detailed
art: a star of ARMS arms, its outline sampled evenly by arc length and wobbled by WOBBLE user units (a
tracer's noise, below the importer's flattening tolerance of 0.1). Used to time the importer and the
element pipeline on large input (docs/scene-format.md, "Large paths")."""
import argparse
import math
import sys


def star_points(n, arms, radius, wobble):
    corners = []
    for k in range(2 * arms):
        r = radius if k % 2 == 0 else radius * 0.45
        a = math.pi * k / arms - math.pi / 2
        corners.append((radius + r * math.cos(a), radius + r * math.sin(a)))
    edge = math.dist(corners[0], corners[1])  # every edge has the same length
    total = edge * len(corners)
    points = []
    for i in range(n):
        s = total * i / n
        k = int(s // edge)
        t = s / edge - k
        (x0, y0), (x1, y1) = corners[k], corners[(k + 1) % len(corners)]
        # Along the edge's normal, alternating sides: a zigzag of amplitude `wobble`.
        nx, ny = (y1 - y0) / edge, -(x1 - x0) / edge
        w = wobble if i % 2 else -wobble
        points.append((x0 + t * (x1 - x0) + w * nx, y0 + t * (y1 - y0) + w * ny))
    return points


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("points", type=int, help="number of points on the path")
    parser.add_argument("--arms", type=int, default=12)
    parser.add_argument("--radius", type=float, default=1000.0, help="outer radius in user units")
    parser.add_argument("--wobble", type=float, default=0.02, help="zigzag amplitude in user units")
    args = parser.parse_args()
    side = 2 * args.radius
    out = sys.stdout
    out.write(f'<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 {side:g} {side:g}">\n<path id="star" d="M')
    for i, (x, y) in enumerate(star_points(args.points, args.arms, args.radius, args.wobble)):
        out.write(f"{' L' if i == 1 else ' '}{x:.3f} {y:.3f}")
    out.write(' Z"/>\n</svg>\n')


if __name__ == "__main__":
    main()
