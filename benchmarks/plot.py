"""riserFoam benchmarks: results/results.json -> results/benchmarks.png and
results/summary.md.

usage: plot.py [results folder]

License: GPL-3.0-or-later
"""
import json
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))

# the targets
TARGET_LAB = {"riserLab": 1.3, "riserLabBasset": 1.5}     # x stock DyM sphereDrag + gravity
TARGET_RISER_FRAME = 2.0                                  # riserFrameBasset x stock static
TARGET_SPEEDUP = 1.7
TARGET_LINEAR = 0.25        # marginal cost per particle-step from 1e3 up within +-25%


def us(x):
    return "%.2f" % (1e6 * x)


def ms(x):
    return "%.3f" % (1e3 * x)


def when(suite):
    """The suite's start, when recorded."""
    if not suite.get("date"):
        return ""
    if suite.get("loadAverage"):
        return " (measured %s, load average %s)" % (suite["date"], " ".join(suite["loadAverage"]))
    return " (measured %s)" % suite["date"]


def verdict(ok):
    return "**met**" if ok else "**missed**"


def against_reference(st, keys, targets):
    """Rows of a suite against its reference (the first of keys): cost per
    particle-step, the ratio to the reference's, the target (targets)."""
    v = st["variants"]
    n = str(st["N"])
    reference = keys[0]
    ref = v[reference]["costPerParticleStep"][n]
    rows = []
    for k in keys:
        c = v[k]["costPerParticleStep"][n]
        target = targets.get(k)
        ratio = v[k].get("ratioToReference", {}).get(n, c / ref)
        spread = v[k].get("ratioToReferenceAllRepeats", {}).get(n, [ratio])
        rows.append({
            "key": k, "label": v[k]["label"],
            "t1": v[k]["cpuPerStep"]["1"], "tN": v[k]["cpuPerStep"][n],
            "perParticleStep": c, "ratio": ratio, "ratioRange": (min(spread), max(spread)),
            "target": target, "met": None if target is None else ratio <= target,
            "ratioTotal": v[k]["cpuPerStep"][n] / v[reference]["cpuPerStep"][n],
        })
    return rows


def analyse(res):
    """The numbers of the summary, and the verdicts."""
    out = {}
    s = res["suites"]
    if "stock" in s:
        out["stock"] = against_reference(
            s["stock"], ("stockDyM", "stockDyMCarrier", "riserLab", "riserLabBasset"), TARGET_LAB)
    if "riserFrame" in s:
        out["riserFrame"] = against_reference(
            s["riserFrame"], ("stockStatic", "stockStaticCarrier", "riserFrame", "riserFrameBasset"),
            {"riserFrameBasset": TARGET_RISER_FRAME})
    if "particles" in s:
        st = s["particles"]
        rows = {}
        for k, v in st["variants"].items():
            ns = sorted(int(n) for n in v["cpuPerStep"])
            marg = v["costPerParticleStepBetween"]
            from1e3 = [marg["%d-%d" % (a, b)] for a, b in zip(ns, ns[1:]) if a >= 1000]
            linear = (max(from1e3) / min(from1e3) - 1 <= 2 * TARGET_LINEAR) if len(from1e3) > 1 else None
            rows[k] = {"label": v["label"], "counts": ns,
                       "t": [v["cpuPerStep"][str(n)] for n in ns],
                       "perParticleStep": [v["costPerParticleStep"].get(str(n)) for n in ns],
                       "marginal": marg, "bytesPerParticle": v["bytesPerParticle"],
                       "rss": [v["peakRssKB"][str(n)] for n in ns],
                       "linear": linear, "from1e3": from1e3,
                       "earlyLate": v.get("stepCostEarlyLate")}
        out["particles"] = rows
    if "processors" in s:
        p = s["processors"]
        out["processors"] = {"N": p["N"], "t1": p["wallPerStep"]["1"], "t2": p["wallPerStep"]["2"],
                             "speedup": p["speedup"], "met": p["speedup"] >= TARGET_SPEEDUP,
                             "speedups": p.get("speedupAllRepeats", [p["speedup"]]),
                             "speedupCpu": p.get("speedupCpu"),
                             "comparison": p["comparison"]}
    return out


def summary(res, a):
    m = res["machine"]
    lines = ["# riserFoam benchmarks", ""]
    if res.get("label"):
        lines += ["**%s**" % res["label"], ""]
    lines += [
             "Machine: %s, %s cores (nproc), %s RAM, Linux %s; %s; OpenFOAM %s. "
             "Date: %s. Load average at start %s, at end %s (a shared machine: "
             "other builds and runs were going on)." % (
                 m["cpu"], m["nproc"], m["memory"], m["kernel"], "riserParcelFoam sha256 "
                 + str(m.get("riserParcelFoamSha256")), m["openfoam"], m["date"],
                 " ".join(m["loadAverageAtStart"]), " ".join(m.get("loadAverageAtEnd", ["?"]))),
             "",
             "Mesh: %s (%d cells, D = 0.1 m, 5 D long, cyclic ends); dt = 1e-4 s; "
             "particles 10 mm, 2000 kg/m^3, placed uniformly over the cross-section "
             "r <= R - d/2 - 5 mm and along the riser (the same seeded list for every "
             "solver), released at the riser's velocity, one-way coupled; no per-particle "
             "output (no cloud functions) in any case. Times are CPU time per step "
             "(median over alternating repeats), per-particle-step cost = "
             "(t(N) - t(1))/(N - 1); ratios are the median of the repeat-by-repeat ratios "
             "(the same run's CPU time varies by up to +-25%% on this shared virtual machine).%s" % (
                 res["mesh"]["command"], res["mesh"]["cells"],
                 " **Quick variant (smaller N, fewer steps).**" if res.get("quick") else ""),
             ""]
    for suite, title in (
            ("stock", "## 1. Against stock on the moving mesh (lab frame, riserOscillation for both)"),
            ("riserFrame", "## 2. Riser frame (static mesh) against stock on the static mesh")):
        if suite not in a:
            continue
        st = res["suites"][suite]
        lines += [title, "",
                  "N = %d particles against N0 = 1, %d steps (measured %d..%d), %d repeats%s." % (
                      st["N"], st["steps"], st["measuredSteps"][0], st["measuredSteps"][1],
                      st["repeats"], when(st)), "",
                  "| solver and models | t(1) ms/step | t(N) ms/step | us per particle-step | "
                  "ratio to stock drag (repeats' range) | target | |",
                  "|---|---:|---:|---:|---:|---:|---|"]
        for r in a[suite]:
            lines.append("| %s | %s | %s | %s | %.2f (%.2f-%.2f) | %s | %s |" % (
                r["label"], ms(r["t1"]), ms(r["tN"]), us(r["perParticleStep"]), r["ratio"],
                r["ratioRange"][0], r["ratioRange"][1],
                "<= %.1f" % r["target"] if r["target"] else "", verdict(r["met"]) if r["target"] else ""))
        lines.append("")
    if "particles" in a:
        st = res["suites"]["particles"]
        lines += ["## 3. Scaling with particles (static mesh; riser frame for riserParcelFoam)", "",
                  "%d steps, measured %d..%d (the Basset window of 0.01 s = 100 steps is full), "
                  "%d repeat(s)%s; memory = peak RSS (VmHWM) difference to N = 1." % (
                      st["steps"], st["measuredSteps"][0], st["measuredSteps"][1], st["repeats"],
                      when(st)), ""]
        for k, r in a["particles"].items():
            lines += ["**%s**" % r["label"], "",
                      "| N | ms/step | us per particle-step (vs N = 1) | marginal us per particle-step "
                      "| peak RSS MB | bytes per particle |",
                      "|---:|---:|---:|---:|---:|---:|"]
            prev = None
            for i, n in enumerate(r["counts"]):
                marg = r["marginal"].get("%d-%d" % (prev, n)) if prev else None
                lines.append("| %d | %s | %s | %s | %.1f | %s |" % (
                    n, ms(r["t"][i]), us(r["perParticleStep"][i]) if r["perParticleStep"][i] else "",
                    us(marg) if marg else "", r["rss"][i] / 1024.0,
                    ("%.0f" % r["bytesPerParticle"][str(n)] if r["bytesPerParticle"][str(n)] > 0
                     else "~0 (below the noise)") if str(n) in r["bytesPerParticle"] else ""))
                prev = n
            if r["linear"] is not None:
                lines.append("")
                lines.append("Linear from 1e3 up (marginal costs within +-%d%% of each other: "
                             "%s us): %s" % (100 * TARGET_LINEAR,
                                             ", ".join(us(x) for x in r["from1e3"]),
                                             verdict(r["linear"])))
            if r.get("earlyLate"):
                e = r["earlyLate"]
                lines.append("")
                lines.append("Step cost at N = %d in the first repeat, median of steps 3-30 "
                             "(Basset window filling): %s ms; steps 102-109 (full): %s ms (on this "
                             "machine the drift between minutes exceeds the window's effect)." % (
                                 e["N"], ms(e["steps 3-30"]), ms(e["steps 102-109"])))
            lines.append("")
    if "processors" in a:
        p = a["processors"]
        c = p["comparison"]
        lines += ["## 4. Scaling with processors (riser frame, full physics)", "",
                  "%d steps, %d repeats%s.%s" % (res["suites"]["processors"]["steps"],
                                             res["suites"]["processors"]["repeats"],
                                             when(res["suites"]["processors"]),
                                             " " + res["suites"]["processors"]["note"][0].upper()
                                             + res["suites"]["processors"]["note"][1:] + "."
                                             if res["suites"]["processors"].get("note") else ""), "",
                  "| N | np 1 ms/step (wall) | np 2 ms/step (wall) | speedup (repeats) | target | |",
                  "|---:|---:|---:|---:|---:|---|",
                  "| %d | %s | %s | %.2f (%s) | >= %.1f | %s |" % (
                      p["N"], ms(p["t1"]), ms(p["t2"]), p["speedup"],
                      ", ".join("%.2f" % x for x in p["speedups"]), TARGET_SPEEDUP,
                      verdict(p["met"])), "",
                  "Wall time per step: the median over the steps of a run, then over the repeats; "
                  "the speedup is the median of the repeat-by-repeat ratios (np 1 and np 2 of a "
                  "repeat ran back to back, each started once the machine's other work was below "
                  "0.3 cores).%s" % (
                      " From the busiest rank's CPU time: %.2f." % p["speedupCpu"]
                      if p.get("speedupCpu") else ""), ""]
        if "maxPositionDifference_m" in c:
            lines.append("Final state, serial against 2 processors (%s particles per processor): "
                         "largest position difference %.2e m, velocity %.2e m/s: %s." % (
                             "/".join(str(x) for x in c["particlesPerProcessor"]),
                             c["maxPositionDifference_m"], c["maxVelocityDifference_m_s"],
                             "the same to round-off (tolerance 1e-9 m, m/s; the processors sum in another order)" if c["identical"] else "**differ**"))
        else:
            lines.append("Final state: particle counts differ: %s" % c)
        lines.append("")
    if "contact" in res["suites"]:
        c = res["suites"]["contact"]
        lines += ["## 5. What one particle at the wall costs the cloud (riser frame, full physics)", "",
                  "N = %d particles away from the wall, with and without one more particle %.2f mm "
                  "from it (riserContact then sub-cycles the step), %d steps, %d repeats%s." % (
                      c["N"], 1e3 * c["nearWallGap_m"], c["steps"], c["repeats"], when(c)), "",
                  "| cloud | ms/step (CPU) | sub-cycles per step |",
                  "|---|---:|---:|",
                  "| %d particles, none near the wall | %s | 1 |" % (c["N"], ms(c["cpuPerStep"]["offWall"])),
                  "| the same + 1 particle at the wall | %s | %s |" % (
                      ms(c["cpuPerStep"]["nearWall"]), c["subCyclesPerStep"]), "",
                  "The cloud's step with one particle at the wall costs %.2f times the step without: "
                  "only the particle at the wall is sub-cycled (riserContact's local sub-cycling; "
                  "a ratio near the sub-cycles per step would mean the whole cloud moved in each)."
                  % c["ratio"], ""]
    extra = res.get("extra", {})
    if "pairCollision" in extra:
        e = extra["pairCollision"]
        v = e["suites"]["pairCollision"]["variants"]
        lines += ["## 6. Stock pairCollision on the moving mesh (measured separately)", "",
                  "`bench.py --suites pairCollision` (not part of Allrun: minutes per step), %s: "
                  "one particle, the same moving mesh; the stock colliding cloud rebuilds its "
                  "InteractionLists from scratch at every step of a moving mesh." % e["machine"]["date"], "",
                  "| solver and contact model | CPU s per step |",
                  "|---|---:|"]
        for k in ("stockDyMPair", "riserLab"):
            if k in v:
                lines.append("| %s | %.3f |" % (v[k]["label"], v[k]["cpuPerStep"]))
        lines.append("")
    if res.get("note"):
        lines += ["Note: %s." % res["note"], ""]
    lines.append("Benchmark run time: %.0f s." % res.get("elapsed_s", 0))
    return "\n".join(lines) + "\n"


SHORT = {
    "stockDyM": "stock: sphereDrag + gravity",
    "stockDyMCarrier": "stock: + SaffmanMei, virtualMass,\npressureGradient",
    "riserLab": "riserParcelFoam: paper forces,\nwall contact",
    "riserLabBasset": "riserParcelFoam: + Basset\n(windowTail)",
    "stockStatic": "stock: sphereDrag + gravity",
    "stockStaticCarrier": "stock: + SaffmanMei, virtualMass,\npressureGradient",
    "riserFrame": "riserParcelFoam riser frame:\npaper forces, wall contact",
    "riserFrameBasset": "riserParcelFoam riser frame:\n+ Basset (full physics)",
}


def chart(res, a, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, axes = plt.subplots(3, 3, figsize=(17, 13.5))
    grey, blue = "#7f7f7f", "#1f77b4"

    def colour(key):
        return blue if key.startswith("riser") else grey

    def bars(ax, rows, title, key, scale, unit):
        vals = [scale * r[key] for r in rows]
        ax.barh(range(len(rows)), vals, color=[colour(r["key"]) for r in rows])
        ax.set_yticks(range(len(rows)))
        ax.set_yticklabels([SHORT.get(r["key"], r["label"]) for r in rows], fontsize=8)
        ax.invert_yaxis()
        ax.set_xlabel(unit)
        ax.set_title(title, fontsize=10)
        for i, r in enumerate(rows):
            txt = "%.3g" % vals[i]
            if key == "perParticleStep":
                txt += "  (%.2fx%s)" % (r["ratio"], "; target %.1fx" % r["target"] if r.get("target") else "")
            ax.text(vals[i], i, " " + txt, va="center", fontsize=8)
        ax.set_xlim(0, max(vals) * 1.7)

    for ax in axes.flat:
        ax.set_visible(False)

    def against_particles(ax, ylabel, title):
        ax.set_xlabel("particles N")
        ax.set_ylabel(ylabel)
        ax.set_title(title, fontsize=10)
        ax.legend(fontsize=8)
        ax.grid(True, which="both", alpha=0.3)

    def use(i, j):
        axes[i][j].set_visible(True)
        return axes[i][j]

    if "stock" in a:
        n = res["suites"]["stock"]["N"]
        bars(use(0, 0), a["stock"], "Moving mesh (lab frame), N = %d:\ncost per particle-step, ratio to stock"
             % n, "perParticleStep", 1e6, "us per particle-step (CPU)")
        bars(use(1, 0), a["stock"], "Moving mesh: time per step with 1 particle\n(mesh motion, carrier, fields)",
             "t1", 1e3, "ms per step (CPU)")
    if "riserFrame" in a:
        n = res["suites"]["riserFrame"]["N"]
        bars(use(0, 1), a["riserFrame"], "Static mesh (riser frame for ours), N = %d:\n"
             "cost per particle-step, ratio to stock" % n, "perParticleStep", 1e6,
             "us per particle-step (CPU)")
        bars(use(1, 1), a["riserFrame"], "Static mesh: time per step with 1 particle",
             "t1", 1e3, "ms per step (CPU)")
    if "processors" in a:
        p = a["processors"]
        ax = use(0, 2)
        ax.bar([0, 1], [1e3 * p["t1"], 1e3 * p["t2"]], color=[blue, blue], width=0.5)
        ax.set_xticks([0, 1])
        ax.set_xticklabels(["1 rank", "2 ranks"])
        ax.set_ylabel("ms per step (wall)")
        ax.set_title("Processors: %d particles, riser frame, full physics" % p["N"], fontsize=10)
        c = p["comparison"]
        ax.text(0.5, 0.95, "speedup %.2f (target >= %.1f)\nfinal states: %s" % (
            p["speedup"], TARGET_SPEEDUP,
            "max |dx| %.1e m, |dU| %.1e m/s" % (c["maxPositionDifference_m"], c["maxVelocityDifference_m_s"])
            if "maxPositionDifference_m" in c else "particle counts differ"),
            transform=ax.transAxes, ha="center", va="top", fontsize=9)
        ax.set_ylim(0, 1e3 * p["t1"] * 1.35)
    if "particles" in a:
        ax = use(1, 2)
        for k, r in a["particles"].items():
            ax.loglog(r["counts"], [1e3 * t for t in r["t"]], "o-", color=colour(k),
                      label=SHORT.get(k, k).replace("\n", " "))
        ref = a["particles"].get("riserFrameBasset")
        if ref and 1000 in ref["counts"]:
            k0 = ref["counts"].index(1000)
            x0, y0 = 1000, 1e3 * ref["t"][k0]
            ax.loglog([x0, ref["counts"][-1]], [y0, y0 * ref["counts"][-1] / x0], "k:", lw=1,
                      label="linear from N = 1e3")
        against_particles(ax, "ms per step (CPU)", "Scaling with particles (static mesh): time per step")
        ax = use(2, 0)
        for k, r in a["particles"].items():
            xs = [n for n in r["counts"] if n > 1]
            ax.semilogx(xs, [1e6 * r["perParticleStep"][r["counts"].index(n)] for n in xs], "o-",
                        color=colour(k), label=SHORT.get(k, k).replace("\n", " "))
        ax.set_ylim(bottom=0)
        against_particles(ax, "us per particle-step (CPU)", "Cost per particle-step, (t(N) - t(1))/(N - 1)")
        ax = use(2, 1)
        for k, r in a["particles"].items():
            bp = r["bytesPerParticle"]
            xm = sorted(int(n) for n in bp)
            ax.semilogx(xm, [bp[str(n)] for n in xm], "s-", color=colour(k),
                        label=SHORT.get(k, k).replace("\n", " "))
        ax.set_ylim(bottom=0)
        against_particles(ax, "bytes per particle", "Memory per particle: peak RSS difference to N = 1")
    # the verdicts in words
    ax = use(2, 2)
    ax.axis("off")
    lines = []
    for r in a.get("stock", []) + a.get("riserFrame", []):
        if r.get("target"):
            lines.append("%-12s %-9s %.2fx stock (<= %.1fx) %s" % (
                "moving mesh" if r["key"].startswith("riserLab") else "riser frame",
                "+ Basset" if r["key"].endswith("Basset") else "no Basset",
                r["ratio"], r["target"], "met" if r["met"] else "MISSED"))
    for k, r in a.get("particles", {}).items():
        if r["linear"] is not None and k.startswith("riser"):
            lines.append("linear from 1e3 (%s us/p-step): %s" % (
                "/".join("%.1f" % (1e6 * x) for x in r["from1e3"]), "met" if r["linear"] else "MISSED"))
    if "processors" in a:
        p = a["processors"]
        lines.append("2 ranks: speedup %.2f (>= %.1f) %s,\n         results %s" % (
            p["speedup"], TARGET_SPEEDUP, "met" if p["met"] else "MISSED",
            "identical" if p["comparison"].get("identical") else "DIFFER"))
    if "contact" in res["suites"]:
        c = res["suites"]["contact"]
        lines.append("1 particle at the wall: step %.0fx dearer\n         (%s sub-cycles of the whole cloud)"
                     % (c["ratio"], c["subCyclesPerStep"]))
    if res.get("label"):
        lines = ["PRIVATE BUILD with the proposed changes", ""] + lines
    ax.text(0, 1, "\n".join(lines), va="top", fontsize=8.5, family="monospace")
    m = res["machine"]
    fig.suptitle("riserParcelFoam against stock OpenFOAM %s, %s (%d cells), dt = 1e-4 s\n%s, %s cores, %s" % (
        m["openfoam"], res["mesh"]["command"], res["mesh"]["cells"], m["cpu"], m["nproc"], m["date"]),
        fontsize=11)
    fig.tight_layout(rect=(0, 0, 1, 0.95))
    fig.savefig(path, dpi=100)


def main():
    folder = sys.argv[1] if len(sys.argv) > 1 else os.path.join(HERE, "results")
    res = json.load(open(os.path.join(folder, "results.json")))
    # measurements made separately, in sub-folders of the results
    res["extra"] = {}
    for name, sub in (("pairCollision", "pairCollision"),):
        path = os.path.join(folder, sub, "results.json")
        if os.path.isfile(path) and os.path.abspath(folder) != os.path.abspath(os.path.dirname(path)):
            res["extra"][name] = json.load(open(path))
    a = analyse(res)
    with open(os.path.join(folder, "summary.md"), "w") as f:
        f.write(summary(res, a))
    chart(res, a, os.path.join(folder, "benchmarks.png"))
    print("wrote %s and %s" % (os.path.join(folder, "summary.md"),
                                os.path.join(folder, "benchmarks.png")))


if __name__ == "__main__":
    main()
