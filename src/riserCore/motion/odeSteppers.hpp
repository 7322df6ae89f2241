// riserCore: explicit Runge–Kutta steppers and a step-size controller,
// generic over the system they integrate. A System has a State type (an
// Eigen vector) and State rate(double t, const State& y) const; the
// steppers know nothing of particles, the controller nothing of the
// system, and events and output live with the schemes that use them
// (motion/riserIntegrators.hpp), as Boost.Odeint keeps system, stepper,
// step controller and observer apart.
//
// dormandPrince5 - the Dormand–Prince 5(4) pair (Dormand & Prince, J. Comput.
//     Appl. Math. 6, 19, 1980): the fifth-order solution, the error
//     estimate against the embedded fourth-order one, and the fourth-order
//     continuous extension over the step (Hairer, Norsett & Wanner, Solving
//     ODEs I, 2nd ed., sec. II.6). The pair is first-same-as-last: the rate
//     at the step's end (its seventh stage) is the next step's first stage,
//     which the caller passes back in while the state is unchanged.
// rungeKutta4 - the classical fourth-order step.
// ErrorControl - the error norm of a step with absolute scales per
//     component and a relative tolerance, and the next step size
//     (no growth right after a rejection: Hairer, Norsett & Wanner, sec.
//     II.4).
//
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef RISERCORE_MOTION_ODESTEPPERS_HPP
#define RISERCORE_MOTION_ODESTEPPERS_HPP

#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <cmath>

namespace riser {

//- A Dormand–Prince step: the solution at its end, the error estimate, the
//  rate at its end, and the coefficients of the continuous extension
template<class State>
struct DenseStep
{
    State y;        //!< the fifth-order solution at t + h
    State err;      //!< fifth minus fourth order
    State rateEnd;  //!< dy/dt at (t + h, y): the next step's first stage
    std::array<State, 5> dense;

    //- The state at t + theta h, theta in [0, 1] (fourth order)
    State at(double theta) const
    {
        const double u = 1.0 - theta;
        return dense[0] + theta*(dense[1] + u*(dense[2] + theta*(dense[3] + u*dense[4])));
    }
};

//- One Dormand–Prince 5(4) step of length h from (t, y), k1 = dy/dt at (t, y)
template<class System>
DenseStep<typename System::State> dormandPrince5
(
    const System& sys, double t, const typename System::State& y, double h,
    const typename System::State& k1
)
{
    // the tableau
    constexpr double c2 = 1.0/5, c3 = 3.0/10, c4 = 4.0/5, c5 = 8.0/9;
    constexpr double a21 = 1.0/5;
    constexpr double a31 = 3.0/40, a32 = 9.0/40;
    constexpr double a41 = 44.0/45, a42 = -56.0/15, a43 = 32.0/9;
    constexpr double a51 = 19372.0/6561, a52 = -25360.0/2187, a53 = 64448.0/6561,
                     a54 = -212.0/729;
    constexpr double a61 = 9017.0/3168, a62 = -355.0/33, a63 = 46732.0/5247,
                     a64 = 49.0/176, a65 = -5103.0/18656;
    constexpr double b1 = 35.0/384, b3 = 500.0/1113, b4 = 125.0/192,
                     b5 = -2187.0/6784, b6 = 11.0/84;
    // b - b* (fifth minus fourth order weights)
    constexpr double e1 = 71.0/57600, e3 = -71.0/16695, e4 = 71.0/1920,
                     e5 = -17253.0/339200, e6 = 22.0/525, e7 = -1.0/40;
    // the continuous extension's
    constexpr double d1 = -12715105075.0/11282082432.0,
                     d3 = 87487479700.0/32700410799.0,
                     d4 = -10690763975.0/1880347072.0,
                     d5 = 701980252875.0/199316789632.0,
                     d6 = -1453857185.0/822651844.0,
                     d7 = 69997945.0/29380423.0;

    using State = typename System::State;
    const State k2 = sys.rate(t + c2*h, y + h*(a21*k1));
    const State k3 = sys.rate(t + c3*h, y + h*(a31*k1 + a32*k2));
    const State k4 = sys.rate(t + c4*h, y + h*(a41*k1 + a42*k2 + a43*k3));
    const State k5 = sys.rate(t + c5*h, y + h*(a51*k1 + a52*k2 + a53*k3 + a54*k4));
    const State k6 = sys.rate(t + h, y + h*(a61*k1 + a62*k2 + a63*k3 + a64*k4 + a65*k5));
    DenseStep<State> st;
    st.y = y + h*(b1*k1 + b3*k3 + b4*k4 + b5*k5 + b6*k6);
    st.rateEnd = sys.rate(t + h, st.y);
    const State& k7 = st.rateEnd;
    st.err = h*(e1*k1 + e3*k3 + e4*k4 + e5*k5 + e6*k6 + e7*k7);
    st.dense[0] = y;
    st.dense[1] = st.y - y;
    st.dense[2] = h*k1 - st.dense[1];
    st.dense[3] = st.dense[1] - h*k7 - st.dense[2];
    st.dense[4] = h*(d1*k1 + d3*k3 + d4*k4 + d5*k5 + d6*k6 + d7*k7);
    return st;
}

//- One classical fourth-order Runge–Kutta step of length h from (t, y)
template<class System>
typename System::State rungeKutta4
(
    const System& sys, double t, const typename System::State& y, double h
)
{
    using State = typename System::State;
    const State k1 = sys.rate(t, y);
    const State k2 = sys.rate(t + 0.5*h, y + 0.5*h*k1);
    const State k3 = sys.rate(t + 0.5*h, y + 0.5*h*k2);
    const State k4 = sys.rate(t + h, y + h*k3);
    return y + h/6.0*(k1 + 2.0*k2 + 2.0*k3 + k4);
}

//- Error norm and step size of an embedded pair of order 5(4)
template<class State>
class ErrorControl
{
public:
    //- tol: relative tolerance; scale: each component's absolute scale
    ErrorControl(double tol, const State& scale)
    :
        tol_(tol), scale_(scale)
    {}

    //- RMS of the error over tol (scale + |y|), y the larger of the states
    //  at the step's two ends: a step is accepted at <= 1
    double norm(const State& err, const State& a, const State& b) const
    {
        double sum = 0.0;
        for (int i = 0; i < err.size(); ++i)
        {
            const double s = scale_(i)*tol_ + tol_*std::max(std::abs(a(i)), std::abs(b(i)));
            sum += (err(i)/s)*(err(i)/s);
        }
        return std::sqrt(sum/err.size());
    }

    //- The step after a rejected step h with error e (may be inf)
    static double afterRejection(double h, double e)
    {
        return h*std::max(0.1, 0.9*std::pow(std::isfinite(e) ? e : 1e10, -0.2));
    }

    //- The step after an accepted step h with error e
    static double afterAcceptance(double h, double e, bool justRejected)
    {
        return h*std::min(justRejected ? 1.0 : 5.0, 0.9*std::pow(std::max(e, 1e-10), -0.2));
    }

private:
    double tol_;
    State scale_;
};

} // namespace riser

#endif
