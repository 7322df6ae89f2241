// Tests of the tabulated pipe profile (src/riserCore/carrier/
// tabulatedPipeProfile.hpp) and of the carrier it gives riser::RiserFlow:
// - Poiseuille flow sampled at uneven radii is reproduced to round-off
//   (the even mirrored samples' three-point slopes and cubic pieces are
//   exact for a quadratic), and so is a quadratic k and nu_t; the carrier
//   on it equals the laminar carrier (velocity, vorticity) to round-off;
// - the turbulent closed form sampled at M radii converges to it away
//   from the wall (the cubic's order, 3, in the speed), and its slope is
//   continuous and zero on the axis;
// - bad samples are refused.
// SPDX-License-Identifier: GPL-3.0-or-later
#include "carrier/riserFlow.hpp"
#include "carrier/tabulatedPipeProfile.hpp"
#include "carrier/turbulentPipeProfile.hpp"

#include <gtest/gtest.h>
#include <cmath>
#include <memory>
#include <stdexcept>

using namespace riser;

namespace {

const double R = 0.15, uc = 4.0;

double poiseuille(double r) { return uc*(1 - r*r/(R*R)); }

// uneven radii from the axis to the wall
std::vector<double> radii()
{
    return {0.0, 0.01, 0.025, 0.03, 0.06, 0.07, 0.1, 0.12, 0.135, 0.15};
}

std::shared_ptr<const TabulatedPipeProfile> sampledPoiseuille()
{
    std::vector<double> w, k, nut;
    for (double r : radii())
    {
        w.push_back(poiseuille(r));
        k.push_back(0.02 + 0.5*r*r);
        nut.push_back(1e-4*(1 - r*r/(R*R)));
    }
    return std::make_shared<const TabulatedPipeProfile>(R, radii(), w, k, nut);
}

} // namespace


TEST(TabulatedPipeProfile, PoiseuilleReproduced)
{
    const auto p = sampledPoiseuille();
    EXPECT_EQ(p->centreLineSpeed(), uc);
    for (int i = 0; i <= 300; ++i)
    {
        const double r = R*i/300;
        // round-off of O(4 m/s) sums over four nodes
        EXPECT_NEAR(p->speed(r), poiseuille(r), 1e-13);
        EXPECT_NEAR(p->speed(-r), poiseuille(r), 1e-13);
        EXPECT_NEAR(p->gradient(r), -2*uc*r/(R*R), 1e-11);
        EXPECT_NEAR(p->turbulentEnergy(r), 0.02 + 0.5*r*r, 1e-15);
        EXPECT_NEAR(p->eddyViscosity(r), 1e-4*(1 - r*r/(R*R)), 1e-18);
    }
    EXPECT_EQ(p->gradient(0.0), 0.0);
    // the carrier on it is the laminar carrier, in a sinusoid riser (the
    // points within the pipe at every phase: offsets below 0.05 + 0.09 m)
    const RiserFlow tab(2*R, p, SinusoidMotion::make(0.05, 2.0, 0.3));
    const RiserFlow lam(2*R, uc, SinusoidMotion::make(0.05, 2.0, 0.3));
    for (const Vector& x : {Vector(0.01, 0.02, 1.0), Vector(-0.07, 0.05, 3.0), Vector(0.09, 0.0, 0.0)})
    {
        for (double t : {0.0, 0.7, 1.9})
        {
            EXPECT_LT((tab.velocity(x, t) - lam.velocity(x, t)).norm(), 1e-13);
            EXPECT_LT((tab.vorticity(x, t) - lam.vorticity(x, t)).norm(), 1e-10);
        }
    }
    EXPECT_STREQ(tab.profile()->type(), "tabulated");
}


TEST(TabulatedPipeProfile, ConvergesToTheTurbulentProfile)
{
    const TurbulentPipeProfile exact(2*R, 3.0, 1e-6, 0.0);
    double error[2];
    const int Ms[2] = {51, 101};
    for (int m = 0; m < 2; ++m)
    {
        std::vector<double> r, w, zero;
        for (int i = 0; i < Ms[m]; ++i)
        {
            r.push_back(R*i/(Ms[m] - 1));
            w.push_back(exact.speed(r.back()));
            zero.push_back(0.0);
        }
        const TabulatedPipeProfile tab(R, r, w, zero, zero);
        error[m] = 0;
        // away from the wall's layer (y > 0.1 R), where the closed form is smooth
        for (int i = 0; i <= 900; ++i)
        {
            const double x = 0.9*R*i/900;
            error[m] = std::max(error[m], std::abs(tab.speed(x) - exact.speed(x)));
        }
    }
    // the speed's error falls as the spacing cubed (the nodal slopes'
    // second-order error times a piece's length): within 0.4 of order 3
    EXPECT_GT(std::log2(error[0]/error[1]), 2.6);
    EXPECT_LT(error[1], 1e-4*exact.centreLineSpeed());
}


TEST(TabulatedPipeProfile, Refused)
{
    const std::vector<double> w{1, 0.9, 0}, k{0.1, 0.1, 0}, nut{1e-4, 1e-4, 0};
    EXPECT_THROW(TabulatedPipeProfile(R, {0.01, 0.1, R}, w, k, nut), std::invalid_argument);
    EXPECT_THROW(TabulatedPipeProfile(R, {0.0, 0.1, 0.14}, w, k, nut), std::invalid_argument);
    EXPECT_THROW(TabulatedPipeProfile(R, {0.0, 0.1, 0.1, R}, {1, 1, 1, 0}, {0, 0, 0, 0},
                                      {0, 0, 0, 0}), std::invalid_argument);
    EXPECT_THROW(TabulatedPipeProfile(R, {0.0, R}, {1, 0}, {0, 0}, {0, 0}), std::invalid_argument);
    EXPECT_THROW(TabulatedPipeProfile(R, {0.0, 0.1, R}, w, {0.1, -0.1, 0}, nut),
                 std::invalid_argument);
    EXPECT_THROW(TabulatedPipeProfile(R, {0.0, 0.1, R}, w, k, {1e-4, NAN, 0}),
                 std::invalid_argument);
    EXPECT_THROW(TabulatedPipeProfile(R, {0.0, 0.1, R}, {1, 0.9}, k, nut), std::invalid_argument);
}
