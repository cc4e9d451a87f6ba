#!/usr/bin/env python3
"""Runs `cordgrasp hand init` on the URDF of every shipped hand description (assets/hands) and
tables the angle between the drafted and the shipped palm normal, whether the draft's own checks
hold and the palm normal guess's confidence (standard library only).

    python3 tools/hand_init_vs_shipped.py --cordgrasp build/tools/cordgrasp --out /tmp/drafts

Hands whose URDF is missing (../shared/data not staged) are listed as such.
"""
import argparse
import glob
import os
import re
import subprocess
import sys

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from hand_zoo_report import angle_deg  # noqa: E402

ASSETS = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "assets", "hands")


def palm_normal(yaml_text):
    """(link, axis) of a description's one-line palm_normal mapping, or None."""
    m = re.search(r'^palm_normal:\s*\{link:\s*"?([^",]*)"?,\s*axis:\s*\[([^\]]*)\]', yaml_text,
                  re.M)
    return (m.group(1), [float(x) for x in m.group(2).split(",")]) if m else None


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--cordgrasp", default="cordgrasp", help="the cordgrasp executable")
    ap.add_argument("--out", required=True, help="folder for the drafts (created)")
    args = ap.parse_args()
    os.makedirs(args.out, exist_ok=True)
    print("| hand | shipped | drafted | angle [°] | checks pass | normal confidence |")
    print("|---|---|---|---|---|---|")
    for path in sorted(glob.glob(os.path.join(ASSETS, "*.yaml")) +
                       glob.glob(os.path.join(ASSETS, "*", "*.yaml"))):
        with open(path) as f:
            text = f.read()
        name = os.path.splitext(os.path.basename(path))[0]
        m = re.search(r'^urdf:\s*"?([^"\n]*)"?', text, re.M)
        shipped = palm_normal(text)
        if not m or not shipped:
            continue
        urdf = os.path.normpath(os.path.join(os.path.dirname(path), m.group(1)))
        if not os.path.exists(urdf):
            print("| %s | URDF missing: %s | | | | |" % (name, urdf))
            continue
        draft = os.path.join(args.out, name + ".yaml")
        run = subprocess.run([args.cordgrasp, "hand", "init", "--urdf", urdf, "--out", draft],
                             capture_output=True, text=True)
        if run.returncode != 0:
            print("| %s | hand init failed: %s | | | | |" % (name, run.stderr.strip()))
            continue
        with open(draft) as f:
            drafted = palm_normal(f.read())
        angle = angle_deg(shipped[1], drafted[1]) if drafted[0] == shipped[0] else float("nan")
        conf = re.search(r"guess palm normal:.*\(confidence ([0-9.]+)", run.stdout)
        print("| %s | `%s` %s | [%s] | %.1f | %s | %s |" % (
            name, shipped[0], shipped[1], ", ".join("%.3f" % x for x in drafted[1]), angle,
            "yes" if "checks: every convention holds" in run.stdout else "no",
            conf.group(1) if conf else "?"))


if __name__ == "__main__":
    main()
