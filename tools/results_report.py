#!/usr/bin/env python3
"""Writes docs/results.md and its plots from the bench outputs of tools/results.sh.

Every number on the page comes from a results.csv under --in-dir; nothing is typed in by hand
except the paper's values, quoted from the spec (docs: /work/shared/docs/cord-planner-spec.md
section 10), and the notes file included verbatim at the end. Plots (PNG, matplotlib) go to
--img-dir and are linked relative to the page. Run with Debian's /usr/bin/python3
(python3-matplotlib).
"""
import argparse
import csv
import glob
import math
import os
import platform
import statistics
import subprocess
from collections import OrderedDict, defaultdict

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

DEG = 180.0 / math.pi
IMG = {"dir": None, "rel": None}   # where plots go, and their path relative to the page
SCALE_TITLE = {1: "×1 (Dex-Net scale, median extent 4.5 cm)",
               2: "×2 (`--scale 2`, an approximation of real size)"}


def tag_of(scale):
    return "" if scale == 1 else f"_x{scale}"


def save_plot(fig, name, out, alt):
    """Saves fig as IMG/name and appends a Markdown image link to out."""
    path = os.path.join(IMG["dir"], name)
    fig.tight_layout()
    fig.savefig(path, dpi=90)
    plt.close(fig)
    out.append(f"![{alt}]({IMG['rel']}/{name})\n")


def alphas(rows):
    return [num(r, "alpha_rad") * DEG for r in ok_rows(rows) if num(r, "alpha_rad") is not None]


def lower(a, b):
    """'mean/sd' verdict: is a's α lower than b's in mean and in sd?"""
    ma, sa, na = mean_sd(a)
    mb, sb, nb = mean_sd(b)
    if na == 0 or nb == 0:
        return "–"
    return f"{'yes' if ma < mb else 'no'}/{'yes' if sa < sb else 'no'}"


def rows_of(in_dir, name):
    path = os.path.join(in_dir, name, "results.csv")
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def num(row, key):
    v = row.get(key, "")
    return float(v) if v != "" else None


def mean_sd(values):
    values = [v for v in values if v is not None]
    if not values:
        return None, None, 0
    m = statistics.fmean(values)
    sd = statistics.stdev(values) if len(values) > 1 else 0.0
    return m, sd, len(values)


def ms(values, digits=3, scale=1.0):
    m, sd, n = mean_sd(values)
    if n == 0:
        return "–"
    return f"{m * scale:.{digits}f} ± {sd * scale:.{digits}f}"


def ok_rows(rows):
    return [r for r in rows if r["status"] == "ok"]


def success(rows):
    return f"{len(ok_rows(rows))}/{len(rows)}"


def command_of(in_dir, name):
    import json
    with open(os.path.join(in_dir, name, "bench.json")) as f:
        meta = json.load(f)
    return meta["command"]


def machine():
    cores = os.cpu_count()
    model = "unknown CPU"
    try:
        with open("/proc/cpuinfo") as f:
            for line in f:
                if line.startswith("model name"):
                    model = line.split(":", 1)[1].strip()
                    break
    except OSError:
        pass
    try:
        nproc = subprocess.run(["nproc"], capture_output=True, text=True).stdout.strip()
    except OSError:
        nproc = str(cores)
    return f"{nproc} cores (`nproc`), {model}, {platform.system()} {platform.release()}"


def fig11(in_dir, out, runs):
    out.append("## Fig. 11: number of sets, with and without local improvement\n")
    out.append(
        f"Long cylinder (shipped `long_cylinder.obj`, Ø 35 mm × 250 mm, real size: `--scale 1`), "
        f"Schunk SAH, cord planner, {runs} runs per setting (seeds 1..{runs}), first "
        "force-closure grasp. α in degrees (Eq. (2), palm normal; 0 = hand aligned with the "
        "principal axis). Exploration time is the cord stage alone; \"rank 0\" is the share of "
        "runs whose grasp came from the best-χ region (the paper measures α of the best-χ set's "
        "grasp; ours is the first force-closure one, which is the best-χ region's in the share "
        "given).\n")
    table = ["| sets | local improvement | FC found | α mean ± sd [deg] | exploration mean ± sd "
             "[s] | regions mean | rank 0 |", "|---|---|---|---|---|---|---|"]
    cmds = []
    series = {True: [], False: []}
    for sets in (5, 10, 20, 40):
        for li, tag in ((True, "li"), (False, "noli")):
            name = f"fig11_sets{sets}_{tag}"
            rows = rows_of(in_dir, name)
            cmds.append(command_of(in_dir, name))
            ok = ok_rows(rows)
            rank0 = sum(1 for r in ok if r["region_rank"] == "0")
            am, asd, _ = mean_sd(alphas(rows))
            tm, tsd, _ = mean_sd([num(r, "exploration_s") for r in rows])
            series[li].append((sets, am, asd, tm, tsd))
            table.append(
                f"| {sets} | {'yes' if li else 'no'} | {success(rows)} | "
                f"{ms(alphas(rows), 1)} | "
                f"{ms([num(r, 'exploration_s') for r in rows], 3)} | "
                f"{statistics.fmean([int(r['regions']) for r in rows]):.0f} | "
                f"{rank0}/{len(ok)} |")
    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(9, 3.4))
    for li, label, mk in ((True, "with local improvement", "o-"), (False, "without", "s--")):
        xs = [v[0] for v in series[li]]
        ax1.errorbar(xs, [v[1] for v in series[li]], yerr=[v[2] for v in series[li]],
                     fmt=mk, capsize=3, label=label)
        ax2.errorbar(xs, [v[3] for v in series[li]], yerr=[v[4] for v in series[li]],
                     fmt=mk, capsize=3, label=label)
    ax1.set_xlabel("number of sets")
    ax1.set_ylabel("α mean ± sd [deg]")
    ax1.set_ylim(bottom=0)
    ax1.legend()
    ax2.set_xlabel("number of sets")
    ax2.set_ylabel("exploration time [s]")
    ax2.set_ylim(bottom=0)
    for ax in (ax1, ax2):
        ax.set_xticks([5, 10, 20, 40])
    fig.suptitle("Fig. 11: long cylinder, Schunk SAH")
    save_plot(fig, "fig11.png", out, "Fig. 11: alpha and exploration time against sets")
    out.extend(table)
    li, noli = series[True], series[False]
    falls = li[-1][1] < li[0][1] and noli[-1][1] < noli[0][1]
    li_lower = sum(1 for a, b in zip(li, noli) if a[1] < b[1])
    out.append(
        f"\n**Against the paper** (α falls with more sets; lower with local improvement; "
        f"exploration time grows with the sets): α {'falls' if falls else 'does not fall'} "
        f"from 5 to 40 sets ({li[0][1]:.1f}° → {li[-1][1]:.1f}° with local improvement, "
        f"{noli[0][1]:.1f}° → {noli[-1][1]:.1f}° without); local improvement gives the lower "
        f"α at {li_lower}/4 set counts; exploration time {li[0][3]:.3f} → {li[-1][3]:.3f} s "
        f"with local improvement, {noli[0][3]:.3f} → {noli[-1][3]:.3f} s without.\n")
    out.append("Commands (one per row, `$OUT` = the results directory):\n")
    out.append("```\n" + "\n".join(cmds) + "\n```\n")


FIG12_PAPER_TIME = {"CoffeeFilters": "2.43 (0.57)", "CokePlasticLarge": "5.70 (0.36)",
                    "KoalaCandy": "2.44 (0.36)", "Pitcher": "4.65 (4.65?)",
                    "Wineglass": "3.75 (0.52)"}


def fig12_scale(in_dir, out, budgets, scale):
    t = tag_of(scale)
    cord = rows_of(in_dir, f"fig12_cord{t}")
    generic = {b: rows_of(in_dir, f"fig12_generic_{b}s{t}") for b in budgets}
    objects = list(OrderedDict.fromkeys(r["object"] for r in cord))
    out.append(f"### Fig. 12 at {SCALE_TITLE[scale]}\n")
    # Plot: alpha mean with sd bars per object, cord and the generic budgets.
    fig, ax = plt.subplots(figsize=(9, 3.6))
    labels = ["cord"] + [f"generic {b} s" for b in budgets]
    width = 0.8 / len(labels)
    for i, lab in enumerate(labels):
        ms_ = []
        for o in objects + ["all"]:
            src = cord if i == 0 else generic[budgets[i - 1]]
            rows = src if o == "all" else [r for r in src if r["object"] == o]
            m, sd, _ = mean_sd(alphas(rows))
            ms_.append((m or 0.0, sd or 0.0))
        xs = [k + (i - (len(labels) - 1) / 2) * width for k in range(len(objects) + 1)]
        ax.bar(xs, [v[0] for v in ms_], width, yerr=[v[1] for v in ms_], capsize=2, label=lab)
    ax.set_xticks(range(len(objects) + 1))
    ax.set_xticklabels(objects + ["all"])
    ax.set_ylabel("α mean ± sd [deg]")
    ax.legend(ncol=4, fontsize=8)
    ax.set_title(f"Fig. 12, Schunk SAH, scale ×{scale}")
    save_plot(fig, f"fig12{t}.png", out, f"Fig. 12 at scale {scale}: alpha cord vs generic")
    head = "| object | cord FC | cord α [deg] | cord time [s] | paper time [s] |"
    rule = "|---|---|---|---|---|"
    for b in budgets:
        head += f" generic {b} s FC | generic {b} s α [deg] |"
        rule += "---|---|"
    head += " cord lower, mean/sd (" + ", ".join(f"{b} s" for b in budgets) + ") |"
    rule += "---|"
    out.append(head)
    out.append(rule)
    verdicts = []
    for o in objects + ["all"]:
        c = cord if o == "all" else [r for r in cord if r["object"] == o]
        line = (f"| {'**all**' if o == 'all' else o} | {success(c)} | {ms(alphas(c), 1)} | "
                f"{ms([num(r, 'total_s') for r in c], 2)} | {FIG12_PAPER_TIME.get(o, '')} |")
        vs = []
        for b in budgets:
            g = generic[b] if o == "all" else [r for r in generic[b] if r["object"] == o]
            line += f" {success(g)} | {ms(alphas(g), 1)} |"
            vs.append(lower(alphas(c), alphas(g)))
        line += " " + ", ".join(vs) + " |"
        out.append(line)
        if o != "all":
            verdicts.append((o, vs))
    # GCP-z alpha (the approach axis), for reference.
    out.append("\nα of the GCP z axis (the approach direction; `alpha_approach_rad`), for "
               "comparison with the palm-normal α above:\n")
    out.append("| object | cord | " + " | ".join(f"generic {b} s" for b in budgets) + " |")
    out.append("|---|---|" + "---|" * len(budgets))
    for o in objects + ["all"]:
        def ap(rows):
            rows = rows if o == "all" else [r for r in rows if r["object"] == o]
            return ms([num(r, "alpha_approach_rad") for r in ok_rows(rows)], 1, DEG)
        out.append(f"| {o} | {ap(cord)} | " + " | ".join(ap(generic[b]) for b in budgets) + " |")
    n = len(objects) * len(budgets)
    mean_ok = sum(v.startswith("yes") for _, vs in verdicts for v in vs)
    sd_ok = sum(v.endswith("/yes") for _, vs in verdicts for v in vs)
    both = [o for o, vs in verdicts if all(v == "yes/yes" for v in vs)]
    fc = f"{len(ok_rows(cord))}/{len(cord)}"
    out.append(
        f"\n**Against the paper** (cord α lower than generic in mean and sd on every object at "
        f"every budget; all cord grasps stable): cord α lower in mean in {mean_ok}/{n} and in "
        f"sd in {sd_ok}/{n} object × budget cells; lower in both at every budget on "
        f"{len(both)}/{len(objects)} objects ({', '.join(both) if both else 'none'}); cord "
        f"force closure {fc}.\n")
    cmds = [command_of(in_dir, f"fig12_cord{t}")] + [
        command_of(in_dir, f"fig12_generic_{b}s{t}") for b in budgets]
    out.append("Commands:\n")
    out.append("```\n" + "\n".join(cmds) + "\n```\n")


def fig12(in_dir, out, budgets):
    out.append("## Fig. 12: cord vs generic α on five KIT objects\n")
    out.append(
        "Schunk SAH; cord planner 10 attempts per object (seeds 1..10); generic (Simox-style "
        "baseline: GCP at a random surface point along the normal, random roll) 10 attempts "
        "per object at each of three time budgets (the paper does not state its budgets; ours "
        f"are {', '.join(b + ' s' for b in budgets)}). α (Eq. (2), measured from the palm "
        "normal, `alpha_rad`) and ε of each attempt's first force-closure grasp; times are the "
        "whole plan (exploration + finger stage + quality). Paper time column: [P] §VI, mean "
        "(SD) total cord-planner time. The last column says, per budget, whether the cord "
        "planner's α is lower than the generic planner's in mean / in sd.\n")
    for scale in (2, 1):
        fig12_scale(in_dir, out, budgets, scale)


def fig13_scale(in_dir, out, scale):
    t = tag_of(scale)
    rows = rows_of(in_dir, f"fig13{t}")
    ok = ok_rows(rows)
    out.append(f"### Fig. 13–14 at {SCALE_TITLE[scale]}\n")
    out.append(f"**Force-closure grasp found: {len(ok)}/{len(rows)}** "
               f"(no grasp: {sum(r['status'] == 'no_grasp' for r in rows)}, errors: "
               f"{sum(r['status'] == 'error' for r in rows)}).\n")
    hist = defaultdict(int)
    for r in ok:
        k = int(r["regions_processed"])
        hist[k if k <= 10 else 11] += 1
    objects = list(OrderedDict.fromkeys(r["object"] for r in rows))
    per_obj = []
    for o in objects:
        g = [r for r in rows if r["object"] == o]
        per_obj.append((o, statistics.fmean(num(r, "exploration_s") for r in g),
                        statistics.fmean(num(r, "finger_s") for r in g),
                        statistics.fmean(num(r, "quality_s") for r in g)))
    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(11, 3.8),
                                   gridspec_kw={"width_ratios": [1, 2.4]})
    keys = list(range(1, 12))
    ax1.bar(keys, [hist.get(k, 0) for k in keys])
    ax1.set_xticks(keys)
    ax1.set_xticklabels([str(k) for k in range(1, 11)] + [">10"], fontsize=8)
    ax1.set_xlabel("regions processed until the first FC grasp")
    ax1.set_ylabel("attempts")
    xs = range(len(per_obj))
    e = [v[1] for v in per_obj]
    f = [v[2] for v in per_obj]
    q = [v[3] for v in per_obj]
    ax2.bar(xs, e, label="exploration")
    ax2.bar(xs, f, bottom=e, label="finger stage")
    ax2.bar(xs, q, bottom=[a + b for a, b in zip(e, f)], label="quality")
    ax2.set_xticks(list(xs))
    ax2.set_xticklabels([v[0] for v in per_obj], rotation=70, fontsize=7)
    ax2.set_ylabel("mean time per attempt [s]")
    ax2.legend(fontsize=8)
    fig.suptitle(f"Fig. 13–14: 26 KIT objects × 10, Schunk SAH, scale ×{scale}")
    save_plot(fig, f"fig13{t}.png", out, f"Fig. 13-14 at scale {scale}")
    out.append("Regions (sets) given to the finger stage until the first force-closure grasp "
               "(Fig. 13 top):\n")
    out.append("| regions processed | " + " | ".join(
        str(k) if k <= 10 else "> 10" for k in sorted(hist)) + " |")
    out.append("|---|" + "---|" * len(hist))
    out.append("| attempts | " + " | ".join(str(hist[k]) for k in sorted(hist)) + " |\n")
    per_run = [num(r, "finger_s") / int(r["finger_attempts"]) for r in ok
               if int(r["finger_attempts"]) > 0]
    per_plan = [num(r, "finger_s") for r in ok]
    below = sum(1 for v in per_run if v < 0.2)
    if per_run:
        out.append(
            "Finger stage (Fig. 13 bottom): per finger-stage run (one region, incl. a rolled "
            f"retry counted as a run): median {statistics.median(per_run):.3f} s, max "
            f"{max(per_run):.3f} s, {below}/{len(per_run)} attempts below 0.2 s per run; "
            f"summed over all runs of a plan: median {statistics.median(per_plan):.3f} s, "
            f"max {max(per_plan):.3f} s, "
            f"{sum(1 for v in per_plan if v < 0.2)}/{len(per_plan)} below 0.2 s.\n")
    out.append("Per object (Fig. 14), times in s:\n")
    out.append("| object | FC found | total mean ± sd | exploration mean | finger mean | quality "
               "mean | regions processed mean | α [deg] |")
    out.append("|---|---|---|---|---|---|---|---|")
    means = []
    for o in objects:
        g = [r for r in rows if r["object"] == o]
        m, _, _ = mean_sd([num(r, "total_s") for r in g])
        means.append(m)
        out.append(
            f"| {o} | {success(g)} | {ms([num(r, 'total_s') for r in g], 3)} | "
            f"{statistics.fmean(num(r, 'exploration_s') for r in g):.3f} | "
            f"{statistics.fmean(num(r, 'finger_s') for r in g):.3f} | "
            f"{statistics.fmean(num(r, 'quality_s') for r in g):.3f} | "
            f"{statistics.fmean(int(r['regions_processed']) for r in g):.1f} | "
            f"{ms(alphas(g), 1)} |")
    failed = sorted({r["object"] for r in rows if r["status"] != "ok"})
    out.append(
        f"\n**Against the paper** (260/260 stable; sets processed concentrated on the top "
        f"ranks; finger stage < 0.2 s): force closure {len(ok)}/{len(rows)} "
        f"({'≥' if len(ok) >= 259 else '<'} 259/260"
        f"{'; without: ' + ', '.join(failed) if failed else ''}); first region succeeds in "
        f"{hist.get(1, 0)}/{len(ok)}, more than 10 regions in {hist.get(11, 0)}/{len(ok)}; "
        f"per-object mean total time {min(means):.3f}–{max(means):.3f} s.\n")
    out.append("Command:\n\n```\n" + command_of(in_dir, f"fig13{t}") + "\n```\n")
    out.append(f"Contact sheets (best first grasp per object): `$OUT/fig13{t}/sheets/*.png`.\n")


def fig13(in_dir, out):
    out.append("## Fig. 13–14: 26 KIT objects × 10 attempts, Schunk SAH\n")
    out.append(
        "Cord planner, seeds 1..10 per object, one force-closure grasp per attempt, no physics "
        "(physics is the last section). Paper: 260/260 stable grasps; sets processed "
        "concentrated on the top ranks; finger stage < 0.2 s in almost all cases; per-object "
        "mean times of the order of 2.4–5.7 s (Fig. 12 objects; Fig. 14's values are not in "
        "the text).\n")
    for scale in (2, 1):
        fig13_scale(in_dir, out, scale)


def fig17(in_dir, out, objects):
    import json
    out.append("## Fig. 17 stand-in: complex objects, cord vs generic\n")
    out.append(
        "The paper's designed objects (Decor, Desk Lamp, Pliers, Sai and Spike weapons) are not "
        "available; stand-ins: YCB mug, pitcher base, large clamp, power drill and scissors "
        "(`../shared/data`, real size) and the shipped pliers and kettle, all at `--scale 1`. "
        "Schunk SAH, 10 attempts per planner and object. Generic timeout = the cord planner's "
        "largest total time on that object (the paper's protocol). α as in Fig. 12 (palm "
        "normal). Paper: 50/50 stable with the cord planner, mean times 9.6–31.8 s; α mean "
        "and sd lower for the cord planner.\n")
    cord = rows_of(in_dir, "fig17_cord")
    table = ["| object | cord FC | cord α [deg] | cord time [s] | generic timeout [s] | "
             "generic FC | generic α [deg] | generic first-FC time [s] | cord lower, mean/sd |",
             "|---|---|---|---|---|---|---|---|---|"]
    cmds = [command_of(in_dir, "fig17_cord")]
    all_g = []
    bars = []
    verdicts = []
    for o in objects:
        c = [r for r in cord if r["object"] == o]
        name = f"fig17_generic_{o}"
        g = rows_of(in_dir, name)
        all_g += g
        cmds.append(command_of(in_dir, name))
        with open(os.path.join(in_dir, name, "bench.json")) as f:
            p = json.load(f)["parameters"]
            # bench.json since typed parameters: parameters.job.plan.time_limit_s
            limit = p["job"]["plan"]["time_limit_s"] if "job" in p else p["time_limit_s"]
        v = lower(alphas(c), alphas(g))
        verdicts.append((o, v))
        bars.append((o, mean_sd(alphas(c)), mean_sd(alphas(g))))
        table.append(
            f"| {o} | {success(c)} | {ms(alphas(c), 1)} | "
            f"{ms([num(r, 'total_s') for r in c], 2)} | {limit:.2f} | {success(g)} | "
            f"{ms(alphas(g), 1)} | "
            f"{ms([num(r, 'first_fc_s') for r in ok_rows(g)], 2)} | {v} |")
    v_all = lower(alphas(cord), alphas(all_g))
    table.append(f"| **all** | {success(cord)} | {ms(alphas(cord), 1)} | "
                 f"{ms([num(r, 'total_s') for r in cord], 2)} | | {success(all_g)} | "
                 f"{ms(alphas(all_g), 1)} | | {v_all} |")
    bars.append(("all", mean_sd(alphas(cord)), mean_sd(alphas(all_g))))
    fig, ax = plt.subplots(figsize=(9, 3.6))
    xs = range(len(bars))
    for i, lab in enumerate(("cord", "generic (timeout = cord's largest time)")):
        ax.bar([x + (i - 0.5) * 0.38 for x in xs], [b[1 + i][0] or 0 for b in bars], 0.38,
               yerr=[b[1 + i][1] or 0 for b in bars], capsize=2, label=lab)
    ax.set_xticks(list(xs))
    ax.set_xticklabels([b[0] for b in bars], fontsize=8, rotation=15)
    ax.set_ylabel("α mean ± sd [deg]")
    ax.legend(fontsize=8)
    ax.set_title("Fig. 17 stand-ins, Schunk SAH, scale ×1 (real size)")
    save_plot(fig, "fig17.png", out, "Fig. 17 stand-ins: alpha cord vs generic")
    out.extend(table)
    mean_ok = [o for o, v in verdicts if v.startswith("yes")]
    not_ok = [o for o, v in verdicts if not v.startswith("yes")]
    out.append(
        f"\n**Against the paper** (cord α lower in mean and sd; all cord grasps stable): whole "
        f"set mean/sd {v_all}; cord mean lower on {len(mean_ok)}/{len(objects)} objects"
        f"{' (not: ' + ', '.join(not_ok) + ')' if not_ok else ''}; cord force closure "
        f"{success(cord)}.\n")
    out.append("Commands:\n\n```\n" + "\n".join(cmds) + "\n```\n")


def physics(in_dir, out, repeats, hands):
    out.append("## Physics: hold rate through lift + shake\n")
    out.append(
        f"The first force-closure grasp of each attempt is simulated in Bullet (settle, close, "
        f"lift, shake ±2 cm and ±15°; `cordgrasp validate` defaults, μ = the planner's "
        f"0.5). Hands: {hands}; {repeats} attempt(s) per object and planner. Held = the object "
        "stayed in the hand through every test; the rate is over the attempts that produced a "
        "grasp. `kit` is the Dex-Net scale, `kit_x2` the KIT meshes at `--scale 2`. The paper "
        "reports 260/260 and 50/50 'stable' grasps, judged by its planner's force closure, not "
        "by a physics simulation.\n")
    out.append("| set | hand | planner | attempts | FC grasp | held | held / FC grasp | "
               "failed in lift | failed in shake | other (close, unstable) |")
    out.append("|---|---|---|---|---|---|---|---|---|---|")
    cmds = []
    for s in ("shipped", "kit", "kit_x2", "ycb"):
        name = f"physics_{s}"
        if not os.path.exists(os.path.join(in_dir, name, "results.csv")):
            continue
        rows = rows_of(in_dir, name)
        cmds.append(command_of(in_dir, name))
        groups = OrderedDict()
        for r in rows:
            groups.setdefault((r["hand"], r["planner"]), []).append(r)
        for (hand, planner), g in groups.items():
            sim = [r for r in g if r["sim_outcome"]]
            held = sum(r["sim_outcome"] == "held" for r in sim)
            lift = sum(r["sim_lift"] not in ("held", "not_run") for r in sim)
            shake = sum(r["sim_lift"] == "held" and r["sim_shake"] != "held" for r in sim)
            other = len(sim) - held - lift - shake
            rate = f"{100.0 * held / len(sim):.0f} %" if sim else "–"
            out.append(f"| {s} | {hand} | {planner} | {len(g)} | {len(ok_rows(g))} | {held} | "
                       f"{rate} | {lift} | {shake} | {other} |")
    out.append("\nCommands:\n\n```\n" + "\n".join(cmds) + "\n```\n")


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--in-dir", required=True)
    ap.add_argument("--img-dir", required=True, help="where the plots go (PNG)")
    ap.add_argument("--mode", default="reduced")
    ap.add_argument("--fig11-runs", type=int, default=30)
    ap.add_argument("--phys-repeats", type=int, default=1)
    ap.add_argument("--phys-hands", default="schunk_sah")
    ap.add_argument("--wall-s", type=int, default=0)
    ap.add_argument("--jobs", default="")
    ap.add_argument("--notes", default="")
    ap.add_argument("--load", default="", help="load average at the end of the run")
    ap.add_argument("--commit", default="", help="git commit the executable was built from")
    ap.add_argument("--out", required=True)
    a = ap.parse_args()
    os.makedirs(a.img_dir, exist_ok=True)
    IMG["dir"] = a.img_dir
    IMG["rel"] = os.path.relpath(a.img_dir, os.path.dirname(os.path.abspath(a.out)))
    load = a.load.split()
    out = ["# Results: the evaluation of Li et al. (T-RO 2015), reproduced\n"]
    out.append("<!-- generated by tools/results.sh (tools/results_report.py); do not edit by "
               "hand: edit docs/results-notes.md or the scripts -->\n")
    out.append(f"- Regenerate: `tools/results.sh{' --full' if a.mode == 'full' else ''} "
               "[OUT_DIR]` (needs `build/tools/cordgrasp`, `../shared/data` and Debian's "
               "`/usr/bin/python3` with python3-matplotlib for the plots).")
    out.append(f"- Machine: {machine()}; load average (1, 5, 15 min) at the end of the run "
               f"{' '.join(load)} (the machine "
               "was shared with other jobs: wall-clock times are inflated, not comparable to the "
               "paper's Core i5 at 3.4 GHz)." if load else f"- Machine: {machine()}.")
    if a.commit:
        out.append(f"- Code: commit `{a.commit}`.")
    out.append(f"- Run: {a.mode} protocol, {a.jobs} bench threads, {a.wall_s // 60} min "
               f"{a.wall_s % 60} s wall time for all experiments.")
    out.append(
        "- **Scale.** The KIT meshes in `../shared/data` are the Dex-Net copies, rescaled to a "
        "4.5 cm median extent, about half the real objects' size (the 1.5 l CokePlasticLarge "
        "is ~0.33 m tall, its mesh 0.164 m). Every KIT experiment is run at `--scale 2`, an "
        "approximation of real size (not the real objects: the Dex-Net copies are not all "
        "shrunk by the same factor), and at `--scale 1` (Dex-Net scale) beside it. The Fig. 11 "
        "cylinder, the YCB and the shipped objects are real size and run at `--scale 1`.")
    out.append(
        "- **α** is Eq. (2) measured from the hand's palm normal (`alpha_rad`, the axis that "
        "points from the palm); Fig. 12 also lists α of the GCP z axis (the approach "
        "direction, `alpha_approach_rad`). Side cords: the default `fallback` (docs/algorithm.md "
        "§4).")
    if a.mode != "full":
        out.append(
            f"- **Reduced** from the paper / issue counts to fit a shared 2-core machine: Fig. 11 "
            f"{a.fig11_runs} runs per setting (paper: 100); physics {a.phys_repeats} attempt per "
            f"object and planner, hand {a.phys_hands} only (full: 10 attempts, schunk_sah and "
            "cordgrasp_sah). Fig. 12, 13–14 and 17 use the full counts. `tools/results.sh "
            "--full` runs the full protocol.")
    out.append("- Timings are wall-clock per attempt, measured while another attempt ran on "
               "the other core.\n")
    fig11(a.in_dir, out, a.fig11_runs)
    fig12(a.in_dir, out, ["0.25", "1", "4"])
    fig13(a.in_dir, out)
    fig17(a.in_dir, out, ["025_mug", "019_pitcher_base", "051_large_clamp", "035_power_drill",
                          "037_scissors", "pliers", "kettle"])
    physics(a.in_dir, out, a.phys_repeats, a.phys_hands)
    if a.notes and os.path.exists(a.notes):
        with open(a.notes) as f:
            out.append(f.read())
    text = "\n".join(out).rstrip() + "\n"
    tmp = a.out + ".tmp"
    with open(tmp, "w") as f:
        f.write(text)
    os.replace(tmp, a.out)


if __name__ == "__main__":
    main()
