#!/usr/bin/env python3
"""Runs `cordgrasp hand init` on every hand of a zoo (tools/make_hand_zoo.py) and tables, per
layout, how many drafts pass their own checks and how far the drafted palm normal lies from
the true one (standard library only).

    python3 tools/make_hand_zoo.py --out /tmp/zoo --count 30 --seed 1
    python3 tools/hand_zoo_report.py --cordgrasp build/tools/cordgrasp /tmp/zoo
"""
import argparse
import glob
import json
import math
import os
import re
import subprocess
import sys


def drafted_normal(yaml_text):
    """The palm_normal axis of a hand description written by `hand init` (its own one-line
    flow mapping)."""
    m = re.search(r"^palm_normal:\s*\{[^}]*axis:\s*\[([^\]]*)\]", yaml_text, re.M)
    return [float(x) for x in m.group(1).split(",")] if m else None


def angle_deg(a, b):
    na, nb = math.sqrt(sum(x * x for x in a)), math.sqrt(sum(x * x for x in b))
    c = sum(x * y for x, y in zip(a, b)) / (na * nb)
    return math.degrees(math.acos(max(-1.0, min(1.0, c))))


def draft_zoo(zoo, cordgrasp):
    """`hand init` on every hand of `zoo`: one dict per hand (layout, hand, digits, returncode,
    passed: its own checks hold, error_deg: drafted vs true palm normal, failed: the check
    lines)."""
    rows = []
    for truth_path in sorted(glob.glob(os.path.join(zoo, "*", "truth.json"))):
        folder = os.path.dirname(truth_path)
        with open(truth_path) as f:
            truth = json.load(f)
        urdf = os.path.join(folder, truth["hand"] + ".urdf")
        draft = os.path.join(folder, "draft.yaml")
        run = subprocess.run([cordgrasp, "hand", "init", "--urdf", urdf, "--out", draft],
                             capture_output=True, text=True)
        normal = None
        if run.returncode == 0 and os.path.exists(draft):
            with open(draft) as f:
                normal = drafted_normal(f.read())
        rows.append({"layout": truth["layout"], "hand": truth["hand"], "digits": truth["digits"],
                     "returncode": run.returncode, "output": run.stdout + run.stderr,
                     "passed": run.returncode == 0 and
                     "checks: every convention holds" in run.stdout,
                     "error_deg": angle_deg(normal, truth["palm_normal"]) if normal
                     else float("nan"),
                     "failed": [line.strip() for line in run.stdout.splitlines()
                                if "check failed" in line]})
    return rows


def table(rows, within_deg):
    """Markdown: one row per hand, then one per layout."""
    out = ["| hand | layout | digits | checks pass | palm normal error [°] |", "|---|---|---|---|---|"]
    for r in rows:
        out.append("| %s | %s | %d | %s | %.1f |" % (r["hand"], r["layout"], r["digits"],
                                                     "yes" if r["passed"] else "no",
                                                     r["error_deg"]))
    out += ["", "| layout | hands | checks pass | normal within %g° | median error [°] |"
            % within_deg, "|---|---|---|---|---|"]
    for layout in sorted({r["layout"] for r in rows}) + ["all"]:
        sel = [r for r in rows if layout in ("all", r["layout"])]
        errs = sorted(r["error_deg"] for r in sel if not math.isnan(r["error_deg"]))
        med = errs[len(errs) // 2] if errs else float("nan")
        out.append("| %s | %d | %d | %d | %.1f |" % (
            layout, len(sel), sum(r["passed"] for r in sel),
            sum(1 for r in sel if r["error_deg"] <= within_deg), med))
    return "\n".join(out)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("zoo", help="folder written by tools/make_hand_zoo.py")
    ap.add_argument("--cordgrasp", default="cordgrasp", help="the cordgrasp executable")
    ap.add_argument("--within-deg", type=float, default=10.0,
                    help="a palm normal this close to the truth counts as right (default 10)")
    args = ap.parse_args()
    rows = draft_zoo(args.zoo, args.cordgrasp)
    if not rows:
        sys.exit("hand_zoo_report: no */truth.json under '%s'" % args.zoo)
    print(table(rows, args.within_deg))


if __name__ == "__main__":
    main()
