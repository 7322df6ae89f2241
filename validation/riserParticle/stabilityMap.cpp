// Where the mesh-free engine's methods fail (riser::PaperScheme and
// riser::AdaptiveScheme of src/riserCore/motion/riserIntegrators.hpp):
//
// 1. flow steps against the particle response time: the f = 0.3 riser scene
//    (A = D = 0.1 m, f = 3 Hz, u_cm = 1 m/s, water, rho_p = 2000 kg/m^3,
//    no wall contact) over one riser period for d = 10 um .. 10 mm, with the
//    paper's drag law (it jumps at Re_p = 1 and 100) and the continuous one,
//    with the paper's fixed fifth-order flow steps h = 3e-6 .. 1e-2 s, against the
//    adaptive scheme at tolerance 1e-11; and the adaptive scheme's own cost
//    at its default tolerance. tau_p = (m_p + m_A)/c, c the drag factor
//    F_D = c w at the particle's terminal slip (Stokes for small d).
// 2. contact steps against the Hertz contact time: a dry normal impact
//    (10 mm ore sphere on the steel wall, doc/theory.md section 3) at 1 m/s with
//    e_n = 0.76 and 1, the paper's RK4 contact step h_c = 1e-3 .. 1 t_c,
//    t_c measured by the adaptive scheme at tolerance 1e-10; the measured
//    restitution's error and, at e_n = 1, the energy change per contact;
//    the adaptive scheme at tolerances 1e-3 .. 1e-10 on the same impact.
// 3. where the paper scheme's contact starts (ContactStart): the energy
//    change per contact at e_n = 1 against the flow step, the contact
//    starting at detection or at the overlap the flow step left.
//
// usage: stabilityMap <results folder>; writes stabilityFlow.dat,
// stabilityContact.dat, stabilityStart.dat and prints a summary.
//
// SPDX-License-Identifier: GPL-3.0-or-later
#include "motion/riserIntegrators.hpp"

#include <chrono>
#include <cstdio>
#include <string>
#include <vector>

using namespace riser;

namespace {

const double D = 0.1, rhoP = 2000.0, rhoF = 1000.0, mu = 1e-3;
const Vector g(0.0, 0.0, -9.81);

HertzMindlinParameters sceneContact(double en)
{
    return HertzMindlinParameters{ElasticMaterial{6e10, 0.26}, ElasticMaterial{2e11, 0.3},
                                  en, 0.7, 0.2, NormalForceFloor::tensionAllowed};
}

// The particle's response time at its terminal slip (the drag's stiffness)
double responseTime(const RiserParticleLaw& law)
{
    const double d = law.diameter();
    const WallFactors w(d/D);
    const double weight = (law.mass() - law.fluidMass())*g.norm();
    double lo = 0.0, hi = 100.0;            // terminal slip by bisection
    for (int i = 0; i < 200; ++i)
    {
        const double s = 0.5*(lo + hi);
        const double F = dragFactor(DragLaw::paper, w, d, mu, rhoF*s*d/mu)*s;
        (F > weight ? hi : lo) = s;
    }
    const double c = dragFactor(DragLaw::paper, w, d, mu, rhoF*lo*d/mu);
    return law.inertia()/c;
}

struct Run
{
    std::vector<Vector> rows;
    IntegratorStats stats;
    std::vector<ContactRecord> contacts;
    bool failed = false;
    double cpu = 0.0;
};

template<class Scheme>
Run run(const Scheme& scheme, const RiserParticleLaw& law, const ParticleState& s,
        double tEnd, double every)
{
    Run r;
    Observer obs;
    obs.row = [&](double, const ParticleState& p) { r.rows.push_back(p.x); };
    obs.contact = [&](const ContactRecord& c) { r.contacts.push_back(c); };
    const auto start = std::chrono::steady_clock::now();
    try
    {
        r.stats = scheme.run(law, 0.0, s, tEnd, every, obs);
    }
    catch (const IntegrationFailure&)
    {
        r.failed = true;
    }
    r.cpu = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return r;
}

double largestDifference(const Run& a, const Run& b)
{
    double worst = 0.0;
    for (std::size_t i = 0; i < std::min(a.rows.size(), b.rows.size()); ++i)
    {
        worst = std::max(worst, (a.rows[i] - b.rows[i]).norm());
    }
    return worst;
}

} // namespace


int main(int argc, char** argv)
{
    const std::string out = argc > 1 ? argv[1] : ".";

    // 1. flow steps against the response time
    {
        const RiserFlow riser(D, 1.0, 0.1, 2.0*M_PI*3.0, 0.0);
        const double T = 1.0/3.0, every = T/50;
        FILE* f = std::fopen((out + "/stabilityFlow.dat").c_str(), "w");
        std::fprintf(f, "# dragLaw d[m] tau_p[s] scheme h[s] h/tau_p positionError/D failed "
                        "forceEvaluations cpu[s] (one period of the f = 0.3 scene, no contact)\n");
        for (DragLaw dragLaw : {DragLaw::paper, DragLaw::continuous})
        for (double d : {1e-5, 3e-5, 1e-4, 3e-4, 1e-3, 3e-3, 1e-2})
        {
            ForceSelection forces;
            forces.dragLaw = dragLaw;
            const char* lawName = dragLaw == DragLaw::paper ? "paper" : "continuous";
            const RiserParticleLaw law(riser, d, rhoP, rhoF, mu, g, forces, std::nullopt);
            const double tau = responseTime(law);
            ParticleState s;
            s.x = Vector(0.02, 0.02, 0.0);
            s.v = riser.velocity(s.x, 0.0);
            const Run ref = run(AdaptiveScheme(1e-11, 1e9), law, s, T, every);
            // the engine's default tolerance (riserParticle's integrator)
            const Run def =
                run(AdaptiveScheme(AdaptiveScheme::defaultTolerance, 1e9), law, s, T, every);
            std::fprintf(f, "%s %g %.4e adaptive %.4e %.4e %.4e %d %ld %.4e\n", lawName, d, tau,
                         T/std::max(1L, def.stats.steps), T/std::max(1L, def.stats.steps)/tau,
                         largestDifference(def, ref)/D, int(def.failed),
                         def.stats.forceEvaluations, def.cpu);
            std::printf("%s drag, d = %g m: tau_p = %.3e s; adaptive (%g): %ld steps per "
                        "period, error %.2e D\n", lawName, d, tau,
                        AdaptiveScheme::defaultTolerance, def.stats.steps,
                        largestDifference(def, ref)/D);
            for (double h : {3e-6, 1e-5, 3e-5, 1e-4, 3e-4, 1e-3, 3e-3, 1e-2})
            {
                const Run p = run(PaperScheme(h, 1e-7, 1e-3), law, s, T, every);
                const double err = p.failed ? NAN : largestDifference(p, ref)/D;
                std::fprintf(f, "%s %g %.4e paper %.4e %.4e %.4e %d %ld %.4e\n", lawName, d, tau,
                             h, h/tau,
                             err, int(p.failed || !(err < 1.0)), p.stats.forceEvaluations, p.cpu);
            }
        }
        std::fclose(f);
    }

    // 2. contact steps against the Hertz contact time
    {
        ForceSelection none = ForceSelection::none();
        const RiserFlow still(D, 1.0, 0.0, 0.0, 0.0);
        const double d = 0.01, v0 = 1.0;
        ParticleState s;
        s.x = Vector(0.5*D - 0.5*d - 1e-4, 0.0, 0.0);  // 0.1 mm from the wall
        s.v = Vector(v0, 0.0, 0.0);
        FILE* f = std::fopen((out + "/stabilityContact.dat").c_str(), "w");
        std::fprintf(f, "# e_n scheme setting h/t_c restitutionError energyChange failed "
                        "contactSteps forceEvaluations (dry normal impact, 10 mm, 1 m/s)\n");
        for (double en : {0.76, 1.0})
        {
            const RiserParticleLaw law(still, d, rhoP, rhoF, mu, g, none, sceneContact(en));
            const Run ref = run(AdaptiveScheme(1e-10, 1e9), law, s, 1e-3, 1e-3);
            const double tc = ref.contacts.at(0).end - ref.contacts.at(0).start;
            if (en == 1.0)
            {
                std::printf("Hertz contact time t_c = %.3e s at %.1f m/s (10 mm ore on steel); "
                            "the paper's contact step 1e-7 s is %.2e t_c\n", tc, v0, 1e-7/tc);
            }
            auto write = [&](const char* scheme, double setting, double hOverTc, const Run& r)
            {
                const bool ok = !r.failed && r.contacts.size() == 1;
                const double e = ok ? r.contacts[0].reboundSpeed/r.contacts[0].impactSpeed : NAN;
                std::fprintf(f, "%g %s %.4e %.4e %.4e %.4e %d %ld %ld\n", en, scheme, setting,
                             hOverTc, std::abs(e - en)/en, e*e - 1.0, int(!ok),
                             r.stats.contactSteps, r.stats.forceEvaluations);
            };
            for (double r : {1e-3, 3e-3, 1e-2, 3e-2, 0.1, 0.2, 0.3, 0.5, 0.7, 1.0})
            {
                // flow steps of 1e-7 s: detection within 0.1 um of the wall
                write("paper", r*tc, r, run(PaperScheme(1e-7, r*tc, 1e-3), law, s, 1e-3, 1e-3));
            }
            for (double tol : {1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8, 1e-9, 1e-10})
            {
                const Run a = run(AdaptiveScheme(tol, 1e9), law, s, 1e-3, 1e-3);
                write("adaptive", tol, 1.0/std::max(1L, a.stats.contactSteps), a);
            }
        }
        std::fclose(f);
    }

    // 3. where the paper scheme's contact starts, against the flow step
    {
        ForceSelection none = ForceSelection::none();
        const RiserFlow still(D, 1.0, 0.0, 0.0, 0.0);
        const double d = 0.01, v0 = 1.0;
        const RiserParticleLaw law(still, d, rhoP, rhoF, mu, g, none, sceneContact(1.0));
        FILE* f = std::fopen((out + "/stabilityStart.dat").c_str(), "w");
        std::fprintf(f, "# flowStep[s] v0*h/deltaMax start energyChange failed "
                        "(dry normal impact, e_n = 1, contact step 1e-8 s)\n");
        const Run ref = run(AdaptiveScheme(1e-10, 1e9), law,
                            ParticleState{Vector(0.5*D - 0.5*d - 1e-4, 0, 0), Vector(v0, 0, 0),
                                          Vector::Zero()}, 1e-3, 1e-3);
        const double deltaMax = ref.contacts.at(0).maxOverlap;
        for (double h : {1e-8, 3e-8, 1e-7, 3e-7, 1e-6, 3e-6, 1e-5, 3e-5, 1e-4})
        {
            for (auto start : {ContactStart::detection, ContactStart::geometric})
            {
                // released 0.1 mm + h/3 from the wall: the flow step that
                // reaches it ends inside by a fraction of v0 h
                ParticleState s;
                s.x = Vector(0.5*D - 0.5*d - 1e-4 - h/3.0, 0.0, 0.0);
                s.v = Vector(v0, 0.0, 0.0);
                const Run r = run(PaperScheme(h, 1e-8, 1e-3, start), law, s, 2e-3, 2e-3);
                const bool ok = !r.failed && !r.contacts.empty();
                const double e = ok ? r.contacts[0].reboundSpeed/r.contacts[0].impactSpeed : NAN;
                std::fprintf(f, "%.4e %.4e %s %.4e %d\n", h, v0*h/deltaMax,
                             start == ContactStart::detection ? "detection" : "geometric",
                             e*e - 1.0, int(!ok));
            }
        }
        std::printf("largest overlap of the 1 m/s impact: %.3e m\n", deltaMax);
        std::fclose(f);
    }
    return 0;
}
