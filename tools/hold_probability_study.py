#!/usr/bin/env python3
"""What P(held) buys (issue 41): does a grasp's P(held) under realistic uncertainty predict
holding under a harsher uncertainty draw, and holding in MuJoCo, better than the planner's
epsilon and the nudged 2-of-3?

  tools/hold_probability_study.py run   --out DIR --hands H1,H2 OBJECT...
  tools/hold_probability_study.py table --out DIR [--csv FILE]
  tools/hold_probability_study.py revalidate --out DIR [--budget-s S] OBJECT...

`revalidate` (the issue's re-validation check): per object
`plan --grasps 3 --validate --uncertainty realistic` (settings: validation.budget_s), then
`validate --tests lift,shake --uncertainty realistic --seed 2 --trials 20` of that plan, and
prints each accepted grasp's P(held) with the other seed and their average.

`run` plans --grasps grasps per (hand, object) with plain `cordgrasp plan` (--seed), then per
plan runs, one process at a time, each step only if its output file does not exist yet (so a
stopped run resumes where it stopped; a failed step leaves a .failed marker and is skipped):

  default   validate --tests lift,shake                                    (as planned, once)
  nudged    validate --tests lift,shake --trials 3                         (the default nudges)
  p_held    validate --tests lift,shake --uncertainty realistic --trials 20 --seed 1
  harsh     validate --tests lift,shake --uncertainty HARSH --min-hold-probability 0.5
                     --trials HARSH_DRAWS --seed 2                         (ground truth 1)
  mujoco    export --format mjcf, then cordgrasp-mujoco-check              (ground truth 2)

Every validate gets --physics DIR/physics.json (the HACD decomposition cache only). The CPU
time of each process (user + system, from getrusage of the children) is recorded in
DIR/HAND/OBJECT.cpu.json. `table` (also printed at the end of `run`) writes the CSV, one row per
grasp, and prints per hand and overall the ROC AUC of each predictor for each label.

AUC is the Mann-Whitney statistic: over all (positive, negative) pairs of grasps the fraction
where the predictor ranks the positive higher, ties counted half (no scipy / sklearn). The 95 %
interval is a percentile bootstrap that resamples (hand, object) groups, since grasps of one
object are not independent.

Labels: harsh_label = the grasp held in >= 50 % of its harsher draws (the sequential test at
0.5 stops once the Wilson 95 % interval excludes 0.5, from 5 draws on or sooner where a fifth
cannot change that, else after HARSH_DRAWS);
mujoco_label = MuJoCo's verdict (held) on the grasp as planned.
Predictors: p_held (P(held), realistic, seed 1), eps (plan.json epsilon), nudged2of3 (held in
>= 2 of the 3 nudged trials, a 0/1 score), nudged_count (held of 3 as the score), as_planned
(the default validate's held, 0/1).
"""
import argparse
import csv
import json
import os
import random
import resource
import subprocess
import sys
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
CG = os.environ.get("CORDGRASP", os.path.join(ROOT, "build/tools/cordgrasp"))
MJ = os.environ.get("MUJOCO_CHECK",
                    os.path.join(ROOT, "build/tools/mujoco_check/cordgrasp-mujoco-check"))

# Twice the realistic sigmas of the pose and the centre of mass; spreads of mu, mass and grip
# raised from 20 / 30 / 20 % to 35 / 50 / 30 % (uniform spreads cannot double without reaching
# near-zero friction or mass). docs/notes/2026-12-05-hold-probability-auc.md.
HARSH = {
    "hand_offset_sigma_m": 0.004,
    "hand_turn_sigma_rad": 0.06981317007977318,  # 4 deg
    "mu_relative_spread": 0.35,
    "mass_relative_spread": 0.5,
    "com_offset_sigma_m": 0.006,
    "squeeze_relative_spread": 0.3,
}


def children_cpu():
    r = resource.getrusage(resource.RUSAGE_CHILDREN)
    return r.ru_utime + r.ru_stime


def run_step(cmd, out, timeout, log, done_marker=None):
    """Runs cmd (writing to tmp_name(out), renamed to out on success; or, with done_marker,
    writing out itself and then the marker) unless out (the marker) or out.failed exists.
    Returns the CPU seconds of the process, or None if skipped or failed."""
    if os.path.exists(done_marker or out) or os.path.exists(out + ".failed"):
        return None
    c0 = children_cpu()
    t0 = time.time()
    try:
        p = subprocess.run(["nice", "-n", "10"] + cmd, stdout=subprocess.PIPE,
                           stderr=subprocess.STDOUT, timeout=timeout, text=True)
        rc = p.returncode
        text = p.stdout
    except subprocess.TimeoutExpired as e:
        rc = "timeout"
        text = (e.stdout or b"").decode(errors="replace") if isinstance(e.stdout, bytes) \
            else (e.stdout or "")
    cpu = children_cpu() - c0
    with open(log, "a") as f:
        f.write("$ %s\n%s\n[rc %s, cpu %.2f s, wall %.2f s]\n\n" %
                (" ".join(cmd), text, rc, cpu, time.time() - t0))
    if done_marker:
        if rc != 0:
            open(out + ".failed", "w").write("rc %s\n" % rc)
            return None
        open(done_marker, "w").write("done\n")
        return cpu
    tmp = tmp_name(out)
    if rc != 0 or not os.path.exists(tmp):
        open(out + ".failed", "w").write("rc %s\n" % rc)
        if os.path.exists(tmp):
            os.remove(tmp)
        return None
    os.replace(tmp, out)
    return cpu


def tmp_name(out):
    d, b = os.path.split(out)
    return os.path.join(d, "tmp." + b)


def object_name(path):
    if os.path.sep not in path and not path.endswith(".obj"):
        return path  # a shipped object name
    return os.path.basename(os.path.dirname(os.path.abspath(path))) + "_" + \
        os.path.splitext(os.path.basename(path))[0]


def cmd_run(a):
    os.makedirs(a.out, exist_ok=True)
    physics = os.path.join(a.out, "physics.json")
    os.makedirs(os.path.join(a.out, "hacd"), exist_ok=True)
    os.makedirs(os.path.join(a.out, "mjcache"), exist_ok=True)
    json.dump({"decomposition_cache_dir": os.path.join(a.out, "hacd")}, open(physics, "w"))
    harsh = os.path.join(a.out, "harsh.json")
    json.dump(HARSH, open(harsh, "w"), indent=1)
    settings = os.path.join(a.out, "plan_settings.yaml")
    open(settings, "w").write("time_limit_s: %g\n" % a.plan_time_limit)
    t_start = time.time()
    hands = a.hands.split(",")
    for obj in a.objects:
        for hand in hands:
            if a.deadline and time.time() - t_start > a.deadline:
                print("deadline reached; stopping (resume with the same command)")
                return
            hdir = os.path.join(a.out, os.path.basename(hand).replace(".yaml", ""))
            os.makedirs(hdir, exist_ok=True)
            base = os.path.join(hdir, object_name(obj))
            log = base + ".log"
            cpu_file = base + ".cpu.json"
            cpu = json.load(open(cpu_file)) if os.path.exists(cpu_file) else {}
            vcommon = ["--tests", "lift,shake", "--physics", physics, "--jobs", "1", "-q"]
            steps = [
                ("plan", base + ".plan.json",
                 [CG, "plan", "--hand", hand, "--object", obj, "--units", "auto",
                  "--grasps", str(a.grasps), "--seed", str(a.seed), "--settings", settings,
                  "-q", "--out", tmp_name(base + ".plan.json")]),
                ("default", base + ".default.json",
                 [CG, "validate", "--plan", base + ".plan.json"] + vcommon +
                 ["--out", tmp_name(base + ".default.json")]),
                ("nudged", base + ".nudged.json",
                 [CG, "validate", "--plan", base + ".plan.json", "--trials", "3"] + vcommon +
                 ["--out", tmp_name(base + ".nudged.json")]),
                ("p_held", base + ".phold.json",
                 [CG, "validate", "--plan", base + ".plan.json", "--uncertainty", "realistic",
                  "--trials", "20", "--seed", "1"] + vcommon +
                 ["--out", tmp_name(base + ".phold.json")]),
                ("harsh", base + ".harsh.json",
                 [CG, "validate", "--plan", base + ".plan.json", "--uncertainty", harsh,
                  "--min-hold-probability", "0.5", "--trials", str(a.harsh_draws),
                  "--seed", "2"] + vcommon + ["--out", tmp_name(base + ".harsh.json")]),
                ("export", base + ".xml",
                 [CG, "export", "--plan", base + ".plan.json", "--format", "mjcf",
                  "--cache-dir", os.path.join(a.out, "mjcache"),
                  "--out", base + ".xml"]),
                ("mujoco", base + ".mujoco.csv",
                 [MJ, "--scene", base + ".xml", "--out", tmp_name(base + ".mujoco.csv")]),
            ]
            for name, out, cmd in steps:
                if name != "plan" and not os.path.exists(base + ".plan.json"):
                    break
                if name == "mujoco" and not os.path.exists(base + ".xml.done"):
                    break
                if a.deadline and time.time() - t_start > a.deadline:
                    print("deadline reached; stopping (resume with the same command)")
                    return
                c = run_step(cmd, out, a.timeout, log,
                             base + ".xml.done" if name == "export" else None)
                if c is not None:
                    cpu[name] = c
                    json.dump(cpu, open(cpu_file, "w"), indent=1)
                    print("%s %s %s: %.1f s CPU" % (os.path.basename(hdir), object_name(obj),
                                                    name, c), flush=True)
    print("all steps done")


def load(path):
    try:
        return json.load(open(path))
    except (OSError, ValueError):
        return None


def collect(out):
    rows = []
    for hand in sorted(os.listdir(out)):
        hdir = os.path.join(out, hand)
        if not os.path.isdir(hdir) or hand in ("hacd", "mjcache", "revalidate"):
            continue
        for f in sorted(os.listdir(hdir)):
            if not f.endswith(".plan.json") or f.startswith("tmp."):
                continue
            obj = f[:-len(".plan.json")]
            base = os.path.join(hdir, obj)
            plan = load(base + ".plan.json")
            sims = {k: load(base + "." + k + ".json")
                    for k in ("default", "nudged", "phold", "harsh")}
            cpu = load(base + ".cpu.json") or {}
            mj = None
            if os.path.exists(base + ".mujoco.csv"):
                mj = {int(r["grasp"]): r for r in csv.DictReader(open(base + ".mujoco.csv"))}
            if plan is None:
                continue
            n = len(plan["grasps"])
            for i, g in enumerate(plan["grasps"]):
                row = {"hand": hand, "object": obj, "grasp": i, "eps": g["epsilon"],
                       "force_closure": int(bool(g.get("force_closure")))}

                def sg(k):
                    s = sims[k]
                    if s is None:
                        return None
                    for x in s["grasps"]:
                        if x["index"] == i:
                            return x
                    return None

                d = sg("default")
                row["as_planned_held"] = None if d is None else int(d["outcome"] == "held")
                row["default_wall_s"] = None if d is None else d.get("wall_time_s")
                nd = sg("nudged")
                row["nudged_held_of_3"] = None if nd is None else nd["trials"]["held"]
                ph = sg("phold")
                hp = ph.get("hold_probability") if ph else None
                for k, col in (("p", "p_held"), ("low", "p_low"), ("high", "p_high"),
                               ("draws", "draws"), ("held", "p_held_draws"),
                               ("verdict", "p_verdict"), ("cpu_s", "p_cpu_s")):
                    row[col] = None if hp is None else hp[k]
                hs = sg("harsh")
                hh = hs.get("hold_probability") if hs else None
                row["harsh_held"] = None if hh is None else hh["held"]
                row["harsh_draws"] = None if hh is None else hh["draws"]
                row["harsh_p"] = None if hh is None else hh["p"]
                row["harsh_cpu_s"] = None if hh is None else hh["cpu_s"]
                row["mujoco_held"] = None if mj is None or i not in mj else int(mj[i]["held"])
                for k in ("plan", "default", "nudged", "p_held", "harsh", "export", "mujoco"):
                    row["proc_cpu_%s_s" % k] = None if k not in cpu else cpu[k] / n
                rows.append(row)
    return rows


def ranks(v):
    order = sorted(range(len(v)), key=lambda i: v[i])
    r = [0.0] * len(v)
    i = 0
    while i < len(order):
        j = i
        while j + 1 < len(order) and v[order[j + 1]] == v[order[i]]:
            j += 1
        for k in range(i, j + 1):
            r[order[k]] = (i + j) / 2.0 + 1
        i = j + 1
    return r


def auc(scores, labels):
    """Mann-Whitney AUC, ties counted half; None without both classes."""
    npos = sum(labels)
    nneg = len(labels) - npos
    if npos == 0 or nneg == 0:
        return None
    r = ranks(scores)
    rpos = sum(ri for ri, l in zip(r, labels) if l)
    return (rpos - npos * (npos + 1) / 2.0) / (npos * nneg)


def spearman(x, y):
    rx, ry = ranks(x), ranks(y)
    n = len(x)
    mx, my = sum(rx) / n, sum(ry) / n
    sxy = sum((a - mx) * (b - my) for a, b in zip(rx, ry))
    sxx = sum((a - mx) ** 2 for a in rx)
    syy = sum((b - my) ** 2 for b in ry)
    return sxy / (sxx * syy) ** 0.5 if sxx > 0 and syy > 0 else None


PREDICTORS = [
    ("p_held", lambda r: r["p_held"]),
    ("eps", lambda r: r["eps"]),
    ("nudged2of3", lambda r: int(r["nudged_held_of_3"] >= 2)),
    ("nudged_count", lambda r: r["nudged_held_of_3"]),
    ("as_planned", lambda r: r["as_planned_held"]),
]
LABELS = [
    ("harsh", lambda r: int(r["harsh_held"] * 2 >= r["harsh_draws"])),
    ("mujoco", lambda r: r["mujoco_held"]),
]


def complete(r, label):
    need = ["p_held", "eps", "nudged_held_of_3", "as_planned_held"]
    need += ["harsh_held"] if label == "harsh" else ["mujoco_held"]
    return all(r.get(k) is not None for k in need)


def boot_ci(rows, pred, lab, reps=1000, seed=7):
    groups = {}
    for r in rows:
        groups.setdefault((r["hand"], r["object"]), []).append(r)
    keys = sorted(groups)
    rng = random.Random(seed)
    vals = []
    for _ in range(reps):
        sample = [r for _k in keys for r in groups[keys[rng.randrange(len(keys))]]]
        v = auc([pred(r) for r in sample], [lab(r) for r in sample])
        if v is not None:
            vals.append(v)
    if len(vals) < reps / 2:
        return None
    vals.sort()
    return vals[int(0.025 * len(vals))], vals[int(0.975 * len(vals)) - 1]


def fmt(x, nd=2):
    return "–" if x is None else ("%.*f" % (nd, x))


def cmd_table(a):
    rows = collect(a.out)
    csv_path = a.csv or os.path.join(a.out, "study.csv")
    if rows:
        with open(csv_path, "w", newline="") as f:
            w = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
            w.writeheader()
            for r in rows:
                w.writerow(r)
    print("%d grasps in %s" % (len(rows), csv_path))
    hands = sorted({r["hand"] for r in rows})
    print("\nAUC (Mann-Whitney, ties half) [95 % bootstrap over objects]")
    for lname, lab in LABELS:
        print("\nlabel: %s" % lname)
        print("| hand | grasps | objects | positives | " +
              " | ".join(p for p, _ in PREDICTORS) + " |")
        print("|---|---|---|---|" + "---|" * len(PREDICTORS))
        for h in hands + ["all"]:
            sub = [r for r in rows if (h == "all" or r["hand"] == h) and complete(r, lname)]
            if not sub:
                continue
            labels = [lab(r) for r in sub]
            cells = []
            for pname, pred in PREDICTORS:
                v = auc([pred(r) for r in sub], labels)
                ci = boot_ci(sub, pred, lab) if a.bootstrap else None
                cells.append(fmt(v) + ("" if ci is None else " [%.2f, %.2f]" % ci))
            print("| %s | %d | %d | %d | %s |" % (
                h, len(sub), len({(r["hand"], r["object"]) for r in sub}), sum(labels),
                " | ".join(cells)))
    print("\nSpearman of each predictor with the harsher held fraction")
    for h in hands + ["all"]:
        sub = [r for r in rows if (h == "all" or r["hand"] == h) and complete(r, "harsh")]
        if len(sub) < 3:
            continue
        frac = [r["harsh_held"] / r["harsh_draws"] for r in sub]
        print("  %s (%d): " % (h, len(sub)) + ", ".join(
            "%s %s" % (p, fmt(spearman([f(r) for r in sub], frac))) for p, f in PREDICTORS))
    print("\nSelection rules: grasps kept, and of them held under the harsher draws / in "
          "MuJoCo (precision; recall = kept positives / all positives)")
    rules = [("P(held) >= %.1f" % t, (lambda t: lambda r: r["p_held"] >= t)(t))
             for t in (0.5, 0.6, 0.7, 0.8, 0.9)]
    rules += [("P(held) decided above 0.8", lambda r: r["p_verdict"] == "above"),
              ("P(held) not decided below 0.8", lambda r: r["p_verdict"] != "below"),
              ("nudged 2-of-3", lambda r: r["nudged_held_of_3"] >= 2),
              ("nudged 3-of-3", lambda r: r["nudged_held_of_3"] >= 3),
              ("held as planned", lambda r: r["as_planned_held"] == 1)]
    for h in hands + ["all"]:
        sub = [r for r in rows if (h == "all" or r["hand"] == h)
               and complete(r, "harsh") and r["mujoco_held"] is not None]
        if not sub:
            continue
        hp = sum(LABELS[0][1](r) for r in sub)
        mp = sum(r["mujoco_held"] for r in sub)
        print("\n%s: %d grasps, harsh positives %d, MuJoCo positives %d" % (h, len(sub), hp, mp))
        print("| rule | kept | harsh held (precision, recall) | MuJoCo held (precision, recall) |")
        print("|---|---|---|---|")
        for name, rule in rules:
            sel = [r for r in sub if rule(r)]
            hh = sum(LABELS[0][1](r) for r in sel)
            mm = sum(r["mujoco_held"] for r in sel)
            print("| %s | %d | %d (%s, %s) | %d (%s, %s) |" % (
                name, len(sel), hh, fmt(hh / len(sel) if sel else None),
                fmt(hh / hp if hp else None), mm, fmt(mm / len(sel) if sel else None),
                fmt(mm / mp if mp else None)))
    print("\nCPU per grasp (median over grasps with both runs)")
    for h in hands + ["all"]:
        sub = [r for r in rows if (h == "all" or r["hand"] == h) and r["p_cpu_s"] is not None
               and r["proc_cpu_default_s"] is not None and r["proc_cpu_p_held_s"] is not None]
        if not sub:
            continue

        def med(v):
            v = sorted(v)
            n = len(v)
            return (v[n // 2] + v[(n - 1) // 2]) / 2.0

        print("  %s (%d grasps): default validate %.2f s per grasp (process CPU / the plan's "
              "grasps); P(held) run %.2f s per grasp (process CPU / grasps, incl. process start "
              "and the as-planned run); draws only (hold_probability.cpu_s) %.2f s; draws + the "
              "default per-grasp CPU %.2f s; median draws %g" % (
                  h, len(sub), med([r["proc_cpu_default_s"] for r in sub]),
                  med([r["proc_cpu_p_held_s"] for r in sub]), med([r["p_cpu_s"] for r in sub]),
                  med([r["p_cpu_s"] + r["proc_cpu_default_s"] for r in sub]),
                  med([r["draws"] for r in sub])))
        for verdict in ("below", "above", "undecided"):
            v = [r for r in sub if r["p_verdict"] == verdict]
            if v:
                print("    %s: %d grasps, draws median %g, draws CPU median %.2f s, max %.2f s" % (
                    verdict, len(v), med([r["draws"] for r in v]),
                    med([r["p_cpu_s"] for r in v]), max(r["p_cpu_s"] for r in v)))


def cmd_revalidate(a):
    os.makedirs(a.out, exist_ok=True)
    physics = os.path.join(a.out, "physics.json")
    os.makedirs(os.path.join(a.out, "hacd"), exist_ok=True)
    json.dump({"decomposition_cache_dir": os.path.join(a.out, "hacd")}, open(physics, "w"))
    settings = os.path.join(a.out, "budget.yaml")
    open(settings, "w").write("validation:\n  budget_s: %g\n" % a.budget_s)
    t_start = time.time()
    rdir = os.path.join(a.out, "revalidate")
    os.makedirs(rdir, exist_ok=True)
    for obj in a.objects:
        if a.deadline and time.time() - t_start > a.deadline:
            print("deadline reached; stopping (resume with the same command)")
            break
        base = os.path.join(rdir, object_name(obj))
        log = base + ".log"
        cpu_file = base + ".cpu.json"
        cpu = json.load(open(cpu_file)) if os.path.exists(cpu_file) else {}
        steps = [
            ("plan_validated", base + ".plan.json",
             [CG, "plan", "--hand", a.hand, "--object", obj, "--units", "auto", "--grasps", "3",
              "--validate", "--uncertainty", "realistic", "--settings", settings,
              "--physics", physics, "--jobs", "1", "-q", "--out", tmp_name(base + ".plan.json")]),
            ("revalidate", base + ".seed2.json",
             [CG, "validate", "--plan", base + ".plan.json", "--tests", "lift,shake",
              "--uncertainty", "realistic", "--seed", "2", "--trials", "20",
              "--physics", physics, "--jobs", "1", "-q",
              "--out", tmp_name(base + ".seed2.json")]),
        ]
        for name, out, cmd in steps:
            if name != "plan_validated" and not os.path.exists(base + ".plan.json"):
                break
            c = run_step(cmd, out, a.timeout, log)
            if c is not None:
                cpu[name] = c
                json.dump(cpu, open(cpu_file, "w"), indent=1)
                print("%s %s: %.1f s CPU" % (object_name(obj), name, c), flush=True)
    ps = []
    print("\n| object | accepted | plan CPU | P(held) seed 1 (plan) | P(held) seed 2 |")
    print("|---|---|---|---|---|")
    for obj in a.objects:
        base = os.path.join(rdir, object_name(obj))
        plan = load(base + ".plan.json")
        sim = load(base + ".seed2.json")
        cpu = load(base + ".cpu.json") or {}
        if plan is None:
            continue
        p1 = [g.get("validation", {}) for g in plan["grasps"]]
        p1 = ["%d/%d" % (v.get("held_trials", 0), v.get("trials", 0)) for v in p1]
        p2 = [] if sim is None else [g["hold_probability"]["p"] for g in sim["grasps"]]
        ps += p2
        print("| %s | %d | %s | %s | %s |" % (
            object_name(obj), len(plan["grasps"]), fmt(cpu.get("plan_validated"), 0) + " s",
            ", ".join(p1), ", ".join("%.2f" % p for p in p2)))
    if ps:
        print("average P(held) with seed 2 over %d accepted grasps: %.3f" % (
            len(ps), sum(ps) / len(ps)))


def main():
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    sp = ap.add_subparsers(dest="cmd", required=True)
    r = sp.add_parser("run")
    r.add_argument("--out", required=True)
    r.add_argument("--hands", default="cordgrasp_sah")
    r.add_argument("--grasps", type=int, default=4)
    r.add_argument("--seed", type=int, default=1)
    r.add_argument("--harsh-draws", type=int, default=16)
    r.add_argument("--plan-time-limit", type=float, default=10)
    r.add_argument("--timeout", type=float, default=900, help="per process [s]")
    r.add_argument("--deadline", type=float, default=0,
                   help="start no new step after this many seconds (0: none)")
    r.add_argument("objects", nargs="+")
    t = sp.add_parser("table")
    t.add_argument("--out", required=True)
    t.add_argument("--csv")
    t.add_argument("--no-bootstrap", dest="bootstrap", action="store_false")
    v = sp.add_parser("revalidate")
    v.add_argument("--out", required=True)
    v.add_argument("--hand", default="cordgrasp_sah")
    v.add_argument("--budget-s", type=float, default=150)
    v.add_argument("--timeout", type=float, default=900, help="per process [s]")
    v.add_argument("--deadline", type=float, default=0)
    v.add_argument("objects", nargs="+")
    a = ap.parse_args()
    if a.cmd == "run":
        cmd_run(a)
        a.csv, a.bootstrap = None, True
        cmd_table(a)
    elif a.cmd == "revalidate":
        cmd_revalidate(a)
    else:
        cmd_table(a)


if __name__ == "__main__":
    main()
