// Tests of the Langevin model of the fluid velocity seen in RAS turbulence
// (src/riserCore/dispersion/langevinSeenVelocity.hpp), by Monte Carlo
// against closed forms.
// SPDX-License-Identifier: GPL-3.0-or-later
#include "dispersion/langevinSeenVelocity.hpp"

#include <gtest/gtest.h>
#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

using namespace riser;

namespace {

struct Normals
{
    std::mt19937_64 engine;
    std::normal_distribution<double> normal;

    explicit Normals(unsigned seed) : engine(seed), normal(0.0, 1.0) {}

    Vector operator()()
    {
        const double x = normal(engine), y = normal(engine), z = normal(engine);
        return Vector(x, y, z);
    }
};

// Taylor (1921): the displacement variance of a tracer whose velocity is a
// stationary Gaussian process of variance sigma^2 and exponential
// autocorrelation of time T: 2 sigma^2 T^2 (t/T - 1 + e^{-t/T})
double taylorVariance(double sigma, double T, double t)
{
    return 2*sigma*sigma*T*T*(t/T - 1 + std::exp(-t/T));
}

} // namespace

// Homogeneous turbulence: tracers moved by the step mean of the seen
// velocity spread as Taylor's closed form at every time, whether the step
// is a hundredth of T or three times T (the step is drawn exactly), and the
// seen fluctuation keeps its variance. N = 20,000 tracers, three components
// each: the sample variance's relative standard error is sqrt(2/(3N)) =
// 0.58 %; tolerance 4 standard errors, 2.3 %.
TEST(LangevinDispersion, TaylorSpreadingAtAnyStep)
{
    const double sigma = 0.08, T = 0.2;
    const int N = 20000;
    const double tolerance = 4*std::sqrt(2.0/(3*N));
    for (const double dtOverT : {0.01, 0.3, 3.0})
    {
        Normals xi(17);
        const double dt = dtOverT*T;
        std::vector<Vector> chi(N), x(N, Vector::Zero());
        for (Vector& c : chi) c = xi();
        const int steps = int(std::lround(15/dtOverT));
        const std::vector<int> checks = {int(std::lround(0.9/dtOverT)), int(std::lround(3/dtOverT)), steps};
        for (int n = 1; n <= steps; ++n)
        {
            for (int i = 0; i < N; ++i)
            {
                const LangevinStep s = langevinStep(chi[i], Vector::Zero(), T, dt, xi(), xi());
                x[i] += sigma*s.chiMean*dt;
                chi[i] = s.chiEnd;
            }
            for (const int c : checks)
            {
                if (n != c) continue;
                double var = 0, chi2 = 0;
                for (int i = 0; i < N; ++i)
                {
                    var += x[i].squaredNorm();
                    chi2 += chi[i].squaredNorm();
                }
                var /= 3*N;
                chi2 /= 3*N;
                const double expected = taylorVariance(sigma, T, n*dt);
                EXPECT_NEAR(var/expected, 1.0, tolerance)
                    << "dt/T = " << dtOverT << ", t/T = " << n*dtOverT;
                EXPECT_NEAR(chi2, 1.0, tolerance) << "dt/T = " << dtOverT;
            }
        }
    }
}

// The diffusivity in the diffusive limit is sigma^2 T_L = nu_t/Sc_t (the
// time scale's definition, checked as arithmetic), and a particle falling
// through the eddies at slip w sees them for T_L/sqrt(1 + (beta w/sigma)^2)
TEST(LangevinDispersion, TimeScales)
{
    const double nut = 1e-3, Sct = 0.7, sigma = 0.05;
    const double TL = lagrangianTime(nut, Sct, sigma);
    EXPECT_NEAR(sigma*sigma*TL, nut/Sct, 1e-15);
    EXPECT_DOUBLE_EQ(crossingTrajectoryTime(TL, 0.0, 3.0, sigma), TL);
    EXPECT_NEAR(crossingTrajectoryTime(TL, 1.0, 0.05*std::sqrt(3.0), sigma), TL/2, 1e-15);
}

// The step's moments against their closed forms from the exact solution:
// the end value's variance 1 - a^2, the step mean's variance
// 2(h - 1 + a)/h^2 from a stationary start (its series and its closed form
// on both sides of h = 1e-2, where the code switches to its series), and
// their covariance (1 - a)/h. These stationary moments are derived apart
// from the code's conditional ones (which they sum). Each to 1e-9 relative:
// the series' truncation is below 4e-10, the closed forms' round-off below.
TEST(LangevinDispersion, StepMomentsExact)
{
    for (const double h : {1e-6, 1e-3, 0.0099, 0.0101, 0.5, 3.0, 40.0})
    {
        const OrnsteinUhlenbeckStep s(1.0, h);
        const double a = std::exp(-h);
        EXPECT_NEAR(s.a*s.a + s.sx*s.sx, 1.0, 1e-12) << h;
        // stationary start, v0 ~ N(0, 1) independent of the noises
        const double varMean = s.m*s.m + s.cx*s.cx + s.sm*s.sm;
        // 2(h - 1 + a)/h^2, by its series where the closed form cancels
        const double expectedVarMean =
            h < 0.02
          ? 1 - h/3 + h*h/12 - h*h*h/60 + h*h*h*h/360
          : 2*(h - 1 + a)/(h*h);
        EXPECT_NEAR(varMean/expectedVarMean, 1.0, 1e-9) << h;
        const double covEndMean = s.a*s.m + s.sx*s.cx;
        EXPECT_NEAR(covEndMean/(-std::expm1(-h)/h), 1.0, 1e-9) << h;
    }
}

// Thomson's well-mixed condition: tracers spread uniformly over a periodic
// interval of inhomogeneous turbulence, sigma(x) = sigma0 (1 + 0.6 sin(2 pi
// x/L)) along x, stay uniform. L = 0.05 m is crossed by diffusion (D =
// sigma0^2 T) in 25 T; after 60 T the counts in 10 bins of N = 10,000
// tracers pass a chi-square test at the 0.1 % level (27.9 for 9 degrees of
// freedom). The step holds sigma and its gradient, a first-order error in
// sigma dt/l, l = sigma/|grad sigma| (here 0.013 m): the chi-square was
// 73 at dt = 0.1 T, 21 at 0.05 T and 7 at 0.02 T, the step used here. Blind check: the naive walk, which keeps the fluctuation u'
// itself from step to step and has no drift term, gathers the tracers where
// the turbulence is weak (the known failure of random walks in
// inhomogeneous turbulence), far beyond that bound.
TEST(LangevinDispersion, WellMixed)
{
    const double L = 0.05, sigma0 = 0.05, T = 0.2, dt = 0.02*T;
    const double pi = 3.14159265358979323846;
    const int N = 10000, bins = 10;
    auto sigmaAt = [&](double x) { return sigma0*(1 + 0.6*std::sin(2*pi*x/L)); };
    auto gradAt = [&](double x) { return sigma0*0.6*2*pi/L*std::cos(2*pi*x/L); };
    auto chiSquare = [&](bool wellMixed)
    {
        Normals xi(5);
        std::vector<double> x(N);
        std::vector<Vector> chi(N), u(N);
        for (int i = 0; i < N; ++i)
        {
            x[i] = (i + 0.5)*L/N;
            chi[i] = xi();
            u[i] = sigmaAt(x[i])*chi[i];
        }
        for (int n = 0; n < int(std::lround(60*T/dt)); ++n)
        {
            for (int i = 0; i < N; ++i)
            {
                const double sigma = sigmaAt(x[i]);
                if (!wellMixed)
                {
                    chi[i] = u[i]/sigma;
                }
                const Vector grad(wellMixed ? gradAt(x[i]) : 0.0, 0, 0);
                const LangevinStep s = langevinStep(chi[i], grad, T, dt, xi(), xi());
                x[i] += sigma*s.chiMean.x()*dt;
                x[i] -= L*std::floor(x[i]/L);
                chi[i] = s.chiEnd;
                u[i] = sigma*s.chiEnd;
            }
        }
        std::vector<double> count(bins, 0.0);
        for (const double xi_ : x) count[std::min(bins - 1, int(xi_/L*bins))] += 1;
        double c2 = 0;
        for (const double c : count) c2 += (c - double(N)/bins)*(c - double(N)/bins)/(double(N)/bins);
        return c2;
    };
    const double wellMixed = chiSquare(true), naive = chiSquare(false);
    std::printf("chi-square of 10 bins: well-mixed %.1f, naive %.1f\n", wellMixed, naive);
    EXPECT_LT(wellMixed, 27.9);
    EXPECT_GT(naive, 10*27.9);
}
