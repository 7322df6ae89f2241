// Tests of the Saffman–Mei lift and Basset coefficients (src/riserCore/lift,
// src/riserCore/basset).
// SPDX-License-Identifier: GPL-3.0-or-later
#include "lift/saffmanMeiLift.hpp"
#include "basset/bassetCoefficient.hpp"

#include <gtest/gtest.h>
#include <cmath>

using namespace riser;

// Low-Re limit: F_L = (pi d^3/8) rho C_L |w| |Omega| equals Saffman's
// 6.46 mu a^2 |w| sqrt(|Omega|/nu) (Saffman, JFM 22, 385, 1965) within 1%.
// Mei's constant 4.1126 pi / 8 = 1.61504 against 6.46 / 4 = 1.615 differs by
// 3e-5; Mei's correction at Re_p = 1e-2 differs from 1 by ~1e-3.
TEST(SaffmanMeiLift, SaffmanLimit)
{
    const double rho = 1000.0, mu = 1e-3, nu = mu/rho;
    const double d = 1e-4, a = 0.5*d;
    for (double Omega : {0.1, 1.0, 10.0})
    {
        const double w = 1e-4;                      // Re_p = 1e-2
        const double Rep = rho*d*w/mu, Res = rho*d*d*Omega/mu;
        const double F = M_PI*d*d*d/8.0*rho*saffmanMeiCoefficient(Rep, Res)*w*Omega;
        const double saffman = 6.46*mu*a*a*w*std::sqrt(Omega/nu);
        EXPECT_NEAR(F/saffman, 1.0, 0.01) << "Omega = " << Omega;
    }
}

// Mei's high-Re branch: f = 0.0524 sqrt(b Re_p) = 0.0524 sqrt(Re_s / 2).
TEST(SaffmanMeiLift, HighReBranch)
{
    EXPECT_NEAR(saffmanMeiCorrection(100.0, 50.0), 0.0524*5.0, 1e-12);
    EXPECT_THROW(saffmanMeiCorrection(-1.0, 1.0), std::invalid_argument);
    EXPECT_THROW(saffmanMeiCoefficient(1.0, 0.0), std::invalid_argument);
}

TEST(BassetCoefficient, ClassicalAndLimits)
{
    const double mu = 1e-3, rho = 1000.0, R = 5e-3;
    EXPECT_EQ(bassetCoefficient(BassetModel::classical, 100.0, mu, rho, R, 3.0), 6.0);
    // Re_p -> 0: the bracket vanishes, C_H -> 6.
    EXPECT_NEAR(bassetCoefficient(BassetModel::michaelidesRoig, 0.0, mu, rho, R, 3.0), 6.0, 1e-15);
    // Large Re_p St^0.82: C_H -> 6 - 3.16 = 2.84.
    EXPECT_NEAR(bassetCoefficient(BassetModel::michaelidesRoig, 1e9, mu, rho, R, 3.0), 2.84, 1e-12);
    // Steady carrier: the classical value, as documented.
    EXPECT_EQ(bassetCoefficient(BassetModel::michaelidesRoig, 100.0, mu, rho, R, 0.0), 6.0);
}

// The reading of the exponent: with St = 1 and 0.14 Re_p = ln 2 the bracket
// [1 - exp(-0.14 Re St^0.82)] is 1/2, so C_H = 6 - 3.16 * 2^-2.5 = 5.441383
// (by hand: 2^-2.5 = 0.1767767).
TEST(BassetCoefficient, ExponentAppliesToTheBracket)
{
    const double mu = 1e-3, rho = 1000.0, R = 1e-3;
    const double f = 9.0*mu/(16.0*M_PI*R*R*rho);    // makes St = 1
    EXPECT_NEAR(bassetStrouhal(mu, rho, R, f), 1.0, 1e-14);
    const double Re = std::log(2.0)/0.14;
    EXPECT_NEAR(bassetCoefficient(BassetModel::michaelidesRoig, Re, mu, rho, R, f), 5.441386, 1e-6);
}

// C_H with the Strouhal factor given (kept by a caller for one particle
// size and fluid) is C_H computed from mu, rho and R_p, to the bit.
TEST(BassetCoefficient, GivenStrouhalFactor)
{
    const double mu = 1e-3, rho = 1000.0, R = 5e-3, f = 3.0;
    const double factor = bassetStrouhalFactor(mu, rho, R, f);
    EXPECT_EQ(factor, std::pow(bassetStrouhal(mu, rho, R, f), 0.82));
    for (double Re : {0.0, 0.3, 17.0, 850.0, 1e9})
    {
        EXPECT_EQ(bassetCoefficient(BassetModel::michaelidesRoig, Re, f, factor),
                  bassetCoefficient(BassetModel::michaelidesRoig, Re, mu, rho, R, f));
        EXPECT_EQ(bassetCoefficient(BassetModel::classical, Re, f, factor), 6.0);
    }
    EXPECT_EQ(bassetCoefficient(BassetModel::michaelidesRoig, 100.0, 0.0, 0.0), 6.0);
    EXPECT_THROW(bassetCoefficient(BassetModel::michaelidesRoig, -1.0, f, factor),
                 std::invalid_argument);
}

TEST(BassetCoefficient, RejectsBadArguments)
{
    EXPECT_THROW(bassetCoefficient(BassetModel::michaelidesRoig, 1.0, 1e-3, 1e3, 1e-3, -1.0),
                 std::invalid_argument);
    EXPECT_THROW(bassetCoefficient(BassetModel::michaelidesRoig, -1.0, 1e-3, 1e3, 1e-3, 1.0),
                 std::invalid_argument);
    EXPECT_THROW(bassetStrouhal(1e-3, 1e3, 0.0, 1.0), std::invalid_argument);
}
