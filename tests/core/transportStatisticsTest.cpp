// Tests of the transport-statistics schema and bins (src/riserCore/output).
// SPDX-License-Identifier: GPL-3.0-or-later
#include "output/transportStatistics.hpp"

#include <gtest/gtest.h>
#include <algorithm>
#include <cmath>
#include <sstream>

using namespace riser;

TEST(TransportStatistics, RadialBinsHaveEqualAreas)
{
    // n annuli of radius R: annulus k is sqrt(k/n) R <= h < sqrt((k+1)/n) R;
    // a uniform grid of points over the disc puts the same share in each
    const double R = 0.05;
    const int n = 5;
    std::vector<int> count(n, 0);
    const int m = 2000;
    int inside = 0;
    for (int i = 0; i < m; ++i)
    {
        for (int j = 0; j < m; ++j)
        {
            const double x = R*(2.0*(i + 0.5)/m - 1.0), y = R*(2.0*(j + 0.5)/m - 1.0);
            const double h = std::hypot(x, y);
            if (h < R)
            {
                ++count[radialBin(h, R, n)];
                ++inside;
            }
        }
    }
    // the grid's area error at the annuli's rims: ~ perimeter x cell / area,
    // 2 pi R (2R/m) / (pi R^2 / n) = 4 n / m = 1e-2; 2e-2 gives margin
    for (int k = 0; k < n; ++k)
    {
        EXPECT_NEAR(double(count[k])/inside, 1.0/n, 2e-2/n) << "annulus " << k;
    }
}

TEST(TransportStatistics, BinsAtTheirEdgesAndBeyond)
{
    const double R = 0.05;
    EXPECT_EQ(radialBin(0.0, R, 4), 0);
    EXPECT_EQ(radialBin(0.5*R*(1 - 1e-12), R, 4), 0);      // (r/R)^2 just under 1/4
    EXPECT_EQ(radialBin(0.5*R*(1 + 1e-12), R, 4), 1);
    EXPECT_EQ(radialBin(R, R, 4), 3);                       // on the wall: the outermost
    EXPECT_EQ(radialBin(2*R, R, 4), 3);
    EXPECT_EQ(axialBin(-0.2, -0.2, 0.4, 4), 0);
    EXPECT_EQ(axialBin(-0.1 + 1e-12, -0.2, 0.4, 4), 1);
    EXPECT_EQ(axialBin(0.2, -0.2, 0.4, 4), 3);              // on the top face
    EXPECT_EQ(axialBin(-0.3, -0.2, 0.4, 4), 0);
}

TEST(TransportStatistics, OneValueForEachColumn)
{
    TransportStatisticsRow row;
    row.t = 0.5;
    row.blockedTime = 0.25;
    const std::vector<double> values = transportStatisticsValues(row);
    ASSERT_EQ(values.size(), transportStatisticsColumns().size());
    EXPECT_EQ(values.front(), 0.5);
    EXPECT_EQ(values.back(), 0.25);

    // the contact columns in their places, each value under its name
    row.impactSpeedMax = 1;
    row.wallEnergy = 2;
    row.pairContacts = 3;
    row.pairContactRate = 4;
    row.pairImpacts = 5;
    row.pairImpactSpeedMean = 6;
    row.pairImpactSpeedMax = 7;
    row.pairEnergy = 8;
    row.blockedBins = 9;
    const std::vector<std::string> names = transportStatisticsColumns();
    const std::vector<double> filled = transportStatisticsValues(row);
    const std::vector<std::string> order{"impactSpeedMax", "wallEnergy", "pairContacts",
        "pairContactRate", "pairImpacts", "pairImpactSpeedMean", "pairImpactSpeedMax",
        "pairEnergy", "blockedBins"};
    const auto first = std::find(names.begin(), names.end(), "impactSpeedMax") - names.begin();
    for (std::size_t k = 0; k < order.size(); ++k)
    {
        ASSERT_LT(first + k, names.size());
        EXPECT_EQ(names[first + k], order[k]);
        EXPECT_EQ(filled[first + k], double(k + 1)) << order[k];
    }

    std::ostringstream os;
    os << statisticsHeader("title", profileColumns("Cv_r", 3));
    writeStatisticsRow(os, {1, 2, 3, 4});
    EXPECT_EQ(os.str(), "# title\n# t Cv_r0 Cv_r1 Cv_r2\n1 2 3 4\n");
}
