// Gondret, Lance & Petit (2002), St = 152: a steel sphere falls from rest in
// silicone oil and bounces on a flat horizontal wall. The sphere, the
// liquid and the wall are the law of ../common/sphereOnFlatWall.hpp (drag
// of an unbounded sphere, C_A = 1/2, classical Basset force, Hertz–Mindlin
// contact). Each run is done with and without the Basset force. The dry
// runs have no lubrication and no wall correction of the drag (no run has
// the latter): the sphere meets the wall with its free-fall speed and
// leaves it with about e_dry times that (0.968 with Basset, 0.971 without:
// the added mass and the history take part in the 16 us contact that was
// calibrated for m_p alone). Two more runs are wet by the restitution
// e = e_dry exp(-35/St), St = (rho_p + rho_f/2) v d/(9 mu) of the approach
// speed (Legendre et al., Chem. Eng. Sci. 61, 3543, 2006), none below St 10.
// Two more are lubricated, with the film's defaults (cutoff 0.1, roughness
// 2e-6, which were chosen to follow Legendre et al.'s fit, not this
// experiment): the dry contact keeps e_dry and the film's force
// -6 pi mu R^2 v (1/max(h, h_r) - 1/h_cut) acts below the gap h_cut = 0.1 R.
//
// Release from rest at a gap of 1 m. Without the Basset force the sphere
// reaches its terminal speed within 0.2 m; with it, it approaches that speed
// only as t^-1/2 (2% below it after 1 m, 1% after 3 m), so the release
// height is one of the checks the program prints.
//
// One constant step for the whole
// run (the history's grid): 5e-7 s, 1/32 of the Hertz contact time; a dry
// impact then rebounds with e = 0.9699 for 0.97. The history costs O(window)
// per step, so the 4e6 steps of a run take a few seconds.
//
// Numbers and their sources:
//   sphere d = 3 mm, 7800 kg/m^3; oil 935 kg/m^3, mu = 0.01 Pa s; St = 152:
//       Gondret, Lance & Petit, Phys. Fluids 14, 643 (2002); the same set in
//       Table 1 of Biegert, Vowinckel & Meiburg, J. Comput. Phys. 340, 105
//       (2017) (u_in = 0.585 m/s, rho_p/rho_f = 8.342, nu = 1.070e-5 m^2/s)
//   e_dry = 0.97: Biegert et al. (2017), Table 1 and sec. 3.2 ("for glass
//       and hard metals e_dry = 0.97 is a typical value", citing Foerster et
//       al. 1994, Joseph et al. 2001, Gondret et al. 2002)
//   wall: glass (assumed; E = 63 GPa, nu = 0.23, typical soda-lime values),
//       sphere: steel (E = 200 GPa, nu = 0.3, as the steel of doc/theory.md section 3). The
//       elastic constants set the contact time (~15 us) only, not e.
//   experiment: the digitized gap h(t) given as the first argument.
//
// usage: gondret <gap csv> <output folder>
// writes <output folder>/curve_<variant>.dat (basset, noBasset, wet,
// wetNoBasset: t after the first contact, gap, v) and prints the comparison (Allrun keeps it in
// results/summary.txt)
// SPDX-License-Identifier: GPL-3.0-or-later
#include "sphereOnFlatWall.hpp"

#include <fstream>
#include <sstream>

using namespace validation;

namespace {

//- Gondret et al.'s steel sphere in silicone oil over a glass wall (assumed)
Scene gondretScene()
{
    //    d [m], rho_p, rho_f [kg/m^3], mu [Pa s], g, C_A, release gap [m], e_dry
    return {3e-3, 7800.0, 935.0, 0.01, 9.81, 0.5, 1.0, 0.97,
            {200e9, 0.3},       // steel
            {63e9, 0.23}};      // glass (assumed)
}

//- Model gap at time t after the first contact (linear between samples)
double gapAt(const Run& r, double t)
{
    const double ta = t + r.t0();
    auto it = std::lower_bound(r.curve.begin(), r.curve.end(), ta,
                               [](const Sample& a, double x) { return a.t < x; });
    if (it == r.curve.begin() || it == r.curve.end()) return NAN;
    const Sample& b = *it;
    const Sample& a = *(it - 1);
    return a.gap + (ta - a.t)/(b.t - a.t)*(b.gap - a.gap);
}

struct Experiment { std::vector<double> t, gap; };

Experiment readExperiment(const std::string& file)
{
    Experiment e;
    std::ifstream in(file);
    std::string line;
    while (std::getline(in, line))
    {
        if (line.empty() || line[0] == '#') continue;
        double t, g;
        char comma;
        std::istringstream row(line);
        if (row >> t >> comma >> g) { e.t.push_back(t); e.gap.push_back(g); }
    }
    return e;
}

//- Every stride-th sample from t0 + from to t0 + to
void writeCurve(const Run& r, const std::string& file, double from, double to, size_t stride)
{
    FILE* f = std::fopen(file.c_str(), "w");
    std::fprintf(f, "# t - t_first_contact [s]  gap [m]  v [m/s]\n");
    for (size_t i = 0; i < r.curve.size(); i += stride)
    {
        const Sample& p = r.curve[i];
        const double t = p.t - r.t0();
        if (t >= from && t <= to) std::fprintf(f, "%.5e %.5e %.5e\n", t, p.gap, p.v);
    }
    std::fclose(f);
}

} // namespace

int main(int argc, char* argv[])
{
    if (argc != 3)
    {
        std::fprintf(stderr, "usage: %s <gap csv> <output folder>\n", argv[0]);
        return 2;
    }
    const Experiment exp = readExperiment(argv[1]);
    const std::string out = argv[2];
    if (exp.t.size() < 10) { std::fprintf(stderr, "no data in %s\n", argv[1]); return 1; }

    const Scene s = gondretScene();
    const double h = 5e-7;              // ~32 steps per contact at 0.585 m/s
    const double windowTime = 1e-4;     // Basset window (200 steps) + tail
    const double tAfter = 0.25;         // followed past the first contact
    const long outputEvery = 20;        // samples every 1e-5 s
    HistoryTailConstants::weights(HistoryTail::leastSquares);    // fit once, untimed

    auto say = [](const char* fmt, auto... args) { std::printf(fmt, args...); };

    // --- experiment: approach speed, apexes (local maxima above 0.3 mm) ----
    double st = 0, sg = 0, stt = 0, stg = 0;
    int n = 0;
    for (size_t i = 0; i < exp.t.size(); ++i)
    {
        if (exp.t[i] >= 0.0) continue;
        st += exp.t[i]; sg += exp.gap[i]; stt += exp.t[i]*exp.t[i]; stg += exp.t[i]*exp.gap[i]; ++n;
    }
    const double vExp = -(n*stg - st*sg)/(n*stt - st*st);
    std::vector<Apex> expApex;
    for (size_t i = 1; i + 1 < exp.t.size(); ++i)
    {
        if (exp.gap[i] > 3e-4 && exp.gap[i] > exp.gap[i - 1] && exp.gap[i] > exp.gap[i + 1])
        {
            expApex.push_back({exp.t[i], exp.gap[i]});
        }
    }
    const Apex published[3] = {{0.037, 7.47e-3}, {0.106, 2.23e-3}, {0.140, 0.52e-3}};

    const SphereOnFlatWall probe(s, false);
    const double Vt = terminalSpeed(s), ReT = s.reynolds(Vt);
    auto stokes = [&s](double v) { return s.stokes(v); };
    say("Gondret, Lance & Petit (2002), St = 152: steel sphere d = %g mm, %g kg/m^3, in silicone oil"
        " (%g kg/m^3, %g Pa s) on a glass wall (assumed)\n", s.d*1e3, s.rhoP, s.rhoF, s.mu);
    say("model: drag Clift-Gauvin (unbounded), C_A = %g, Basset C_H = 6 or none, Hertz-Mindlin with"
        " e_dry = %g (steel on glass); dry and wet: no lubrication; film: the lubrication film (cutoff 0.1, roughness 2e-6); no wall-corrected drag\n", s.CA, s.eDry);
    say("release from rest at a gap of %.2f m; constant step h = %.1e s; Basset window %.0e s + tail"
        " (least-squares constants)\n", s.releaseGap, h, windowTime);
    say("terminal speed of the drag law: %.4f m/s (Re = %.1f, St = %.1f)\n", Vt, ReT, stokes(Vt));
    say("Hertz contact time at 0.585 m/s: %.1f us = %.0f steps; a dry impact with this stepper and step"
        " rebounds with e = %.5f at 0.585 m/s, %.5f at 0.1 m/s\n",
        probe.contactTime(0.585)*1e6, probe.contactTime(0.585)/h,
        dryRestitution(s, 0.585, h), dryRestitution(s, 0.1, h));
    say("experiment: approach speed %.4f m/s (least-squares slope of its %d points before contact)\n\n",
        vExp, n);

    struct Variant { const char* name; const char* title; bool basset; Wetness wet; };
    const Variant variants[] =
        {{"basset", "with Basset", true, Wetness::dry},
         {"noBasset", "no Basset", false, Wetness::dry},
         {"wet", "wet, Basset", true, Wetness::restitution},
         {"wetNoBasset", "wet, no Basset", false, Wetness::restitution},
         {"film", "film, Basset", true, Wetness::film},
         {"filmNoBasset", "film, no Basset", false, Wetness::film}};
    const int nVariants = sizeof variants/sizeof variants[0];
    std::vector<Run> runs;
    for (const Variant& v : variants)
    {
        runs.push_back(bounce(s, v.basset, h, windowTime, tAfter, outputEvery, v.wet));
        writeCurve(runs.back(), out + "/curve_" + v.name + ".dat", -0.05, tAfter, 10);
    }

    auto apexGap = [](const Run& r, int a) { return a < int(r.apexes.size()) ? r.apexes[a].gap*1e3 : NAN; };
    auto apexTime = [](const Run& r, int a) { return a < int(r.apexes.size()) ? r.apexes[a].t - r.t0() : NAN; };
    auto rmsGap = [&exp](const Run& r, double* worst)
    {
        double sq = 0.0;
        *worst = 0.0;
        for (size_t i = 0; i < exp.t.size(); ++i)
        {
            const double d = gapAt(r, exp.t[i]) - exp.gap[i];
            sq += d*d;
            *worst = std::max(*worst, std::abs(d));
        }
        return std::sqrt(sq/exp.t.size());
    };
    //- a row: the label, the experiment's column, then value(k) of each
    //  variant k
    auto row = [&](const char* label, const std::string& expCol, const char* fmt, auto value)
    {
        say("%-32s %18s", label, expCol.c_str());
        for (int k = 0; k < nVariants; ++k) say(fmt, value(k));
        say("\n");
    };
    auto text = [](const char* fmt, auto... args)
    {
        char b[64];
        std::snprintf(b, sizeof b, fmt, args...);
        return std::string(b);
    };

    say("%-32s %18s", "", "exp. (digitized)");
    for (const Variant& v : variants) say(" %14s", v.title);
    say("\n");
    row("impact speed [m/s]", text("%.3f", 0.585), " %14.4f",
        [&](int k) { return -runs[k].contacts[0].vTouch; });
    for (int a = 0; a < 3; ++a)
    {
        const double e = a < int(expApex.size()) ? expApex[a].gap*1e3 : NAN;
        const double te = a < int(expApex.size()) ? expApex[a].t : NAN;
        row(text("apex %d gap [mm]", a + 1).c_str(), text("%.2f (%7.3f)", published[a].gap*1e3, e),
            " %14.3f", [&](int k) { return apexGap(runs[k], a); });
        row(text("apex %d time [s]", a + 1).c_str(), text("%.3f (%7.4f)", published[a].t, te),
            " %14.4f", [&](int k) { return apexTime(runs[k], a); });
    }
    std::vector<double> rms, worst(nVariants);
    for (int k = 0; k < nVariants; ++k) rms.push_back(rmsGap(runs[k], &worst[k]));
    row("RMS gap difference [mm]", "-", " %14.3f", [&](int k) { return rms[k]*1e3; });
    row("largest gap difference [mm]", "-", " %14.3f", [&](int k) { return worst[k]*1e3; });
    say("  (over its %zu points, t = %.4f .. %.4f s; t = 0 at the first contact of each;"
        " published values first, digitized maxima in brackets)\n",
        exp.t.size(), exp.t.front(), exp.t.back());
    row("CPU time [s]", "-", " %14.2f", [&](int k) { return runs[k].cpu; });
    row("steps (release to +0.25 s)", "-", " %14ld", [&](int k) { return runs[k].steps; });

    for (int k = 0; k < nVariants; ++k)
    {
        say("\ncontacts %s (t after the first; St = rho_p d v_in/(9 mu); e = v_out/v_in over the"
            " contact):\n", variants[k].title);
        for (size_t c = 0; c < runs[k].contacts.size() && c < 6; ++c)
        {
            const Contact& C = runs[k].contacts[c];
            say("  %zu: t = %.4f s, v_in = %.4f m/s, St = %5.1f, ", c + 1, C.tTouch - runs[k].t0(),
                -C.vTouch, stokes(C.vTouch));
            if (std::isnan(C.tLeave)) say("stays on the wall\n");
            else say("v_out = %.4f m/s, e = %.4f, %.1f us\n", C.vLeave, -C.vLeave/C.vTouch,
                     (C.tLeave - C.tTouch)*1e6);
        }
    }

    // --- numerical checks and the release height (with Basset) ------------
    say("\nchecks, with Basset: impact speed [m/s], apex gaps [mm], RMS [mm]\n");
    say("  %-26s %.4f, %.3f %.3f %.3f, %.3f\n", "this run", -runs[0].contacts[0].vTouch,
        apexGap(runs[0], 0), apexGap(runs[0], 1), apexGap(runs[0], 2), rms[0]*1e3);
    struct Check { const char* name; double h, window, release; };
    const Check checks[] = {
        {"h = 1e-6 s", 1e-6, windowTime, s.releaseGap},
        {"h = 1e-6 s, window 5e-4 s", 1e-6, 5e-4, s.releaseGap},
        {"h = 1e-6 s, release 0.2 m", 1e-6, windowTime, 0.2},
        {"h = 1e-6 s, release 3 m", 1e-6, windowTime, 3.0}};
    for (const Check& c : checks)
    {
        Scene sc = s;
        sc.releaseGap = c.release;
        const Run r = bounce(sc, true, c.h, c.window, 0.18, std::lround(1e-5/c.h));
        double w;
        say("  %-26s %.4f, %.3f %.3f %.3f, %.3f  (cpu %.1f s)\n", c.name, -r.contacts[0].vTouch,
            apexGap(r, 0), apexGap(r, 1), apexGap(r, 2), rmsGap(r, &w)*1e3, r.cpu);
    }
    return 0;
}
