// A sphere falling from rest in a quiescent liquid onto a flat horizontal
// wall, vertical motion only: the model of doc/theory.md section 1 with the
// carrier at rest,
//
//   (m_p + C_A m_f) dv/dt = -c(Re) v - (m_p - m_f) g + F_H + F_C,   dz/dt = v
//
// c(Re): the standard drag curve of Clift & Gauvin (riser::dragFactor,
// DragLaw::continuous) with the pipe's wall factors switched off (d/D = 0:
// an unbounded sphere; no wall correction of the drag near the flat wall
// either); F_H the Basset force with the classical C_H = 6
// (riser::HistoryStepper, newest weight implicit, window + tail), with the
// classical kernel or Mei & Adrian's finite-Re one; F_C the
// Hertz–Mindlin wall force with Tsuji damping calibrated to e_dry
// (riser::HertzMindlin), dry, wet by its restitution e(St)
// (riser::WetRestitution, the library's `wet { type stokesRestitution; }`,
// calibrated as in the library for the inertia m_p + C_A m_f) or dry behind
// the lubrication film (riser::LubricationFilm, `wet { type lubrication; }`
// with its defaults).
//
// Position and velocity share the stepper's trapezoidal rule: the law keeps
// the last committed state (t_n, z_n, v_n) and evaluates the force at
// z = z_n + (t - t_n)(v_n + v)/2, so the stepper's fixed-point iteration on
// v_{n+1} solves the contact implicitly. The film enters each step as its
// exact impulse between the step's two gaps over the step (the gap at the
// step's end from the stepper's own iteration), as the library's contact
// kernel takes it; the trapezoid then applies half of it in the step and
// half in the next, so the film's whole impulse is kept.
//
// Used by validation/gondret (a bouncing steel sphere, St = 152) and
// validation/tenCate (a nylon sphere settling onto the bottom, St 0.2–4).
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef VALIDATION_SPHEREONFLATWALL_HPP
#define VALIDATION_SPHEREONFLATWALL_HPP

#include "basset/bassetCoefficient.hpp"
#include "contact/hertzMindlin.hpp"
#include "drag/dragCoefficient.hpp"
#include "motion/historyStepper.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <string>
#include <vector>

namespace validation {

using namespace riser;

//- The sphere, the liquid and the wall
struct Scene
{
    double d, rhoP, rhoF, mu, g;    //!< [m], [kg/m^3], [kg/m^3], [Pa s], [m/s^2]
    double CA;                      //!< added-mass coefficient
    double releaseGap;              //!< gap at release from rest [m]
    double eDry;                    //!< dry restitution
    ElasticMaterial sphere, wall;

    double R() const { return 0.5*d; }
    double volume() const { return M_PI*d*d*d/6.0; }
    double mp() const { return rhoP*volume(); }
    double mf() const { return rhoF*volume(); }
    //- Impact Stokes number rho_p v d/(9 mu) (Joseph et al. 2001)
    double stokes(double v) const { return rhoP*d*std::abs(v)/(9.0*mu); }
    double reynolds(double v) const { return rhoF*d*std::abs(v)/mu; }
};

//- Dry, wet by its restitution e(St), or wet by its lubrication film
enum class Wetness { dry, restitution, film };

//- The law of motion, vertical (z up, wall at z = 0), as a System of
//  riser::HistoryStepper. fluid = false leaves the contact alone (the dry
//  impact check).
class SphereOnFlatWall
{
public:
    using Value = double;

    SphereOnFlatWall(const Scene& s, bool basset, bool fluid = true, Wetness wet = Wetness::dry)
    :
        s_(s), fluid_(fluid), tauD_(s.d*s.d*s.rhoF/s.mu),
        KH_(basset && fluid ? classicalBassetCoefficient*s.d*s.d/4.0*std::sqrt(M_PI*s.rhoF*s.mu) : 0.0),
        unbounded_(0.0),
        contact_(lawOf(s, wet)),
        body_(s.R(), wet == Wetness::restitution ? s.mp() + s.CA*s.mf() : s.mp())
    {}

    static HertzMindlinParameters lawOf(const Scene& s, Wetness wet)
    {
        HertzMindlinParameters p{s.sphere, s.wall, s.eDry, 1.0, 0.0};
        if (wet == Wetness::restitution) p.wet = WetRestitution{s.mu};
        if (wet == Wetness::film) p.film = LubricationFilm{s.mu};
        return p;
    }

    double mass() const { return s_.mp(); }
    double addedMass() const { return fluid_ ? s_.CA*s_.mf() : 0.0; }
    double historyCoefficient() const { return KH_; }
    //- s* of the finite-Re history kernel at velocity v
    double historyAgeScale(double v, double) const
    {
        return meiAdrianAgeScale(s_.reynolds(v), tauD_);
    }
    double carrierVelocity(double) const { return 0.0; }
    double carrierAcceleration(double) const { return 0.0; }

    //- Centre height at time t >= t_n for velocity v at t (trapezoidal)
    double height(double v, double t) const { return z_ + 0.5*(t - t_)*(v_ + v); }

    double force(double v, double t) const
    {
        double F = 0.0;
        if (fluid_)
        {
            F = -dragFactor(DragLaw::continuous, unbounded_, s_.d, s_.mu, s_.reynolds(v))*v
              - (s_.mp() - s_.mf())*s_.g;
        }
        return F + contactForce(height(v, t), v) + filmForce(height(v, t), t);
    }

    //- The film's impulse from the committed gap to the gap at t, over the
    //  step (upwards while the gap closes)
    double filmForce(double z, double t) const
    {
        if (!contact_.film() || t <= t_) return 0.0;
        return -contact_.film()->impulse(s_.R(), gap(), z - s_.R())/(t - t_);
    }

    double contactForce(double z, double v) const
    {
        const double overlap = s_.R() - z;
        if (overlap <= 0.0) return 0.0;
        const Vector n(0.0, 0.0, -1.0);       // centre -> wall
        // the approach speed: the last committed velocity out of contact
        const double vIn = std::isnan(vIn_) ? -v_ : vIn_;
        return contact_.force(body_, overlap, n, Vector(0.0, 0.0, v), Vector::Zero(), vIn)
               .normal.z();
    }

    void place(double t, double z, double v) { t_ = t; z_ = z; v_ = v; }
    void commit(double t, double v)
    {
        const double vBefore = v_;
        place(t, height(v, t), v);
        if (gap() > 0.0) vIn_ = NAN;
        else if (std::isnan(vIn_)) vIn_ = -vBefore;
    }
    double gap() const { return z_ - s_.R(); }
    double contactTime(double v) const { return contact_.contactTime(body_, v); }
    const HertzMindlin& contact() const { return contact_; }

private:
    const Scene& s_;
    bool fluid_;
    double tauD_;       //!< d^2/nu [s]
    double KH_;
    WallFactors unbounded_;
    HertzMindlin contact_;
    ContactBody body_;
    double t_ = 0.0, z_ = 0.0, v_ = 0.0;
    double vIn_ = NAN;      //!< approach speed of the contact in progress
};

struct Sample { double t, gap, v; };

//- A contact: touch and separation times (interpolated in the step) and the
//  speeds at the steps just before and just after it (free flight)
struct Contact { double tTouch, vTouch, tLeave = NAN, vLeave = NAN; };
struct Apex { double t, gap; };

struct Run
{
    std::vector<Sample> curve;      // every outputEvery steps, t from release
    std::vector<Contact> contacts;
    std::vector<Apex> apexes;       // highest gap after each contact
    long steps = 0;
    double cpu = 0.0;
    double vFastest = 0.0;          //!< fastest descent (v < 0) [m/s]
    double tFastest = 0.0;          //!< its time from release [s]
    double vUpMax = 0.0;            //!< fastest ascent after the fastest descent [m/s]
    double t0() const { return contacts.at(0).tTouch; }
};

//- The history force through a contact: kept (the unbounded kernel over
//  the contact's reversal), or started anew as the sphere leaves the wall,
//  with its slip then as the initial slip (restart: an impulsively started
//  boundary layer) or without it (forget)
enum class HistoryAtContact { keep, restart, forget };

//- Release from rest, follow the sphere to tAfter past the first contact,
//  or to tEnd after release, whichever comes first
inline Run bounce(const Scene& s, bool basset, double h, double windowTime, double tAfter,
                  long outputEvery, Wetness wet = Wetness::dry, double tEnd = HUGE_VAL,
                  HistoryKernelLaw kernel = HistoryKernelLaw::classical,
                  HistoryAtContact atContact = HistoryAtContact::keep)
{
    SphereOnFlatWall law(s, basset, true, wet);
    law.place(0.0, s.releaseGap + s.R(), 0.0);
    // without the Basset force (K_H = 0) the history is carried but unused
    const long window = basset ? std::max(2L, std::lround(windowTime/h)) : 2L;
    Run r;
    const std::clock_t start = std::clock();
    HistoryStepper<SphereOnFlatWall> stepper(law, HistoryMethod::windowTail, h, window, 0.0, 0.0,
                                             NewestHistoryWeight::implicit, HistoryTail::leastSquares,
                                             kernel);
    double gapOld = law.gap(), vOld = 0.0;
    bool flying = true;
    while (stepper.time() < tEnd)
    {
        stepper.step();
        const double t = stepper.time(), v = stepper.velocity();
        law.commit(t, v);
        const double gap = law.gap();
        ++r.steps;
        if (v < r.vFastest) { r.vFastest = v; r.tFastest = t; r.vUpMax = 0.0; }
        r.vUpMax = std::max(r.vUpMax, v);
        if (flying != (gap > 0.0))
        {
            const double tc = t - h*gap/(gap - gapOld);
            flying = !flying;
            if (!flying)
            {
                r.contacts.push_back({tc, vOld});
                if (r.contacts.size() == 1) tEnd = std::min(tEnd, tc + tAfter);
            }
            else
            {
                r.contacts.back().tLeave = tc;
                r.contacts.back().vLeave = v;
                r.apexes.push_back({t, gap});
                if (atContact != HistoryAtContact::keep)
                {
                    stepper.restartHistory(atContact == HistoryAtContact::restart);
                }
            }
        }
        if (flying && !r.apexes.empty() && gap > r.apexes.back().gap) r.apexes.back() = {t, gap};
        if (r.steps % outputEvery == 0) r.curve.push_back({t, gap, v});
        gapOld = gap;
        vOld = v;
    }
    r.cpu = double(std::clock() - start)/CLOCKS_PER_SEC;
    return r;
}

//- Restitution of one impact at speed v without fluid, same stepper and step
//  (the speed at the first step after the contact: there is no other force)
inline double dryRestitution(const Scene& s, double v, double h)
{
    SphereOnFlatWall law(s, false, false);
    law.place(0.0, s.R() + 0.5*v*h, -v);       // half a step above the wall
    HistoryStepper<SphereOnFlatWall> stepper(law, HistoryMethod::windowTail, h, 2, -v);
    bool touched = false;
    for (long k = 0; k < 10000000L; ++k)
    {
        stepper.step();
        law.commit(stepper.time(), stepper.velocity());
        touched = touched || law.gap() <= 0.0;
        if (touched && law.gap() > 0.0) return stepper.velocity()/v;
    }
    return NAN;
}

//- The speed V at which drag(V), the drag force at speed V (growing with
//  V), carries the weight less the buoyancy, (m_p - m_f) g: by bisection
template<class Drag>
double terminalSpeedOf(const Scene& s, Drag drag)
{
    double lo = 0.0, hi = 10.0;
    for (int i = 0; i < 200; ++i)
    {
        const double V = 0.5*(lo + hi);
        (drag(V) < (s.mp() - s.mf())*s.g ? lo : hi) = V;
    }
    return 0.5*(lo + hi);
}

//- Terminal speed of the model's drag law, c(Re) V = (m_p - m_f) g, by
//  bisection: unbounded (dOverD = 0) or on the axis of a pipe of diameter
//  ratio d/D (the library's pipe wall factors)
inline double terminalSpeed(const Scene& s, double dOverD = 0.0)
{
    const WallFactors walls(dOverD);
    return terminalSpeedOf(s, [&](double V)
    {
        return dragFactor(DragLaw::continuous, walls, s.d, s.mu, s.reynolds(V))*V;
    });
}

} // namespace validation

#endif
