#!/usr/bin/env python3
"""Writes the tables of one section of docs/results.md from a run of lixel bench: its
text output (the summary) and its --csv rows. The section is the part of the document
from its "## " heading to the next "## " heading; in it, the first table is the summary
and the tables after the headings "### Mismatch", "### Plane maps", "### Frame time" and
"### Shadow passes" are the per-configuration ones. Only the table lines change.
Usage: results-tables.py DOC.md "## Default scene, 1024x1024" BENCH.txt BENCH.csv"""
import csv
import sys


def summary_rows(text_path):
    """The summary block of the text output: a row per run, split on spaces."""
    rows, inside = [], False
    for line in open(text_path):
        if line.startswith("method "):
            inside = True
            continue
        if inside:
            if not line.strip() or line.startswith("("):
                break
            f = line.split()
            # name, frame, (min-max), /none, /uniform, shadow, main, lookups, setup,
            # setup again, mismatch, worst, -uniform, soft, two plane columns
            rows.append(f)
    return rows


def summary_table(rows, planes):
    head = ("| method | frame ms, median (min-max) | / none | / uniform | shadow passes ms | main pass ms | "
            "lookups % | set-up us | set-up again at once us | mismatch %, median | worst % | "
            f"most above uniform (points) | worst m_max {planes[0]} | {planes[1]} |")
    out = [head, "|" + "---|" * 14]
    for f in rows:
        out.append("| " + " | ".join([f[0], f"{f[1]} {f[2]}"] + f[3:13] + f[-2:]) + " |")
    return out


def per_config(rows, methods, configs, cell):
    out = ["| configuration | " + " | ".join(methods) + " |", "|" + "---|" * (len(methods) + 1)]
    for c in configs:
        out.append("| " + c + " | " + " | ".join(cell(rows[(m, c)]) for m in methods) + " |")
    return out


def lpp_cell(r, plane):
    lpp, used = r.get("lpp_" + plane, ""), r.get("lixels_used_" + plane, "")
    if not lpp:
        return "-"
    return f"{float(lpp):.3g} / {int(float(used))}"


def plane_table(rows, configs, planes):
    cols = [(m, p) for m in ("plane", "plane/square") for p in planes]
    out = ["| configuration | " + " | ".join(f"{m} {p} lpp / lixels used" for m, p in cols) + " |",
           "|" + "---|" * (len(cols) + 1)]
    for c in configs:
        out.append("| " + c + " | " + " | ".join(lpp_cell(rows[(m, c)], p) for m, p in cols) + " |")
    return out


def replace_table(lines, start, end, new):
    """The first table at or after line start (before end) replaced by new."""
    i = start
    while i < end and not lines[i].startswith("|"):
        i += 1
    if i == end:
        sys.exit(f"results-tables: no table after line {start + 1}")
    j = i
    while j < end and lines[j].startswith("|"):
        j += 1
    lines[i:j] = new
    return i + len(new)


def main():
    if len(sys.argv) != 5:
        sys.exit(__doc__.strip().splitlines()[-1])
    doc, section, text_path, csv_path = sys.argv[1:]
    rows, methods, configs = {}, [], []
    for r in csv.DictReader(open(csv_path)):
        name = r["method"] if r.get("filter", "none") == "none" else r["method"] + "+" + r["filter"]
        rows[(name, r["config"])] = r
        if name not in methods:
            methods.append(name)
        if r["config"] not in configs:
            configs.append(r["config"])
    planes = [k[len("lpp_"):] for k in next(iter(rows.values())) if k.startswith("lpp_")]
    lines = open(doc).read().split("\n")
    try:
        s = lines.index(section)
    except ValueError:
        sys.exit(f"results-tables: {doc} has no line '{section}'")
    e = next((k for k in range(s + 1, len(lines)) if lines[k].startswith("## ")), len(lines))
    n0 = len(lines)
    replace_table(lines, s, e, summary_table(summary_rows(text_path), planes))
    e += len(lines) - n0
    tables = {
        "### Mismatch": per_config(rows, methods, configs, lambda r: f"{float(r['mismatch_pct']):.4f}"),
        "### Plane maps": plane_table(rows, configs, planes),
        "### Frame time": per_config(rows, methods, configs, lambda r: f"{float(r['frame_ms_median']):.2f}"),
        "### Shadow passes": per_config(
            rows, ["none", "uniform", "plane"], configs,
            lambda r: f"{float(r['shadow_ms_median']):.2f} + {float(r['main_ms_median']):.2f} "
                      f"({float(r['lookup_pct']):.1f}%)"),
    }
    for head, new in tables.items():
        k = next((k for k in range(s, e) if lines[k].startswith(head)), None)
        if k is None:
            sys.exit(f"results-tables: section '{section}' has no '{head}' heading")
        n0 = len(lines)
        replace_table(lines, k, e, new)
        e += len(lines) - n0
    open(doc, "w").write("\n".join(lines))


main()
