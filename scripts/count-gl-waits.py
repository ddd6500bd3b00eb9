#!/usr/bin/env python3
"""Counts, per frame of an apitrace dump, the GL calls that make the CPU wait for the GPU, and
the dispatches, draws and barriers (docs/gpu.md, "A frame that never waits").

    apitrace dump --color=never view.trace | scripts/count-gl-waits.py --warmup 3 --assert-no-waits

Frames end at each glXSwapBuffers / eglSwapBuffers. Steady-state frames are the complete frames
after the first `--warmup` (the calls after the last swap, the teardown and the outputs written
at exit, are not a frame). A call waits for the GPU when the driver must finish GPU work before
it returns:
  glGetQueryObject*  with GL_QUERY_RESULT (GL_QUERY_RESULT_AVAILABLE and _NO_WAIT do not wait);
  glGet(Named)BufferSubData, glMap(Named)Buffer(Range) (lfd maps only at setup: any map in a
    frame counts);
  glReadPixels, glReadnPixels, glGet(n)TexImage, glGetTexture(Sub)Image, glGetCompressed* into
    client memory (no GL_PIXEL_PACK_BUFFER bound: into a pixel buffer they are GPU copies);
  glFinish; glClientWaitSync with a timeout other than 0.
Prints a table (median, min and max per steady frame) and exits 1 with --assert-no-waits when a
steady frame has a waiting call (each is printed), 2 on input without frames."""
import argparse
import re
import statistics
import sys

CALL = re.compile(r"^(\d+) (\w+)\((.*)\)")
PIXEL_READS = ("glReadPixels", "glReadnPixels", "glGetTexImage", "glGetnTexImage", "glGetTextureImage",
               "glGetTextureSubImage", "glGetCompressedTexImage", "glGetCompressedTextureImage",
               "glGetCompressedTextureSubImage", "glGetnCompressedTexImage")
BUFFER_READS = ("glGetBufferSubData", "glGetNamedBufferSubData", "glMapBuffer", "glMapBufferRange",
                "glMapNamedBuffer", "glMapNamedBufferRange")
SWAPS = ("glXSwapBuffers", "eglSwapBuffers")


def argument(args, name):
    m = re.search(r"\b" + name + r" = ([^,)]+)", args)
    return m.group(1).strip() if m else None


class Frame:
    def __init__(self):
        self.waits = []  # the dump lines of waiting calls
        self.counts = {"dispatches": 0, "draws": 0, "barriers": 0, "uniform look-ups": 0,
                       "framebuffers made": 0, "calls": 0}


def classify(name, args, pack_buffer, frame):
    """Counts one call into `frame`; returns True when it waits for the GPU."""
    c = frame.counts
    c["calls"] += 1
    if name.startswith("glDispatchCompute"):
        c["dispatches"] += 1
    elif name.startswith("glDraw") or name.startswith("glMultiDraw"):
        c["draws"] += 1
    elif name in ("glMemoryBarrier", "glMemoryBarrierByRegion", "glTextureBarrier"):
        c["barriers"] += 1
    elif name == "glGetUniformLocation":
        c["uniform look-ups"] += 1
    elif name in ("glCreateFramebuffers", "glGenFramebuffers"):
        c["framebuffers made"] += 1
    if name.startswith("glGetQueryObject") or name.startswith("glGetQueryBufferObject"):
        return argument(args, "pname") == "GL_QUERY_RESULT" and name.startswith("glGetQueryObject")
    if name in BUFFER_READS or name == "glFinish":
        return True
    if name in PIXEL_READS:
        return pack_buffer == 0
    if name == "glClientWaitSync":
        timeout = argument(args, "timeout")
        return timeout is None or int(timeout, 0) != 0
    return False


def parse(lines):
    frames = [Frame()]
    pack_buffer = 0
    for line in lines:
        m = CALL.match(line)
        if not m:
            continue
        number, name, args = m.groups()
        if name == "glBindBuffer" and argument(args, "target") == "GL_PIXEL_PACK_BUFFER":
            pack_buffer = int(argument(args, "buffer") or 0)
        if classify(name, args, pack_buffer, frames[-1]):
            frames[-1].waits.append(line.rstrip())
        if name in SWAPS:
            frames.append(Frame())
    return frames[:-1]  # the calls after the last swap are no frame


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("dump", nargs="?", help="the output of `apitrace dump --color=never` (default: stdin)")
    parser.add_argument("--warmup", type=int, default=3, help="frames left out at the start")
    parser.add_argument("--label", default="", help="a name printed with the table")
    parser.add_argument("--assert-no-waits", action="store_true", help="exit 1 if a steady frame waits")
    a = parser.parse_args()
    lines = open(a.dump, encoding="utf-8", errors="replace") if a.dump else sys.stdin
    frames = parse(lines)
    steady = frames[a.warmup:]
    if not steady:
        print(f"count-gl-waits: {len(frames)} frames in the trace, none after the {a.warmup} of warm-up",
              file=sys.stderr)
        return 2
    print(f"{a.label}: {len(steady)} steady frames (after {a.warmup} of warm-up); per frame median [min, max]")
    rows = [("GPU waits", [len(f.waits) for f in steady])]
    rows += [(k, [f.counts[k] for f in steady]) for k in steady[0].counts]
    for name, values in rows:
        print(f"  {name:18s} {statistics.median(values):8g}  [{min(values)}, {max(values)}]")
    waiting = [(i + a.warmup, w) for i, f in enumerate(steady) for w in f.waits]
    for frame, line in waiting[:20]:
        print(f"  frame {frame} waits: {line}")
    if a.assert_no_waits and waiting:
        print(f"count-gl-waits: {len(waiting)} calls wait for the GPU in steady frames", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
