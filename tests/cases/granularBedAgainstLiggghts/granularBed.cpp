// Pours the grains of a LIGGGHTS data file (atom_style granular: id type
// diameter density x y z) into a closed vertical riser section, a cylinder
// of radius R about the z axis on a floor at z = 0, with riserCore's grain
// engine, and writes the final grains (x y z radius) and the mean
// coordination number, the largest pair overlap (fraction of the smaller
// diameter) and the largest velocity component.
//
// Usage: granularBed <data> <E> <nu> <e_n> <mu> <dt> <steps> <R> <out>
//
// The contact law is the one of LIGGGHTS' `pair_style gran model hertz
// tangential history` for the same inputs: k_n, k_t, E_eq, G_eq and the
// normal damping are the same functions of (E, nu, e_n); LIGGGHTS damps the
// tangential spring with sqrt(5/6) times the normal damping ratio, so the
// tangential restitution passed here is the e_t of that damping ratio.
// SPDX-License-Identifier: GPL-3.0-or-later
#include "granular/granularSystem.hpp"
#include "riser/sinusoidMotion.hpp"
#include "wall/cylinderWall.hpp"
#include "wall/planeWall.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>

using namespace riser;

int main(int argc, char** argv)
{
    if (argc != 10)
    {
        std::cerr << "usage: granularBed <data> <E> <nu> <e_n> <mu> <dt> <steps> <R> <out>\n";
        return 2;
    }
    const double E = std::atof(argv[2]), nu = std::atof(argv[3]);
    const double e = std::atof(argv[4]), mu = std::atof(argv[5]);
    const double dt = std::atof(argv[6]);
    const long steps = std::atol(argv[7]);
    const double R = std::atof(argv[8]);

    const double lnE = std::log(e);
    const double zetaN = -lnE/std::sqrt(M_PI*M_PI + lnE*lnE);
    const double zetaT = std::sqrt(5.0/6.0)*zetaN;
    const double et = std::exp(-M_PI*zetaT/std::sqrt(1.0 - zetaT*zetaT));

    const ElasticMaterial ore(E, nu);
    const HertzMindlin law(HertzMindlinParameters{ore, ore, e, et, mu});
    GranularSystem s(law, law, Vector(0, 0, -9.81), true);
    const CylinderWall riserWall(2.0*R, SinusoidMotion::atRest());
    const PlaneWall floor(Vector::Zero(), Vector(0, 0, 1));
    s.addWall(riserWall);
    s.addWall(floor);

    std::ifstream in(argv[1]);
    std::string line;
    bool atoms = false;
    while (std::getline(in, line))
    {
        if (line.rfind("Atoms", 0) == 0) { atoms = true; continue; }
        if (!atoms) continue;
        std::istringstream l(line);
        long id, type;
        double d, rho, x, y, z;
        if (!(l >> id >> type >> d >> rho >> x >> y >> z)) continue;
        const double r = 0.5*d;
        s.addGrain(Grain{Vector(x, y, z), Vector::Zero(), Vector::Zero(), r,
                         rho*4.0/3.0*M_PI*r*r*r});
    }
    for (long k = 0; k < steps; ++k) s.step(dt);

    std::ofstream out(argv[9]);
    out.precision(10);
    for (const Grain& g : s.grains())
    {
        out << g.x.x() << ' ' << g.x.y() << ' ' << g.x.z() << ' ' << g.radius << '\n';
    }
    double vmax = 0.0;
    for (const Grain& g : s.grains()) vmax = std::max(vmax, g.v.cwiseAbs().maxCoeff());
    std::printf("grains %zu coordination %.6f largestPairOverlap %.4g maxSpeed %.4g\n",
                s.grains().size(), s.coordinationNumber(), s.largestPairOverlap(), vmax);
    return 0;
}
