// Oracle for the settling case tests: the terminal velocity of a sphere at
// which the core's wall-corrected drag balances the buoyant weight,
//     (rho_p - rho_f) V g = (pi d mu / 8) C_D(Re) Re v,   Re = rho_f d v / mu,
// found by bisection (the drag is increasing in v away from the jumps of the
// paper correlation; the cases are placed where the root is unique).
//
// usage: terminalVelocity d rho_p rho_f mu g D paper|continuous
// SPDX-License-Identifier: GPL-3.0-or-later
#include "drag/dragCoefficient.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

int main(int argc, char* argv[])
{
    if (argc != 8)
    {
        std::fprintf(stderr, "usage: %s d rho_p rho_f mu g D paper|continuous\n", argv[0]);
        return 2;
    }
    const double d = std::atof(argv[1]), rhoP = std::atof(argv[2]), rhoF = std::atof(argv[3]);
    const double mu = std::atof(argv[4]), g = std::atof(argv[5]), D = std::atof(argv[6]);
    const std::string name = argv[7];
    const riser::DragLaw law = name == "continuous" ? riser::DragLaw::continuous : riser::DragLaw::paper;
    const riser::WallFactors w(d/D);
    const double weight = (rhoP - rhoF)*M_PI*d*d*d/6.0*g;
    auto excess = [&](double v)
    {
        const double Re = rhoF*d*v/mu;
        return weight - M_PI*d*mu/8.0*riser::dragCoefficientTimesRe(law, Re, w)*v;
    };
    double lo = 0.0, hi = 1.0;
    while (excess(hi) > 0.0) hi *= 2.0;
    for (int i = 0; i < 200 && hi - lo > 1e-15*hi; ++i)
    {
        const double mid = 0.5*(lo + hi);
        (excess(mid) > 0.0 ? lo : hi) = mid;
    }
    std::printf("%.12g\n", 0.5*(lo + hi));
    return 0;
}
