// riserCore: Hertz–Mindlin soft-sphere contact between a sphere and a wall of
// infinite radius and mass (Wei et al., Phys. Fluids 35, 113311, 2023, sec.
// II C; Tsuji et al., Powder Technol. 71, 239, 1992; Mindlin 1949).
//
//   E_eq = [ (1 - nu_p^2)/E_p + (1 - nu_w^2)/E_w ]^-1
//   G_eq = [ 2(2 + nu_p - nu_p^2)/E_p + 2(2 + nu_w - nu_w^2)/E_w ]^-1
//   R_eq = R_p,  M_eq = the particle's inertia     (wall: infinite R and m)
//   k_n  = 4/3 E_eq sqrt(R_eq),   eta_n = alpha_n sqrt(k_n M_eq) delta_n^(1/4)
//   F_n  = -( k_n delta_n^(3/2) + eta_n (U . n) ) n
//   k_t  = 8 G_eq sqrt(R_eq delta_n),   eta_t = 2 zeta_t sqrt(k_t M_eq)
//   F_t* = -k_t delta_t - eta_t U_t                  (trial force)
//   F_t  = F_t*                          while |F_t*| <= mu_c |F_n|
//        = mu_c |F_n| F_t*/|F_t*|        otherwise (sliding: delta_t is reset
//          to -F_t/k_t, so that the spring alone carries the limit)
//
// The Coulomb limit bounds the whole tangential force, spring and dashpot
// together (Tsuji et al. 1992; as LAMMPS and LIGGGHTS do): |F_t| <= mu_c |F_n|
// always. F_t is a continuous function of (delta_t, U_t): the switch between
// sticking and sliding puts no jump into the force, which an adaptive
// integrator needs (doc/theory.md section 3.4). With mu_c |F_n| = 0 there is
// no tangential force.
//
// n: unit normal from the particle centre towards the wall; delta_n >= 0 the
// overlap; U the velocity of the contact point relative to the wall, U_t its
// tangential part; delta_t the tangential spring (the caller accumulates U_t
// over the contact and keeps it in the current tangent plane).
//
// Damping: alpha_n from the normal restitution e_n by dampingRatio() in
// restitution.hpp (closed form when the dashpot may pull, calibrated when
// the normal force is clipped at zero). The tangential spring is linear at
// a given overlap, so its damping ratio zeta_t comes from the tangential
// restitution e_t by the linear-oscillator relation
// zeta_t = -ln e_t / sqrt(pi^2 + ln^2 e_t).
//
// Wet (optional, wetRestitution.hpp): the contact in a liquid rebounds with
// e(St) of its normal approach speed at its start, so each contact gets the
// damping ratio of that restitution; force() then needs the approach speed
// (a contact whose approach speed is not known is an error, not a dry one).
// Needs tensionAllowed (e = 0 has no finite damping ratio otherwise).
//
// Or lubricated (optional, lubrication.hpp): the law keeps its dry damping
// and the liquid film acts before and after the contact (contactKernel.hpp
// steps it), so that e(St) comes out of the dynamics. One contact is wet
// one way or the other, not both.
//
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef RISERCORE_CONTACT_HERTZMINDLIN_HPP
#define RISERCORE_CONTACT_HERTZMINDLIN_HPP

#include "contact/lubrication.hpp"
#include "contact/restitution.hpp"
#include "contact/wetRestitution.hpp"

#include "vector.hpp"

#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>

namespace riser {

//- Isotropic linear-elastic material.
struct ElasticMaterial
{
    double E;   //!< Young's modulus [Pa]
    double nu;  //!< Poisson ratio [-]

    ElasticMaterial(double youngModulus, double poissonRatio)
    :
        E(youngModulus), nu(poissonRatio)
    {
        requirePositive("riser::ElasticMaterial", "E", E);
        requireInRange("riser::ElasticMaterial", "nu", nu, -1.0, Bound::open, 0.5, Bound::open);
    }
};

inline double equivalentYoungModulus(const ElasticMaterial& p, const ElasticMaterial& w)
{
    return 1.0/((1.0 - p.nu*p.nu)/p.E + (1.0 - w.nu*w.nu)/w.E);
}

inline double equivalentShearModulus(const ElasticMaterial& p, const ElasticMaterial& w)
{
    return 1.0/(2.0*(2.0 + p.nu - p.nu*p.nu)/p.E + 2.0*(2.0 + w.nu - w.nu*w.nu)/w.E);
}

//- Linear-oscillator damping ratio for restitution e in (0, 1].
inline double linearDampingRatio(double e)
{
    requireInRange("riser::linearDampingRatio", "e", e, 0.0, Bound::open, 1.0, Bound::closed);
    const double l = std::log(e);
    return -l/std::sqrt(M_PI*M_PI + l*l);
}

//- The material side of the contact law, in SI units; the particle's
//  radius and mass are arguments of each force evaluation, so that one law
//  (with its damping calibrated once) serves particles of any size.
struct HertzMindlinParameters
{
    ElasticMaterial particle;
    ElasticMaterial wall;
    double normalRestitution;      //!< e_n in (0, 1]
    double tangentialRestitution;  //!< e_t in (0, 1]
    double friction;        //!< Coulomb coefficient mu_c >= 0
    NormalForceFloor floor = NormalForceFloor::tensionAllowed;
    std::optional<WetRestitution> wet = std::nullopt;  //!< in a liquid: e(St)
    std::optional<LubricationFilm> film = std::nullopt; //!< in a liquid: its film
};

//- The particle in contact: R_eq = R_p and M_eq against the wall, M_eq the
//  inertia the contact force accelerates (m_p + C_A m_f in a fluid, where
//  the added mass moves with the particle: doc/theory.md section 3.7).
struct ContactBody
{
    double radius;          //!< particle radius R_p [m]
    double mass;            //!< the inertia M_eq [kg]

    ContactBody(double r, double m)
    :
        radius(r), mass(m)
    {
        requirePositive("riser::ContactBody", "R_p", r);
        requirePositive("riser::ContactBody", "m_p", m);
    }
};

//- Contact force on the particle and the tangential spring to keep.
struct ContactForce
{
    Vector normal;          //!< F_n [N]
    Vector tangential;      //!< F_t [N]
    Vector springAfter;     //!< delta_t after the Coulomb cap [m]
    bool sliding;
};

class HertzMindlin
{
public:
    explicit HertzMindlin(const HertzMindlinParameters& p)
    :
        Eeq_(riser::equivalentYoungModulus(p.particle, p.wall)),
        Geq_(riser::equivalentShearModulus(p.particle, p.wall)),
        alphaN_(dampingRatio(p.normalRestitution, p.floor)),
        zetaT_(linearDampingRatio(p.tangentialRestitution)),
        friction_(p.friction),
        floor_(p.floor),
        eDry_(p.normalRestitution),
        wet_(p.wet),
        film_(p.film)
    {
        requireNonNegative("riser::HertzMindlin", "mu_c", p.friction);
        if (wet_)
        {
            wet_->check();
            if (floor_ != NormalForceFloor::tensionAllowed)
            {
                throw std::invalid_argument
                (
                    "riser::HertzMindlin: a wet contact needs the normal force"
                    " floor tensionAllowed (e = 0 has no finite damping ratio"
                    " with noTension)"
                );
            }
        }
        if (film_)
        {
            film_->check();
            if (wet_)
            {
                throw std::invalid_argument
                (
                    "riser::HertzMindlin: a contact is wet by its restitution"
                    " e(St) or by its lubrication film, not both (the film"
                    " would take the liquid's loss a second time)"
                );
            }
        }
    }

    double equivalentYoungModulus() const { return Eeq_; }
    double equivalentShearModulus() const { return Geq_; }
    //- The dry contact's normal damping ratio (of e_n)
    double normalDampingRatio() const { return alphaN_; }

    //- In a liquid (wet)?
    const std::optional<WetRestitution>& wet() const { return wet_; }

    //- The liquid film before and after a contact (lubricated)?
    const std::optional<LubricationFilm>& film() const { return film_; }

    //- The film's cut-off gap for R* (0 when dry): how far beyond touch
    //  the law still acts
    double filmGap(double R) const { return film_ ? film_->cutoffGap(R) : 0.0; }

    //- The dry restitution e_n
    double dryRestitution() const { return eDry_; }

    //- The normal damping ratio of a contact of body b that began with
    //  normal approach speed vIn (towards the wall or the other body): the
    //  dry one, or wet that of e(St) (vIn NaN: an error)
    double normalDampingRatio(const ContactBody& b, double vIn) const
    {
        if (!wet_) return alphaN_;
        if (!std::isfinite(vIn))
        {
            throw std::invalid_argument
            (
                "riser::HertzMindlin: a wet contact evaluated without its"
                " approach speed"
            );
        }
        return wet_->dampingRatio(eDry_, wet_->stokesNumber(b.mass, b.radius, vIn));
    }

    //- k_n = 4/3 E_eq sqrt(R_eq)
    double normalStiffness(const ContactBody& b) const
    {
        return 4.0/3.0*Eeq_*std::sqrt(b.radius);
    }

    //- Hertz contact time of an undamped impact at speed v (Johnson 1985)
    double contactTime(const ContactBody& b, double v) const
    {
        requirePositive("riser::HertzMindlin::contactTime", "v", v);
        return 2.8683*std::pow(b.mass*b.mass/(b.radius*Eeq_*Eeq_*v), 0.2);
    }

    //- Force on body b for overlap deltaN >= 0 along unit normal n (from
    //  the centre towards the wall), contact-point velocity U relative to
    //  the wall, tangential spring deltaT, and the normal approach speed
    //  vIn at the contact's start (used by a wet law only).
    ContactForce force(const ContactBody& b, double deltaN, const Vector& n,
                       const Vector& U, const Vector& deltaT, double vIn) const
    {
        ContactForce c{Vector::Zero(), Vector::Zero(), Vector::Zero(), false};
        if (deltaN <= 0.0) return c;

        const double kn = normalStiffness(b);
        const double Un = U.dot(n);
        const double sqrtDelta = std::sqrt(deltaN);
        double fn = kn*deltaN*sqrtDelta
                  + normalDampingRatio(b, vIn)*std::sqrt(kn*b.mass)*std::sqrt(sqrtDelta)*Un;
        if (floor_ == NormalForceFloor::noTension && fn < 0.0) fn = 0.0;
        c.normal = -fn*n;

        const Vector Ut = U - Un*n;
        const double kt = 8.0*Geq_*std::sqrt(b.radius*deltaN);
        const double etaT = 2.0*zetaT_*std::sqrt(kt*b.mass);
        const double limit = friction_*std::abs(fn);
        const Vector trial = -kt*deltaT - etaT*Ut;
        const double magTrial = trial.norm();
        if (limit <= 0.0)
        {
            // no limit (mu_c = 0 or F_n = 0): no tangential force
            c.sliding = magTrial > 0.0;
        }
        else if (magTrial <= limit)
        {
            c.tangential = trial;
            c.springAfter = deltaT;
        }
        else
        {
            c.tangential = (limit/magTrial)*trial;
            c.springAfter = -c.tangential/kt;
            c.sliding = true;
        }
        return c;
    }

    //- The same for a dry law (a wet law: an error, as its approach speed
    //  is not given)
    ContactForce force(const ContactBody& b, double deltaN, const Vector& n,
                       const Vector& U, const Vector& deltaT) const
    {
        return force(b, deltaN, n, U, deltaT, std::numeric_limits<double>::quiet_NaN());
    }

private:
    double Eeq_, Geq_, alphaN_, zetaT_, friction_;
    NormalForceFloor floor_;
    double eDry_;
    std::optional<WetRestitution> wet_;
    std::optional<LubricationFilm> film_;
};

} // namespace riser

#endif
