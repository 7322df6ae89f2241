// Tests of the turbulent pipe profile (src/riserCore/carrier/
// turbulentPipeProfile.hpp) and of riser::RiserFlow carrying it:
// - the Colebrook friction factor against Prandtl-Karman's (smooth, within
//   1 %), against McKeon et al.'s fit of the Princeton superpipe data
//   (J. Fluid Mech. 538, 429-443, 2005: 1/sqrt(f) = 1.930 log10(Re sqrt(f))
//   - 0.537; within 2 %, the spread of the data about the classical law)
//   and against Haaland's explicit formula (J. Fluids Eng. 105, 89-90,
//   1983; within 2 %, his stated agreement with Colebrook being 1.5 %);
// - the profile: its mean over the section equal to the bulk speed
//   (independent midpoint quadrature, 1e-6), zero slope on the axis, the
//   gradient against central differences, u+ = y+ in the viscous
//   sublayer, the log law u+ = ln(y+)/0.41 + 5.2 at y+ 50-300 within 1 %
//   (Re 1e5, 1e6), and the centre-line speed against Nikuradse's
//   measurements (U_b/U_c = 2 n^2/((n + 1)(2 n + 1)) of the power-law
//   exponents n = 7, 8.8, 10 at Re = 1.1e5, 1.1e6, 3.2e6; Schlichting,
//   Boundary-Layer Theory, table 20.1) within 2 %;
// - the carrier: its curl against central differences of its velocity,
//   Du/Dt the riser's acceleration (a fluid particle keeps its radius);
// - bad arguments refused.
// SPDX-License-Identifier: GPL-3.0-or-later
#include "carrier/riserFlow.hpp"
#include "carrier/turbulentPipeProfile.hpp"
#include "riser/sinusoidMotion.hpp"

#include <gtest/gtest.h>
#include <cmath>
#include <memory>
#include <stdexcept>

using namespace riser;

namespace {

const double reynolds[] = {1e4, 2e4, 5e4, 1e5, 2e5, 5e5, 1e6};

//- 1/sqrt(f) of x = F(x) by fixed-point iteration (an independent solver
//  of the implicit fits)
template<class F>
double solveImplicit(const F& fn)
{
    double x = 7.0;
    for (int i = 0; i < 200; ++i) x = fn(x);
    return 1.0/(x*x);
}

} // namespace


TEST(FrictionFactor, ColebrookSmoothIsPrandtlKarman)
{
    for (double Re : reynolds)
    {
        const double fc = colebrookFrictionFactor(Re, 0.0);
        const double fp = solveImplicit
        (
            [Re](double x) { return 2.0*std::log10(Re/x) - 0.8; }
        );
        EXPECT_NEAR(fc/fp, 1.0, 1e-2) << "Re " << Re;
        // the superpipe's fit
        const double fm = solveImplicit
        (
            [Re](double x) { return 1.930*std::log10(Re/x) - 0.537; }
        );
        EXPECT_NEAR(fc/fm, 1.0, 2e-2) << "Re " << Re;
    }
}

TEST(FrictionFactor, ColebrookRoughIsHaaland)
{
    for (double Re : reynolds)
    {
        for (double rough : {1e-5, 1e-4, 1e-3, 1e-2})
        {
            const double x = -1.8*std::log10(std::pow(rough/3.7, 1.11) + 6.9/Re);
            EXPECT_NEAR(colebrookFrictionFactor(Re, rough)*x*x, 1.0, 2e-2)
                << "Re " << Re << " k_s/D " << rough;
        }
    }
}

TEST(TurbulentPipeProfile, MeanIsTheBulkSpeed)
{
    for (double Re : {1e4, 1e5, 1e6})
    {
        for (double ks : {0.0, 1e-4})
        {
            const double D = 0.3, nu = 1e-6;
            const TurbulentPipeProfile p(D, Re*nu/D, nu, ks);
            // midpoint rule in r, 4e5 cells (the viscous layer, 1e-5 R at
            // Re 1e6, holds u linear: the rule's error there is of the
            // cells' size squared)
            const int n = 400000;
            const double R = 0.5*D;
            double sum = 0.0;
            for (int i = 0; i < n; ++i)
            {
                const double r = (i + 0.5)/n*R;
                sum += p.speed(r)*r;
            }
            const double mean = 2.0*sum*(R/n)/(R*R);
            EXPECT_NEAR(mean/p.bulkSpeed(), 1.0, 1e-6) << "Re " << Re << " k_s " << ks;
        }
    }
}

TEST(TurbulentPipeProfile, SlopeZeroOnTheAxisAndGradientOfTheSpeed)
{
    const TurbulentPipeProfile p(0.3, 3.0, 1e-6, 5e-5);
    EXPECT_LT(std::abs(p.gradient(0.0)), 1e-12*p.frictionVelocity()/0.15);
    for (double r : {1e-4, 0.01, 0.07, 0.14, 0.1499})
    {
        const double h = 1e-8;
        const double fd = (p.speed(r + h) - p.speed(r - h))/(2*h);
        EXPECT_NEAR(p.gradient(r), fd, 1e-6*std::abs(fd) + 1e-6) << "r " << r;
    }
    // a smooth wall: u = 0, shear u_tau^2/nu (a rough wall's viscous
    // shear is less: the roughness takes part of the stress as form drag)
    const TurbulentPipeProfile smooth(0.3, 3.0, 1e-6, 0.0);
    EXPECT_EQ(smooth.speed(0.15), 0.0);
    EXPECT_NEAR(smooth.gradient(0.15)/(-std::pow(smooth.frictionVelocity(), 2)/1e-6), 1.0,
                1e-12);
}

TEST(TurbulentPipeProfile, LawOfTheWall)
{
    for (double Re : {1e5, 1e6})
    {
        const TurbulentPipeProfile p(0.2, Re*1e-6/0.2, 1e-6, 0.0);
        for (double yp : {0.1, 0.5, 1.0})
        {
            EXPECT_NEAR(p.uPlus(yp)/yp, 1.0, 1e-2) << "y+ " << yp;
        }
        for (double yp = 50; yp <= 300; yp += 25)
        {
            EXPECT_NEAR(p.uPlus(yp)/(std::log(yp)/0.41 + 5.2), 1.0, 1e-2) << "y+ " << yp;
        }
    }
}

TEST(TurbulentPipeProfile, CentreLineSpeedAgainstNikuradse)
{
    const double Re[] = {1.1e5, 1.1e6, 3.2e6}, n[] = {7.0, 8.8, 10.0};
    for (int i = 0; i < 3; ++i)
    {
        const TurbulentPipeProfile p(0.2, Re[i]*1e-6/0.2, 1e-6, 0.0);
        const double measured = (n[i] + 1)*(2*n[i] + 1)/(2*n[i]*n[i]);
        EXPECT_NEAR(p.centreLineSpeed()/p.bulkSpeed()/measured, 1.0, 2e-2) << "Re " << Re[i];
    }
}

TEST(TurbulentPipeProfile, RefusesBadArguments)
{
    EXPECT_THROW(TurbulentPipeProfile(0.2, 3, 1e-6, -1e-5), std::invalid_argument);
    EXPECT_THROW(TurbulentPipeProfile(0.2, 3, 1e-6, 0.1), std::invalid_argument);
    EXPECT_THROW(TurbulentPipeProfile(0.2, 0.01, 1e-6, 0), std::invalid_argument);  // Re 2000
    EXPECT_THROW(TurbulentPipeProfile(0.2, NAN, 1e-6, 0), std::invalid_argument);
    EXPECT_THROW(colebrookFrictionFactor(1e5, -0.1), std::invalid_argument);
}

// The carrier with the profile: w(|r|) about the moving axis, its curl
// against central differences (h = 1e-6 m; the profile's second
// derivative ~ u_tau^2/nu / y near the wall: kept 5 mm off it), Du/Dt the
// riser's
TEST(TurbulentPipeProfile, TheCarrierCarriesIt)
{
    auto profile = std::make_shared<const TurbulentPipeProfile>(0.3, 3.0, 1e-6, 0.0);
    const RiserFlow flow(0.3, profile, SinusoidMotion::make(0.2, 2*M_PI*0.3, 0.1));
    EXPECT_EQ(flow.centreLineSpeed(), profile->centreLineSpeed());
    const double h = 1e-6;
    for (double t : {0.0, 0.7, 2.9})
    {
        for (const Vector& r : {Vector(0.01, 0.02, 0), Vector(-0.1, 0.05, 0), Vector(0, -0.14, 0)})
        {
            const Vector x = flow.motion().toLabFrame(Vector(r.x(), r.y(), 3.0), t);
            EXPECT_NEAR(flow.velocity(x, t).z(), profile->speed(r.norm()), 1e-12);
            Vector grad[3];
            for (int i = 0; i < 3; ++i)
            {
                Vector e = Vector::Zero();
                e[i] = h;
                grad[i] = (flow.velocity(x + e, t) - flow.velocity(x - e, t))/(2*h);
            }
            const Vector curl(grad[1].z() - grad[2].y(), grad[2].x() - grad[0].z(),
                              grad[0].y() - grad[1].x());
            EXPECT_LT((flow.vorticity(x, t) - curl).norm(), 1e-5*curl.norm() + 1e-6);
            EXPECT_EQ(flow.materialDerivative(x, t), flow.motion().acceleration(3.0, t));
        }
    }
}
