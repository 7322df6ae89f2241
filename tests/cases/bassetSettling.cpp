// Oracle for the Basset settling case test: the settling velocity from rest
// of a sphere in quiescent fluid with creeping-flow drag corrected for the
// riser wall (the core's K(d/D): drag 3 pi mu d K w, the Re_p <= 1 branch of
// the wall-corrected law), added mass C_A = 1/2, the classical Basset force
// and the buoyant weight: the closed form of tests/oracles/bassetClosedForms.hpp
// with alpha = 3 pi mu d K/M.
//
// usage: bassetSettling d rho_p rho_f mu g D < times   (prints "t V" lines)
// SPDX-License-Identifier: GPL-3.0-or-later
#include "bassetClosedForms.hpp"
#include "drag/dragCoefficient.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iostream>

int main(int argc, char* argv[])
{
    if (argc != 7)
    {
        std::fprintf(stderr, "usage: %s d rho_p rho_f mu g D < times\n", argv[0]);
        return 2;
    }
    const double d = std::atof(argv[1]), rhoP = std::atof(argv[2]), rhoF = std::atof(argv[3]);
    const double mu = std::atof(argv[4]), g = std::atof(argv[5]), D = std::atof(argv[6]);
    const double a = 0.5*d, V = M_PI*d*d*d/6.0;
    const double M = (rhoP + 0.5*rhoF)*V;
    const double K = riser::WallFactors(d/D).K;
    const double alpha = 3.0*M_PI*mu*d*K/M;
    const double gamma = 6.0*M_PI*a*a*std::sqrt(rhoF*mu)/M;
    const double G = (rhoP - rhoF)*V*g/M;
    double t;
    while (std::cin >> t)
    {
        std::printf("%.17g %.17g\n", t, oracle::settlingFromRest(alpha, gamma, G, t));
    }
    return 0;
}
