#!/usr/bin/env python3
"""How dense and how even animpak packs (docs/quality.md, "Still reference"; docs/benchmark.md).

    scripts/packing-bench.py [--animpak PATH] [--out DIR] [--discs 19,37,61] [--disc-seeds 1,2,3]
                             [--examples default,clipart] [--frames 100] [--size 200] [--device NAME]

Two tables, each packing run by `animpak pack` to its stop and measured on its rendered frames:

  discs      N equal discs (the art) in a circle (the container), standing still, `offset` 0.04, 12
             slices: coverage against the best-known packing of N equal circles in a circle
             (Packomania: 19 0.803, 37 0.810, 61 0.813), times the channel factor (r / (r + offset))²
             that each disc's channel leaves of its envelope (r = 0.5, the disc in its own units). One
             row per seed in --disc-seeds (default 1): a packing can jam with a hole where a disc would
             fit, and which seeds do says more than one seed.
  examples   each example scene packed standing still (`pack --still`) and as it is: the coverage of
             both, the animated packing's lowest frame over the still packing's mean, the wall ratio,
             the largest empty disc, iterations and simulation time.

`--discs ''` or `--examples ''` skips a table. Packs take minutes each (the examples tens of minutes in
all on two cores); the folders stay in --out (default: a new folder under /tmp) for a look at the
frames. Prints Markdown.
"""
import argparse
import json
import os
import subprocess
import sys
import tempfile

BEST_KNOWN = {19: 0.803, 37: 0.810, 61: 0.813}  # Packomania, equal circles in a circle
DISC_OFFSET = 0.04
ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def pack(animpak, scene, out, args, still=False):
    cmd = [animpak, "pack", scene, "--out", out, "--force", "--frames", str(args.frames), "--size", str(args.size),
           "--format", "png"]
    if still:
        cmd.append("--still")
    if args.device:
        cmd += ["--device", args.device]
    print("$ " + " ".join(cmd), file=sys.stderr, flush=True)
    run = subprocess.run(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    if run.returncode != 0:
        sys.exit("packing-bench: `%s` failed (exit %d):\n%s" % (" ".join(cmd), run.returncode, run.stderr))
    with open(os.path.join(out, "stats.json")) as f:
        return json.load(f)


def summary(stats):
    q = stats["quality"]["frames"]
    return {
        "min": q["coverage"]["min"],
        "max": q["coverage"]["max"],
        "mean": q["coverage"]["mean"],
        "wall": q["wall_ratio"]["median"],
        "disc": q["empty_disc"]["median"],
        "disc_worst": q["empty_disc"]["worst"],
        "iterations": stats["iterations"],
        "seconds": stats["seconds"]["simulation"],
    }


def fmt(v, digits=2):
    return "n/a" if v is None else "%.*f" % (digits, v)


def pct(lo, hi):
    return "%d–%d %%" % (round(100 * lo), round(100 * hi))


def disc_scene(folder, count, seed=1):
    os.makedirs(folder, exist_ok=True)
    with open(os.path.join(folder, "disc.svg"), "w") as f:
        f.write('<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 100 100">'
                '<circle cx="50" cy="50" r="50" fill="#c33"/></svg>\n')
    with open(os.path.join(folder, "circle.svg"), "w") as f:
        f.write('<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 200 200">'
                '<circle cx="100" cy="100" r="100" fill="#eee"/></svg>\n')
    scene = os.path.join(folder, "scene.json")
    with open(scene, "w") as f:
        json.dump({"container": {"art": "circle.svg"},
                   "elements": [{"name": "disc", "art": "disc.svg", "count": count}],
                   "seed": seed, "loop": True, "slices": 12, "params": {"offset": DISC_OFFSET}}, f)
    return scene


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--animpak", default=os.path.join(ROOT, "build", "release", "animpak"))
    ap.add_argument("--out", default=None)
    ap.add_argument("--discs", default="19,37,61")
    ap.add_argument("--disc-seeds", default="1")
    ap.add_argument("--examples", default="default,clipart,aquarium,annulus,aquatic-loop")
    ap.add_argument("--frames", type=int, default=100)
    ap.add_argument("--size", type=int, default=200)
    ap.add_argument("--device", default=None)
    args = ap.parse_args()
    out = args.out or tempfile.mkdtemp(prefix="animpak-packing-bench-")
    os.makedirs(out, exist_ok=True)

    discs = [int(n) for n in args.discs.split(",") if n.strip()]
    if discs:
        factor = (0.5 / (0.5 + DISC_OFFSET)) ** 2
        seeds = [int(k) for k in args.disc_seeds.split(",") if k.strip()]
        print("| discs | seed | coverage | best known × channel | share of it | wall ratio | largest empty disc |"
              " iterations | simulation |")
        print("| --- | --- | --- | --- | --- | --- | --- | --- | --- |")
        for n in discs:
            for seed in seeds:
                folder = os.path.join(out, "discs-%d-seed-%d" % (n, seed))
                s = summary(pack(args.animpak, disc_scene(folder, n, seed), os.path.join(folder, "packing"), args))
                limit = BEST_KNOWN.get(n)
                bound = None if limit is None else limit * factor
                print("| %d | %d | %s | %s | %s | %s | %s | %d | %.0f s |" % (
                    n, seed, fmt(100 * s["mean"], 1) + " %", fmt(bound, 3),
                    fmt(None if bound is None else s["mean"] / bound), fmt(s["wall"]), fmt(s["disc"]),
                    s["iterations"], s["seconds"]), flush=True)
        print()

    examples = [e for e in args.examples.split(",") if e.strip()]
    if examples:
        print("| example | still | animated | lowest frame / still | wall ratio | largest empty disc (worst) |"
              " iterations (still) | simulation (still) |")
        print("| --- | --- | --- | --- | --- | --- | --- | --- |")
        for name in examples:
            scene = os.path.join(ROOT, "examples", name, "scene.json")
            still = summary(pack(args.animpak, scene, os.path.join(out, name + "-still"), args, still=True))
            moving = summary(pack(args.animpak, scene, os.path.join(out, name), args))
            print("| %s | %s | %s | %s | %s | %s (%s) | %d (%d) | %.0f s (%.0f s) |" % (
                name, pct(still["min"], still["max"]), pct(moving["min"], moving["max"]),
                fmt(moving["min"] / still["mean"]), fmt(moving["wall"]), fmt(moving["disc"]),
                fmt(moving["disc_worst"]), moving["iterations"], still["iterations"], moving["seconds"],
                still["seconds"]), flush=True)
    print("\n(folders in %s)" % out, file=sys.stderr)


if __name__ == "__main__":
    main()
