"""A model of riserParcelFoam's wall time for a long riser with 1e6-1e8 ores
with wall and pair contact, on 16-4,096 processors, from costs measured on
this machine (benchmarks/oreCloud.py --dense: results/oreDense.json) and its
chart, with LIGGGHTS measured side by side on a settled bed (benchmarks/
granular.py --dense: results/granularDense.json) and Lethe-DEM's published
scale for reference.

The riser is split along its axis into P slabs of equal length (OpenFOAM's
simple decomposition along z, as in the measurement). A processor holds
n = N/P ores and, each flow step:
  - steps its own ores:                 n c(n)
      c: the measured serial cost per particle-step in the dense phase,
      linear in log N between the measured sizes (flat beyond the
      largest: assumed, not measured); it includes the tracking, the
      forces with the Basset history, the mesh's share and the contacts;
  - steps the copies of the other processors' ores within the contact
    reach of its two faces (its halo), each at the cost of an own ore:
                                        h c(n)
      h: the copies a processor receives per step, measured on 2
      processors (2 faces each: the section's ends are cyclic) and
      independent of N and P while a slab is longer than the reach (the
      ores per metre are fixed by the section and C_v);
  - sends and receives the halo's records (b bytes a copy, measured: the
    plan's rows, the sub-steps' states and springs) to its two
    neighbours, in m messages a step each way, and takes part in k global
    reductions:                         2 m alpha + h b / beta + k alpha 2 log2(P)
      m = 4 + s (the plan's rows and needs, the group's states and
      springs, and s exchanges of the sub-steps' states: the most by one
      processor in a step, measured), k = 20
      (the cloud's moves, the plan's rounds, the sub-steps' count:
      counted from the code, rounded up), alpha = 2 us and beta = 5 GB/s
      (an InfiniBand-class cluster: assumed, not measured here);
  - waits for the busiest processor: the load imbalance f >= 1 multiplies
    the compute terms; f is calibrated so that the model gives the
    measured 2-processor time of the largest measured N (the only
    parameter fitted).

A flow step of dt = 1e-4 s (the measured scene's): wall time per
simulated second = 1e4 t_step. Memory per processor: n times the measured
bytes per particle (the mesh's growth included).

What the model leaves out: a decomposition other than slabs (a riser
hundreds of metres long and 0.1 m wide makes slabs the natural one), load
balance that changes in time (the imbalance is taken from one scene),
the two-way coupled fluid solve (its own scaling), output.

usage: scalingModel.py --results DIR   (reads oreDense.json, granularDense.json;
writes scalingModel.json, scalingModel.md and scalingModel.png there)
License: GPL-3.0-or-later
"""
import argparse
import json
import math
import os

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

ALPHA = 2e-6        # latency of one message [s] (assumed)
BETA = 5e9          # bandwidth of one link [byte/s] (assumed)
REDUCTIONS = 20     # global reductions per flow step (counted, rounded up)
DT = 1e-4           # flow step of the measured scene [s]
# Lethe-DEM (Golshan et al., Comput. Part. Mech., 2023,
# doi:10.1007/s40571-022-00478-6) report their
# best parallel efficiency at 5,000-15,000 particles per core; the order of
# their throughput, about 1e5 particle-steps per core-second, is drawn as a
# band, not re-measured here
LETHE_PARTICLES_PER_CORE = (5000, 15000)
LETHE_THROUGHPUT = 1e5


def measured(results):
    dense = json.load(open(os.path.join(results, "oreDense.json")))
    rows = sorted(dense["rows"], key=lambda r: r["N"])
    return dense, rows


def cost(rows, n):
    """measured serial cost per particle-step [s] at n particles: linear in
    log N between the measured sizes, the nearest one's outside them"""
    Ns = [math.log(r["N"]) for r in rows]
    cs = [1e-6 * r["us_per_particle_step"] for r in rows]
    x = math.log(max(n, 1))
    if x <= Ns[0]:
        return cs[0]
    for (a, ca), (b, cb) in zip(zip(Ns, cs), zip(Ns[1:], cs[1:])):
        if x <= b:
            return ca + (cb - ca) * (x - a) / (b - a)
    return cs[-1]


def model(rows, N, P, f, halo, bytes_per_copy, exchanges):
    n = N / P
    c = cost(rows, n)
    compute = f * (n + (halo if P > 1 else 0.0)) * c
    messages = 2 * (4 + exchanges) * ALPHA if P > 1 else 0.0
    volume = halo * bytes_per_copy / BETA if P > 1 else 0.0
    reductions = REDUCTIONS * ALPHA * 2 * math.log2(P) if P > 1 else 0.0
    return compute + messages + volume + reductions


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--results", required=True)
    args = ap.parse_args()
    dense, rows = measured(args.results)
    big = rows[-1]
    steps = big["steps"] - 10
    # per processor and step, on 2 processors: copies received (= sent,
    # summed over both) and their bytes
    halo = big["copies_per_step"] / 2
    bytes_per_copy = big["bytes_per_step"] / max(big["copies_per_step"], 1)
    exchanges = big["exchanges_per_step"]
    # the imbalance that reproduces the measured 2-processor step
    t1 = min(big["serial_s"]) / steps
    t2 = min(big["np2_s"]) / steps
    unit = model(rows, big["N"], 2, 1.0, halo, bytes_per_copy, exchanges)
    comm = unit - (big["N"] / 2 + halo) * cost(rows, big["N"] / 2)
    f = max(1.0, (t2 - comm) / (unit - comm))   # (1: the model is not below the measurement)
    check = model(rows, big["N"], 2, f, halo, bytes_per_copy, exchanges)

    Ns = (1e6, 1e7, 1e8)
    Ps = (16, 64, 256, 1024, 4096)
    memory = big.get("bytes_per_particle") or (big["peak_rss_MB"] * 2**20 / big["N"])
    table = []
    for N in Ns:
        for P in Ps:
            t = model(rows, N, P, f, halo, bytes_per_copy, exchanges)
            table.append({"N": N, "P": P, "particles_per_processor": N / P, "step_s": t,
                          "wall_s_per_simulated_s": t / DT,
                          "particle_steps_per_core_second": N / (P * t),
                          "efficiency": (N * cost(rows, N / P)) / (P * t),
                          "memory_per_processor_GB": N / P * memory / 1e9})
    granular = json.load(open(os.path.join(args.results, "granularDense.json")))
    liggghts = [(r["N"], 1e9 / min(r["ns_per_grain_step"]["liggghts1"])) for r in granular["rows"]]
    engine = [(r["N"], 1e9 / min(r["ns_per_grain_step"]["ours"])) for r in granular["rows"]]
    result = {"dense": {"date": dense["date"], "load": dense["load"]},
              "assumed": {"alpha_s": ALPHA, "beta_byte_per_s": BETA, "reductions": REDUCTIONS},
              "measured": {"halo_copies_per_processor_step": halo,
                           "bytes_per_copy": bytes_per_copy, "exchanges_per_step": exchanges,
                           "serial_step_s": t1, "np2_step_s": t2,
                           "bytes_per_particle": memory},
              "fitted": {"imbalance": f, "np2_step_model_s": check},
              "predicted": table,
              "liggghts_particle_steps_per_core_second": liggghts,
              "grain_engine_particle_steps_per_core_second": engine}
    with open(os.path.join(args.results, "scalingModel.json"), "w") as out:
        json.dump(result, out, indent=1)

    with open(os.path.join(args.results, "scalingModel.md"), "w") as out:
        out.write("# A model of the wall time for 1e6-1e8 ores (benchmarks/scalingModel.py)\n\n")
        out.write("From `oreDense.json` (measured %s): the dense-phase cost per particle-step "
                  "at %s ores, %.0f halo copies per processor and step (2 processors), %.0f bytes "
                  "a copy, %g exchanges of the sub-steps' states a step, %.0f bytes per particle; assumed latency "
                  "%g us, bandwidth %g GB/s, %d global reductions a step; load imbalance fitted to "
                  "the 2-processor step %.2f (at least 1; that step measured %.3g s, modelled %.3g s; "
                  "serial %.3g s). Compute share: the time the processors spend on their own ores "
                  "over the whole (the rest: halo, messages, imbalance). "
                  "The model and its assumptions are in the script's header.\n\n"
                  % (dense["date"], ", ".join("%d" % r["N"] for r in rows), halo, bytes_per_copy,
                     exchanges, memory, ALPHA * 1e6, BETA / 1e9, REDUCTIONS, f, t2, check, t1))
        out.write("| ores | processors | ores per processor | wall s per simulated s | "
                  "particle-steps per core-second | compute share | memory per "
                  "processor [GB] |\n|---|---|---|---|---|---|---|\n")
        for r in table:
            out.write("| %.0e | %d | %.0f | %.3g | %.3g | %.2f | %.2f |\n"
                      % (r["N"], r["P"], r["particles_per_processor"], r["wall_s_per_simulated_s"],
                         r["particle_steps_per_core_second"], r["efficiency"],
                         r["memory_per_processor_GB"]))
        out.write("\nMeasured on this machine, particle-steps per core-second: riserParcelFoam "
                  "(full physics, dense phase) %s; the grain engine alone (pure DEM, a settled "
                  "bed: granularDense.json) %s; LIGGGHTS 3.8 on 1 rank on the same bed %s. "
                  "Lethe-DEM: about %.0e, at its best %d-%d particles per core (published, "
                  "not re-measured).\n"
                  % (", ".join("%.3g at %d ores" % (1e6 / r["us_per_particle_step"], r["N"])
                               for r in rows),
                     ", ".join("%.3g at %d" % (t, n) for n, t in engine),
                     ", ".join("%.3g at %d" % (t, n) for n, t in liggghts),
                     LETHE_THROUGHPUT, *LETHE_PARTICLES_PER_CORE))

    fig, (a, b) = plt.subplots(1, 2, figsize=(12, 4.6))
    for N in Ns:
        rs = [r for r in table if r["N"] == N]
        a.loglog([r["P"] for r in rs], [r["wall_s_per_simulated_s"] for r in rs], "o-",
                 label="%.0e ores (model)" % N)
        b.loglog([r["particles_per_processor"] for r in rs],
                 [r["particle_steps_per_core_second"] for r in rs], "o-",
                 label="%.0e ores (model)" % N)
    b.loglog([r["N"] for r in rows], [1e6 / r["us_per_particle_step"] for r in rows], "ks",
             label="riserParcelFoam, 1 core (measured)")
    b.loglog([r["N"] / 2 for r in rows],
             [r["N"] / (2 * min(r["np2_s"]) / (r["steps"] - 10)) for r in rows], "k^",
             label="riserParcelFoam, 2 cores (measured)")
    b.loglog([n for n, _ in engine], [t for _, t in engine], "bD",
             label="grain engine alone, pure DEM (measured)")
    b.loglog([n for n, _ in liggghts], [t for _, t in liggghts], "rv",
             label="LIGGGHTS 3.8, 1 rank, same scene (measured)")
    b.fill_between(LETHE_PARTICLES_PER_CORE, LETHE_THROUGHPUT / 2, LETHE_THROUGHPUT * 2,
                   color="0.8", label="Lethe-DEM, order published")
    a.set_xlabel("processors")
    a.set_ylabel("wall seconds per simulated second")
    a.set_title("model: dense phase, dt = 1e-4 s")
    a.grid(True, which="both", alpha=0.3)
    a.legend(fontsize=8)
    b.set_xlabel("particles per processor")
    b.set_ylabel("particle-steps per core-second")
    b.grid(True, which="both", alpha=0.3)
    b.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(os.path.join(args.results, "scalingModel.png"), dpi=110)


if __name__ == "__main__":
    main()
