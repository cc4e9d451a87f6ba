#!/usr/bin/env python3
"""Compares two runs of the same commands with the same seeds, timings aside.

    tools/compare_runs.py A B

A and B hold *.plan.json files and bench/results.csv (tools/determinism_run.sh writes them).
Prints, per file, whether the two agree once wall-clock fields are dropped (plan.json: every
"*_s" field of "stats" and each grasp's "timings_s"; results.csv: the *_s time columns);
exits 1 if any differs."""
import csv, glob, json, os, sys
TIMING_CSV = {"first_fc_s", "exploration_s", "finger_s", "quality_s", "total_s", "sim_wall_s",
              "validated_first_accepted_cpu_s", "validated_cpu_s"}
def strip(x, key=""):
    if isinstance(x, dict):
        return {k: strip(v, k) for k, v in x.items()
                if k != "timings_s" and not (key == "stats" and k.endswith("_s"))}
    if isinstance(x, list):
        return [strip(v, key) for v in x]
    return x
a, b = sys.argv[1:3]
ok = True
for f in sorted(glob.glob(f"{a}/*.plan.json")):
    name = os.path.basename(f)
    ja, jb = (json.load(open(p)) for p in (f, f"{b}/{name}"))
    same = strip(ja) == strip(jb)
    raw = open(f, "rb").read() == open(f"{b}/{name}", "rb").read()
    print(f"{name}: {'identical' if same else 'DIFFERENT'} timings aside "
          f"(byte-identical with timings: {raw}); grasps {len(ja['grasps'])}")
    ok &= same
ra, rb = (list(csv.DictReader(open(f"{d}/bench/results.csv"))) for d in (a, b))
cols = [c for c in ra[0] if c not in TIMING_CSV]
diff = [(i, c) for i, (x, y) in enumerate(zip(ra, rb)) for c in cols if x[c] != y[c]]
print(f"results.csv: {len(ra)} / {len(rb)} rows, {len(cols)} columns compared, "
      f"{len(diff)} differing cells {diff[:5]}")
ok &= not diff and len(ra) == len(rb)
sys.exit(0 if ok else 1)
