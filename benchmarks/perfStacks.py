"""Summarise `perf script` call stacks (perf record --call-graph dwarf):
self time and inclusive time per function (template arguments folded to
<>), plus the callers of selected functions.

usage: perfStacks.py <perf script output> [top] [--ours] [function whose callers to list ...]

--ours: also the phases of the run (what main calls; inside the cloud's
evolve, what the time goes to) and the inclusive time of the project's own
functions (namespace riser::, carrierFlow, the riser submodels, the
HistoryParcel layer's own work, riserParcelFoam's imposeCarrier).

License: GPL-3.0-or-later
"""
import collections
import re
import sys


def simplify(symbol):
    """Fold template arguments and drop offsets: Foam::X<...>::f."""
    symbol = re.sub(r"\+0x[0-9a-f]+$", "", symbol.strip())
    out, depth = [], 0
    for ch in symbol:
        if ch == "<":
            if depth == 0:
                out.append("<>")
            depth += 1
        elif ch == ">":
            depth = max(0, depth - 1)
        elif depth == 0:
            out.append(ch)
    s = "".join(out)
    s = s.replace(" (inlined)", "")
    s = re.sub(r"\(.*\)$", "", s) if not s.startswith("operator") else s
    return s.strip()


def read_stacks(path):
    """Yield one stack (list of (function, library), innermost first) per sample."""
    stack = []
    for line in open(path, errors="replace"):
        line = line.rstrip("\n")
        if not line.strip():
            if stack:
                yield stack
            stack = []
            continue
        if not line.startswith((" ", "\t")):
            continue            # the sample's header line
        parts = line.strip().split(None, 1)
        if len(parts) < 2:
            continue
        rest = parts[1]
        m = re.match(r"(.*) \(([^()]*)\)$", rest)
        sym, dso = (m.group(1), m.group(2)) if m else (rest, "?")
        inlined = sym.endswith("(inlined)")
        stack.append((simplify(sym), dso.rsplit("/", 1)[-1], inlined))
    if stack:
        yield stack


OURS = ("riser::", "Foam::carrierFlow", "Foam::Riser", "Foam::WallCorrectedDrag",
        "Foam::ParticleForceFields", "Foam::particleForces", "Foam::riserOscillation",
        "Foam::HistoryParcel<>::transformProperties", "Foam::HistoryParcel<>::writeFields",
        "Foam::HistoryParcel<>::readFields")

# inside the cloud's evolve: the first rule whose function is on the stack
EVOLVE_RULES = [
    ("Foam::KinematicParcel<>::trackingData::trackingData<>",
     "interpolation set-up: cellPoint point field of U (volPointInterpolation)"),
    ("Foam::RiserContact<>", "wall contact (riserContact)"),
    ("Foam::CloudFunctionObjectList<>", "cloud functions (riserParticleTable, particleForceFields)"),
    ("Foam::ParticleForceList<>", "particle forces"),
    ("Foam::Cloud<>::move<>", "tracking and the stock parcel (move, calc)"),
    ("Foam::KinematicCloud<>::postEvolve", "post-evolve (cloud functions' output)"),
    ("Foam::CollidingCloud<>::info", "cloud statistics written to the log each step (info)"),
    ("Foam::KinematicCloud<>::preEvolve", "pre-evolve (log, forces' cacheFields)"),
    ("Foam::InjectionModelList<>", "injection"),
]


def ours(name):
    return name.startswith(OURS)


def phases(stacks, total):
    main_callee = collections.Counter()
    evolve = collections.Counter()
    our_incl = collections.Counter()
    for stack in stacks:
        names = [f for f, _, _ in stack]
        if "main" in names:
            i = names.index("main")
            callee = names[i - 1] if i > 0 else "main (self)"
            if callee == "operator()" or callee.startswith("riser::"):
                callee = "imposeCarrier (the analytic carrier on every cell and face)"
            main_callee[callee] += 1
            if callee == "Foam::CollidingCloud<>::evolve":
                for fn, label in EVOLVE_RULES:
                    if fn in names:
                        evolve[label] += 1
                        break
                else:
                    evolve["other"] += 1
        seen = set()
        for f in names:
            if ours(f) and f not in seen:
                our_incl[f] += 1
                seen.add(f)
        if "main" in names and main_callee and names.index("main") > 0 \
           and (names[names.index("main") - 1] == "operator()"
                or names[names.index("main") - 1].startswith("riser::")):
            our_incl["imposeCarrier (riserParcelFoam main)"] += 1
    print("\nphases: what main calls (inclusive)")
    for f, c in main_callee.most_common(12):
        print("%6.2f%%  %s" % (100.0 * c / total, f))
    print("\ninside Foam::CollidingCloud<>::evolve (first match on the stack)")
    for f, c in evolve.most_common():
        print("%6.2f%%  %s" % (100.0 * c / total, f))
    print("\nthe project's own functions (inclusive, with what they call)")
    for f, c in our_incl.most_common(15):
        print("%6.2f%%  %s" % (100.0 * c / total, f))


def main():
    path = sys.argv[1]
    top = int(sys.argv[2]) if len(sys.argv) > 2 else 25
    want_ours = "--ours" in sys.argv[3:]
    targets = [t for t in sys.argv[3:] if t != "--ours"]
    self_count = collections.Counter()
    incl_count = collections.Counter()
    callers = {t: collections.Counter() for t in targets}
    total = 0
    for stack in read_stacks(path):
        total += 1
        self_count[(stack[0][0], stack[0][1])] += 1
        seen = set()
        for f, dso, _ in stack:
            if f not in seen:
                incl_count[f] += 1
                seen.add(f)
        for t in targets:
            for i, (f, _, _) in enumerate(stack):
                if f == t:
                    # the first caller that is not the target or an inlined helper of it
                    j = i + 1
                    while j < len(stack) and (stack[j][0] == t or stack[j][0].startswith("Foam::particle::")):
                        j += 1
                    callers[t][stack[j][0] if j < len(stack) else "?"] += 1
                    break
    print("samples: %d" % total)
    print("\nself time (top %d)" % top)
    for (f, dso), c in self_count.most_common(top):
        print("%6.2f%%  %-28s %s" % (100.0 * c / total, dso[:28], f))
    print("\ninclusive time (top %d)" % top)
    for f, c in incl_count.most_common(top):
        print("%6.2f%%  %s" % (100.0 * c / total, f))
    if want_ours:
        phases(read_stacks(path), total)
    for t in targets:
        n = sum(callers[t].values())
        print("\ncallers of %s (%.2f%% of all samples)" % (t, 100.0 * n / max(total, 1)))
        for f, c in callers[t].most_common(15):
            print("%6.2f%%  %s" % (100.0 * c / total, f))


if __name__ == "__main__":
    main()
