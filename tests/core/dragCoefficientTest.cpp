// Tests of the wall-corrected drag coefficient (src/riserCore/drag).
// SPDX-License-Identifier: GPL-3.0-or-later
#include "drag/dragCoefficient.hpp"

#include <gtest/gtest.h>
#include <cmath>

using namespace riser;

// Stokes limit: for d/D -> 0 the wall factor tends to 1, so C_D Re_p / 24 -> 1.
// With d/D = 1e-6 the factor is 1 + 2.105e-6 (first-order term of K), and
// the continuous law's inertial part adds 0.15 Re^0.687 relative (1.3e-3 at
// Re_p = 1e-3, 1.14e-5 at 1e-6); tolerances sit just above these deviations.
TEST(DragCoefficient, StokesLimit)
{
    const WallFactors w(1e-6);
    EXPECT_NEAR(dragCoefficient(DragLaw::paper, 1e-3, w)*1e-3/24.0, 1.0, 3e-6);
    EXPECT_NEAR(dragCoefficient(DragLaw::continuous, 1e-3, w)*1e-3/24.0, 1.0, 1.5e-3);
    EXPECT_NEAR(dragCoefficient(DragLaw::continuous, 1e-6, w)*1e-6/24.0, 1.0, 1.5e-5);
}

// K at d/D = 0.1, evaluated by hand from the Clift-Grace-Weber formula:
// (1 - 7.5857e-6) / (1 - 0.2105 + 0.0020865 - 1.7068e-5 + 7.2603e-7) = 1.26331.
// The reference value is 1.2633 (5 digits): tolerance half a unit of its last digit.
TEST(DragCoefficient, WallFactorAtOneTenth)
{
    const WallFactors w(0.1);
    EXPECT_NEAR(w.K, 1.2633, 5e-5);
    // K_F1 = 1 / (1 - 1.6 * 0.1^1.6): 0.1^1.6 = 0.0251189, by hand 1/0.9598097 = 1.041873.
    EXPECT_NEAR(w.KF1, 1.041873, 1e-6);
    // The Stokes branch is 24 K / Re.
    EXPECT_NEAR(dragCoefficient(DragLaw::paper, 0.5, w), 48.0*1.2633, 48.0*5e-5);
}

// The paper's correlation: find every jump on a fine logarithmic scan of
// Re_p in [1e-2, 1e6] by bisection and check where they are. Expected: Re = 1
// (24 K -> 24 K + 4), Re = 100 (the large one, about 1.10 -> 0.42 for small
// d/D), Re = 1e5 (K_F1 -> K_F2); none at 600, where the branch was extended.
TEST(DragCoefficient, PaperJumpsWhereExpected)
{
    const WallFactors w(1e-3);
    auto cd = [&](double Re) { return dragCoefficient(DragLaw::paper, Re, w); };
    std::vector<double> jumps;
    double largestJump = 0.0, largestAt = 0.0;
    const int n = 20000;
    for (int i = 0; i < n; ++i)
    {
        double a = std::pow(10.0, -2.0 + 8.0*i/n);
        double b = std::pow(10.0, -2.0 + 8.0*(i + 1)/n);
        // a smooth branch changes by at most ~0.2% over one scan interval
        if (std::abs(cd(b) - cd(a)) < 0.01*cd(a)) continue;
        for (int k = 0; k < 80; ++k)
        {
            const double m = std::sqrt(a*b);
            (std::abs(cd(m) - cd(a)) < 0.01*cd(a) ? a : b) = m;
        }
        jumps.push_back(b);
        const double size = std::abs(cd(b) - cd(a))/cd(a);   // relative
        if (size > largestJump) { largestJump = size; largestAt = b; }
    }
    ASSERT_EQ(jumps.size(), 2u);  // Re=1 and Re=100 (K_F1 = K_F2 + O(1e-5) at small d/D)
    EXPECT_NEAR(jumps[0], 1.0, 1e-9);
    EXPECT_NEAR(jumps[1], paperDragJumpRe, 1e-7);
    EXPECT_NEAR(largestAt, 100.0, 1e-7);
    // the two sides of the jump at 100, by hand for d/D = 1e-3 (K = 1.00211)
    EXPECT_NEAR(cd(100.0*(1.0 - 1e-12)), 1.1023, 1e-4);   // 0.24 (21.5443/6 + 1.00211)
    EXPECT_NEAR(cd(100.0), 0.42, 1e-4);                   // 0.42 K_F1, K_F1 = 1 + 2.5e-5
    // the extension: no jump at 600
    EXPECT_DOUBLE_EQ(cd(599.0), cd(601.0));
}

// The continuous alternative has no jump anywhere the paper's law has one:
// across each point the change over a relative step of 1e-9 is below 1e-6
// relative (a smooth function changes by ~1e-9 there).
TEST(DragCoefficient, ContinuousAlternativeIsContinuous)
{
    const WallFactors w(0.1);
    for (double Re : {1.0, 40.0, 100.0, 600.0, 1e5})
    {
        const double lo = dragCoefficient(DragLaw::continuous, Re*(1.0 - 1e-9), w);
        const double hi = dragCoefficient(DragLaw::continuous, Re*(1.0 + 1e-9), w);
        EXPECT_LT(std::abs(hi - lo), 1e-6*lo) << "at Re = " << Re;
    }
    // Newton regime, d/D -> 0: the standard drag curve (Clift, Grace & Weber
    // 1978, table 5.2) gives C_D = 0.405 at Re = 1e4; the fit is within 3%.
    const WallFactors w0(0.0);
    EXPECT_NEAR(dragCoefficient(DragLaw::continuous, 1e4, w0), 0.405, 0.03*0.405);
    // ... and carries the Newton-regime wall factor K_F1 there: the ratio to
    // the unbounded value tends to K_F1 as the Stokes part 24(K - K_F1)/Re fades.
    const double ratio = dragCoefficient(DragLaw::continuous, 1e4, w)
                       / dragCoefficient(DragLaw::continuous, 1e4, w0);
    EXPECT_NEAR(ratio, w.KF1, 0.01);
}

TEST(DragCoefficient, TimesReIsFiniteAtZeroSlip)
{
    const WallFactors w(0.1);
    EXPECT_DOUBLE_EQ(dragCoefficientTimesRe(DragLaw::paper, 0.0, w), 24.0*w.K);
    EXPECT_DOUBLE_EQ(dragCoefficientTimesRe(DragLaw::paper, 3.0, w),
                     3.0*dragCoefficient(DragLaw::paper, 3.0, w));
}

TEST(DragCoefficient, RejectsBadArguments)
{
    EXPECT_THROW(WallFactors(1.0), std::invalid_argument);
    EXPECT_THROW(WallFactors(-0.1), std::invalid_argument);
    const WallFactors w(0.1);
    EXPECT_THROW(dragCoefficient(DragLaw::paper, 0.0, w), std::invalid_argument);
    EXPECT_THROW(dragCoefficient(DragLaw::paper, NAN, w), std::invalid_argument);
    try
    {
        WallFactors bad(1.5);
        FAIL();
    }
    catch (const std::invalid_argument& e)
    {
        EXPECT_NE(std::string(e.what()).find("'d/D'"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("[0, 1)"), std::string::npos) << e.what();
    }
}

// The voidage functions against their closed forms. At eps = 1 the drag is
// the single sphere's; in the Stokes regime (c independent of Re) a
// homogeneous suspension settles where c eps^-chi w = c u_t, so
// w/u_t = eps^chi: Richardson & Zaki's slip exponent n - 1 = chi, 3.65 for
// Wen & Yu and 3.7 for Di Felice (n = 4.65, 4.7), 2.65 (eps + 1) for Rong,
// Dong & Yu. Di Felice's chi is 3.7 - 0.65 = 3.05 where log10 Re_s = 1.5,
// and tends to 3.7 both ways.
TEST(DragCoefficient, VoidageFunctions)
{
    const riser::WallFactors w(0.05);
    const double d = 1e-3, mu = 1e-3;
    for (const auto v : {riser::Voidage::none, riser::Voidage::wenYu, riser::Voidage::diFelice,
                         riser::Voidage::rong})
    {
        for (const double Re : {0.0, 0.5, 30.0, 3000.0})
        {
            EXPECT_DOUBLE_EQ(riser::suspensionDragFactor(riser::DragLaw::continuous, w, d, mu,
                                                         Re, v, 1.0),
                             riser::dragFactor(riser::DragLaw::continuous, w, d, mu, Re));
        }
    }

    // Stokes regime: only the factor eps^-chi remains (C_D Re = 24 K up to
    // Clift-Gauvin's 0.15 Re^0.687, 4e-6 of it at Re = 1e-8)
    const double eps = 0.7, tiny = 1e-8;
    const double single = riser::dragFactor(riser::DragLaw::continuous, w, d, mu, 0.0);
    EXPECT_NEAR(riser::suspensionDragFactor(riser::DragLaw::continuous, w, d, mu, tiny,
                                            riser::Voidage::wenYu, eps)/single,
                std::pow(0.7, -3.65), 1e-5);
    EXPECT_NEAR(riser::suspensionDragFactor(riser::DragLaw::continuous, w, d, mu, tiny,
                                            riser::Voidage::diFelice, eps)/single,
                std::pow(0.7, -3.7), 1e-5);
    EXPECT_NEAR(riser::suspensionDragFactor(riser::DragLaw::continuous, w, d, mu, tiny,
                                            riser::Voidage::rong, eps)/single,
                std::pow(0.7, -2.65*1.7), 1e-5);

    // Di Felice's dip: Re_s = 10^1.5
    const double ReS = std::pow(10.0, 1.5);
    EXPECT_NEAR(riser::voidageExponent(riser::Voidage::diFelice, eps, ReS), 3.05, 1e-14);
    EXPECT_NEAR(riser::suspensionDragFactor(riser::DragLaw::paper, w, d, mu, ReS/eps,
                                            riser::Voidage::diFelice, eps),
                riser::dragFactor(riser::DragLaw::paper, w, d, mu, ReS)*std::pow(eps, -3.05),
                1e-12*riser::dragFactor(riser::DragLaw::paper, w, d, mu, ReS));
    EXPECT_NEAR(riser::voidageExponent(riser::Voidage::diFelice, eps, 1e6), 3.7, 1e-3);
    EXPECT_EQ(riser::voidageExponent(riser::Voidage::diFelice, eps, 0.0), 3.7);
    // Wen & Yu's chi does not depend on eps or Re_s
    EXPECT_EQ(riser::voidageExponent(riser::Voidage::wenYu, 0.5, 1e3), 3.65);
}

// Rong, Dong & Yu's (2013) chi = 2.65 (eps + 1) - (5.3 - 3.5 eps) eps^2
// exp(-(1.5 - log10 Re_s)^2/2) against values worked out by hand. The
// tolerance, 1e-13, is round-off: log10 of 10^1.5 or 10^3.5 is 1.5 or 3.5
// to a few ulps, and the rest is a handful of products of numbers of order 5.
TEST(DragCoefficient, RongVoidageExponent)
{
    using riser::Voidage;
    using riser::voidageExponent;
    // at the dip, log10 Re_s = 1.5 (exp = 1): 2.65 * 1.8 - 2.5 * 0.64 = 4.77 - 1.6
    EXPECT_NEAR(voidageExponent(Voidage::rong, 0.8, std::pow(10.0, 1.5)), 3.17, 1e-13);
    // eps = 1 at the dip: 5.3 - 1.8
    EXPECT_NEAR(voidageExponent(Voidage::rong, 1.0, std::pow(10.0, 1.5)), 3.5, 1e-13);
    // high Re_s, log10 Re_s = 3.5 (exp(-2)): 2.65 * 1.7 - 2.85 * 0.49 exp(-2)
    //   = 4.505 - 1.3965 * 0.135335283 = 4.316004
    EXPECT_NEAR(voidageExponent(Voidage::rong, 0.7, std::pow(10.0, 3.5)),
                4.505 - 1.3965*std::exp(-2.0), 1e-13);
    EXPECT_NEAR(voidageExponent(Voidage::rong, 0.7, std::pow(10.0, 3.5)), 4.316004, 1e-6);
    // low Re_s, log10 Re_s = -0.5 (exp(-2) again): 2.65 * 1.9 - 2.15 * 0.81 exp(-2)
    EXPECT_NEAR(voidageExponent(Voidage::rong, 0.9, std::pow(10.0, -0.5)),
                5.035 - 1.7415*std::exp(-2.0), 1e-13);
    // Stokes limit Re_s = 0: the dip vanishes, 2.65 (eps + 1)
    EXPECT_NEAR(voidageExponent(Voidage::rong, 0.6, 0.0), 4.24, 1e-13);
    // far beyond the dip chi tends to the same 2.65 (eps + 1): at Re_s = 1e12
    // the dip is 1.152 exp(-55.1) ~ 1e-24
    EXPECT_NEAR(voidageExponent(Voidage::rong, 0.6, 1e12), 4.24, 1e-13);

    // the drag factor uses chi at eps and Re_s = eps Re
    const riser::WallFactors w(0.1);
    const double d = 1e-2, mu = 1e-3, eps = 0.8, Re = 5000.0;
    EXPECT_NEAR(riser::suspensionDragFactor(riser::DragLaw::continuous, w, d, mu, Re,
                                            Voidage::rong, eps),
                riser::dragFactor(riser::DragLaw::continuous, w, d, mu, eps*Re)
                    *std::pow(eps, -voidageExponent(Voidage::rong, eps, eps*Re)),
                1e-12*riser::dragFactor(riser::DragLaw::continuous, w, d, mu, eps*Re));
}
