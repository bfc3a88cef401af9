#!/usr/bin/env python3
"""docs/first-scene.md runs as written: every file it asks the user to create (the fenced block after a
`<!-- first-scene: file NAME -->` line) is written into a scratch folder, every command block after a
`<!-- first-scene: run -->` line is run there with bash, in the order of the document, and what the
document shows is checked against what the commands made:
- each `pack` and `render` line's output folder holds what its `--frames` and `--format` promise (with
  the defaults `--help` gives where an option is left out): that many PNG frames, a GIF with that many
  frames, a Lottie document whose in and out points span that many frames, and stats.json's frames;
- every `quality:` line the document quotes is one a command printed (a packing is deterministic: the
  same scene and seed give the same frames on every device), and names no element outside and no
  overlapping pair, and neither does any command's own `quality:` line;
- each picture after a `<!-- first-scene: picture PATH -->` line exists as PATH at that point of the
  document, with the size of the picture the document shows.
Only a leading `animpak` of a command line is replaced, by the binary given.

Usage: first_scene.py ANIMPAK SOURCE_DIR [--update-pictures]
--update-pictures copies each PATH over the document's picture (how docs/images/first-scene/ is made).
Exits 77 (skipped) without ffmpeg, which the GIF needs; 1 under CI=true, where nothing may skip."""
import json
import os
import pathlib
import re
import shlex
import shutil
import struct
import subprocess
import sys
import tempfile

MARKER = re.compile(r"^<!-- first-scene: (file (?P<name>\S+)|run|picture (?P<picture>\S+)) -->$")
FENCE = re.compile(r"^```")
IMAGE = re.compile(r"!\[[^\]]*\]\(([^)\s]+)\)")
# The frame defaults `animpak pack --help` and `render --help` print.
DEFAULT_FRAMES = 100
DEFAULT_FORMATS = ["png", "gif"]

failures = []


def fail(message):
    failures.append(message)
    print(f"FAIL {message}")


def steps(doc, text):
    """The document's marked blocks in order: ("file", name, body), ("run", None, body) or
    ("picture", path, the image the next line shows)."""
    lines = text.splitlines()
    out = []
    i = 0
    while i < len(lines):
        match = MARKER.match(lines[i].strip())
        i += 1
        if not match:
            continue
        if match.group("picture"):
            image = IMAGE.search(lines[i]) if i < len(lines) else None
            if not image:
                sys.exit(f"{doc}:{i}: a picture marker must be followed by a line with an image")
            out.append(("picture", match.group("picture"), image.group(1)))
            continue
        if i >= len(lines) or not FENCE.match(lines[i]):
            sys.exit(f"{doc}:{i}: a first-scene marker must be followed immediately by a fenced block")
        start = i + 1
        end = start
        while end < len(lines) and not FENCE.match(lines[end]):
            end += 1
        body = "\n".join(lines[start:end]) + "\n"
        out.append(("file", match.group("name"), body) if match.group("name") else ("run", None, body))
        i = end + 1
    return out


def gif_frames(path):
    """The number of images in a GIF (its image descriptors), read block by block."""
    data = path.read_bytes()
    if data[:6] not in (b"GIF87a", b"GIF89a"):
        raise ValueError("not a GIF")
    pos = 13
    flags = data[10]
    if flags & 0x80:
        pos += 3 * (2 ** ((flags & 7) + 1))
    frames = 0

    def skip_sub_blocks(p):
        while data[p] != 0:
            p += data[p] + 1
        return p + 1

    while pos < len(data):
        block = data[pos]
        if block == 0x3B:  # trailer
            return frames
        if block == 0x21:  # extension: label, then sub-blocks
            pos = skip_sub_blocks(pos + 2)
        elif block == 0x2C:  # image descriptor, optional local colour table, LZW size, sub-blocks
            frames += 1
            local = data[pos + 9]
            pos += 10
            if local & 0x80:
                pos += 3 * (2 ** ((local & 7) + 1))
            pos = skip_sub_blocks(pos + 1)
        else:
            raise ValueError(f"unexpected block 0x{block:02x} at byte {pos}")
    raise ValueError("no trailer")


def png_size(path):
    data = path.read_bytes()[:24]
    if data[:8] != b"\x89PNG\r\n\x1a\n":
        raise ValueError("not a PNG")
    return struct.unpack(">II", data[16:24])


def check_quality_line(where, line):
    match = re.search(r"(\d+) of \d+ element-frames outside .*?(\d+) overlapping pair-frames in (\d+) pairs", line)
    if not match:
        fail(f"{where}: no outside/overlap counts in {line!r}")
    elif any(int(g) for g in match.groups()):
        fail(f"{where}: the document shows a clean packing, but {line!r}")


def check_outputs(work, command, output):
    """What one pack or render line promises in its output folder."""
    words = shlex.split(command)
    if len(words) < 2 or words[1] not in ("pack", "render"):
        return
    options = {}
    positional = []
    i = 2
    while i < len(words):
        if words[i].startswith("--"):
            if i + 1 < len(words) and not words[i + 1].startswith("--"):
                options[words[i]] = words[i + 1]
                i += 2
                continue
            options[words[i]] = True
        else:
            positional.append(words[i])
        i += 1
    folder = work / (options["--out"] if words[1] == "pack" else positional[0])
    frames = int(options.get("--frames", DEFAULT_FRAMES))
    formats = options["--format"].split(",") if "--format" in options else DEFAULT_FORMATS
    where = f"`{command}`"
    if options.get("--no-render"):
        return
    pngs = sorted((folder / "frames").glob("frame_*.png"))
    if "png" in formats and len(pngs) != frames:
        fail(f"{where}: {len(pngs)} PNG frames in {folder.name}/frames, expected {frames}")
    if "gif" in formats:
        try:
            count = gif_frames(folder / "animation.gif")
            if count != frames:
                fail(f"{where}: animation.gif has {count} frames, expected {frames}")
        except (OSError, ValueError) as error:
            fail(f"{where}: animation.gif: {error}")
    if "lottie" in formats:
        try:
            lottie = json.loads((folder / "animation.json").read_text())
            if lottie["op"] - lottie["ip"] != frames or not lottie.get("layers"):
                fail(f"{where}: animation.json spans frames {lottie['ip']}..{lottie['op']} with "
                     f"{len(lottie.get('layers', []))} layers, expected {frames} frames")
        except (OSError, ValueError, KeyError) as error:
            fail(f"{where}: animation.json: {error!r}")
    stats = json.loads((folder / "stats.json").read_text())
    if len(stats.get("frames", [])) != frames:
        fail(f"{where}: stats.json measures {len(stats.get('frames', []))} frames, expected {frames}")
    for line in output.splitlines():
        if line.startswith("quality:"):
            check_quality_line(where, line)
    print(f"ok   {where}: {frames} frames as {','.join(formats)} in {folder.relative_to(work)}/")


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    animpak = pathlib.Path(sys.argv[1]).resolve()
    source = pathlib.Path(sys.argv[2])
    update = "--update-pictures" in sys.argv[3:]
    if shutil.which("ffmpeg") is None:
        if os.environ.get("CI") == "true":  # CI installs every tool: a skip there hides a missing install step
            print("CI=true, where nothing may skip: ffmpeg is not installed (scripts/install-deps.sh)")
            sys.exit(1)
        print("skipped: ffmpeg, which writes the GIF, is not installed (scripts/install-deps.sh)")
        sys.exit(77)
    doc = source / "docs/first-scene.md"
    text = doc.read_text()
    quoted = [line for line in text.splitlines() if line.startswith("quality:")]
    for line in quoted:
        check_quality_line("docs/first-scene.md", line)
    printed = set()
    blocks = steps(doc, text)
    if not any(kind == "run" for kind, _, _ in blocks) or not any(kind == "file" for kind, _, _ in blocks):
        sys.exit("docs/first-scene.md: no marked files or commands found")
    with tempfile.TemporaryDirectory(prefix="animpak-first-scene-") as scratch:
        work = pathlib.Path(scratch)
        for kind, name, body in blocks:
            if kind == "file":
                (work / name).write_text(body)
                print(f"ok   wrote {name}")
            elif kind == "picture":
                made = work / name
                shown = doc.parent / body
                if not made.exists():
                    fail(f"the document shows {body} as {name}, which the commands did not make")
                elif update:
                    shown.parent.mkdir(parents=True, exist_ok=True)
                    shutil.copyfile(made, shown)
                    print(f"ok   copied {name} to {shown.relative_to(source)}")
                elif not shown.exists():
                    fail(f"{body}, shown for {name}, is not in docs/ (--update-pictures)")
                elif png_size(made) != png_size(shown):
                    fail(f"{name} is {png_size(made)} px, the document's {body} {png_size(shown)}")
                else:
                    print(f"ok   {name} made, as shown ({body})")
            else:
                for command in body.splitlines():
                    if not command.strip() or command.lstrip().startswith("#"):
                        continue
                    run = re.sub(r"^animpak(?=\s|$)", shlex.quote(str(animpak)), command)
                    result = subprocess.run(["bash", "-c", run], cwd=work, capture_output=True, text=True)
                    if result.returncode != 0:
                        fail(f"`{command}` exited {result.returncode}:\n{result.stdout}{result.stderr}")
                        print(f"{len(failures)} failure(s)")
                        sys.exit(1)
                    print(f"ok   `{command}`")
                    printed.update(line.strip() for line in (result.stdout + result.stderr).splitlines())
                    check_outputs(work, command, result.stdout + result.stderr)
    for line in quoted:
        if line.strip() in printed:
            print(f"ok   the document's {line[:40]}... line is what the commands printed")
        else:
            said = [p for p in printed if p.startswith("quality:")]
            fail(f"docs/first-scene.md quotes {line!r}, which no command printed (they printed {said})")
    print(f"{len(failures)} failure(s)")
    sys.exit(1 if failures else 0)


main()
