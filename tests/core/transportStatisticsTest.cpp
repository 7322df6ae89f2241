// Tests of the transport-statistics schema and bins (src/riserCore/output).
// SPDX-License-Identifier: GPL-3.0-or-later
#include "output/transportStatistics.hpp"

#include <gtest/gtest.h>
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

    std::ostringstream os;
    os << statisticsHeader("title", profileColumns("Cv_r", 3));
    writeStatisticsRow(os, {1, 2, 3, 4});
    EXPECT_EQ(os.str(), "# title\n# t Cv_r0 Cv_r1 Cv_r2\n1 2 3 4\n");
}
