"""The claims table of the validation report: one row per claim of Wei et
al. (2023), our number (from results/claims.json, written by the figure
scripts, and the regime map's fit), and whether we agree, decided here from
the numbers. Rewrites the table between the markers of validation/README.md;
with --check, exits nonzero if any claim decided 'agree' in a quick run
fails (the quick subset of ./Alltest).

usage: report.py [--check] [results folder]
SPDX-License-Identifier: GPL-3.0-or-later
"""
import json
import os
import sys

here = os.path.dirname(os.path.abspath(__file__))
check = "--check" in sys.argv
args = [a for a in sys.argv[1:] if a != "--check"]
results = args[0] if args else os.path.join(here, "results")
claims = json.load(open(os.path.join(results, "claims.json")))


def get(key):
    return claims[key]["value"] if key in claims else None


def text(*keys):
    return " ".join(claims[k]["text"] + "." for k in keys if k in claims)


def monotonic(values, rising):
    return all((b > a) if rising else (b < a) for a, b in zip(values, values[1:]))


rows = []   # (claim, our number, verdict, reason)

v = get("releaseForgotten_f0.05")
w = get("releaseForgotten_f0.15")
if v is not None:
    rows.append(("the release position is forgotten", text("releaseForgotten_f0.05", "releaseForgotten_f0.15"),
                 ("agree" if v < 1e-3 else "differ")
                 + (" without contact, differ with contacts" if w is not None and w > 1e-2 else ""),
                 "without contact the releases collapse onto one motion; with contacts (f = 0.15) "
                 "the wall-to-wall motion keeps a release-dependent phase (%.2g D apart after 10 "
                 "periods) while the mean vertical speed is nearly the same" % w
                 if w is not None and w > 1e-2 else ""))
v = get("verticalAtTwiceFrequency")
if v is not None:
    ok = all(abs(r - 2.0) < 0.05 for r in v[1:])
    rows.append(("the vertical velocity oscillates at twice the riser frequency", text("verticalAtTwiceFrequency"),
                 "agree" if ok else "differ",
                 "f = 0.025: the run's second half holds 1.25 periods, too few to resolve the "
                 "spectrum finely" if abs(v[0] - 2.0) >= 0.05 else ""))
v = get("frequencyTrends")
if v is not None:
    ok = monotonic(v["lateral"], True) and monotonic(v["lift"], False)
    rows.append(("the relative lateral velocity rises and the lifting distance falls with f",
                 text("frequencyTrends"), "agree" if ok else "differ", ""))
a, b = get("amplitudeTrends_f0.05"), get("amplitudeTrends_f0.3")
if a is not None and b is not None:
    ok = all(monotonic(x["lateral"], True) and monotonic(x["lift"], False) for x in (a, b))
    rows.append(("the relative lateral velocity rises and the lifting distance falls with A",
                 text("amplitudeTrends_f0.05", "amplitudeTrends_f0.3"), "agree" if ok else "differ", ""))
v = get("contactDropsVertical")
if v is not None:
    rows.append(("contacts drop the vertical velocity", text("contactDropsVertical"),
                 "agree" if v < 0 else "differ", "Coulomb friction at the wall (mu_c = 0.2) during each contact"))
v = get("phaseShiftWithContacts")
if v is not None:
    shift = v["0.3"] - v["0.05"]
    rows.append(("contacts shift the phase of the particle's motion", text("phaseShiftWithContacts"),
                 "agree" if abs(shift) > 5 else "differ", "a shift of %.1f deg" % shift))
v = get("bassetNegligible")
if v is not None:
    lift = max(x[2] for x in v.values())
    rows.append(("the Basset force is negligible for this particle", text("bassetNegligible"),
                 "agree" if lift < 0.05 else "differ",
                 "for the lifting distance (at most %.1f %%); with contacts (f = 0.2) the two runs' "
                 "contacts drift apart in time, so instantaneous velocities differ" % (100 * lift)))
v = get("saffmanMigration")
if v is not None:
    rows.append(("Saffman lift drives particles to the axis", text("saffmanMigration"),
                 "agree" if v < 1e-2 else "differ", ""))
regime = os.path.join(here, "../riserParticle/results/summary.txt")
if os.path.exists(regime) and not check:
    fits = [l.strip() for l in open(regime) if l.startswith("boundary")]
    rows.append(("regime boundaries follow f (A - a0) = c", "; ".join(fits),
                 "not compared", "the fitted form holds (figures/regime_map.png); the paper's constants "
                 "are not among our reference data"))
for f in ("0.05", "0.3"):
    v = get("enginesAgree_f" + f)
    if v is not None:
        rows.append(("(ours) the solver and the mesh-free engine agree, f = " + f,
                     text("enginesAgree_f" + f), "agree" if v["lift"] < 0.01 else "differ",
                     "the solver's cloud step is first order in deltaT"))

table = ["| claim of the paper | our number | verdict | why |", "|---|---|---|---|"]
table += ["| %s | %s | %s | %s |" % r for r in rows]
print("\n".join(table))
if check:
    failed = [r[0] for r in rows if r[2].startswith("differ")]
    print("%d claims checked, %d differ%s" % (len(rows), len(failed),
                                            (": " + "; ".join(failed)) if failed else ""))
    sys.exit(1 if failed else 0)
budget_rows = ["| scene | force | RMS / W | max / W | dropped: lifting distance | dropped: trajectory | "
               "dropped: CPU | needed |", "|---|---|---|---|---|---|---|---|"]
budgets = os.path.join(results, "budgets.json")
for scene in json.load(open(budgets)) if os.path.exists(budgets) else []:
    for force, v in scene["forces"].items():
        dropped = v["liftChange"] is not None
        budget_rows.append("| %s (%.0f D/u_cm, lift %.1f D) | %s | %.3g | %.3g | %s | %s | %s | %s |" % (
            scene["scene"], scene["duration"], scene["lift"], force, v["rms"], v["max"],
            "%+.2f D (%+.1f %%)" % (v["liftChange"], 100 * v["liftChange"] / scene["lift"]) if dropped else "-",
            "%.3g D" % v["trajectoryChange"] if dropped else "-",
            "x %.2f" % v["cpu"] if dropped else "-",
            ("yes" if v["needed"] else "no") if dropped else "always"))
readme = os.path.join(here, "../README.md")
text_ = open(readme).read()
begin, end = "<!-- claims table: begin (validation/paper/report.py) -->", "<!-- claims table: end -->"
for (begin, end), lines in (((begin, end), table),
                            (("<!-- budget table: begin (validation/paper/report.py) -->",
                              "<!-- budget table: end -->"), budget_rows)):
    if begin not in text_:
        sys.exit("report.py: no '%s' in %s" % (begin, readme))
    head, rest = text_.split(begin)
    text_ = head + begin + "\n" + "\n".join(lines) + "\n" + end + rest.split(end)[1]
open(readme, "w").write(text_)
print("rewrote the claims table in", readme)
