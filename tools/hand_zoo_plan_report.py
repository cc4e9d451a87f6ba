#!/usr/bin/env python3
"""Drafts every hand of a zoo (tools/make_hand_zoo.py) with `cordgrasp hand init`, plans one
grasp per (hand, object) pair with the drafted description and tables, per layout and object,
the pairs where the planner found force closure (standard library only).

    python3 tools/make_hand_zoo.py --out /tmp/zoo --count 30 --seed 1
    python3 tools/hand_zoo_plan_report.py --cordgrasp build/tools/cordgrasp /tmp/zoo

Each pair runs `cordgrasp plan --hand DRAFT --object OBJ --grasps 1 --seed SEED --settings S`,
S setting `time_limit_s`; the plan, its log and the settings are written into each hand's
folder. Deterministic for a zoo, a seed and a build.
"""
import argparse
import json
import os
import subprocess
import sys

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import hand_zoo_report  # noqa: E402

OBJECTS = ("box", "long_cylinder", "sphere", "bottle", "mug")


def plan_zoo(zoo, cordgrasp, objects, seed, time_limit_s):
    """Drafts the zoo (hand_zoo_report.draft_zoo), then plans each hand × object: one dict per
    hand (the draft's row) with `fc`: object -> force closure found (bool)."""
    rows = hand_zoo_report.draft_zoo(zoo, cordgrasp)
    settings = os.path.join(zoo, "plan_settings.yaml")
    with open(settings, "w") as f:
        f.write("time_limit_s: %g\n" % time_limit_s)
    for r in rows:
        folder = os.path.join(zoo, r["hand"])
        draft = os.path.join(folder, "draft.yaml")
        r["fc"] = {}
        for obj in objects:
            out = os.path.join(folder, "plan_%s.json" % obj)
            if os.path.exists(out):
                os.remove(out)
            found = False
            if r["returncode"] == 0:
                run = subprocess.run([cordgrasp, "plan", "--hand", draft, "--object", obj,
                                      "--grasps", "1", "--seed", str(seed), "--settings",
                                      settings, "--out", out, "--quiet"],
                                     capture_output=True, text=True)
                with open(os.path.join(folder, "plan_%s.log" % obj), "w") as f:
                    f.write(run.stdout + run.stderr)
                if os.path.exists(out):
                    with open(out) as f:
                        found = len(json.load(f).get("grasps", [])) > 0
            r["fc"][obj] = found
    return rows


def table(rows, objects):
    """Markdown: one row per hand (x = force closure found), then per layout and object the
    pairs with force closure."""
    out = ["| hand | layout | checks pass | " + " | ".join(objects) + " |",
           "|---|---|---|" + "---|" * len(objects)]
    for r in rows:
        out.append("| %s | %s | %s | %s |" % (r["hand"], r["layout"],
                                              "yes" if r["passed"] else "no",
                                              " | ".join("x" if r["fc"][o] else "."
                                                         for o in objects)))
    out += ["", "| layout | hands | " + " | ".join(objects) +
            " | pairs with force closure | hands with ≥ 1 |",
            "|---|---|" + "---|" * (len(objects) + 2)]
    for layout in sorted({r["layout"] for r in rows}) + ["all"]:
        sel = [r for r in rows if layout in ("all", r["layout"])]
        pairs = sum(r["fc"][o] for r in sel for o in objects)
        out.append("| %s | %d | %s | %d of %d (%.0f %%) | %d |" % (
            layout, len(sel), " | ".join(str(sum(r["fc"][o] for r in sel)) for o in objects),
            pairs, len(sel) * len(objects), 100.0 * pairs / max(1, len(sel) * len(objects)),
            sum(1 for r in sel if any(r["fc"].values()))))
    return "\n".join(out)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("zoo", help="folder written by tools/make_hand_zoo.py")
    ap.add_argument("--cordgrasp", default="cordgrasp", help="the cordgrasp executable")
    ap.add_argument("--objects", default=",".join(OBJECTS),
                    help="shipped objects, comma-separated (default %s)" % ",".join(OBJECTS))
    ap.add_argument("--seed", type=int, default=1, help="the planner's seed (default 1)")
    ap.add_argument("--time-limit-s", type=float, default=10.0,
                    help="the planner's time_limit_s per pair (default 10)")
    ap.add_argument("--json", help="also write the rows (hand, layout, checks, fc) here")
    args = ap.parse_args()
    objects = [o for o in args.objects.split(",") if o]
    rows = plan_zoo(args.zoo, args.cordgrasp, objects, args.seed, args.time_limit_s)
    if not rows:
        sys.exit("hand_zoo_plan_report: no */truth.json under '%s'" % args.zoo)
    if args.json:
        with open(args.json, "w") as f:
            json.dump([{k: r[k] for k in ("hand", "layout", "passed", "error_deg", "fc")}
                       for r in rows], f, indent=1)
    print(table(rows, objects))


if __name__ == "__main__":
    main()
