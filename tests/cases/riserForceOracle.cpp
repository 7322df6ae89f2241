// Oracle for the exact-carrier force test: the forces of the riser force
// models on particles, evaluated directly with the physics core.
//
// usage: riserForceOracle rho_f mu t D uCentre A omega phi0 paper|continuous CA
//   stdin: one particle a line, "x y z ux uy uz d rho_p"
//   stdout: one particle a line, the forces drag, lift, added mass (explicit
//           part C_A rho_f V Du/Dt) and fluid stress, 12 numbers.
// SPDX-License-Identifier: GPL-3.0-or-later
#include "carrier/riserFlow.hpp"
#include "drag/dragCoefficient.hpp"
#include "lift/saffmanMeiLift.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <string>

int main(int argc, char* argv[])
{
    if (argc != 11)
    {
        std::fprintf(stderr, "usage: %s rho_f mu t D uCentre A omega phi0 law CA\n", argv[0]);
        return 2;
    }
    const double rho = std::atof(argv[1]), mu = std::atof(argv[2]), t = std::atof(argv[3]);
    const riser::RiserFlow flow(std::atof(argv[4]), std::atof(argv[5]), std::atof(argv[6]),
                                std::atof(argv[7]), std::atof(argv[8]));
    const riser::DragLaw law =
        std::string(argv[9]) == "continuous" ? riser::DragLaw::continuous : riser::DragLaw::paper;
    const double CA = std::atof(argv[10]);

    riser::Vector x, v;
    double d, rhoP;
    while (std::cin >> x[0] >> x[1] >> x[2] >> v[0] >> v[1] >> v[2] >> d >> rhoP)
    {
        const riser::Vector u = flow.velocity(x, t);
        const riser::Vector w = u - v;
        const riser::Vector Omega = flow.vorticity(x, t);
        const riser::Vector DuDt = flow.materialDerivative(x, t);
        const double V = M_PI*d*d*d/6.0;
        const double Rep = rho*w.norm()*d/mu;
        const double Res = rho*d*d*Omega.norm()/mu;

        const riser::WallFactors walls(d/flow.diameter());
        const riser::Vector drag =
            M_PI*d*d/8.0*rho*riser::dragCoefficient(law, Rep, walls)*w.norm()*w;
        const riser::Vector lift =
            M_PI*d*d*d/8.0*rho*riser::saffmanMeiCoefficient(Rep, Res)*w.cross(Omega);
        const riser::Vector fluidStress = rho*V*DuDt;
        const riser::Vector addedMass = CA*fluidStress;

        for (const riser::Vector& f : {drag, lift, addedMass, fluidStress})
        {
            std::printf("%.17g %.17g %.17g ", f[0], f[1], f[2]);
        }
        std::printf("\n");
    }
    return 0;
}
