/*---------------------------------------------------------------------------*\
  riserFoam: particle transport in vibrating risers, on OpenFOAM
  License: GPL-3.0-or-later
\*---------------------------------------------------------------------------*/

#include "integratorChoice.H"

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

Foam::integratorChoice Foam::readIntegrator
(
    const Time& runTime,
    const argList& args,
    const riserScene& s
)
{
    using namespace checkedEntry;
    dictionary dict;
    IOobject io
    (
        "riserParticleDict", runTime.system(), runTime,
        IOobject::MUST_READ, IOobject::NO_WRITE, false
    );
    if (io.typeHeaderOk<IOdictionary>(true))
    {
        dict = IOdictionary(io);
    }
    allowedKeys(dict, {"writeFrom", "integrator", "adaptiveCoeffs", "paperCoeffs"});
    integratorChoice c;
    // rows from writeFrom on: at or after endTime there would be none
    c.writeFrom = inRange(dict, "writeFrom", 0, true, s.endTime, false, 0);
    c.name = args.getOrDefault<word>
    (
        "integrator", dict.lookupOrDefault<word>("integrator", "adaptive")
    );
    const scalar unit = s.riser.diameter()/max(s.riser.centreLineSpeed(), SMALL);
    if (c.name == "adaptive")
    {
        const dictionary& coeffs = dict.subOrEmptyDict("adaptiveCoeffs");
        allowedKeys(coeffs, {"tolerance", "maxStep"});
        const scalar tol = inRange
        (
            coeffs, "tolerance", 1e-14, true, 1, false,
            riser::AdaptiveScheme::defaultTolerance
        );
        const scalar maxStep = inRange(coeffs, "maxStep", 1e-10, true, VGREAT, true, VGREAT);
        c.adaptive.reset(new riser::AdaptiveScheme(tol, maxStep));
    }
    else if (c.name == "paper")
    {
        const dictionary& coeffs = dict.subOrEmptyDict("paperCoeffs");
        // (the other reading of the paper's contact start, at the
        // penetration the flow step left, gains energy at every contact
        // and runs away in the riser scenes: doc/theory.md section 7.3; it
        // is not offered)
        allowedKeys(coeffs, {"flowStep", "contactStep", "eps"});
        const scalar flow = inRange(coeffs, "flowStep", 1e-10, true, VGREAT, true, 1e-3*unit);
        const scalar contact =
            inRange(coeffs, "contactStep", 1e-10, true, VGREAT, true, 1e-6*unit);
        const scalar eps = inRange(coeffs, "eps", 0, true, 1, false, 1e-3);
        c.paper.reset
        (
            new riser::PaperScheme(flow, contact, eps, riser::ContactStart::detection)
        );
    }
    else
    {
        FatalIOErrorInFunction(dict)
            << "integrator '" << c.name << "' is not one of: adaptive paper"
            << exit(FatalIOError);
    }
    return c;
}


// ************************************************************************* //
