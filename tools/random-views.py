#!/usr/bin/env python3
"""Measures methods on random views of both built-in scenes beyond the standard
configurations: each view a random eye, target, point light and animation time (the same
views for a given seed), rendered once per method with `lixel render --measure --json`;
prints, per scene, each method's mean and median mismatch, how many views it is more than
0.01 points worse than uniform on, and its worst such excess. Two renders run at a time.
Usage: random-views.py LIXEL [--seed N] [--views N] [--size WxH] [--methods LIST] [--worst N]
                       [--depth-precision P] [--against SPEC] [--scenes LIST] [--lights random|scene]
  LIXEL     the lixel binary (build/lixel)
  --depth-precision  as lixel render takes it (auto, highp, mediump, texture; default:
            lixel's own): mediump measures the fp16 path a Mali-400 takes
  --worst   also list, per scene and method, the N views it is furthest above uniform on,
            with the render options that give each view
  --against also count, per scene and method, the views it is above, at and below this
            method spec on (added to the methods when missing): two settings view by view
  --methods comma-separated method specs as lixel render --method takes them (default
            uniform,plane,plane/similar,plane/shared,plane/shared/similar); uniform is
            added first when missing, being the reference of the counts
  --scenes  comma-separated built-in scenes the views take in turn (default default,table)
  --lights  random (default: a random white point light in place of the scene's first
            light) or scene (the scene's own lights: a spotlight, a projector or two
            lights stay what they are, only the eye, target and time are random)"""
import argparse
import json
import os
import random
import statistics
import subprocess
import sys
import tempfile
from concurrent.futures import ThreadPoolExecutor


def views(seed, count, scenes=("default", "table")):
    """(scene, eye, at, light, time) per view, the scenes in turn (the same draws whatever
    the scenes: a seed's views over default and table are those it always gave)."""
    rnd = random.Random(seed)
    out = []
    for k in range(count):
        scene = scenes[k % len(scenes)]
        eye = (rnd.uniform(-5, 5), rnd.uniform(0.3, 5), rnd.uniform(-1, 6))
        at = (rnd.uniform(-1.5, 1.5), rnd.uniform(0, 1.2), rnd.uniform(-3, 1))
        light = (rnd.uniform(-6, 6), rnd.uniform(1.0, 7), rnd.uniform(-4, 6))
        out.append((scene, eye, at, light, rnd.uniform(0, 5)))
    return out


def triple(v):
    return "%g,%g,%g" % v


def main():
    ap = argparse.ArgumentParser(description="methods on random views (see the module text)")
    ap.add_argument("lixel")
    ap.add_argument("--seed", type=int, default=7)
    ap.add_argument("--views", type=int, default=200)
    ap.add_argument("--size", default="640x480")
    ap.add_argument("--methods", default="uniform,plane,plane/similar,plane/shared,plane/shared/similar")
    ap.add_argument("--worst", type=int, default=0)
    ap.add_argument("--depth-precision", choices=("auto", "highp", "mediump", "texture"))
    ap.add_argument("--against")
    ap.add_argument("--scenes", default="default,table")
    ap.add_argument("--lights", choices=("random", "scene"), default="random")
    a = ap.parse_args()
    scenes = [x for x in a.scenes.split(",") if x]
    if not scenes:
        ap.error("--scenes: expected a comma-separated list of built-in scenes")
    methods = [m for m in a.methods.split(",") if m]
    if "uniform" not in methods:
        methods.insert(0, "uniform")
    if a.against and a.against not in methods:
        methods.append(a.against)
    vs = views(a.seed, a.views, scenes)
    tmp = tempfile.mkdtemp(prefix="lixel-views-")
    env = dict(os.environ, LP_NUM_THREADS="1")

    def run(job):
        k, (scene, eye, at, light, t), method = job
        out = os.path.join(tmp, "%d-%s.png" % (k, method.replace("/", "-")))
        cmd = [a.lixel, "render", "--scene", scene, "--eye", triple(eye), "--at", triple(at)] + \
            (["--light", triple(light)] if a.lights == "random" else []) + ["--time", "%g" % t, "--method", method, "--size", a.size, "--frames", "1", "--measure", "--json",
               "--out", out] + (["--depth-precision", a.depth_precision] if a.depth_precision else [])
        r = subprocess.run(cmd, capture_output=True, text=True, env=env)
        if os.path.exists(out):
            os.remove(out)
        try:
            return json.loads(r.stdout)["mismatch_pct"]
        except (ValueError, KeyError):
            return None  # the camera degenerate, or bad input: the view is left out

    jobs = [(k, v, m) for k, v in enumerate(vs) for m in methods]
    with ThreadPoolExecutor(2) as ex:
        got = list(ex.map(run, jobs))
    os.rmdir(tmp)
    pct = {}
    for (k, _, m), p in zip(jobs, got):
        pct.setdefault(m, {})[k] = p
    print("random-views: seed %d, %d views, %s, `lixel render --measure%s`%s" %
          (a.seed, a.views, a.size, " --depth-precision " + a.depth_precision if a.depth_precision else "",
           ", the scenes' own lights" if a.lights == "scene" else ""))
    for scene in dict.fromkeys(scenes):
        ks = [k for k, v in enumerate(vs) if v[0] == scene and all(pct[m][k] is not None for m in methods)]
        print("%s scene: %d views" % (scene, len(ks)))
        if not ks:
            continue
        for m in methods:
            vals = [pct[m][k] for k in ks]
            over = [pct[m][k] - pct["uniform"][k] for k in ks]
            print("  %-22s mean %.4f%%  median %.4f%%  more than 0.01 points above uniform on %d  worst %+.4f" %
                  (m, statistics.mean(vals), statistics.median(vals), sum(d > 0.01 for d in over), max(over)))
        for m in [m for m in methods if a.against and m != a.against]:
            d = [pct[m][k] - pct[a.against][k] for k in ks]
            print("  %-22s against %s: above on %d (at most %+.4f points), the same on %d, below on %d" %
                  (m, a.against, sum(x > 0 for x in d), max(d), sum(x == 0 for x in d), sum(x < 0 for x in d)))
        for m in methods[1:] if a.worst > 0 else []:
            for k in sorted(ks, key=lambda k: pct["uniform"][k] - pct[m][k])[:a.worst]:
                _, eye, at, light, t = vs[k]
                lit = " --light " + triple(light) if a.lights == "random" else ""
                print("    %s view %d: %.4f%% against uniform's %.4f%%: --scene %s --eye %s --at %s%s --time %g" %
                      (m, k, pct[m][k], pct["uniform"][k], scene, triple(eye), triple(at), lit, t))
    return 0


if __name__ == "__main__":
    sys.exit(main())
