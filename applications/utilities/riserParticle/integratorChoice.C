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
    integratorChoice c;
    if (dict.found("writeFrom"))
    {
        c.writeFrom = checkedEntry::nonNegative(dict, "writeFrom");
    }
    c.name = args.getOrDefault<word>
    (
        "integrator", dict.lookupOrDefault<word>("integrator", "adaptive")
    );
    const scalar unit = s.riser.diameter()/max(s.riser.centreLineSpeed(), SMALL);
    if (c.name == "adaptive")
    {
        const dictionary& coeffs = dict.subOrEmptyDict("adaptiveCoeffs");
        const scalar tol =
            coeffs.found("tolerance") ? inRange(coeffs, "tolerance", 0, false, 1, false) : 1e-6;
        const scalar maxStep =
            coeffs.found("maxStep") ? positive(coeffs, "maxStep") : VGREAT;
        c.adaptive.reset(new riser::AdaptiveScheme(tol, maxStep));
    }
    else if (c.name == "paper")
    {
        const dictionary& coeffs = dict.subOrEmptyDict("paperCoeffs");
        const scalar flow =
            coeffs.found("flowStep") ? positive(coeffs, "flowStep") : 1e-3*unit;
        const scalar contact =
            coeffs.found("contactStep") ? positive(coeffs, "contactStep") : 1e-6*unit;
        const scalar eps = coeffs.found("eps") ? nonNegative(coeffs, "eps") : 1e-3;
        const word start = coeffs.lookupOrDefault<word>("contactStart", "detection");
        if (start != "detection" && start != "geometric")
        {
            FatalIOErrorInFunction(coeffs)
                << "contactStart '" << start << "' is not one of: detection geometric"
                << exit(FatalIOError);
        }
        c.paper.reset
        (
            new riser::PaperScheme
            (
                flow, contact, eps,
                start == "detection"
              ? riser::ContactStart::detection : riser::ContactStart::geometric
            )
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
