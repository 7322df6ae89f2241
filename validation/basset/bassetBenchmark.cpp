// Basset history benchmark: cost per particle-step against history length,
// memory per particle, work-precision on the settling closed form, and the
// stability limit of an explicit newest weight. Writes its numbers into the
// folder given as argument (costPerStep.dat, workPrecision.dat,
// stability.dat); validation/basset/Allrun runs it and plots them.
//
// The measured step is what a cloud does for each particle and step: the
// known part of the history at the next time and the push of the newest
// value, for a 3-vector history (riser::HistoryKernel, HistoryState).
//
// usage: bassetBenchmark <output folder>
// SPDX-License-Identifier: GPL-3.0-or-later
#include "basset/historyIntegral.hpp"
#include "motion/historyStepper.hpp"
#include "bassetClosedForms.hpp"

#include <Eigen/Core>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <string>
#include <vector>

using namespace riser;
using Vec = Eigen::Vector3d;

namespace {

// g values of a smooth, non-trivial slip history
Vec sample(long k)
{
    const double t = 1e-3*k;
    return Vec(std::sin(t), std::cos(1.3*t), std::sin(0.7*t + 1.0));
}

// Best-of-five wall time per step [ns] of knownPart + push at history length n
double costPerStep(const HistoryKernel& kernel, long n, long steps, Vec& sink)
{
    HistoryState<Vec> state = kernel.start(Vec(0.1, 0.0, 0.0), sample(0));
    for (long k = 1; k <= n; ++k) kernel.push(state, sample(k));
    double best = HUGE_VAL;
    for (int rep = 0; rep < 5; ++rep)
    {
        HistoryState<Vec> s = state;
        const auto start = std::chrono::steady_clock::now();
        for (long k = 1; k <= steps; ++k)
        {
            sink += kernel.knownPart(s);
            kernel.push(s, sample(n + k));
        }
        const auto end = std::chrono::steady_clock::now();
        best = std::min(best, std::chrono::duration<double, std::nano>(end - start).count()/steps);
    }
    return best;
}

// Heap and object bytes a particle's history holds
long bytesPerParticle(const HistoryKernel& kernel, long n)
{
    HistoryState<Vec> s = kernel.start(Vec::Zero().eval(), Vec::Zero().eval());
    for (long k = 1; k <= n; ++k) kernel.push(s, sample(k));
    return long(sizeof(s) + s.window.capacity()*sizeof(Vec));
}

struct Run { double cpu, error; };

// Settling from rest to tEnd: CPU time of the stepping alone, and the
// largest error against the closed form relative to V(tEnd)
Run settling(const oracle::StokesSphere& s, HistoryMethod method, HistoryTail tail,
             double h, double windowTime, double tEnd)
{
    const long n = std::lround(tEnd/h);
    const long window = method == HistoryMethod::windowTail ? std::max(2L, std::lround(windowTime/h)) : 0;
    std::vector<double> v(n);
    // repeated until 0.2 s of CPU time have passed (short runs are below
    // the clock's resolution), the time per run reported
    int runs = 0;
    const std::clock_t start = std::clock();
    do
    {
        HistoryStepper<oracle::StokesSphere> stepper(s, method, h, window, 0.0, 0.0,
                                                     NewestHistoryWeight::implicit, tail);
        for (long k = 0; k < n; ++k)
        {
            stepper.step();
            v[k] = stepper.velocity();
        }
        ++runs;
    } while (std::clock() - start < CLOCKS_PER_SEC/5);
    const double cpu = double(std::clock() - start)/CLOCKS_PER_SEC/runs;
    oracle::StokesSphere withBasset = s;
    withBasset.CH = 6.0;
    double worst = 0.0;
    for (long k = 0; k < n; ++k)
    {
        worst = std::max(worst, std::abs(v[k] - oracle::settlingClosedForm(withBasset, (k + 1)*h)));
    }
    return {cpu, worst/oracle::settlingClosedForm(withBasset, tEnd)};
}

} // namespace

int main(int argc, char* argv[])
{
    if (argc != 2)
    {
        std::fprintf(stderr, "usage: %s <output folder>\n", argv[0]);
        return 2;
    }
    const std::string out = argv[1];
    Vec sink = Vec::Zero();

    // --- cost per step and memory against history length -----------------
    {
        FILE* f = std::fopen((out + "/costPerStep.dat").c_str(), "w");
        std::fprintf(f, "# method window n ns_per_step bytes_per_particle\n");
        const double h = 1e-3;
        struct Case { const char* name; HistoryMethod method; long window; };
        const Case cases[] = {
            {"windowTail", HistoryMethod::windowTail, 20},
            {"windowTail", HistoryMethod::windowTail, 100},
            {"fullHistory", HistoryMethod::fullHistory, 0}};
        for (const Case& c : cases)
        {
            const HistoryKernel kernel(c.method, h, c.window);
            double first = 0.0;
            for (long n : {1000L, 10000L, 100000L})
            {
                // the full history grows while it is timed: 5% of n steps
                const long steps = c.method == HistoryMethod::fullHistory ? std::max(20L, n/20) : 200000L;
                const double ns = costPerStep(kernel, n, steps, sink);
                if (n == 1000) first = ns;
                const long bytes = bytesPerParticle(kernel, n);
                std::fprintf(f, "%s %ld %ld %.2f %ld\n", c.name, c.window, n, ns, bytes);
                std::printf("%-11s N = %3ld  history %6ld steps: %10.1f ns/step (x%.3f of 1e3), %7ld bytes/particle\n",
                            c.name, c.window, n, ns, ns/first, bytes);
            }
        }
        std::fclose(f);
    }

    // --- work-precision on the settling closed form ----------------------
    {
        FILE* f = std::fopen((out + "/workPrecision.dat").c_str(), "w");
        std::fprintf(f, "# method tail windowTime[s] h[s] cpu[s] maxRelError\n");
        const oracle::StokesSphere sphere{5e-4, 2000.0};
        HistoryTailConstants::weights(HistoryTail::leastSquares);    // fit once, untimed
        const double tEnd = 1.0;
        struct Case { const char* name; HistoryMethod method; HistoryTail tail; double windowTime; double CH; };
        const Case cases[] = {
            {"fullHistory", HistoryMethod::fullHistory, HistoryTail::vanHinsberg2011, 0.0, 6.0},
            {"windowTail", HistoryMethod::windowTail, HistoryTail::vanHinsberg2011, 0.1, 6.0},
            {"windowTail", HistoryMethod::windowTail, HistoryTail::leastSquares, 0.1, 6.0},
            {"windowTail", HistoryMethod::windowTail, HistoryTail::vanHinsberg2011, 0.01, 6.0},
            {"noBasset", HistoryMethod::windowTail, HistoryTail::vanHinsberg2011, 0.01, 0.0}};
        for (const Case& c : cases)
        {
            oracle::StokesSphere s = sphere;
            s.CH = c.CH;
            for (double h : {1e-2, 5e-3, 2e-3, 1e-3, 5e-4, 2e-4, 1e-4})
            {
                const Run r = settling(s, c.method, c.tail, h, c.windowTime, tEnd);
                const char* tail = c.tail == HistoryTail::leastSquares ? "leastSquares" : "vanHinsberg2011";
                std::fprintf(f, "%s %s %g %g %.6g %.6e\n", c.name, tail, c.windowTime, h, r.cpu, r.error);
                std::printf("%-11s %-15s window %5.3f s  h = %6.0e s: cpu %.3e s, error %.3e\n",
                            c.name, tail, c.windowTime, h, r.cpu, r.error);
            }
        }
        std::fclose(f);
    }

    // --- stability of the newest weight: light particle ------------------
    {
        FILE* f = std::fopen((out + "/stability.dat").c_str(), "w");
        std::fprintf(f, "# h[s] h/hCrit largest|v|/Vt_lagged largest|v|/Vt_implicit\n");
        const oracle::StokesSphere s{5e-4, 100.0};          // rho_p/rho_f = 0.1
        const double nu = s.mu/s.rhoF, beta = s.rhoP/s.rhoF;
        // K_H (4/3) sqrt(h) = m_p + m_A  <=>  h = pi a^2 (beta + 1/2)^2/(36 nu)
        const double hCrit = M_PI*s.a*s.a*(beta + 0.5)*(beta + 0.5)/(36.0*nu);
        const double Vt = std::abs(oracle::settlingClosedForm(s, 1e3));
        for (double ratio : {0.1, 0.2, 0.3, 0.35, 0.38, 0.4, 0.42, 0.45, 0.5, 1.0, 2.0, 5.0, 10.0})
        {
            const double h = ratio*hCrit;
            const long n = std::max(200L, std::lround(2.0/h));
            HistoryStepper<oracle::StokesSphere> lagged(s, HistoryMethod::windowTail, h, 50, 0.0, 0.0,
                                                        NewestHistoryWeight::lagged);
            HistoryStepper<oracle::StokesSphere> implicit(s, HistoryMethod::windowTail, h, 50, 0.0);
            double worstLagged = 0.0, worstImplicit = 0.0;
            for (long k = 0; k < n; ++k)
            {
                lagged.step();
                implicit.step();
                const double vl = std::abs(lagged.velocity());
                worstLagged = std::isfinite(vl) ? std::max(worstLagged, vl) : HUGE_VAL;
                worstImplicit = std::max(worstImplicit, std::abs(implicit.velocity()));
                if (worstLagged > 1e30) break;
            }
            std::fprintf(f, "%g %g %.6e %.6e\n", h, ratio, std::min(worstLagged/Vt, 1e30), worstImplicit/Vt);
            std::printf("light particle h = %.3e s = %5.2f h_crit: largest |v|/V_t lagged %.3e, implicit %.4f\n",
                        h, ratio, std::min(worstLagged/Vt, 1e30), worstImplicit/Vt);
        }
        std::fclose(f);
    }
    std::printf("(checksum %g)\n", sink.norm());
    return 0;
}
