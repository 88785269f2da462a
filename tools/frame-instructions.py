#!/usr/bin/env python3
"""Counts the instructions one frame of `lixel render` executes, by thread and by whose
code, under valgrind's callgrind: a figure that does not move with the host's load (the
same to 0.01 million between runs), where frame times on a shared machine move by a
third. The same view is rendered with 10 and with 18 timed frames (after the 3 warm-up
frames), and the difference over 8 is one frame's mean count over a whole cycle of the
atlas's eight depth slots (one clear in eight frames), start-up, shader compiles and the
reference left out (Mesa's shader cache is disabled, so both runs compile the same
shaders, a variant first needed at the first slots' clear included). LP_NUM_THREADS=1, as the bench:
the application's thread builds and sends the draws (and, while the GL draws, the next
frame's set-up); llvmpipe's rasterizer thread draws them. Instructions are not time (a
cache miss or a wide vector costs more than one), but two methods' counts on one view,
taken the same way, say which does more work and where: on the facing view at 1024x1024
they give plane-optimal's frame about 7% more than uniform's, as the bench's timed ratio
does on a quiet day (docs/results.md, "Instructions, not time").
With --sending (before the render options) two more runs count only what the application
does inside lx_renderer_shadow_passes and lx_renderer_main_pass, the sending of the draws
(the GL's vertex work, triangle set-up and binning, state changes): on one llvmpipe thread
the rasterizer starts a pass only once it is sent, so that part lies on the frame's path,
where the planning made while the GL draws does not (docs/results.md, "A quiet day's
rounds, and what facing's frame waits for").
Usage: frame-instructions.py [--sending] LIXEL [RENDER OPTIONS...]
  e.g. tools/frame-instructions.py build/lixel --config facing --method plane --size 1024x1024
Needs valgrind; takes one to two minutes a view at 1024x1024, twice that with --sending."""
import collections
import os
import re
import shutil
import subprocess
import sys
import tempfile

FIRST, SPAN = 10, 8  # timed frames of the two runs: SPAN a whole cycle of depth slots
KINDS = ("lixel", "GL in C", "shader JIT", "LLVM compile", "libc, other")
SENDING = ("lx_renderer_shadow_passes", "lx_renderer_main_pass")  # the passes' draws sent


def kind(name):
    """Whose code a callgrind_annotate function line names, by its object file."""
    obj = re.search(r"\[([^\]]*)\]\s*$", name)
    obj = os.path.basename(obj.group(1)) if obj else ""
    if obj == "???" or (not obj and name.startswith("???:0x")):
        return "shader JIT"  # code llvmpipe generated at run time: no object file
    if "LLVM" in obj or "llvm::" in name:
        return "LLVM compile"
    if "OSMesa" in obj or "gallium" in obj or "_dri" in obj or "GL" in obj or "glapi" in obj:
        return "GL in C"
    if obj.startswith("lixel") or "/src/" in name or name.startswith("src/"):  # a lixel built here: paths relative
        return "lixel"
    return "libc, other"


def work(d):
    """A thread's instructions but the shader compiler's."""
    return sum(v for k, v in d.items() if k != "LLVM compile")


def counts(path):
    """Instructions of one thread's callgrind file, by kind."""
    out = subprocess.run(["callgrind_annotate", "--inclusive=no", "--threshold=100", "--auto=no", path],
                         capture_output=True, text=True, check=True).stdout
    c = collections.Counter()
    for line in out.splitlines():
        m = re.match(r"\s*([\d,]+)\s+\([^)]*\)\s+(\S.*)$", line)
        if m and "PROGRAM TOTALS" not in line:
            c[kind(m.group(2))] += int(m.group(1).replace(",", ""))
    return c


def run(lixel, args, frames, tmp, only=()):
    """Thread number -> its counts by kind, for `lixel render ARGS --frames FRAMES`; with
    `only`, of what runs inside those functions alone."""
    tag = "cg-%s%d" % ("sending-" if only else "", frames)
    out = os.path.join(tmp, tag)
    env = dict(os.environ, LP_NUM_THREADS="1", MESA_SHADER_CACHE_DISABLE="true")
    cmd = ["valgrind", "--tool=callgrind", "--smc-check=all", "--separate-threads=yes",
           "--callgrind-out-file=" + out] + ["--toggle-collect=" + f for f in only] + \
          [lixel, "render"] + args + ["--frames", str(frames), "--out", os.path.join(tmp, "frame.png")]
    r = subprocess.run(cmd, capture_output=True, text=True, env=env)
    if r.returncode != 0:  # lixel's own message, without valgrind's lines
        sys.stderr.write("".join(l + "\n" for l in r.stderr.splitlines() if not l.startswith("==")))
        sys.stderr.write("frame-instructions: lixel render failed (exit status %d)\n" % r.returncode)
        sys.exit(r.returncode)
    threads = {}
    for name in os.listdir(tmp):
        m = re.fullmatch(re.escape(tag) + r"-(\d+)", name)
        if m:
            threads[int(m.group(1))] = counts(os.path.join(tmp, name))
    return threads


def per_frame(a, b, t):
    """Thread t's millions of instructions a frame by kind: runs a (FIRST frames) and b
    (FIRST + SPAN) apart, over SPAN."""
    return {k: (b.get(t, {}).get(k, 0) - a.get(t, {}).get(k, 0)) / (SPAN * 1e6) for k in KINDS}


def row(name, d):
    print("%-26s %10.2f" % (name, work(d)) + "".join(" %12.2f" % d[k] for k in KINDS))


def main():
    argv = sys.argv[1:]
    sending = bool(argv) and argv[0] == "--sending"
    argv = argv[1:] if sending else argv
    if not argv or argv[0] in ("-h", "--help"):
        print(__doc__)
        return 0 if argv else 2
    if any(a in ("--frames", "--out") for a in argv[1:]):
        sys.stderr.write("frame-instructions: --frames and --out are the tool's own; expected the other render options\n")
        return 2
    if not shutil.which("valgrind") or not shutil.which("callgrind_annotate"):
        sys.exit("frame-instructions: valgrind (its callgrind) is needed: apt-get install valgrind")
    lixel, args = argv[0], argv[1:]
    tmp = tempfile.mkdtemp(prefix="lixel-instructions-")
    try:
        a, b = run(lixel, args, FIRST, tmp), run(lixel, args, FIRST + SPAN, tmp)
        if sending:
            sa, sb = run(lixel, args, FIRST, tmp, SENDING), run(lixel, args, FIRST + SPAN, tmp, SENDING)
    finally:
        shutil.rmtree(tmp)
    print("frame-instructions: lixel render %s: instructions a frame, millions ((%d frames - %d frames) / %d)"
          % (" ".join(args), FIRST + SPAN, FIRST, SPAN))
    print("(all: every kind but LLVM compile, whose few tenths of a million either way are the compiler's own\n"
          " variation between the two runs, not the frames' work)")
    print("%-26s %10s" % ("thread", "all") + "".join(" %12s" % k for k in KINDS))
    total = collections.Counter()
    for t in sorted(set(a) | set(b)):
        d = per_frame(a, b, t)
        if all(abs(v) < 0.005 for v in d.values()):
            continue  # a thread that did nothing in the frames (Mesa's queue threads)
        total.update(d)
        row("application (thread 1)" if t == 1 else "GL (thread %d)" % t, d)
    row("all", total)
    if sending:
        row("application, sending", per_frame(sa, sb, 1))
        print("(application, sending: its instructions inside %s, which the rasterizer waits for)" % " and ".join(SENDING))
    return 0


if __name__ == "__main__":
    sys.exit(main())
