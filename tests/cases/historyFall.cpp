// Oracle for the finite-Re Basset case test: the descent speed from rest of
// a sphere in quiescent liquid on the riser's axis under its buoyant weight,
// the library's continuous drag law with the pipe's wall factors
// (riser::dragFactor, DragLaw::continuous, d/D), added mass C_A = 1/2 and the
// history force with the classical or the finite-Re kernel, by the
// independent full-history quadrature of tests/oracles/historyFall.hpp at
// step h, linearly interpolated at the times read.
//
// usage: historyFall d rho_p rho_f mu g D classical|meiAdrian h < times
//        (prints "t V" lines)
// SPDX-License-Identifier: GPL-3.0-or-later
#include "historyFall.hpp"
#include "drag/dragCoefficient.hpp"

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iostream>

int main(int argc, char* argv[])
{
    if (argc != 9)
    {
        std::fprintf(stderr, "usage: %s d rho_p rho_f mu g D classical|meiAdrian h < times\n",
                     argv[0]);
        return 2;
    }
    const double d = std::atof(argv[1]), rhoP = std::atof(argv[2]), rhoF = std::atof(argv[3]);
    const double mu = std::atof(argv[4]), g = std::atof(argv[5]), D = std::atof(argv[6]);
    const bool finiteRe = std::strcmp(argv[7], "meiAdrian") == 0;
    const double h = std::atof(argv[8]);
    const riser::WallFactors walls(d/D);
    oracle::FallingSphere s{d, rhoP, rhoF, mu, g, 0.5, [&](double V)
    {
        return riser::dragFactor(riser::DragLaw::continuous, walls, d, mu, rhoF*d*V/mu)*V;
    }};
    std::vector<double> times;
    double t;
    while (std::cin >> t) times.push_back(t);
    if (times.empty()) return 0;
    const std::vector<double> u =
        oracle::historyFall(s, finiteRe, h, HUGE_VAL, long(times.back()/h) + 2);
    for (const double time : times)
    {
        const double x = time/h;
        const size_t i = std::min(size_t(x), u.size() - 2);
        std::printf("%.17g %.17g\n", time, u[i] + (x - i)*(u[i + 1] - u[i]));
    }
    return 0;
}
